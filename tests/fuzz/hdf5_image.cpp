// FileImage <-> bytes <-> HDF5 file (hdf5_image.hpp). HDF5's C API: the fuzz harness checks
// every return code itself and skips what HDF5 refuses, without exceptions in the loop.
#include "hdf5_image.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace wpg_fuzz {
namespace {

// Declared rows beyond this are reduced: 2^40 rows is already far past any memory, and keeps
// rows * columns * 8 bytes inside HDF5's 64-bit size arithmetic.
constexpr std::uint64_t kMaxRows = std::uint64_t{1} << 40;
constexpr std::uint64_t kChunkRows = 4096;

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return position_ >= size_; }
  std::size_t remaining() const { return size_ - position_; }
  // Little-endian; zeros past the end of the input.
  std::uint64_t unsignedValue(int bytes) {
    std::uint64_t value = 0;
    for (int i = 0; i < bytes && position_ < size_; ++i, ++position_) {
      value |= std::uint64_t{data_[position_]} << (8 * i);
    }
    return value;
  }
  double number() {
    const std::uint64_t bits = unsignedValue(8);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  std::string text() {
    const std::uint64_t declared = unsignedValue(2);
    const std::size_t length = std::min<std::size_t>(declared, remaining());
    std::string value(reinterpret_cast<const char*>(data_ + position_), length);
    position_ += length;
    return value;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

class ByteWriter {
 public:
  void unsignedValue(std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }
  void number(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    unsignedValue(bits, 8);
  }
  void text(const std::string& value) {
    const std::size_t length = std::min(value.size(), kMaxStringBytes);
    unsignedValue(length, 2);
    bytes_.insert(bytes_.end(), value.begin(), value.begin() + static_cast<long>(length));
  }
  std::vector<std::uint8_t> bytes() && { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

std::uint64_t valueCount(const ArrayEntry& array) {
  return array.rank == 1 ? array.rows : array.rows * array.columns;
}

// The int32 an integer dataset stores for `value` (clamped; NaN -> 0): no UB in the harness.
std::int32_t toInt32(double value) {
  if (std::isnan(value)) return 0;
  const double clamped = std::clamp(value, double(std::numeric_limits<std::int32_t>::min()),
                                    double(std::numeric_limits<std::int32_t>::max()));
  return static_cast<std::int32_t>(clamped);
}

double valueAt(const ArrayEntry& array, std::uint64_t i) {
  const std::uint64_t v = array.values.size();
  if (v == 0) return static_cast<double>(i) * array.step;
  return array.values[i % v] + static_cast<double>(i / v) * array.step;
}

// Suppresses HDF5's error stack printing for the lifetime of the object.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

// A 1-D dataset of variable-length UTF-8 strings, `texts` repeated over its rows.
void writeTextDataset(hid_t file, hid_t link_plist, const std::string& path,
                      const ArrayEntry& array) {
  const hsize_t rows = std::min<hsize_t>(array.rows, kMaxWrittenValues);
  const hid_t space = H5Screate_simple(1, &rows, nullptr);
  if (space < 0) return;
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t dataset =
      H5Dcreate2(file, path.c_str(), type, space, link_plist, H5P_DEFAULT, H5P_DEFAULT);
  if (dataset >= 0 && rows > 0) {
    static const std::string empty;
    std::vector<const char*> pointers(rows);
    for (hsize_t i = 0; i < rows; ++i) {
      pointers[i] = (array.texts.empty() ? empty : array.texts[i % array.texts.size()]).c_str();
    }
    H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
  }
  if (dataset >= 0) H5Dclose(dataset);
  H5Tclose(type);
  H5Sclose(space);
}

void writeDataset(hid_t file, hid_t link_plist, const std::string& path, const ArrayEntry& array) {
  if (array.text) return writeTextDataset(file, link_plist, path, array);
  const hsize_t dims[2] = {array.rows, array.columns};
  const hid_t space = H5Screate_simple(array.rank, dims, nullptr);
  if (space < 0) return;
  const std::uint64_t count = valueCount(array);
  const hid_t create_plist = H5Pcreate(H5P_DATASET_CREATE);
  const bool declared_only = count > kMaxWrittenValues;
  if (declared_only) {
    // Chunked, nothing written: no chunk is allocated, readers get the fill value.
    const hsize_t chunk[2] = {std::min<hsize_t>(array.rows, kChunkRows),
                              std::max<hsize_t>(array.columns, 1)};
    H5Pset_chunk(create_plist, array.rank, chunk);
  }
  const hid_t file_type =
      array.integer ? (array.byte ? H5T_STD_U8LE : H5T_STD_I32LE) : H5T_IEEE_F64LE;
  const hid_t dataset =
      H5Dcreate2(file, path.c_str(), file_type, space, link_plist, create_plist, H5P_DEFAULT);
  if (dataset >= 0 && !declared_only && count > 0) {
    if (array.integer) {
      std::vector<std::int32_t> values(count);
      for (std::uint64_t i = 0; i < count; ++i) values[i] = toInt32(valueAt(array, i));
      H5Dwrite(dataset, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    } else {
      std::vector<double> values(count);
      for (std::uint64_t i = 0; i < count; ++i) values[i] = valueAt(array, i);
      H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
  }
  if (dataset >= 0) H5Dclose(dataset);
  H5Pclose(create_plist);
  H5Sclose(space);
}

void writeAttribute(hid_t file, hid_t link_plist, const std::string& path,
                    const AttributeEntry& attribute) {
  hid_t object = H5Oopen(file, path.c_str(), H5P_DEFAULT);
  if (object < 0) {
    object = H5Gcreate2(file, path.c_str(), link_plist, H5P_DEFAULT, H5P_DEFAULT);
    if (object < 0) return;
  }
  if (H5Aexists(object, attribute.name.c_str()) > 0) H5Adelete(object, attribute.name.c_str());
  const hsize_t items = attribute.kind == AttributeEntry::Kind::kString ? attribute.texts.size()
                                                                        : attribute.numbers.size();
  const hid_t space = attribute.list ? H5Screate_simple(1, &items, nullptr) : H5Screate(H5S_SCALAR);
  hid_t type = -1;
  if (attribute.kind == AttributeEntry::Kind::kString) {
    // Variable-length, as hdf5_writing.cpp stores the scenario and every text attribute.
    type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
  } else {
    type = H5Tcopy(attribute.kind == AttributeEntry::Kind::kDouble ? H5T_IEEE_F64LE
                                                                  : H5T_STD_I32LE);
  }
  const hid_t created =
      H5Acreate2(object, attribute.name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (created >= 0 && attribute.list) {
    if (attribute.kind == AttributeEntry::Kind::kString) {
      std::vector<const char*> pointers;
      for (const std::string& text : attribute.texts) pointers.push_back(text.c_str());
      if (!pointers.empty()) H5Awrite(created, type, pointers.data());
    } else if (attribute.kind == AttributeEntry::Kind::kDouble) {
      if (!attribute.numbers.empty()) H5Awrite(created, H5T_NATIVE_DOUBLE, attribute.numbers.data());
    } else {
      std::vector<std::int32_t> values;
      for (const double number : attribute.numbers) values.push_back(toInt32(number));
      if (!values.empty()) H5Awrite(created, H5T_NATIVE_INT32, values.data());
    }
    H5Aclose(created);
  } else if (created >= 0) {
    if (attribute.kind == AttributeEntry::Kind::kString) {
      const char* text = attribute.text.c_str();  // an embedded NUL ends the stored text
      H5Awrite(created, type, &text);
    } else if (attribute.kind == AttributeEntry::Kind::kDouble) {
      H5Awrite(created, H5T_NATIVE_DOUBLE, &attribute.number);
    } else {
      const std::int32_t value = toInt32(attribute.number);
      H5Awrite(created, H5T_NATIVE_INT32, &value);
    }
    H5Aclose(created);
  }
  H5Tclose(type);
  H5Sclose(space);
  H5Oclose(object);
}

// ---- reading an existing file (seeds) ----------------------------------------------------

struct Visit {
  hid_t file;
  std::uint64_t max_rows;
  FileImage* image;
};

std::string absolutePath(const char* name) {
  return std::strcmp(name, ".") == 0 ? std::string("/") : "/" + std::string(name);
}

// The scalar attribute `index` of `object` (string, or the first number of a numeric one);
// false for other types.
bool readAttribute(hid_t object, hsize_t index, Entry* entry) {
  const hid_t attribute =
      H5Aopen_by_idx(object, ".", H5_INDEX_NAME, H5_ITER_INC, index, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return false;
  AttributeEntry& result = entry->attribute;
  const ssize_t name_length = H5Aget_name(attribute, 0, nullptr);
  std::vector<char> name(static_cast<std::size_t>(std::max<ssize_t>(name_length, 0)) + 1);
  H5Aget_name(attribute, name.size(), name.data());
  result.name = name.data();
  const hid_t type = H5Aget_type(attribute);
  const H5T_class_t type_class = H5Tget_class(type);
  bool keep = true;
  const hid_t attribute_space = H5Aget_space(attribute);
  const int rank = H5Sget_simple_extent_ndims(attribute_space);
  const hssize_t points = H5Sget_simple_extent_npoints(attribute_space);
  H5Sclose(attribute_space);
  if (rank == 1 && points >= 0 && static_cast<std::size_t>(points) <= kMaxListItems &&
      (type_class == H5T_STRING || type_class == H5T_FLOAT || type_class == H5T_INTEGER)) {
    // A list: variable-length strings (the summary's `columns`) or numbers.
    result.list = true;
    if (type_class == H5T_STRING) {
      result.kind = AttributeEntry::Kind::kString;
      std::vector<char*> texts(static_cast<std::size_t>(points), nullptr);
      if (H5Tis_variable_str(type) > 0 && points > 0 &&
          H5Aread(attribute, type, texts.data()) >= 0) {
        for (char* text : texts) {
          result.texts.emplace_back(text ? text : "");
          H5free_memory(text);
        }
      }
    } else {
      result.kind = type_class == H5T_FLOAT ? AttributeEntry::Kind::kDouble
                                            : AttributeEntry::Kind::kInt;
      result.numbers.resize(static_cast<std::size_t>(points));
      if (points > 0 && H5Aread(attribute, H5T_NATIVE_DOUBLE, result.numbers.data()) < 0) {
        result.numbers.clear();
      }
    }
  } else if (type_class == H5T_STRING) {
    result.kind = AttributeEntry::Kind::kString;
    if (H5Tis_variable_str(type) > 0) {
      char* text = nullptr;
      if (H5Aread(attribute, type, &text) >= 0 && text != nullptr) {
        result.text = text;
        H5free_memory(text);
      }
    } else {
      std::vector<char> text(H5Tget_size(type) + 1, '\0');
      H5Aread(attribute, type, text.data());
      result.text = text.data();
    }
    keep = result.text.size() <= kMaxStringBytes;
  } else if (type_class == H5T_FLOAT || type_class == H5T_INTEGER) {
    result.kind = type_class == H5T_FLOAT ? AttributeEntry::Kind::kDouble
                                          : AttributeEntry::Kind::kInt;
    const hid_t space = H5Aget_space(attribute);
    const hssize_t count = H5Sget_simple_extent_npoints(space);
    std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(count, 1)));
    if (count >= 1 && H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) >= 0) {
      result.number = values[0];
    }
    H5Sclose(space);
  } else {
    keep = false;
  }
  H5Tclose(type);
  H5Aclose(attribute);
  return keep;
}

void readAttributes(hid_t object, const std::string& path, FileImage* image) {
  H5O_info_t info;
  if (H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS) < 0) return;
  for (hsize_t i = 0; i < info.num_attrs; ++i) {
    Entry entry;
    entry.kind = Entry::Kind::kAttribute;
    entry.path = path;
    if (readAttribute(object, i, &entry)) image->entries.push_back(entry);
  }
}

void readTextDataset(hid_t dataset, const std::string& path, FileImage* image) {
  const hid_t space = H5Dget_space(dataset);
  const int rank = H5Sget_simple_extent_ndims(space);
  const hssize_t rows = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  if (rank != 1 || rows < 0 || static_cast<std::size_t>(rows) > kMaxListItems) return;
  Entry entry;
  entry.kind = Entry::Kind::kDataset;
  entry.path = path;
  entry.array.text = true;
  entry.array.rows = static_cast<std::uint64_t>(rows);
  std::vector<char*> texts(static_cast<std::size_t>(rows), nullptr);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  if (rows > 0 && H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()) >= 0) {
    for (char* text : texts) {
      entry.array.texts.emplace_back(text ? text : "");
      H5free_memory(text);
    }
  }
  H5Tclose(type);
  image->entries.push_back(entry);
}

void readDataset(hid_t dataset, const std::string& path, std::uint64_t max_rows,
                 FileImage* image) {
  const hid_t type = H5Dget_type(dataset);
  const H5T_class_t type_class = H5Tget_class(type);
  const std::size_t type_size = H5Tget_size(type);
  const bool variable_string = type_class == H5T_STRING && H5Tis_variable_str(type) > 0;
  H5Tclose(type);
  if (variable_string) {
    readTextDataset(dataset, path, image);
    return;
  }
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER) return;
  const hid_t space = H5Dget_space(dataset);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank != 1 && rank != 2) {
    H5Sclose(space);
    return;
  }
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  Entry entry;
  entry.kind = Entry::Kind::kDataset;
  entry.path = path;
  ArrayEntry& array = entry.array;
  array.integer = type_class == H5T_INTEGER;
  array.byte = array.integer && type_size == 1;
  array.rank = rank;
  array.rows = dims[0];
  array.columns = static_cast<std::uint32_t>(rank == 2 ? dims[1] : 1);
  const std::uint64_t count = valueCount(array);
  if (array.columns > kMaxColumns || count > kMaxWrittenValues) return;
  std::vector<double> values(count);
  if (count > 0 && H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                           values.data()) < 0) {
    return;
  }
  const std::uint64_t kept = std::min(array.rows, max_rows) * (rank == 2 ? array.columns : 1);
  array.values.assign(values.begin(), values.begin() + static_cast<long>(kept));
  // The continuation repeats the kept block shifted by what the first value gained over it:
  // exact for time, a plausible walk for the rest.
  if (kept > 0 && kept < count) array.step = values[kept] - values[0];
  image->entries.push_back(entry);
}

