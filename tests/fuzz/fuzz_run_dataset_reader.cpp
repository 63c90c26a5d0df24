// libFuzzer target: the run dataset reader (datasets/run_dataset_reader.hpp), what `wpg replay`
// and `wpg analyze` read. The input describes the content of a valid HDF5 file (hdf5_image.hpp
// says why not raw HDF5 bytes); it is written to a temporary file, because the reader opens a
// path, its heap damages applied (heap_damage.hpp), and read the way the CLI reads it:
//   wpg analyze: listRuns, then readRunDataset of each run;
//   wpg replay:  readRunDataset of the only run, then its stored scenario through
//                loadScenarioText with the replay overrides.
// Seeds: tests/fuzz/make_dataset_seeds.cpp on real run datasets (scripts/fuzz.sh).
//
// Properties checked, beyond "no crash, no sanitizer report, no hang, no huge allocation"
// (libFuzzer's -malloc_limit_mb): bad input is an InputError (the CLI's exit 2), any other
// exception escapes and is a crash; an accepted run has as many rows in every per-sample
// field as in its time, and as many MPC log rows as its log's time.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hdf5_image.hpp"
#include "private_folder.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "../common/source_dir.hpp"

namespace {

std::string g_path;  // the temporary HDF5 file, rewritten for every input
// WPG_FUZZ_MAX_ROWS (environment): the largest number of rows a dataset may declare, 2^40 by
// default. A smaller value explores past a known crash on huge declared sizes (until the
// reader refuses them) instead of finding it again at every run.
std::uint64_t g_max_rows = std::uint64_t{1} << 40;


[[noreturn]] void propertyViolated(const std::string& what) {
  std::fprintf(stderr, "fuzz_run_dataset_reader: %s\n", what.c_str());
  std::abort();
}

void checkRun(const wpg::datasets::StoredRun& stored) {
  const wpg::WalkTrajectory& t = stored.result.trajectory;
  const std::size_t n = t.time.size();
  if (n == 0) propertyViolated("an accepted run has no samples");
  if (t.com.size() != n || t.com_vel.size() != n || t.com_acc.size() != n ||
      t.cop.size() != n || t.left_foot.size() != n || t.right_foot.size() != n ||
      t.free_flyer_yaw.size() != n || t.support.size() != n) {
    propertyViolated("an accepted run has per-sample fields of different lengths");
  }
}

void readLikeReplay(const std::string& robots) {
  wpg::datasets::StoredRun stored;
  try {
    stored = wpg::datasets::readRunDataset(g_path);
  } catch (const wpg::datasets::InputError&) {
    return;
  }
  checkRun(stored);
  try {
    wpg::datasets::loadScenarioText(stored.scenario_yaml, g_path + ":/scenario",
                                    {"replay=true", "filter=false", "filter_settings.mode=offline"},
                                    robots);
  } catch (const wpg::datasets::InputError&) {
  }
}

void readLikeAnalyze() {
  std::vector<std::string> names;
  try {
    names = wpg::datasets::listRuns(g_path);
  } catch (const wpg::datasets::InputError&) {
    return;
  }
  for (const std::string& name : names) {
    try {
      checkRun(wpg::datasets::readRunDataset(g_path, name));
    } catch (const wpg::datasets::InputError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_path = wpg_fuzz::scratchFile("wpg-fuzz-dataset-");  // tmpfs when there is one
  if (const char* max_rows = std::getenv("WPG_FUZZ_MAX_ROWS")) {
    g_max_rows = std::strtoull(max_rows, nullptr, 10);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string robots = std::string(wpg_test::sourceDir()) + "/robots";
  const wpg_fuzz::FileImage image = wpg_fuzz::decode(data, size, g_max_rows);
  if (!wpg_fuzz::writeHdf5(image, g_path)) propertyViolated("cannot create " + g_path);
  wpg_fuzz::applyImageDamage(image, g_path);
  readLikeReplay(robots);
  readLikeAnalyze();
  return 0;
}
