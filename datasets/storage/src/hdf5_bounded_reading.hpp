#pragma once
// Reading from HDF5 files we did not write, bounded: every size a file declares (a dataspace's rank
// and dimensions, an attribute's element count) is checked against the limits of
// wpg/datasets/storage/read_limits.hpp before anything is allocated for it, and attributes read
// into one value must hold exactly one (the C++ API would write past the value otherwise). Failures
// are InputError, one line: "FILE: <what> ..., expected ...".
#include <cstdint>
#include <string>
#include <vector>

#include <H5Cpp.h>

namespace wpg::datasets::detail {

// The file `path` open for reading, checked first (checkInputFile: a regular file this process
// may read), then its signature ("PATH: not an HDF5 file"). Every reader here opens its file so.
H5::H5File openFileForReading(const std::string& path);

// The dimensions of `space` (empty for a scalar; {0} for a null dataspace), after checking that
// it is simple, that its element count is at most `max_elements` and that count x
// `element_size` is at most kMaxReadBytes. `what` names the object in messages ("dataset
// /runs/x/com", "attribute /runs/x:scenario"); `file` is the file's path.
std::vector<hsize_t> boundedExtent(const H5::DataSpace& space, std::size_t element_size,
                                   std::uint64_t max_elements, const std::string& file,
                                   const std::string& what);

// The string attribute `name` of `object` (one element, of a string type; a variable-length
// one's global heap checked first). `where` prefixes the name in messages ("/runs/x:", "/:").
std::string readStringAttribute(const H5::H5Object& object, const std::string& name,
                                const std::string& file, const std::string& where);

// The number attribute `name` (one element, integer or floating-point), as a double.
double readNumberAttribute(const H5::H5Object& object, const std::string& name,
                           const std::string& file, const std::string& where);

// Every element of a dataset or attribute of variable-length strings, read as UTF-8. The caller
// has bounded its extent (boundedExtent): this allocates one pointer per element. The strings'
// global heaps are checked first (string_heap_check.hpp); `what` names the dataset or
// attribute in messages.
std::vector<std::string> readVariableStrings(const H5::DataSet& dataset, const std::string& file,
                                             const std::string& what);
std::vector<std::string> readVariableStrings(const H5::Attribute& attribute,
                                             const std::string& file, const std::string& what);

// The string-list attribute `name` (scalar or 1-D, of variable-length strings), bounded.
std::vector<std::string> readStringListAttribute(const H5::H5Object& object,
                                                 const std::string& name, const std::string& file,
                                                 const std::string& where);

}  // namespace wpg::datasets::detail