herr_t visitObject(hid_t, const char* name, const H5O_info_t* info, void* data) {
  auto* visit = static_cast<Visit*>(data);
  const std::string path = absolutePath(name);
  const hid_t object = H5Oopen(visit->file, path.c_str(), H5P_DEFAULT);
  if (object < 0) return 0;
  if (info->type == H5O_TYPE_GROUP) {
    Entry entry;
    entry.kind = Entry::Kind::kGroup;
    entry.path = path;
    if (path != "/") visit->image->entries.push_back(entry);
  } else if (info->type == H5O_TYPE_DATASET) {
    readDataset(object, path, visit->max_rows, visit->image);
  }
  readAttributes(object, path, visit->image);
  H5Oclose(object);
  return 0;
}

}  // namespace

FileImage decode(const std::uint8_t* data, std::size_t size, std::uint64_t max_rows) {
  max_rows = std::min(max_rows, kMaxRows);
  ByteReader in(data, size);
  FileImage image;
  while (!in.empty() && image.entries.size() < kMaxEntries) {
    Entry entry;
    // Kind byte: 0x80 a link (0x40: external), else 0x20 a heap damage, else group, dataset,
    // attribute (mod 3).
    const std::uint64_t kind = in.unsignedValue(1);
    entry.kind = (kind & 0x80) != 0
                     ? ((kind & 0x40) != 0 ? Entry::Kind::kExternalLink : Entry::Kind::kSoftLink)
                 : (kind & 0x20) != 0 ? Entry::Kind::kHeapDamage
                                      : static_cast<Entry::Kind>(kind % 3);
    entry.path = in.text();
    if (entry.kind == Entry::Kind::kDataset) {
      ArrayEntry& array = entry.array;
      // Flags: 1 integer, 2 two columns or more, 4 uint8 (integer) or text (not integer).
      const std::uint64_t flags = in.unsignedValue(1);
      array.integer = (flags & 1) != 0;
      array.byte = array.integer && (flags & 4) != 0;
      array.text = !array.integer && (flags & 4) != 0;
      array.rank = (flags & 2) != 0 && !array.text ? 2 : 1;
      array.rows = in.unsignedValue(8) % ((array.text ? kMaxWrittenValues : max_rows) + 1);
      array.columns = static_cast<std::uint32_t>(in.unsignedValue(1) % (kMaxColumns + 1));
      if (array.rank == 1) array.columns = 1;
      array.step = in.number();
      const std::uint64_t wanted = in.unsignedValue(4);
      if (array.text) {
        const std::uint64_t count = std::min<std::uint64_t>({wanted, kMaxListItems, in.remaining()});
        for (std::uint64_t i = 0; i < count && !in.empty(); ++i) array.texts.push_back(in.text());
      } else {
        const std::uint64_t available = in.remaining() / 8;
        const std::uint64_t count =
            std::min({wanted, valueCount(array), kMaxWrittenValues, available});
        array.values.resize(count);
        for (double& value : array.values) value = in.number();
      }
    } else if (entry.kind == Entry::Kind::kAttribute) {
      AttributeEntry& attribute = entry.attribute;
      attribute.name = in.text();
      // Kind byte: string, double, int (mod 3 of the low 7 bits); 0x80 a list of them.
      const std::uint64_t attribute_kind = in.unsignedValue(1);
      attribute.kind = static_cast<AttributeEntry::Kind>((attribute_kind & 0x7f) % 3);
      attribute.list = (attribute_kind & 0x80) != 0;
      if (attribute.list) {
        const std::uint64_t count =
            std::min<std::uint64_t>({in.unsignedValue(2), kMaxListItems, in.remaining()});
        for (std::uint64_t i = 0; i < count && !in.empty(); ++i) {
          if (attribute.kind == AttributeEntry::Kind::kString) {
            attribute.texts.push_back(in.text());
          } else {
            attribute.numbers.push_back(in.number());
          }
        }
      } else if (attribute.kind == AttributeEntry::Kind::kString) {
        attribute.text = in.text();
      } else {
        attribute.number = in.number();
      }
    } else if (entry.kind == Entry::Kind::kExternalLink) {
      entry.target_file = in.text();
      entry.target = in.text();
    } else if (entry.kind == Entry::Kind::kSoftLink) {
      entry.target = in.text();
    } else if (entry.kind == Entry::Kind::kHeapDamage) {
      HeapDamage& damage = entry.damage;
      const std::uint64_t target = in.unsignedValue(1);
      damage.heap_id = (target & 1) != 0;
      damage.which = static_cast<std::uint16_t>(in.unsignedValue(2));
      damage.offset = static_cast<std::uint16_t>(in.unsignedValue(2));
      damage.mode = static_cast<std::uint8_t>(in.unsignedValue(1) % 4);
      damage.length = static_cast<std::uint8_t>(in.unsignedValue(1) % 64 + 1);
      damage.bytes = in.text();
    }
    image.entries.push_back(std::move(entry));
  }
  return image;
}

