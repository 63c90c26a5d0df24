// Field-by-field comparison of two HDF5 datasets (wpg/datasets/storage/dataset_diff.hpp). Generic
// on purpose: every group, dataset and attribute of the files is visited, whatever the schema
// holds, so that a regression reference also catches a field nobody thought of checking. The files
// may be anyone's: every size is bounded before it is allocated (read_limits.hpp), and the walk
// follows each pair of groups once, at most kMaxGroupDepth levels deep (hard and soft links can
// make cycles and exponentially many paths).
#include "wpg/datasets/storage/dataset_diff.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fnmatch.h>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>

#include <H5Cpp.h>

#include "external_link_guard.hpp"

#include "hdf5_bounded_reading.hpp"
#include "string_heap_check.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets {
namespace {


// The contents of one dataset or attribute, as numbers or as text.
struct Field {
  enum class Kind { kNumber, kText, kOther } kind = Kind::kOther;
  std::vector<hsize_t> dims;         // empty: scalar
  std::string type_name;             // "f8", "i4", "u1", "str", ... for messages
  std::vector<double> numbers;       // kNumber, row-major
  std::vector<std::string> texts;    // kText, one per element
  std::vector<unsigned char> bytes;  // kOther: the raw elements in the file's type
};

std::string typeName(const H5::DataType& type) {
  const std::size_t size = type.getSize();
  switch (type.getClass()) {
    case H5T_FLOAT: return "f" + std::to_string(size);
    case H5T_INTEGER: {
      const H5::IntType integer(type.getId());
      return (integer.getSign() == H5T_SGN_NONE ? "u" : "i") + std::to_string(size);
    }
    case H5T_STRING: return "str";
    default: return "class " + std::to_string(static_cast<int>(type.getClass()));
  }
}

std::size_t elementCount(const std::vector<hsize_t>& dims) {
  std::size_t count = 1;
  for (const hsize_t d : dims) count *= d;
  return count;
}

// Where a field is, for messages: the file and the object ("dataset /runs/x/com").
struct FieldPlace {
  const std::string& file;
  std::string what;
};

// Reads a dataset or an attribute (`read(buffer, memory_type)` is given by the caller, as the
// two classes of the C++ API order their arguments differently), its size bounded first.
template <typename Read>
Field readField(const H5::DataType& file_type, const H5::DataSpace& space,
                const FieldPlace& place, Read read) {
  Field field;
  const H5T_class_t file_class = file_type.getClass();
  // Bytes per element in memory: a double for numbers, a pointer for a variable-length string.
  const std::size_t element_size = std::max<std::size_t>(
      {file_type.getSize(), sizeof(double),
       file_class == H5T_STRING ? sizeof(char*) : std::size_t{1}});
  field.dims = detail::boundedExtent(space, element_size, kMaxReadElements, place.file,
                                     place.what);
  if (space.getSimpleExtentType() == H5S_NULL) field.dims.clear();
  field.type_name = typeName(file_type);
  const std::size_t count =
      space.getSimpleExtentType() == H5S_NULL ? 0 : elementCount(field.dims);
  const H5T_class_t type_class = file_class;
  if (type_class == H5T_FLOAT || type_class == H5T_INTEGER) {
    field.kind = Field::Kind::kNumber;
    field.numbers.resize(count);
    // int32 and uint8 convert to double exactly.
    if (count > 0) read(field.numbers.data(), H5::PredType::NATIVE_DOUBLE);
  } else if (type_class == H5T_STRING) {
    field.kind = Field::Kind::kText;
    const H5::StrType file_string(file_type.getId());
    if (count == 0) return field;
    if (file_string.isVariableStr()) {
      H5::StrType memory_type(H5::PredType::C_S1, H5T_VARIABLE);
      memory_type.setCset(file_string.getCset());
      std::vector<char*> pointers(count, nullptr);
      read(pointers.data(), memory_type);
      for (const char* text : pointers) field.texts.emplace_back(text ? text : "");
      H5Dvlen_reclaim(memory_type.getId(), space.getId(), H5P_DEFAULT, pointers.data());
    } else {
      const std::size_t size = file_string.getSize();
      std::vector<char> buffer(count * size);
      read(buffer.data(), file_string);
      for (std::size_t i = 0; i < count; ++i) {
        const char* begin = buffer.data() + i * size;
        field.texts.emplace_back(begin, std::find(begin, begin + size, '\0'));
      }
    }
  } else {
    field.bytes.resize(count * file_type.getSize());
    if (count > 0) read(field.bytes.data(), file_type);
  }
  return field;
}

Field readDataset(const H5::DataSet& dataset, const FieldPlace& place,
                  detail::VariableDataChecker& checker) {
  checker.check(dataset, place.file, place.what);  // before HDF5 reads a heap
  return readField(dataset.getDataType(), dataset.getSpace(), place,
                   [&](void* buffer, const H5::DataType& type) { dataset.read(buffer, type); });
}

Field readAttribute(const H5::Attribute& attribute, const FieldPlace& place,
                    detail::VariableDataChecker& checker) {
  checker.check(attribute, place.file, place.what);
  return readField(attribute.getDataType(), attribute.getSpace(), place,
                   [&](void* buffer, const H5::DataType& type) { attribute.read(type, buffer); });
}

// The file and address of an object: the same group reached by two links has the same key.
std::string objectKey(const H5::H5Object& object) {
#if H5_VERSION_GE(1, 12, 0)
  H5O_info2_t info;
  if (H5Oget_info3(object.getId(), &info, H5O_INFO_BASIC) < 0) throw H5::Exception("H5Oget_info3", "");
  return std::to_string(info.fileno) + ":" +
         std::string(reinterpret_cast<const char*>(&info.token), sizeof info.token);
#else
  H5O_info_t info;
  if (H5Oget_info2(object.getId(), &info, H5O_INFO_BASIC) < 0) throw H5::Exception("H5Oget_info2", "");
  return std::to_string(info.fileno) + ":" + std::to_string(info.addr);
#endif
}

std::string shapeText(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return "scalar";
  std::string text = "(";
  for (std::size_t i = 0; i < dims.size(); ++i) {
    text += (i ? ", " : "") + std::to_string(dims[i]);
  }
  return text + (dims.size() == 1 ? ",)" : ")");
}

// "x, y, z" -> {"x", "y", "z"}.
std::vector<std::string> splitColumns(const std::string& columns) {
  std::vector<std::string> names;
  std::stringstream stream(columns);
  std::string name;
  while (std::getline(stream, name, ',')) {
    const auto first = name.find_first_not_of(' ');
    names.push_back(first == std::string::npos ? "" : name.substr(first));
  }
  return names;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::stringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) result.push_back(line);
  return result;
}

