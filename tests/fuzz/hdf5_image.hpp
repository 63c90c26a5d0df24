#pragma once
// The input format of fuzz_run_dataset_reader and fuzz_shard_reader: a description of an HDF5
// file's content (groups, numeric and text datasets with their declared shapes, attributes,
// soft and external links) that the fuzzer mutates,
// decoded from bytes, written as a valid HDF5 file, and encoded back (make_dataset_seeds turns
// real run datasets into seeds).
//
// Why not raw HDF5 bytes: HDF5 1.10's own parser is not hardened against malformed containers
// (dozens of CVEs on crafted files); a raw-bytes target would spend its time in HDF5's bugs,
// which we cannot fix, and its reports would stop every run. What our reader must survive is
// what a valid container can carry: any shapes, types, values (NaN, inf, huge), declared sizes
// far beyond the stored data, missing or extra objects and attributes, any scenario text.
#include <cstdint>
#include <string>
#include <vector>

#include "heap_damage.hpp"

namespace wpg_fuzz {

// One numeric dataset. Its rows * columns values are `values`, continued when shorter by
// values[i % v] + (i / v) * step (v = values.size(); i * step when v = 0): a short input can
// declare a long walk with a monotonic time. Past kMaxWrittenValues the dataset is chunked and
// no value is written: HDF5 reads the fill value (0), and the file stays a few KB however many
// rows it declares (e.g. a 226 KB file declaring 2e8 rows).
// A text dataset (`text`) is 1-D, variable-length UTF-8 strings (as the summary table's `name`
// column): its rows are `texts`, repeated cyclically up to `rows` (at most kMaxWrittenValues;
// empty strings when there is none).
struct ArrayEntry {
  bool integer = false;  // int32 (H5T_STD_I32LE) rather than float64
  bool byte = false;     // with `integer`: uint8 (H5T_STD_U8LE, the summary's `done` column)
  bool text = false;     // variable-length strings (not with `integer`)
  std::vector<std::string> texts;
  int rank = 1;          // 1: (rows,); 2: (rows, columns)
  std::uint64_t rows = 0;
  std::uint32_t columns = 1;
  double step = 0.0;
  std::vector<double> values;  // integer datasets: truncated to int32 when written
};

// A scalar attribute, or with `list` a 1-D one: `texts` (strings) or `numbers`.
struct AttributeEntry {
  enum class Kind : std::uint8_t { kString, kDouble, kInt } kind = Kind::kString;
  std::string name;
  std::string text;
  double number = 0.0;
  bool list = false;
  std::vector<std::string> texts;
  std::vector<double> numbers;
};

// An object of the file: a group, a dataset, an attribute on the object at `path` (created
// as a group when missing), or a link at `path`: soft (to `target`, a path in the file) or
// external (to `target_file`:`target`, whatever file that names: a shard, the other shard, a
// device).
// A heap damage (heap_damage.hpp) is applied to the written file, after every object.
struct Entry {
  enum class Kind : std::uint8_t {
    kGroup, kDataset, kAttribute, kSoftLink, kExternalLink, kHeapDamage
  } kind = Kind::kGroup;
  std::string path;  // absolute, e.g. /runs/walk_forward/com
  ArrayEntry array;
  AttributeEntry attribute;
  std::string target_file, target;  // links
  HeapDamage damage;
};

struct FileImage {
  std::vector<Entry> entries;
};

constexpr std::size_t kMaxEntries = 1024;
constexpr std::size_t kMaxStringBytes = 1 << 16;
constexpr std::uint64_t kMaxWrittenValues = 1 << 16;
constexpr std::uint32_t kMaxColumns = 64;
constexpr std::size_t kMaxListItems = 1 << 12;  // texts of a text dataset or list attribute

// Never fails: a truncated input ends the image, out-of-range fields are reduced into range
// (declared rows into [0, max_rows]).
FileImage decode(const std::uint8_t* data, std::size_t size,
                 std::uint64_t max_rows = std::uint64_t{1} << 40);
// decode(encode(image)) == image for an image within the limits above.
std::vector<std::uint8_t> encode(const FileImage& image);
// Writes the image as a new HDF5 file at `path` (replaced). Entries HDF5 refuses (a name
// that is not a valid path, a dataset where a group is, ...) are skipped. False when the file
// itself cannot be created.
bool writeHdf5(const FileImage& image, const std::string& path);
// The image's heap damages applied to the file writeHdf5 wrote, in order.
void applyImageDamage(const FileImage& image, const std::string& path);
// Reads every group, numeric dataset and attribute of an existing HDF5 file (seeds), with at
// most `max_rows` rows of each dataset stored explicitly (the rest continued by the step).
FileImage readHdf5(const std::string& path, std::uint64_t max_rows);

}  // namespace wpg_fuzz
