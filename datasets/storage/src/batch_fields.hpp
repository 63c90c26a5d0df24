#pragma once
// The root attribute `fields` of a batch or shard file (datasets/SCHEMA.md, "Lean runs"): the
// fields its runs store, read back for `--resume` and `wpg merge`, which refuse to mix them.
#include <string>

#include <H5Cpp.h>

namespace wpg::datasets {

// "summary, footsteps", or "all" for a file without the attribute (every field, as in every
// file written before lean runs). Read bounded (the file may be anyone's); throws InputError
// naming `path` for a malformed attribute. The caller holds hdf5Mutex().
std::string storedFieldsText(const H5::H5File& file, const std::string& path);

}  // namespace wpg::datasets
