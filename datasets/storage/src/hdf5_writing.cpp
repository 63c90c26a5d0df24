// HDF5 writing helpers (hdf5_writing.hpp).
#include "hdf5_writing.hpp"

namespace wpg::datasets::detail {

void writeStringAttribute(H5::H5Object& object, const std::string& name,
                          const std::string& value) {
  commitAttribute(object.getId(), {name, value});
}

void writeIntAttribute(H5::H5Object& object, const std::string& name, int value) {
  commitAttribute(object.getId(), {name, value});
}

void writeDoubleAttribute(H5::H5Object& object, const std::string& name, double value) {
  commitAttribute(object.getId(), {name, value});
}

void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                              const std::vector<std::string>& values) {
  commitAttribute(object.getId(), {name, values});
}

std::vector<double> rowMajor(const Eigen::MatrixXd& matrix) {
  std::vector<double> values(static_cast<std::size_t>(matrix.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), matrix.rows(), matrix.cols()) = matrix;
  return values;
}

}  // namespace wpg::datasets::detail