class Comparison {
 public:
  Comparison(const DiffSettings& settings, const std::string& path_a, const std::string& path_b)
      : settings_(settings), path_a_(path_a), path_b_(path_b) {}

  DatasetDiff result;

  void compareGroups(const std::string& path, const H5::Group& a, const H5::Group& b,
                     int depth = 0) {
    if (depth > kMaxGroupDepth) {
      throw InputError(path_a_ + " / " + path_b_ + ": group " + path + " is nested " +
                       std::to_string(depth) + " levels deep: expected at most " +
                       std::to_string(kMaxGroupDepth) + " (a link cycle?)");
    }
    // A pair of groups seen before (reached by another link) is not compared again.
    if (!visited_.insert({objectKey(a), objectKey(b)}).second) return;
    compareAttributes(path, a, b, path == "/");
    std::set<std::string> names;
    for (hsize_t i = 0; i < a.getNumObjs(); ++i) names.insert(a.getObjnameByIdx(i));
    for (hsize_t i = 0; i < b.getNumObjs(); ++i) names.insert(b.getObjnameByIdx(i));
    for (const std::string& name : names) {
      const std::string child = (path == "/" ? "/" : path + "/") + name;
      if ((settings_.ignore_wall_time && isWallTimeField(child)) || ignoredByPattern(child)) {
        result.ignored.push_back(child);
        continue;
      }
      const bool in_a = a.nameExists(name), in_b = b.nameExists(name);
      if (!in_a || !in_b) {
        structural(child, false, in_a ? "only in A" : "only in B");
        continue;
      }
      const H5O_type_t type_a = a.childObjType(name), type_b = b.childObjType(name);
      if (type_a != type_b) {
        structural(child, false, "a group in one file, a dataset in the other");
      } else if (type_a == H5O_TYPE_GROUP) {
        compareGroups(child, a.openGroup(name), b.openGroup(name), depth + 1);
      } else if (type_a == H5O_TYPE_DATASET) {
        const H5::DataSet dataset_a = a.openDataSet(name), dataset_b = b.openDataSet(name);
        compareAttributes(child, dataset_a, dataset_b, false);
        ++result.datasets_compared;
        compareFields(child, false,
                      readDataset(dataset_a, {path_a_, "dataset " + child}, checker_),
                      readDataset(dataset_b, {path_b_, "dataset " + child}, checker_),
                      columnNames(dataset_a, {path_a_, "attribute " + child + "@columns"}));
      }
    }
  }

