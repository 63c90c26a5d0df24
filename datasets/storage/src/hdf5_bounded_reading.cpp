// Bounded reads from untrusted HDF5 files (hdf5_bounded_reading.hpp).
#include "hdf5_bounded_reading.hpp"

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/input_file.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "string_heap_check.hpp"

namespace wpg::datasets::detail {

H5::H5File openFileForReading(const std::string& path) {
  checkInputFile(path);
  if (!H5::H5File::isHdf5(path)) throw InputError(path + ": not an HDF5 file");
  return H5::H5File(path, H5F_ACC_RDONLY);
}
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw InputError(file + ": " + message);
}

// The attribute `name`, holding exactly one element of class `type_class`.
H5::Attribute openSingleAttribute(const H5::H5Object& object, const std::string& name,
                                  H5T_class_t type_class, const char* expected,
                                  const std::string& file, const std::string& where) {
  const std::string what = "attribute " + where + name;
  if (!object.attrExists(name)) fail(file, what + " is missing");
  H5::Attribute attribute = object.openAttribute(name);
  const H5T_class_t found = attribute.getTypeClass();
  if (found != type_class &&
      !(type_class == H5T_FLOAT && found == H5T_INTEGER)) {  // an integer is a number too
    fail(file, what + ": expected " + expected);
  }
  // Checked before the count is formed (a wrapped product of dimensions could be 1).
  std::uint64_t count = 1;
  for (const hsize_t d : boundedExtent(attribute.getSpace(), 0, kMaxReadElements, file, what)) {
    count *= d;
  }
  if (count != 1) fail(file, what + ": expected one value, got " + std::to_string(count));
  return attribute;
}

}  // namespace

std::vector<hsize_t> boundedExtent(const H5::DataSpace& space, std::size_t element_size,
                                   std::uint64_t max_elements, const std::string& file,
                                   const std::string& what) {
  const H5S_class_t space_class = space.getSimpleExtentType();
  if (space_class == H5S_NULL) return {0};
  if (space_class != H5S_SIMPLE && space_class != H5S_SCALAR) {
    fail(file, what + " has an unknown dataspace: expected a scalar or an array");
  }
  const int rank = space.getSimpleExtentNdims();
  if (rank < 0 || rank > H5S_MAX_RANK) fail(file, what + " has an invalid rank");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) space.getSimpleExtentDims(dims.data());
  // The product is formed with an overflow check: 32 dimensions of 2^32 would wrap to 0.
  std::uint64_t count = 1;
  for (const hsize_t d : dims) {
    if (d != 0 && count > max_elements / d) {
      count = max_elements + 1;
      break;
    }
    count *= d;
  }
  if (count > max_elements) {
    std::string shape;
    for (std::size_t i = 0; i < dims.size(); ++i) shape += (i ? " x " : "") + std::to_string(dims[i]);
    fail(file, what + " declares " + shape + " elements: expected at most " +
                   std::to_string(max_elements) + " (the readers' limit, datasets/SCHEMA.md)");
  }
  if (element_size != 0 && count > kMaxReadBytes / element_size) {
    fail(file, what + " declares " + std::to_string(count) + " elements of " +
                   std::to_string(element_size) + " bytes: expected at most " +
                   std::to_string(kMaxReadBytes) + " bytes (the readers' limit, datasets/SCHEMA.md)");
  }
  return dims;
}

std::string readStringAttribute(const H5::H5Object& object, const std::string& name,
                                const std::string& file, const std::string& where) {
  const H5::Attribute attribute =
      openSingleAttribute(object, name, H5T_STRING, "a string", file, where);
  const H5::StrType type = attribute.getStrType();
  // A fixed-length string is read whole into a buffer of its declared size.
  if (!type.isVariableStr() && type.getSize() > kMaxReadBytes) {
    fail(file, "attribute " + where + name + " declares a string of " +
                   std::to_string(type.getSize()) + " bytes: expected at most " +
                   std::to_string(kMaxReadBytes));
  }
  // A variable-length one through its pointer: the C++ API's read into a std::string calls
  // strlen on it, and a null string (a heap ID of address 0) is a null pointer (found by
  // fuzz_shard_reader's heap damage).
  if (type.isVariableStr()) return readVariableStrings(attribute, file, "attribute " + where + name)[0];
  std::string value;
  attribute.read(type, value);
  return value;
}

double readNumberAttribute(const H5::H5Object& object, const std::string& name,
                           const std::string& file, const std::string& where) {
  const H5::Attribute attribute =
      openSingleAttribute(object, name, H5T_FLOAT, "a number", file, where);
  double value = 0.0;
  attribute.read(H5::PredType::NATIVE_DOUBLE, &value);
  return value;
}

namespace {

// HDF5 hands variable-length strings over as pointers it allocated; they are copied, then
// reclaimed. `read` reads into the pointers with the given memory type, of the stored
// strings' character set (HDF5 converts none into another: ASCII strings read as UTF-8 fail).
template <typename Read>
std::vector<std::string> copyVariableStrings(const H5::DataSpace& space, H5T_cset_t cset,
                                             Read read) {
  const std::size_t count = static_cast<std::size_t>(space.getSimpleExtentNpoints());
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(cset == H5T_CSET_ASCII ? H5T_CSET_ASCII : H5T_CSET_UTF8);
  std::vector<char*> pointers(count, nullptr);
  if (count > 0) read(type, pointers.data());
  std::vector<std::string> values;
  values.reserve(count);
  for (const char* pointer : pointers) values.emplace_back(pointer ? pointer : "");
  if (count > 0) H5Dvlen_reclaim(type.getId(), space.getId(), H5P_DEFAULT, pointers.data());
  return values;
}

}  // namespace

std::vector<std::string> readVariableStrings(const H5::DataSet& dataset, const std::string& file,
                                             const std::string& what) {
  checkVariableData(dataset, file, what);
  return copyVariableStrings(dataset.getSpace(), H5Tget_cset(dataset.getDataType().getId()),
                             [&](const H5::StrType& type, char** pointers) {
                               dataset.read(pointers, type);
                             });
}

std::vector<std::string> readVariableStrings(const H5::Attribute& attribute,
                                             const std::string& file, const std::string& what) {
  checkVariableData(attribute, file, what);
  return copyVariableStrings(attribute.getSpace(), H5Tget_cset(attribute.getDataType().getId()),
                             [&](const H5::StrType& type, char** pointers) {
                               attribute.read(type, pointers);
                             });
}

std::vector<std::string> readStringListAttribute(const H5::H5Object& object,
                                                 const std::string& name, const std::string& file,
                                                 const std::string& where) {
  const std::string what = "attribute " + where + name;
  if (!object.attrExists(name)) fail(file, what + " is missing");
  const H5::Attribute attribute = object.openAttribute(name);
  if (attribute.getTypeClass() != H5T_STRING) fail(file, what + ": expected a list of strings");
  const H5::DataSpace space = attribute.getSpace();
  const std::vector<hsize_t> dims =
      boundedExtent(space, sizeof(char*), kMaxReadElements, file, what);
  if (dims.size() > 1) fail(file, what + ": expected a list of strings, got a " +
                                      std::to_string(dims.size()) + "-D array");
  return readVariableStrings(attribute, file, what);
}

}  // namespace wpg::datasets::detail
