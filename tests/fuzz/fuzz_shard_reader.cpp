// libFuzzer target: the reader of shard files (datasets/batch_index.hpp), what `wpg merge OUT.h5
// SHARD...` does: readShardContents of each shard, writeBatchIndex (the checks of every shard's
// study and summary table, then the index of links or of copies), then readBatchSummary of the
// index, from which `wpg merge` writes OUT.summary.csv/.md; and readComparisonRuns of the
// first shard, as `wpg view` reads a comparison's study file. The image's heap damages
// (heap_damage.hpp) are applied to both shards.
//
// The input describes the content of a valid HDF5 file (hdf5_image.hpp; why not raw HDF5
// bytes: README.md), written as two shards in a private folder:
//   a.h5: the image as it is;
//   b.h5: the same image with the odd rows of every dataset named `done` 0 (not done).
// Both are merged, b.h5 first, into an index of links and into one of copies (the even runs
// from b.h5, the odd ones from a.h5, their summary rows copied over b.h5's), and a.h5 alone
// into a third.
// Links of the image may point anywhere (the other shard, the image itself, a device): the
// library's external link guard checks them.
// Seeds: tests/fuzz/seeds/shard_reader/, the files of the 2-run study tests/cli/studies/
// tiny_batch.yaml (`wpg batch --shard 0/2` and `1/2`, the whole batch) and of tiny_compare.yaml
// (`wpg compare`), encoded by make_dataset_seeds with 40 rows kept (17-30 kB each).
//
// WPG_FUZZ_VERBOSE=1 (environment) prints what each merge made of an input.
//
// Properties checked, beyond "no crash, no sanitizer report, no hang, no leak, no huge
// allocation": bad input is an InputError (the CLI's exit 2); any other exception escapes and is
// reported as a crash (a shard the checks accepted must not fail while the index is written);
// an index written has every run done and is read back with one summary row per run.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "hdf5_image.hpp"
#include "private_folder.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/comparison_runs.hpp"

namespace {

namespace fs = std::filesystem;

std::string g_folder;  // private folder of the shards and indexes, rewritten for every input

void removeFolder() {
  std::error_code ignored;
  fs::remove_all(g_folder, ignored);
}

[[noreturn]] void propertyViolated(const std::string& what) {
  std::fprintf(stderr, "fuzz_shard_reader: %s\n", what.c_str());
  std::abort();
}

bool isDoneDataset(const wpg_fuzz::Entry& entry) {
  const std::string suffix = "/done";
  return entry.kind == wpg_fuzz::Entry::Kind::kDataset && entry.path.size() >= suffix.size() &&
         entry.path.compare(entry.path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The other shard's image: every `done` dataset's odd rows 0 (not done), its even rows as they
// are. Merged first, it gives the even runs; the odd ones come from the image itself (their
// summary rows copied from the second shard).
wpg_fuzz::FileImage evenRunsOnly(wpg_fuzz::FileImage image) {
  for (wpg_fuzz::Entry& entry : image.entries) {
    if (!isDoneDataset(entry)) continue;
    wpg_fuzz::ArrayEntry& array = entry.array;
    const std::uint64_t rows = std::min<std::uint64_t>(array.rows * array.columns, 4096);
    std::vector<double> values(rows, 0.0);
    for (std::uint64_t i = 0; i < rows; i += 2) {
      const std::size_t v = array.values.size();
      values[i] = v == 0 ? static_cast<double>(i) * array.step
                         : array.values[i % v] + static_cast<double>(i / v) * array.step;
    }
    array.values = std::move(values);
    array.step = 0.0;
  }
  return image;
}

bool verbose() {
  static const bool verbose = std::getenv("WPG_FUZZ_VERBOSE") != nullptr;
  return verbose;
}

void merge(const std::string& output, const std::vector<std::string>& shards,
           wpg::datasets::IndexLayout layout) {
  wpg::datasets::IndexReport report;
  try {
    report = wpg::datasets::writeBatchIndex(output, shards, layout);
    if (verbose()) std::fprintf(stderr, "%s: %zu runs\n", output.c_str(), report.runs);
  } catch (const wpg::datasets::InputError& error) {
    if (verbose()) std::fprintf(stderr, "%s: %s\n", output.c_str(), error.what());
    std::error_code ec;
    if (fs::exists(output, ec)) propertyViolated("a refused merge left " + output);
    return;
  }
  const wpg::datasets::ShardContents index = wpg::datasets::readShardContents(output);
  if (index.done.size() != report.runs) propertyViolated("the index has not every run");
  for (const bool done : index.done) {
    if (!done) propertyViolated("the index has a run not done");
  }
  // What `wpg merge` then reads for OUT.summary.csv/.md. A run an index links to may still be
  // unreadable (a shard's run group that is no group): that is the readers' business, an
  // InputError at worst.
  try {
    const wpg::datasets::BatchSummaryTable table = wpg::datasets::readBatchSummary(output);
    if (table.rows != report.runs) propertyViolated("the index's summary has not one row per run");
  } catch (const wpg::datasets::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_folder = wpg_fuzz::makePrivateFolder("wpg-fuzz-shards-");
  if (g_folder.empty()) propertyViolated("cannot create a private folder");
  std::atexit(removeFolder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path folder(g_folder);
  std::error_code ec;
  for (const char* name : {"index.h5", "copy.h5", "alone.h5"}) fs::remove(folder / name, ec);
  const std::string a = (folder / "a.h5").string(), b = (folder / "b.h5").string();
  const wpg_fuzz::FileImage image = wpg_fuzz::decode(data, size);
  if (!wpg_fuzz::writeHdf5(image, a)) propertyViolated("cannot create " + a);
  if (!wpg_fuzz::writeHdf5(evenRunsOnly(image), b)) propertyViolated("cannot create " + b);
  wpg_fuzz::applyImageDamage(image, a);
  wpg_fuzz::applyImageDamage(image, b);
  // What `wpg view` of a comparison reads of its study file (the comparison file reader).
  try {
    (void)wpg::datasets::readComparisonRuns(a);
  } catch (const wpg::datasets::InputError&) {
  }

  try {
    (void)wpg::datasets::readShardContents(a);
  } catch (const wpg::datasets::InputError& error) {
    if (verbose()) std::fprintf(stderr, "%s\n", error.what());
    return 0;  // every merge of it refuses it the same way
  }
  merge((folder / "index.h5").string(), {b, a}, wpg::datasets::IndexLayout::kLinks);
  merge((folder / "copy.h5").string(), {b, a}, wpg::datasets::IndexLayout::kCopy);
  merge((folder / "alone.h5").string(), {a}, wpg::datasets::IndexLayout::kLinks);
  return 0;
}
