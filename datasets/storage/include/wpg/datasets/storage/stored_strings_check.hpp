#pragma once
// The variable-length strings of a file checked before a reader outside this library (the
// figure scripts of `wpg plot`, h5py in the Python package) reads them: HDF5 loops forever on
// a zeroed global heap and aborts or segfaults on an overwritten one, inside any process that
// reads the file, h5py's too. The library's own readers check each string as they read it
// (datasets/storage/src/string_heap_check.hpp).
#include <string>

namespace wpg::datasets {

// Checks every variable-length attribute and dataset of the objects below `group` of the file
// at `path` (and of the objects its external links lead to) against the global heaps they
// point into. Throws InputError, one line naming the file and the object ("PATH: attribute
// /runs/a_0:scenario: damaged variable-length data (...)"), or the refusal of an external link.
// Returns quietly when the file is not an HDF5 file HDF5 can open, or has no such group: the
// reader that follows reports those in its own words. Holds hdf5Mutex().
void checkStoredStrings(const std::string& path, const std::string& group = "/");

}  // namespace wpg::datasets
