#pragma once
// Limits on what a scenario, study or --set override may ask for (documented in
// datasets/SCENARIOS.md, "Limits"). Past them the input is refused before anything runs (exit 2,
// one line naming the file and the key).
#include <cstddef>

namespace wpg::datasets {

// Scenario, study and robot files: regular files of at most this size, read with this cap
// (a device such as /dev/zero or a FIFO would never end). The largest shipped file (the study
// obstacle_scenes.yaml) is 74 kB; 100 000 circles, one flow map a line, take 5.9 MB.
constexpr std::size_t kMaxInputFileBytes = 16u << 20;  // 16 MiB

// Names and indices in a --set key (`a.b[2].c` has 4): assigning a path walks it recursively.
constexpr std::size_t kMaxOverridePathSteps = 32;

// Every length and position of a scenario (obstacles, goal, planner distances and bounds,
// generated worlds, the robot's lengths) is at most this in magnitude [m]: FCL squares
// coordinates, and 1e155 m overflows to inf there.
constexpr double kMaxLength = 1e4;

// Circles of a generated random field (comparison studies).
constexpr int kMaxGeneratedObstacles = 10000;

// Push forces [N] at most this in magnitude (the paper's largest recovered push is ~500 N): a
// 1e30 N push drives the inverse kinematics of the replay to non-finite joint angles.
constexpr double kMaxPushForce = 1e5;

// Names (scenario, robot, study, world, variant) become file names and HDF5 names: at most
// this many characters (a file name is at most 255 bytes, with room for ".h5" and a
// temporary suffix).
constexpr std::size_t kMaxNameLength = 128;
// Study, world and variant names at most this long: a run's name joins them
// (`<study>_<number>`, `<world>.<variant>.<seed>`) and is a scenario name.
constexpr std::size_t kMaxStudyNameLength = 32;

// Runs a comparison study (worlds x variants x seeds) expands to, at most; also the most
// `sweep.random.samples` and a count of `seeds`. Every comparison run is listed before the
// first walk: a product of 2^64 would wrap to 0.
constexpr std::size_t kMaxStudyRuns = 1000000;

// Runs of a sweep study (grid x zip x random samples), at most: 2^31 - 1, as the batch files
// number them (int32 `index` and `run_count`). Its runs are computed one at a time from their
// index (study_runs.hpp), so a study of 10^7 runs costs no more memory than one of 10; a
// product over it (up to 2^64 and beyond) is refused, counted factor by factor without wrapping.
constexpr std::size_t kMaxSweepRuns = 2147483647;

// Rows of one batch file's summary table (a whole batch, an MPI shard, an index), at most: a
// table of every run is allocated when the file is created (10^7 rows: ~80 MB a column). A
// larger study runs as slices (`wpg batch --shard K/N`), whose tables hold their runs only.
constexpr std::size_t kMaxBatchFileRuns = 10000000;

}  // namespace wpg::datasets
