#pragma once
// Writing plain HDF5 that h5py reads without code of ours (conventions: datasets/SCHEMA.md):
// scalar and string-list attributes on open objects (the writers of the batch and comparison
// tables; a run's group is built as an image and committed: hdf5_image.hpp), and the rows of
// a walk in the flat, time-major layout of its datasets.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <H5Cpp.h>

#include "hdf5_image.hpp"

namespace wpg::datasets::detail {

// --- attributes on open objects (the caller holds hdf5Mutex()) --------------------------------

void writeStringAttribute(H5::H5Object& object, const std::string& name,
                          const std::string& value);
void writeIntAttribute(H5::H5Object& object, const std::string& name, int value);
void writeDoubleAttribute(H5::H5Object& object, const std::string& name, double value);
// A 1-D attribute of variable-length UTF-8 strings (h5py: an array of str).
void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                              const std::vector<std::string>& values);

// The last reference to an HDF5 object held by a C++ object of HDF5's, dropped quietly. HDF5's
// C++ destructors report a failed close on std::cerr whatever dontPrint() says (after a full
// disk: one line per object). Declared before that C++ object, this reference outlives it:
// its destructor then only drops a reference, which cannot fail, and the close happens here,
// its error on HDF5's error stack (printing off), the failure itself already an exception.
class QuietLastReference {
 public:
  QuietLastReference() = default;
  explicit QuietLastReference(hid_t id) : id_(id) {
    if (id_ >= 0 && H5Iinc_ref(id_) < 0) id_ = -1;
  }
  ~QuietLastReference() {
    if (id_ >= 0) H5Idec_ref(id_);
  }
  QuietLastReference(QuietLastReference&& other) noexcept : id_(other.id_) { other.id_ = -1; }
  QuietLastReference& operator=(QuietLastReference&& other) noexcept {
    std::swap(id_, other.id_);
    return *this;
  }

 private:
  hid_t id_ = -1;
};

// --- rows to the flat, time-major layout ------------------------------------------------------

// The rows are stored back to back (a fixed-size Eigen vector is its Size doubles): one copy,
// not one insertion per row (the batch writer runs this on its serial path too).
template <int Size>
std::vector<double> flatten(const std::vector<Eigen::Matrix<double, Size, 1>>& rows) {
  static_assert(sizeof(Eigen::Matrix<double, Size, 1>) == Size * sizeof(double),
                "rows without padding");
  if (rows.empty()) return {};
  const double* first = rows.front().data();
  return std::vector<double>(first, first + rows.size() * Size);
}

// get(row) for every row.
template <typename Row, typename Get>
std::vector<double> column(const std::vector<Row>& rows, Get get) {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const Row& row : rows) values.push_back(get(row));
  return values;
}

// An Eigen matrix as a time-major (row-major) vector; a 1-column matrix stays 2-D.
std::vector<double> rowMajor(const Eigen::MatrixXd& matrix);

}  // namespace wpg::datasets::detail
