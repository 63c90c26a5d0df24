// Committing the image of an HDF5 group to a file (hdf5_image.hpp), with HDF5's C API: every
// object it makes is closed explicitly once written, in order, and a failure is one exception.
// The objects left open by a failure are closed by their handles without a word (the C++
// API's destructors report failed closes on std::cerr whatever dontPrint() says: one line
// per object unwound after a full disk).
#include <array>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <hdf5.h>

#include "chunk_layout.hpp"
#include "hdf5_image.hpp"

namespace wpg::datasets::detail {
namespace {

// An HDF5 id and the function that closes it. close() in the normal path, in order, reporting
// its error; the destructor closes what an error left open, quietly (the error is already
// reported). A failed close is never tried again (HDF5 1.10.8 crashes on a second close of a
// file whose close failed; an object's id is released whatever its close returns).
class Handle {
 public:
  using Close = herr_t (*)(hid_t);
  Handle(hid_t id, Close close, const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("cannot " + what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t id() const { return id_; }
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    if (close_(id) < 0) throw std::runtime_error("cannot close " + what);
  }

 private:
  hid_t id_;
  Close close_;
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("cannot " + what);
}

// The attributes' string type and scalar dataspace, made once (HDF5 copies them into each
// attribute, so the file is the same): making and closing them for each of a run's ~110
// attributes was ~7 % of the batch writer's serial work. Made on first use, by a caller holding
// hdf5Mutex() like every writer here, and never closed (HDF5 closes them at exit).
hid_t utf8StringType() {
  static const hid_t type = [] {
    const hid_t made = H5Tcopy(H5T_C_S1);
    if (made < 0 || H5Tset_size(made, H5T_VARIABLE) < 0 ||
        H5Tset_cset(made, H5T_CSET_UTF8) < 0) {
      throw std::runtime_error("cannot make HDF5's UTF-8 string type");
    }
    return made;
  }();
  return type;
}

hid_t scalarSpace() {
  static const hid_t space = H5Screate(H5S_SCALAR);
  if (space < 0) throw std::runtime_error("cannot make HDF5's scalar dataspace");
  return space;
}

// The creation properties of a chunked dataset (chunk shape, shuffle, deflate), made once per
// chunk shape for the same reason: HDF5 copies them into each dataset it creates, so the file
// is the same, and making, filling and closing them for each of a run's ~20 chunked datasets
// was ~8 % of the batch writer's serial work. The shapes of a study's runs are few (the chunk
// holds the whole dataset up to kChunkBytes); the cache starts again past kMaxShapes. Used
// under hdf5Mutex(), like the two above.
hid_t chunkedProperties(int rank, hsize_t chunk_rows, hsize_t columns) {
  constexpr std::size_t kMaxShapes = 256;
  using Shape = std::array<hsize_t, 3>;
  static auto* const made = new std::map<Shape, hid_t>();  // never destroyed
  const Shape shape = {static_cast<hsize_t>(rank), chunk_rows, columns};
  const auto found = made->find(shape);
  if (found != made->end()) return found->second;
  if (made->size() >= kMaxShapes) {
    for (const auto& entry : *made) H5Pclose(entry.second);
    made->clear();
  }
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  const hsize_t chunk[2] = {chunk_rows, columns};
  if (properties < 0 || H5Pset_chunk(properties, rank, chunk) < 0 ||
      H5Pset_shuffle(properties) < 0 || H5Pset_deflate(properties, kDeflateLevel) < 0) {
    if (properties >= 0) H5Pclose(properties);
    throw std::runtime_error("cannot make a chunked dataset's creation properties");
  }
  return made->emplace(shape, properties).first->second;
}

// A 1-D dataset of variable-length strings, contiguous.
void commitStrings(const DatasetImage& image, hid_t group) {
  const std::string what = "dataset " + image.name;
  const hsize_t count = image.strings.size();
  Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose, "make the space of " + what);
  Handle dataset(H5Dcreate2(group, image.name.c_str(), utf8StringType(), space.id(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, "create " + what);
  space.close("the space of " + what);
  std::vector<const char*> texts;
  texts.reserve(image.strings.size());
  for (const std::string& text : image.strings) texts.push_back(text.c_str());
  if (count > 0) {
    check(H5Dwrite(dataset.id(), utf8StringType(), H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()),
          "write " + what);
  }
  for (const AttributeImage& attribute : image.attributes) commitAttribute(dataset.id(), attribute);
  dataset.close(what);
}

void commitDataset(const DatasetImage& image, hid_t group) {
  if (image.type == ElementType::kString) return commitStrings(image, group);
  const int rank = image.columns == 0 ? 1 : 2;
  const hsize_t dimensions[2] = {image.rows, image.columns};
  hid_t file_type = H5T_IEEE_F64LE;
  if (image.type == ElementType::kInt32) file_type = H5T_STD_I32LE;
  if (image.type == ElementType::kUint8) file_type = H5T_STD_U8LE;
  const std::string what = "dataset " + image.name;
  Handle space(H5Screate_simple(rank, dimensions, nullptr), H5Sclose, "make the space of " + what);
  Handle dataset(H5Dcreate2(group, image.name.c_str(), file_type, space.id(), H5P_DEFAULT,
                            image.rows > 0 ? chunkedProperties(rank, image.chunk_rows, image.columns)
                                           : H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose, "create " + what);
  space.close("the space of " + what);
  for (std::size_t c = 0; c < image.chunks.size(); ++c) {
    const hsize_t offset[2] = {c * image.chunk_rows, 0};
    const std::vector<unsigned char>& chunk = image.chunks[c];
    check(H5Dwrite_chunk(dataset.id(), H5P_DEFAULT, 0, offset, chunk.size(), chunk.data()),
          "write a chunk of " + what);
  }
  for (const AttributeImage& attribute : image.attributes) commitAttribute(dataset.id(), attribute);
  dataset.close(what);
}

}  // namespace

void commitAttribute(std::int64_t object, const AttributeImage& attribute) {
  const std::string what = "attribute " + attribute.name;
  const char* name = attribute.name.c_str();
  std::visit(
      [&](const auto& value) {
        using Value = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<Value, int>) {
          Handle made(H5Acreate2(object, name, H5T_STD_I32LE, scalarSpace(), H5P_DEFAULT,
                                 H5P_DEFAULT),
                      H5Aclose, "create " + what);
          check(H5Awrite(made.id(), H5T_NATIVE_INT, &value), "write " + what);
          made.close(what);
        } else if constexpr (std::is_same_v<Value, double>) {
          Handle made(H5Acreate2(object, name, H5T_IEEE_F64LE, scalarSpace(), H5P_DEFAULT,
                                 H5P_DEFAULT),
                      H5Aclose, "create " + what);
          check(H5Awrite(made.id(), H5T_NATIVE_DOUBLE, &value), "write " + what);
          made.close(what);
        } else if constexpr (std::is_same_v<Value, std::string>) {
          Handle made(H5Acreate2(object, name, utf8StringType(), scalarSpace(), H5P_DEFAULT,
                                 H5P_DEFAULT),
                      H5Aclose, "create " + what);
          const char* text = value.c_str();
          check(H5Awrite(made.id(), utf8StringType(), &text), "write " + what);
          made.close(what);
        } else {
          const hsize_t count = value.size();
          Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose, "make the space of " + what);
          Handle made(H5Acreate2(object, name, utf8StringType(), space.id(), H5P_DEFAULT,
                                 H5P_DEFAULT),
                      H5Aclose, "create " + what);
          std::vector<const char*> texts;
          texts.reserve(value.size());
          for (const std::string& text : value) texts.push_back(text.c_str());
          if (count > 0) check(H5Awrite(made.id(), utf8StringType(), texts.data()), "write " + what);
          made.close(what);
          space.close("the space of " + what);
        }
      },
      attribute.value);
}

void commit(const GroupImage& image, std::int64_t target) {
  // Errors are this function's exceptions, not HDF5's printout (H5Eset_auto2: for this thread's
  // error stack; Debian's HDF5 keeps one for the process).
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  for (const GroupImage::Entry& entry : image.entries()) {
    if (const auto* attribute = std::get_if<AttributeImage>(&entry)) {
      commitAttribute(target, *attribute);
    } else if (const auto* dataset = std::get_if<DatasetImage>(&entry)) {
      commitDataset(*dataset, target);
    } else if (const auto* child = std::get_if<std::unique_ptr<GroupImage::Child>>(&entry)) {
      const std::string what = "group " + (*child)->name;
      const char* name = (*child)->name.c_str();
      Handle group((*child)->exists ? H5Gopen2(target, name, H5P_DEFAULT)
                                    : H5Gcreate2(target, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Gclose, ((*child)->exists ? "open " : "create ") + what);
      commit((*child)->group, group.id());
      group.close(what);
    } else {
      commit(*std::get<std::shared_ptr<const GroupImage>>(entry), target);
    }
  }
}

void commitFile(const std::string& path, const GroupImage& root) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are exceptions, not HDF5's printout
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "make the file access properties");
  check(H5Pset_fclose_degree(access.id(), H5F_CLOSE_STRONG), "set the file's close degree");
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id());
  if (file < 0) throw std::runtime_error("cannot create the file");
  try {
    commit(root, file);
  } catch (const std::runtime_error&) {
    // HDF5 1.10.8 frees part of a file whose close failed and crashes when it is closed
    // again: closed once, its error ignored (this error is the one reported).
    H5Fclose(file);
    throw;
  }
  if (H5Fclose(file) < 0) throw std::runtime_error("cannot close the file");
}

}  // namespace wpg::datasets::detail
