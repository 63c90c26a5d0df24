#pragma once
// Variable-length data checked before HDF5 reads it: the one place every reader of this
// library goes through before it reads a variable-length string (hdf5_bounded_reading.cpp,
// dataset_diff.cpp), and the whole-file check of `wpg plot`, the package's tables and the
// damage check of `--resume`. The heap IDs are found in the file's bytes (a contiguous
// dataset's data; an attribute's message in its object's header) and checked against their
// global heap collections (global_heap_check.hpp). Failures are InputError, one line:
// "FILE: <what>: damaged variable-length data (<why>)".
#include <map>
#include <memory>
#include <string>

#include <H5Cpp.h>

namespace wpg::datasets::detail {

// The checks below for a reader that reads many objects: each file's bytes are opened, and
// each of its global heap collections is read and walked, once per checker rather than once
// per object. `wpg diff` of two 48-run batch files checks about 3000 variable-length
// attributes: opening the file's bytes for each took 23 % of its time and re-reading the same
// collections 8 %. A checker serves files that stay unchanged while it lives (readers only);
// files are told apart by HDF5's file number, which no other file opened later gets.
class VariableDataChecker {
 public:
  VariableDataChecker();
  ~VariableDataChecker();
  VariableDataChecker(const VariableDataChecker&) = delete;
  VariableDataChecker& operator=(const VariableDataChecker&) = delete;

  // The elements of `dataset`, when its type is variable-length (a string or a sequence).
  // `what` names it in messages ("dataset /batch/summary/name").
  void check(const H5::DataSet& dataset, const std::string& file, const std::string& what);
  // The attribute's elements likewise, found in its object's header.
  void check(const H5::Attribute& attribute, const std::string& file, const std::string& what);

 private:
  struct OpenFile;
  OpenFile& openFile(hid_t object, unsigned long file_number);
  std::map<unsigned long, std::unique_ptr<OpenFile>> files_;
};

// One object's checks, through a checker of its own.
void checkVariableData(const H5::DataSet& dataset, const std::string& file,
                       const std::string& what);
void checkVariableData(const H5::Attribute& attribute, const std::string& file,
                       const std::string& what);

// Every variable-length attribute and dataset of the objects below `group` (hard links), and
// of the objects its external links lead to (through the link guard, external_link_guard.hpp).
void checkVariableDataUnder(const H5::Group& group, const std::string& file);

}  // namespace wpg::datasets::detail