 private:
  const DiffSettings& settings_;
  const std::string& path_a_;
  const std::string& path_b_;
  std::set<std::pair<std::string, std::string>> visited_;
  detail::VariableDataChecker checker_;  // both files' bytes and heaps, each read once

  bool ignoredByPattern(const std::string& path) const {
    for (const std::string& pattern : settings_.ignore_patterns) {
      if (fnmatch(pattern.c_str(), path.c_str(), 0) == 0) return true;
    }
    return false;
  }

  void structural(const std::string& path, bool attribute, const std::string& what) {
    FieldDifference difference;
    difference.path = path;
    difference.attribute = attribute;
    difference.what = what;
    result.differences.push_back(std::move(difference));
  }

  std::vector<std::string> columnNames(const H5::H5Object& object, const FieldPlace& place) {
    if (!object.attrExists("columns")) return {};
    const Field columns = readAttribute(object.openAttribute("columns"), place, checker_);
    if (columns.kind != Field::Kind::kText || columns.texts.size() != 1) return {};
    return splitColumns(columns.texts[0]);
  }

  void compareAttributes(const std::string& path, const H5::H5Object& a, const H5::H5Object& b,
                         bool root) {
    std::set<std::string> names;
    for (int i = 0; i < a.getNumAttrs(); ++i) names.insert(a.openAttribute(i).getName());
    for (int i = 0; i < b.getNumAttrs(); ++i) names.insert(b.openAttribute(i).getName());
    for (const std::string& name : names) {
      const std::string where = path + "@" + name;
      if ((root && isProvenanceAttribute(name)) || ignoredByPattern(where)) {
        result.ignored.push_back(where);
        continue;
      }
      const bool in_a = a.attrExists(name), in_b = b.attrExists(name);
      if (!in_a || !in_b) {
        structural(where, true, in_a ? "only in A" : "only in B");
        continue;
      }
      ++result.attributes_compared;
      compareFields(where, true,
                    readAttribute(a.openAttribute(name), {path_a_, "attribute " + where}, checker_),
                    readAttribute(b.openAttribute(name), {path_b_, "attribute " + where}, checker_),
                    {});
    }
  }

  void compareFields(const std::string& path, bool attribute, const Field& a, const Field& b,
                     const std::vector<std::string>& column_names) {
    if (a.kind != b.kind || (a.kind == Field::Kind::kNumber && a.type_name != b.type_name) ||
        (a.kind == Field::Kind::kOther && a.type_name != b.type_name)) {
      structural(path, attribute, "type " + a.type_name + " vs " + b.type_name);
      return;
    }
    if (a.kind == Field::Kind::kText) return compareTexts(path, attribute, a, b);
    if (a.dims != b.dims) {
      // Same columns and different lengths (a walk that ended at another time): the common
      // leading rows are compared too, so that the first differing sample is still reported.
      FieldDifference difference;
      difference.path = path;
      difference.attribute = attribute;
      difference.what = "shape " + shapeText(a.dims) + " vs " + shapeText(b.dims);
      if (a.kind == Field::Kind::kNumber && a.dims.size() == b.dims.size() && !a.dims.empty() &&
          std::equal(a.dims.begin() + 1, a.dims.end(), b.dims.begin() + 1)) {
        const std::size_t columns = elementCount(a.dims) / std::max<hsize_t>(a.dims[0], 1);
        const std::size_t rows = std::min(a.dims[0], b.dims[0]);
        compareNumbers(a.numbers, b.numbers, rows * columns, columns, column_names, &difference);
      }
      result.differences.push_back(std::move(difference));
      return;
    }
    if (a.kind == Field::Kind::kOther) {
      if (a.bytes != b.bytes) structural(path, attribute, "values (" + a.type_name + ", compared as bytes)");
      return;
    }
    FieldDifference difference;
    difference.path = path;
    difference.attribute = attribute;
    difference.what = "values";
    difference.scalar = a.dims.empty();
    const std::size_t columns = a.dims.size() >= 2 ? elementCount(a.dims) / std::max<hsize_t>(a.dims[0], 1) : 1;
    compareNumbers(a.numbers, b.numbers, a.numbers.size(), columns, column_names, &difference);
    if (difference.differing_samples > 0) {
      result.differences.push_back(std::move(difference));
      return;
    }
    if (difference.max_relative > result.max_relative_within) {
      result.max_relative_within = difference.max_relative;
      result.max_relative_within_path = path;
    }
    result.max_absolute_within = std::max(result.max_absolute_within, difference.max_absolute);
  }

