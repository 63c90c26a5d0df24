#pragma once
// A study split over several files (datasets/SCHEMA.md, "Sharded batches"): shard files, each a
// batch file of the study (batch_dataset.hpp) holding only some of its runs (`done` marks them;
// a slice's table has its runs' rows only, an MPI rank's every run's), and the index file that readers open: the study's root attributes, /batch/summary with
// every row, and /runs/<name> as an HDF5 external link to the run's group in the shard that
// holds it, its file name relative to the index's folder (the folder of index + shards can be
// moved). `wpg batch --shard K/N` writes slices, `wpg batch` under MPI writes one shard per
// rank, and both end with writeBatchIndex (`wpg merge`).
//
// Why external links and not virtual datasets: a run is a group of ~40 datasets with attributes
// on the group and on each dataset; a virtual dataset maps one dataset's elements only, so the
// index would have to rebuild every group, every attribute and every dataset's layout (and VDS
// drops the chunks' compression, filters stay in the source). One link per run keeps the run as
// it was written, bit for bit, and h5py, `wpg analyze` and `wpg diff` follow links unchanged.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace wpg::datasets {

// The slicing rule of `--shard K/N` (0 <= K < N): run i belongs to slice i mod N. Strided, not
// blocks: neighbouring runs of a sweep cost about the same, so every slice gets its share of the
// slow ones.
inline bool inShardSlice(std::size_t run_index, int shard, int shard_count) {
  return static_cast<int>(run_index % static_cast<std::size_t>(shard_count)) == shard;
}

// How many runs of a study of `runs` slice K/N holds, and its row of run `run_index` (in it).
inline std::size_t sliceRunCount(std::size_t runs, int shard, int shard_count) {
  const auto k = static_cast<std::size_t>(shard), n = static_cast<std::size_t>(shard_count);
  return runs > k ? (runs - k - 1) / n + 1 : 0;
}

// The label a shard file carries in its root attribute `shard`: "K/N" for a slice,
// "rank R of S" for an MPI rank.
std::string shardSliceLabel(int shard, int shard_count);
std::string mpiRankLabel(int rank, int ranks);

// What a shard file holds, read without changing it.
struct ShardContents {
  std::string path;
  std::string label;  // root attribute `shard`; empty for a plain batch file
  std::string study_name, study_fingerprint;
  std::string created_by;  // root attribute: "wpg batch", "wpg compare"
  std::size_t run_count = 0;  // runs of the study (root attribute run_count)
  std::string fields = "all";  // what its runs store (root attribute `fields`: "summary, com")
  // Per row of its summary table: the run's index (every run of the study for a whole batch
  // or an MPI rank's shard, a slice's runs for a slice) and whether the run is in the file.
  std::vector<std::size_t> runs;
  std::vector<bool> done;
};

// Throws InputError (one line naming `path`) when it is not a readable batch file.
ShardContents readShardContents(const std::string& path);

enum class IndexLayout {
  kLinks,  // /runs/<name> external links into the shards (default of `wpg merge`)
  kCopy,   // /runs/<name> copied (H5Ocopy: chunks as they are): one self-contained file
};

struct IndexReport {
  std::size_t runs = 0;         // runs in the index (the whole study)
  std::size_t shards_used = 0;  // shards at least one run is taken from
};

// Writes the index of `shards` (shard or batch files of one study, in any order; a run done in
// several is taken from the first) to `output` through a temporary file renamed over it
// (output_file.hpp): nothing is written when it throws. Throws InputError (one line) when a
// file is not a readable batch file, holds another study (name, fingerprint or summary columns
// differ from the first's), or when runs are in none of the files (naming the missing slices
// K/N when the shards are slices); std::runtime_error on I/O errors. `complete` (may be empty)
// is called with the written index's temporary path before it is renamed over `output` (e.g. to
// add a comparison's table): what it throws is thrown, and no index is left.
IndexReport writeBatchIndex(const std::string& output, const std::vector<std::string>& shards,
                            IndexLayout layout,
                            const std::function<void(const std::string& index)>& complete = {});

}  // namespace wpg::datasets