std::vector<std::uint8_t> encode(const FileImage& image) {
  ByteWriter out;
  for (const Entry& entry : image.entries) {
    const std::uint64_t kind = entry.kind == Entry::Kind::kExternalLink ? 0xc0
                               : entry.kind == Entry::Kind::kSoftLink   ? 0x80
                               : entry.kind == Entry::Kind::kHeapDamage ? 0x20
                                                                        : static_cast<std::uint64_t>(entry.kind);
    out.unsignedValue(kind, 1);
    out.text(entry.path);
    if (entry.kind == Entry::Kind::kDataset) {
      const ArrayEntry& array = entry.array;
      out.unsignedValue((array.integer ? 1 : 0) | (array.rank == 2 ? 2 : 0) |
                            (array.byte || array.text ? 4 : 0),
                        1);
      out.unsignedValue(array.rows, 8);
      out.unsignedValue(array.columns, 1);
      out.number(array.step);
      if (array.text) {
        out.unsignedValue(array.texts.size(), 4);
        for (const std::string& text : array.texts) out.text(text);
      } else {
        out.unsignedValue(array.values.size(), 4);
        for (const double value : array.values) out.number(value);
      }
    } else if (entry.kind == Entry::Kind::kAttribute) {
      const AttributeEntry& attribute = entry.attribute;
      out.text(attribute.name);
      out.unsignedValue(static_cast<std::uint64_t>(attribute.kind) | (attribute.list ? 0x80 : 0), 1);
      if (attribute.list) {
        const bool texts = attribute.kind == AttributeEntry::Kind::kString;
        out.unsignedValue(texts ? attribute.texts.size() : attribute.numbers.size(), 2);
        if (texts) {
          for (const std::string& text : attribute.texts) out.text(text);
        } else {
          for (const double number : attribute.numbers) out.number(number);
        }
      } else if (attribute.kind == AttributeEntry::Kind::kString) {
        out.text(attribute.text);
      } else {
        out.number(attribute.number);
      }
    } else if (entry.kind == Entry::Kind::kExternalLink) {
      out.text(entry.target_file);
      out.text(entry.target);
    } else if (entry.kind == Entry::Kind::kSoftLink) {
      out.text(entry.target);
    } else if (entry.kind == Entry::Kind::kHeapDamage) {
      const HeapDamage& damage = entry.damage;
      out.unsignedValue(damage.heap_id ? 1 : 0, 1);
      out.unsignedValue(damage.which, 2);
      out.unsignedValue(damage.offset, 2);
      out.unsignedValue(damage.mode, 1);
      out.unsignedValue(damage.length - 1u, 1);
      out.text(damage.bytes);
    }
  }
  return std::move(out).bytes();
}

