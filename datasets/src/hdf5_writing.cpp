// HDF5 writing helpers (hdf5_writing.hpp).
#include "hdf5_writing.hpp"

#include <algorithm>

namespace wpg::datasets::detail {
namespace {

constexpr int kDeflateLevel = 4;
constexpr hsize_t kChunkBytes = 64 * 1024;  // ~64 KiB per chunk: small files, fast reads

void describeDataset(H5::DataSet& dataset, const DatasetInfo& info) {
  writeStringAttribute(dataset, "units", info.units);
  if (info.frame) writeStringAttribute(dataset, "frame", info.frame);
  writeStringAttribute(dataset, "description", info.description);
  if (info.columns) writeStringAttribute(dataset, "columns", info.columns);
}

}  // namespace

void writeStringAttribute(H5::H5Object& object, const std::string& name,
                          const std::string& value) {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
  attribute.write(type, value);
}

void writeIntAttribute(H5::H5Object& object, const std::string& name, int value) {
  H5::Attribute attribute =
      object.createAttribute(name, H5::PredType::STD_I32LE, H5::DataSpace(H5S_SCALAR));
  attribute.write(H5::PredType::NATIVE_INT, &value);
}

void writeDoubleAttribute(H5::H5Object& object, const std::string& name, double value) {
  H5::Attribute attribute =
      object.createAttribute(name, H5::PredType::IEEE_F64LE, H5::DataSpace(H5S_SCALAR));
  attribute.write(H5::PredType::NATIVE_DOUBLE, &value);
}

void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                              const std::vector<std::string>& values) {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  const hsize_t count = values.size();
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(1, &count));
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  if (count > 0) attribute.write(type, pointers.data());
}

H5::DataSet writeDataset(H5::Group& group, const std::string& name, const void* data,
                         hsize_t rows, hsize_t columns, const H5::PredType& memory_type,
                         const H5::PredType& file_type, const DatasetInfo& info) {
  const int rank = columns == 0 ? 1 : 2;
  const hsize_t dimensions[2] = {rows, columns};
  const H5::DataSpace space(rank, dimensions);
  H5::DSetCreatPropList properties;
  if (rows > 0) {
    const hsize_t row_bytes = std::max<hsize_t>(1, columns) * file_type.getSize();
    const hsize_t chunk[2] = {std::min(rows, std::max<hsize_t>(1, kChunkBytes / row_bytes)),
                              columns};
    properties.setChunk(rank, chunk);
    properties.setShuffle();
    properties.setDeflate(kDeflateLevel);
  }
  H5::DataSet dataset = group.createDataSet(name, file_type, space, properties);
  if (rows > 0) dataset.write(data, memory_type);
  describeDataset(dataset, info);
  return dataset;
}

void writeDoubles(H5::Group& group, const std::string& name, const std::vector<double>& values,
                  hsize_t columns, const DatasetInfo& info) {
  const hsize_t rows = columns == 0 ? values.size() : values.size() / columns;
  writeDataset(group, name, values.data(), rows, columns, H5::PredType::NATIVE_DOUBLE,
               H5::PredType::IEEE_F64LE, info);
}

void writeInts(H5::Group& group, const std::string& name, const std::vector<int>& values,
               const DatasetInfo& info) {
  writeDataset(group, name, values.data(), values.size(), 0, H5::PredType::NATIVE_INT,
               H5::PredType::STD_I32LE, info);
}

H5::DataSet writeCodes(H5::Group& group, const std::string& name,
                       const std::vector<std::uint8_t>& values, const DatasetInfo& info) {
  return writeDataset(group, name, values.data(), values.size(), 0, H5::PredType::NATIVE_UINT8,
                      H5::PredType::STD_U8LE, info);
}

std::vector<double> rowMajor(const Eigen::MatrixXd& matrix) {
  std::vector<double> values(static_cast<std::size_t>(matrix.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), matrix.rows(), matrix.cols()) = matrix;
  return values;
}

}  // namespace wpg::datasets::detail
