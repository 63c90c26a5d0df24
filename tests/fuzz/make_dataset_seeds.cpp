// make_dataset_seeds OUT_DIR MAX_ROWS FILE.h5...: encodes real run datasets as inputs of
// fuzz_run_dataset_reader, or shard files as inputs of fuzz_shard_reader (hdf5_image.hpp),
// OUT_DIR/<file name without .h5>, every dataset with at most MAX_ROWS rows stored (the rest
// continued by the image's step: same declared shapes, a short input). Checks that each seed decodes to what was encoded.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "hdf5_image.hpp"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: make_dataset_seeds OUT_DIR MAX_ROWS FILE.h5...\n");
    return 2;
  }
  const std::filesystem::path out_dir = argv[1];
  const std::uint64_t max_rows = std::strtoull(argv[2], nullptr, 10);
  std::filesystem::create_directories(out_dir);
  for (int i = 3; i < argc; ++i) {
    wpg_fuzz::FileImage image = wpg_fuzz::readHdf5(argv[i], max_rows);
    // Without what the reader never opens (recomputed on replay, run_dataset_reader.hpp): the
    // checks, obstacles and timing groups, the multibody datasets (its attributes stay) and the
    // documentation attributes of the datasets (but mpc/slack's, which name its columns).
    // Each input is then written several times faster, and mutations land where they matter.
    const auto unread = [](const wpg_fuzz::Entry& entry) {
      for (const char* group : {"/checks", "/obstacles", "/timing"}) {
        if (entry.path.find(group) != std::string::npos) return true;
      }
      if (entry.kind == wpg_fuzz::Entry::Kind::kDataset) {
        return entry.path.find("/multibody/") != std::string::npos;
      }
      if (entry.kind != wpg_fuzz::Entry::Kind::kAttribute) return false;
      const bool slack = entry.path.size() >= 6 &&
                         entry.path.compare(entry.path.size() - 6, 6, "/slack") == 0;
      // The summary table's `columns` (shard files) is read by `wpg merge`.
      const bool summary = entry.path == "/batch/summary";
      for (const char* name : {"description", "units", "frame", "columns", "codes"}) {
        if (entry.attribute.name == name && !slack && !summary) return true;
      }
      return false;
    };
    image.entries.erase(std::remove_if(image.entries.begin(), image.entries.end(), unread),
                        image.entries.end());
    if (image.entries.empty()) {
      std::fprintf(stderr, "make_dataset_seeds: %s: nothing read (not an HDF5 file?)\n", argv[i]);
      return 1;
    }
    const std::vector<std::uint8_t> bytes = wpg_fuzz::encode(image);
    if (wpg_fuzz::encode(wpg_fuzz::decode(bytes.data(), bytes.size())) != bytes) {
      std::fprintf(stderr, "make_dataset_seeds: %s: the seed does not decode to itself\n", argv[i]);
      return 1;
    }
    const std::filesystem::path out = out_dir / std::filesystem::path(argv[i]).stem();
    std::ofstream(out, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    std::printf("%s: %zu objects, %zu bytes\n", out.c_str(), image.entries.size(), bytes.size());
  }
  return 0;
}
