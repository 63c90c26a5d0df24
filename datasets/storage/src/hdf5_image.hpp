#pragma once
// An HDF5 group built in memory, then committed to a file: the writers of a run build its
// image (groups, attributes, datasets whose chunks are already shuffled and deflated) without
// any HDF5 call, so on any thread and off the HDF5 lock; commit() then makes the objects, in
// the order they were built, under the lock. Compressing the chunks is most of a run's writing
// time: a batch's workers build their runs' images and the one thread that holds the lock only
// commits them. Debian's HDF5 is not thread-safe, so commit runs under hdf5Mutex().
//
// The chunks are HDF5's shuffle and deflate filters' output (a zlib stream, written by
// libdeflate) and are written as they are (H5Dwrite_chunk): h5py and HDF5 read them with the
// standard filters. A file committed from an image is the file the same writer calls made
// directly before (the same objects in the same order).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace wpg::datasets::detail {

// An attribute: int32, float64, a UTF-8 string, or a 1-D list of UTF-8 strings.
struct AttributeImage {
  std::string name;
  std::variant<int, double, std::string, std::vector<std::string>> value;
};

// Something that holds attributes (a group or a dataset), in the order they are added.
class ObjectImage {
 public:
  virtual ~ObjectImage() = default;
  virtual void add(AttributeImage attribute) = 0;
};

// Numbers little-endian in the file; kString: variable-length UTF-8 strings, 1-D, contiguous.
enum class ElementType { kFloat64, kInt32, kUint8, kString };

// A dataset: rows x columns, time-major (columns == 0: 1-D), chunked by chunk_rows and
// compressed when it has rows; a 0-row dataset is contiguous and holds nothing.
struct DatasetImage : ObjectImage {
  std::string name;
  std::uint64_t rows = 0, columns = 0, chunk_rows = 0;
  ElementType type = ElementType::kFloat64;
  std::vector<std::vector<unsigned char>> chunks;  // shuffled + deflated, in row order
  std::vector<std::string> strings;                // kString: the values
  std::vector<AttributeImage> attributes;
  void add(AttributeImage attribute) override { attributes.push_back(std::move(attribute)); }
};

// A group: what it holds, in the order it was added. An entry is an attribute, a dataset, a
// group to create, a group the file already holds (made by an earlier entry) to add to, or a
// part built elsewhere (another thread) whose entries belong here, in its place.
class GroupImage : public ObjectImage {
 public:
  struct Child;
  using Entry = std::variant<AttributeImage, DatasetImage, std::unique_ptr<Child>,
                             std::shared_ptr<const GroupImage>>;

  void add(AttributeImage attribute) override { entries_.emplace_back(std::move(attribute)); }
  DatasetImage& addDataset(DatasetImage dataset);
  GroupImage& createGroup(const std::string& name);
  // A group an earlier entry created (in this image or in a part of it), to add to.
  GroupImage& openGroup(const std::string& name);
  void addPart(std::shared_ptr<const GroupImage> part);
  const std::deque<Entry>& entries() const { return entries_; }

 private:
  std::deque<Entry> entries_;  // a deque: what add* returned stays where it is
};

struct GroupImage::Child {
  std::string name;
  bool exists = false;  // openGroup: the group is already in the file
  GroupImage group;
};

// Writes the image's entries into `target` (an open group id: a file's root, or a group), in
// order, closing each object it makes once written. The caller holds hdf5Mutex(). Throws
// std::runtime_error naming the object on an HDF5 error; the objects it made are then closed
// quietly (HDF5's error stack printing off), so that the error is the one report.
void commit(const GroupImage& image, std::int64_t target);
// A new file at `path` (replacing what is there) holding `root` (its attributes and groups),
// closed with a strong close: a write that fails in the close (a full disk) is its error too.
// The caller holds hdf5Mutex(). Throws std::runtime_error as commit().
void commitFile(const std::string& path, const GroupImage& root);
// One attribute on the object `object` (an open id), the same way.
void commitAttribute(std::int64_t object, const AttributeImage& attribute);

// --- building ---------------------------------------------------------------------------------

// What describes a numeric dataset (datasets/SCHEMA.md): its attributes.
struct DatasetInfo {
  const char* units;        // "s", "m", "m, m, m, rad" (one per column when they differ), "1"
  const char* frame;        // "world", or nullptr where no frame applies
  const char* description;  // one sentence
  const char* columns;      // column names of a 2-D dataset, nullptr for 1-D
};

// A dataset of `rows` x `columns` elements at `data` (row-major; columns == 0: 1-D), its chunks
// compressed here, described by `info`. Any thread.
DatasetImage& writeDataset(GroupImage& group, const std::string& name, const void* data,
                           std::uint64_t rows, std::uint64_t columns, ElementType type,
                           const DatasetInfo& info);
// float64; rows = values.size() / columns (1-D when columns == 0).
DatasetImage& writeDoubles(GroupImage& group, const std::string& name,
                           const std::vector<double>& values, std::uint64_t columns,
                           const DatasetInfo& info);
DatasetImage& writeInts(GroupImage& group, const std::string& name,
                        const std::vector<int>& values, const DatasetInfo& info);  // int32, 1-D
DatasetImage& writeCodes(GroupImage& group, const std::string& name,
                         const std::vector<std::uint8_t>& values,
                         const DatasetInfo& info);  // uint8, 1-D; the caller adds `codes`

// A 1-D dataset of variable-length UTF-8 strings (h5py: bytes objects), `units` 1.
DatasetImage& writeStrings(GroupImage& group, const std::string& name,
                           const std::vector<std::string>& values, const char* description);

void writeStringAttribute(ObjectImage& object, const std::string& name, const std::string& value);
// `lines` as one string attribute, each line ending with a line feed; no attribute when `lines`
// is empty (a run without the loader's warnings reads as before they were recorded).
void writeLinesAttribute(ObjectImage& object, const std::string& name,
                         const std::vector<std::string>& lines);
void writeIntAttribute(ObjectImage& object, const std::string& name, int value);
void writeDoubleAttribute(ObjectImage& object, const std::string& name, double value);
void writeStringListAttribute(ObjectImage& object, const std::string& name,
                              const std::vector<std::string>& values);

}  // namespace wpg::datasets::detail