  // Compares the first `count` elements (row-major, `columns` per row); fills the sample fields.
  void compareNumbers(const std::vector<double>& a, const std::vector<double>& b,
                      std::size_t count, std::size_t columns,
                      const std::vector<std::string>& column_names,
                      FieldDifference* difference) const {
    difference->compared_samples = count;
    for (std::size_t i = 0; i < count; ++i) {
      const double x = a[i], y = b[i];
      if (x == y || (std::isnan(x) && std::isnan(y))) continue;
      const double absolute = std::abs(x - y);  // NaN or inf when one side is not finite
      const double scale = std::max(std::abs(x), std::abs(y));
      const double relative = std::isfinite(absolute) ? absolute / scale : INFINITY;
      const double tolerance = settings_.atol + settings_.rtol * scale;
      difference->max_relative = std::max(difference->max_relative, relative);
      difference->max_absolute = std::max(difference->max_absolute,
                                          std::isfinite(absolute) ? absolute : INFINITY);
      if (std::isfinite(absolute) && absolute <= tolerance) continue;
      if (difference->differing_samples++ == 0) {
        difference->has_sample = true;
        difference->row = i / columns;
        difference->column = i % columns;
        if (difference->column < column_names.size() && columns > 1) {
          difference->column_name = column_names[difference->column];
        }
        difference->a = x;
        difference->b = y;
        difference->tolerance = tolerance;
      }
    }
  }

  void compareTexts(const std::string& path, bool attribute, const Field& a, const Field& b) {
    if (a.texts == b.texts && a.dims == b.dims) return;
    FieldDifference difference;
    difference.path = path;
    difference.attribute = attribute;
    difference.what = "text";
    // One string: the first differing line; a list: the first differing element.
    std::vector<std::string> items_a = a.texts, items_b = b.texts;
    if (a.texts.size() == 1 && b.texts.size() == 1) {
      items_a = lines(a.texts[0]);
      items_b = lines(b.texts[0]);
    }
    const std::size_t common = std::min(items_a.size(), items_b.size());
    std::size_t i = 0;
    while (i < common && items_a[i] == items_b[i]) ++i;
    difference.line = i + 1;
    difference.text_a = i < items_a.size() ? items_a[i] : "(nothing)";
    difference.text_b = i < items_b.size() ? items_b[i] : "(nothing)";
    result.differences.push_back(std::move(difference));
  }
};

H5::H5File openDataset(const std::string& path) {
  H5::H5File file = detail::openFileForReading(path);
  if (!file.attrExists("schema_version") || !file.nameExists("runs") ||
      file.childObjType("runs") != H5O_TYPE_GROUP) {
    throw InputError(path + ": not a wpg run or batch dataset (expected the root attribute "
                     "schema_version and the group /runs)");
  }
  return file;
}

}  // namespace

bool isWallTimeField(const std::string& path) {
  const auto slash = path.rfind('/');
  const std::string name = path.substr(slash + 1);
  const std::string parent = slash == std::string::npos ? "" : path.substr(0, slash);
  const std::string parent_name = parent.substr(parent.rfind('/') + 1);
  if (parent_name == "mpc") return name == "solve_time";
  if (parent_name == "plans") return name == "planning_time" || name == "simplification_time";
  if (parent == "/batch/summary") return name.rfind("nmpc_time_", 0) == 0;
  // The timing/ group of a replayed run: every field in it is a wall time.
  return name == "timing" && parent.rfind("/runs/", 0) == 0;
}

bool isProvenanceAttribute(const std::string& name) {
  return name == "wpg_version" || name == "created_by" || name == "wpg_commit" ||
         name == "created_on" || name == "created_at";
}

DatasetDiff diffDatasets(const std::string& path_a, const std::string& path_b,
                         const DiffSettings& settings) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  std::string current = path_a;
  try {
    const H5::H5File file_a = openDataset(path_a);
    current = path_b;
    const H5::H5File file_b = openDataset(path_b);
    current = path_a + " / " + path_b;
    Comparison comparison(settings, path_a, path_b);
    comparison.compareGroups("/", file_a.openGroup("/"), file_b.openGroup("/"));
    return std::move(comparison.result);
  } catch (const H5::Exception& error) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
    throw InputError(current + ": cannot read the file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

}  // namespace wpg::datasets