bool writeHdf5(const FileImage& image, const std::string& path) {
  const QuietHdf5 quiet;
  // Built in memory and written out once when closed (HDF5's core driver with a backing
  // store): a fraction of the system calls of the default driver's many small writes. Grown
  // 16 MiB at a time: by 1 MiB, 65 536 strings took 12 s of reallocations under ASan.
  const hid_t access_plist = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(access_plist, 1 << 24, 1);
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access_plist);
  H5Pclose(access_plist);
  if (file < 0) return false;
  const hid_t link_plist = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(link_plist, 1);
  for (const Entry& entry : image.entries) {
    if (entry.path.empty() || entry.path.find('\0') != std::string::npos) continue;
    switch (entry.kind) {
      case Entry::Kind::kGroup: {
        const hid_t group =
            H5Gcreate2(file, entry.path.c_str(), link_plist, H5P_DEFAULT, H5P_DEFAULT);
        if (group >= 0) H5Gclose(group);
        break;
      }
      case Entry::Kind::kDataset:
        writeDataset(file, link_plist, entry.path, entry.array);
        break;
      case Entry::Kind::kAttribute:
        if (entry.attribute.name.find('\0') == std::string::npos) {
          writeAttribute(file, link_plist, entry.path, entry.attribute);
        }
        break;
      case Entry::Kind::kSoftLink:
        if (entry.target.find('\0') == std::string::npos) {
          H5Lcreate_soft(entry.target.c_str(), file, entry.path.c_str(), link_plist, H5P_DEFAULT);
        }
        break;
      case Entry::Kind::kExternalLink:
        if (entry.target.find('\0') == std::string::npos &&
            entry.target_file.find('\0') == std::string::npos) {
          H5Lcreate_external(entry.target_file.c_str(), entry.target.c_str(), file,
                             entry.path.c_str(), link_plist, H5P_DEFAULT);
        }
        break;
      case Entry::Kind::kHeapDamage: break;  // applyImageDamage, once the file is closed
    }
  }
  H5Pclose(link_plist);
  return H5Fclose(file) >= 0;
}

FileImage readHdf5(const std::string& path, std::uint64_t max_rows) {
  const QuietHdf5 quiet;
  FileImage image;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return image;
  Visit visit{file, max_rows, &image};
  H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, visitObject, &visit, H5O_INFO_BASIC);
  H5Fclose(file);
  return image;
}

}  // namespace wpg_fuzz
