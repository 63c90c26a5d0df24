#pragma once
// Reading datasets and attributes back with the plain HDF5 C++ API, for the dataset tests
// (a reader independent of the writer under test).
#include <string>
#include <vector>

#include <H5Cpp.h>

namespace wpg_test {

inline std::vector<hsize_t> dimensions(const H5::DataSet& dataset) {
  const H5::DataSpace space = dataset.getSpace();
  std::vector<hsize_t> dims(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(dims.data());
  return dims;
}

// Every element of a dataset, row-major; its shape in *dims when given.
template <typename T>
std::vector<T> readAll(const H5::Group& group, const std::string& name,
                       const H5::PredType& memory_type, std::vector<hsize_t>* dims = nullptr) {
  const H5::DataSet dataset = group.openDataSet(name);
  const std::vector<hsize_t> shape = dimensions(dataset);
  if (dims) *dims = shape;
  hsize_t count = 1;
  for (const hsize_t d : shape) count *= d;
  std::vector<T> values(count);
  if (count > 0) dataset.read(values.data(), memory_type);
  return values;
}

inline std::vector<double> readDoubles(const H5::Group& group, const std::string& name,
                                       std::vector<hsize_t>* dims = nullptr) {
  return readAll<double>(group, name, H5::PredType::NATIVE_DOUBLE, dims);
}

inline std::vector<int> readInts(const H5::Group& group, const std::string& name,
                                 std::vector<hsize_t>* dims = nullptr) {
  return readAll<int>(group, name, H5::PredType::NATIVE_INT, dims);
}

inline std::string stringAttribute(const H5::H5Object& object, const std::string& name) {
  const H5::Attribute attribute = object.openAttribute(name);
  std::string value;
  attribute.read(attribute.getStrType(), value);
  return value;
}

inline std::vector<std::string> stringListAttribute(const H5::H5Object& object,
                                                    const std::string& name) {
  const H5::Attribute attribute = object.openAttribute(name);
  hsize_t count = 0;
  attribute.getSpace().getSimpleExtentDims(&count);
  std::vector<char*> pointers(count);
  const H5::StrType type = attribute.getStrType();
  if (count > 0) attribute.read(type, pointers.data());
  std::vector<std::string> values(pointers.begin(), pointers.end());
  if (count > 0) H5::DataSet::vlenReclaim(pointers.data(), type, attribute.getSpace());
  return values;
}

inline double doubleAttribute(const H5::H5Object& object, const std::string& name) {
  double value = 0.0;
  object.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &value);
  return value;
}

inline int intAttribute(const H5::H5Object& object, const std::string& name) {
  int value = 0;
  object.openAttribute(name).read(H5::PredType::NATIVE_INT, &value);
  return value;
}

}  // namespace wpg_test
