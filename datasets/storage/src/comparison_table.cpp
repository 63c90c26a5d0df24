// The table of a comparison study in its batch file (wpg/datasets/storage/comparison_table.hpp).
#include "wpg/datasets/storage/comparison_table.hpp"

#include <mutex>
#include <stdexcept>

#include <H5Cpp.h>

#include "hdf5_writing.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets {

void writeComparisonTable(const std::string& path, const std::vector<std::string>& worlds,
                          const std::vector<std::string>& variants, const std::vector<int>& seeds,
                          const std::vector<TableColumn>& columns) {
  const std::size_t rows =
      columns.empty() ? 0 : (columns.front().text ? columns.front().strings.size()
                                                  : columns.front().numbers.size());
  std::vector<std::string> names;
  for (const TableColumn& column : columns) {
    if ((column.text ? column.strings.size() : column.numbers.size()) != rows) {
      throw std::invalid_argument("writeComparisonTable: column '" + column.name + "' has not " +
                                  std::to_string(rows) + " rows");
    }
    names.push_back(column.name);
  }
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    H5::H5File file(path, H5F_ACC_RDWR);
    // A resumed comparison that had finished (or was killed while writing its table): the
    // table is made again from the runs, the same.
    if (file.nameExists("compare")) file.unlink("compare");
    H5::Group compare = file.createGroup("compare");
    detail::writeStringListAttribute(compare, "worlds", worlds);
    detail::writeStringListAttribute(compare, "variants", variants);
    std::vector<std::string> seed_texts;
    for (const int seed : seeds) seed_texts.push_back(std::to_string(seed));
    detail::writeStringListAttribute(compare, "seeds", seed_texts);
    H5::Group table = compare.createGroup("summary");
    detail::writeStringAttribute(table, "description",
                                 "one row per world x variant, from the runs of every seed");
    detail::writeStringListAttribute(table, "columns", names);
    const hsize_t count = rows;
    const H5::DataSpace space(1, &count);
    H5::StrType string_type(H5::PredType::C_S1, H5T_VARIABLE);
    string_type.setCset(H5T_CSET_UTF8);
    for (const TableColumn& column : columns) {
      H5::DataSet dataset;
      if (column.text) {
        dataset = table.createDataSet(column.name, string_type, space);
        std::vector<const char*> pointers;
        for (const std::string& value : column.strings) pointers.push_back(value.c_str());
        if (rows > 0) dataset.write(pointers.data(), string_type);
      } else {
        dataset = table.createDataSet(column.name, H5::PredType::IEEE_F64LE, space);
        if (rows > 0) dataset.write(column.numbers.data(), H5::PredType::NATIVE_DOUBLE);
      }
      detail::writeStringAttribute(dataset, "units", column.units);
      detail::writeStringAttribute(dataset, "description", column.description);
    }
    file.close();
  } catch (const H5::Exception& error) {
    throw std::runtime_error(path + ": cannot write /compare/summary (" + error.getFuncName() +
                             ": " + error.getDetailMsg() + ")");
  }
}

}  // namespace wpg::datasets
