// Files we did not write: a real run dataset (walk_forward, 4 s, written as
// `wpg run` writes it) edited with the HDF5 C/C++ API into what a hostile or corrupt file holds.
// Every reader must refuse it with one InputError line naming the file, the dataset (and row)
// and what was expected, without allocating what the file declares, and without crashing or
// looping: readRunDataset and checkStoredRunMatchesScenario (`wpg replay`, `wpg analyze`),
// diffDatasets (`wpg diff`), readBatchSummary and BatchDatasetWriter::resume (`wpg batch`).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/dataset_diff.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/datasets/storage/stored_run_consistency.hpp"
#include "wpg/walk_generator.hpp"

namespace fs = std::filesystem;
using wpg::datasets::InputError;
using wpg::datasets::Scenario;
using wpg::datasets::StoredRun;

namespace {

// One real run, generated once for all tests (the NMPC is the slow part).
const std::string& realRunFile() {
  static const std::string path = [] {
    const std::string file =
        (fs::temp_directory_path() / ("wpg_test_hostile_" + std::to_string(::getpid()) + ".h5"))
            .string();
    const Scenario scenario = wpg::datasets::loadScenario(
        wpg_test::kScenariosDir + "/walk_forward.yaml", {"duration=4"}, wpg_test::kRobotsDir);
    const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
    wpg::datasets::writeRunDataset(file, scenario, result);
    return file;
  }();
  return path;
}

class HostileFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  HostileFiles() : ScratchDirectoryTest("wpg_test_hostile_files") {}
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove(realRunFile(), ec);
  }

  // A fresh copy of the real run, to edit.
  std::string copy(const std::string& name) const {
    const std::string path = (directory_ / name).string();
    fs::copy_file(realRunFile(), path);
    return path;
  }

  static void writeDoubleAt(const std::string& file, const std::string& dataset,
                            hsize_t row, hsize_t column, double value) {
    H5::H5File f(file, H5F_ACC_RDWR);
    H5::DataSet set = f.openDataSet(dataset);
    H5::DataSpace space = set.getSpace();
    const int rank = space.getSimpleExtentNdims();
    const hsize_t start[2] = {row, column}, count[2] = {1, 1};
    space.selectHyperslab(H5S_SELECT_SET, count, start);
    const H5::DataSpace one(rank, count);
    set.write(&value, H5::PredType::NATIVE_DOUBLE, one, space);
  }

  static double readDoubleAt(const std::string& file, const std::string& dataset, hsize_t row) {
    H5::H5File f(file, H5F_ACC_RDONLY);
    H5::DataSet set = f.openDataSet(dataset);
    H5::DataSpace space = set.getSpace();
    const int rank = space.getSimpleExtentNdims();
    const hsize_t start[2] = {row, 0}, count[2] = {1, 1};
    space.selectHyperslab(H5S_SELECT_SET, count, start);
    const H5::DataSpace one(rank, count);
    double value = 0.0;
    set.read(&value, H5::PredType::NATIVE_DOUBLE, one, space);
    return value;
  }

  static void replaceStringAttribute(const std::string& file, const std::string& name,
                                     const std::string& value) {
    H5::H5File f(file, H5F_ACC_RDWR);
    f.removeAttr(name);
    const H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
    f.createAttribute(name, type, H5::DataSpace(H5S_SCALAR)).write(type, value);
  }

  static std::string rootScenario(const std::string& file) {
    H5::H5File f(file, H5F_ACC_RDONLY);
    const H5::Attribute attribute = f.openAttribute("scenario");
    std::string text;
    attribute.read(attribute.getStrType(), text);
    return text;
  }

  // `dataset` replaced by a chunked one that declares `rows` x `columns` and stores nothing
  // (unwritten chunks read as the fill value: a few bytes of metadata declare gigabytes).
  static void declareRows(const std::string& file, const std::string& dataset, hsize_t rows,
                          hsize_t columns) {
    H5::H5File f(file, H5F_ACC_RDWR);
    if (f.nameExists(dataset)) f.unlink(dataset);
    const hsize_t dims[2] = {rows, columns};
    const hsize_t max_dims[2] = {H5S_UNLIMITED, columns};
    const hsize_t chunk[2] = {1024, columns};
    const int rank = columns == 0 ? 1 : 2;
    H5::DSetCreatPropList properties;
    properties.setChunk(rank, chunk);
    f.createDataSet(dataset, H5::PredType::IEEE_F64LE, H5::DataSpace(rank, dims, max_dims),
                    properties);
  }

  static StoredRun read(const std::string& file) { return wpg::datasets::readRunDataset(file); }

  // The stored scenario of `file`, loaded as `wpg replay` loads it.
  static Scenario storedScenario(const StoredRun& stored, const std::string& file) {
    return wpg::datasets::loadScenarioText(stored.scenario_yaml, file + ":/scenario", {},
                                           wpg_test::kRobotsDir);
  }
};

TEST_F(HostileFiles, TheRealRunIsAcceptedWhole) {
  const std::string file = copy("run.h5");
  const StoredRun stored = read(file);
  EXPECT_EQ(stored.result.trajectory.time.size(), 801u);  // 4 s at 5 ms and the closing sample
  EXPECT_EQ(stored.result.trajectory.mpc.size(), 40u);
  EXPECT_EQ(stored.result.trajectory.footsteps.size(), 4u);  // the initial feet, two steps
  EXPECT_NO_THROW(wpg::datasets::checkStoredRunMatchesScenario(file, stored,
                                                               storedScenario(stored, file)));
}

TEST_F(HostileFiles, NanTimeIsRefusedWithItsRow) {
  const std::string file = copy("nan_time.h5");
  writeDoubleAt(file, "/runs/walk_forward/time", 12, 0, std::nan(""));
  wpg_test::expectInputError([&] { read(file); }, file,
                             {"/runs/walk_forward/time row 12", "expected a finite number"});
}

TEST_F(HostileFiles, NonMonotonicTimeIsRefusedWithItsRow) {
  const std::string file = copy("time_backwards.h5");
  writeDoubleAt(file, "/runs/walk_forward/time", 30, 0, 0.1);  // row 30 is at 0.15 s
  wpg_test::expectInputError([&] { read(file); }, file,
                             {"/runs/walk_forward/time row 30", "strictly increasing"});
}

TEST_F(HostileFiles, NanInTheMpcTimeOrTheSamplesIsRefused) {
  const std::string mpc = copy("mpc_time.h5");
  writeDoubleAt(mpc, "/runs/walk_forward/mpc/time", 3, 0, 0.1);
  wpg_test::expectInputError([&] { read(mpc); }, mpc,
                             {"/runs/walk_forward/mpc/time row 3", "strictly increasing"});
  const std::string com = copy("com.h5");
  writeDoubleAt(com, "/runs/walk_forward/com", 12, 1, std::numeric_limits<double>::infinity());
  wpg_test::expectInputError([&] { read(com); }, com,
                             {"/runs/walk_forward/com row 12 column 1", "finite"});
}

TEST_F(HostileFiles, NanFootstepIsRefusedWithItsRow) {
  const std::string file = copy("nan_footstep.h5");
  writeDoubleAt(file, "/runs/walk_forward/footsteps", 3, 1, std::nan(""));
  wpg_test::expectInputError([&] { read(file); }, file,
                             {"/runs/walk_forward/footsteps row 3 column 1", "finite"});
}

// The walk at 5 ms paired with a scenario at 10 ms: `wpg replay` filtered it into NaN
// (zmp_multibody_filtered) before; now the pair is refused.
TEST_F(HostileFiles, StoredScenarioWithAnotherControlPeriodIsRefused) {
  const std::string file = copy("other_period.h5");
  std::string text = rootScenario(file);
  const std::string key = "control_period: 0.005";
  ASSERT_NE(text.find(key), std::string::npos) << text;
  text.replace(text.find(key), key.size(), "control_period: 0.01");
  replaceStringAttribute(file, "scenario", text);
  const StoredRun stored = read(file);
  const Scenario scenario = storedScenario(stored, file);
  wpg_test::expectInputError(
      [&] { wpg::datasets::checkStoredRunMatchesScenario(file, stored, scenario); }, file,
      {"/runs/walk_forward/time row 1", "walking.control_period 0.01", "does not match"});
}

TEST_F(HostileFiles, StoredScenarioWithAnotherCentreOfMassHeightOrDurationIsRefused) {
  const std::string file = copy("other_height.h5");
  const StoredRun stored = read(file);
  Scenario scenario = storedScenario(stored, file);
  scenario.walking.com_height += 0.05;
  wpg_test::expectInputError(
      [&] { wpg::datasets::checkStoredRunMatchesScenario(file, stored, scenario); }, file,
      {"/runs/walk_forward/com row 0 column 2", "walking.com_height"});
  scenario = storedScenario(stored, file);
  scenario.request.duration = 1.0;
  wpg_test::expectInputError(
      [&] { wpg::datasets::checkStoredRunMatchesScenario(file, stored, scenario); }, file,
      {"/runs/walk_forward/time has 801 rows", "expected at most 201"});
  scenario = storedScenario(stored, file);
  scenario.robot = "other";
  wpg_test::expectInputError(
      [&] { wpg::datasets::checkStoredRunMatchesScenario(file, stored, scenario); }, file,
      {"/runs/walk_forward:robot"});
}

TEST_F(HostileFiles, FootstepsOutOfTheWalkAreRefused) {
  const std::string file = copy("late_step.h5");
  writeDoubleAt(file, "/runs/walk_forward/footsteps", 3, 0, 50.0);  // landing at 50 s of 4 s
  const StoredRun stored = read(file);
  wpg_test::expectInputError(
      [&] {
        wpg::datasets::checkStoredRunMatchesScenario(file, stored, storedScenario(stored, file));
      },
      file, {"/runs/walk_forward/footsteps row 3 column 0", "landing time"});
}

// 2e8 rows declared in a file of a few hundred kB: refused from the dataspace, before any
// allocation (reading would need 4.8 GB for com alone).
TEST_F(HostileFiles, DeclaredSizesBeyondTheLimitAreRefusedBeforeAllocation) {
  const std::string file = copy("huge.h5");
  declareRows(file, "/runs/walk_forward/com", 200000000, 3);
  EXPECT_LT(fs::file_size(file), 1u << 20);
  const auto start = std::chrono::steady_clock::now();
  wpg_test::expectInputError([&] { read(file); }, file,
                             {"/runs/walk_forward/com declares 200000000 rows",
                              "expected at most " + std::to_string(wpg::datasets::kMaxStoredSamples)});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));

  const std::string steps = copy("huge_steps.h5");
  declareRows(steps, "/runs/walk_forward/footsteps", 200000000, 4);
  wpg_test::expectInputError([&] { read(steps); }, steps,
                             {"/runs/walk_forward/footsteps declares 200000000 rows"});
}

// mpc/plan/ is read back as it was written, every number bit for bit, so that a replayed or
// rewritten run keeps what each NMPC iteration predicted.
TEST_F(HostileFiles, ThePlanIsReadBackAsWritten) {
  const Scenario scenario = wpg::datasets::loadScenario(
      wpg_test::kScenariosDir + "/walk_forward.yaml", {"duration=4"}, wpg_test::kRobotsDir);
  const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
  const wpg::PlanLog& written = result.trajectory.plans;
  ASSERT_EQ(written.size(), 40u);
  const wpg::PlanLog& read_back = read(copy("plan.h5")).result.trajectory.plans;
  EXPECT_EQ(read_back.max_samples, written.max_samples);
  EXPECT_EQ(read_back.steps, written.steps);
  EXPECT_EQ(read_back.families, written.families);
  EXPECT_EQ(read_back.sampling_period, written.sampling_period);
  EXPECT_EQ(read_back.samples, written.samples);
  EXPECT_EQ(read_back.com_position, written.com_position);
  EXPECT_EQ(read_back.com_velocity, written.com_velocity);
  EXPECT_EQ(read_back.com_acceleration, written.com_acceleration);
  EXPECT_EQ(read_back.jerk, written.jerk);
  EXPECT_EQ(read_back.cop, written.cop);
  EXPECT_EQ(read_back.step, written.step);
  EXPECT_EQ(read_back.step_side, written.step_side);
  EXPECT_EQ(read_back.active_rows, written.active_rows);
}

// A plan's sizes come from its attributes, bounded before any dataset is read; each dataset
// must hold exactly its iterations' rows.
TEST_F(HostileFiles, APlanOfBadSizesIsRefusedWithItsDataset) {
  const std::string plan = "/runs/walk_forward/mpc/plan";
  const std::string huge = copy("huge_plan.h5");
  {
    H5::H5File f(huge, H5F_ACC_RDWR);
    H5::Group group = f.openGroup(plan);
    group.removeAttr("samples");
    group.createAttribute("samples", H5::PredType::NATIVE_INT, H5::DataSpace(H5S_SCALAR))
        .write(H5::PredType::NATIVE_INT, std::vector<int>{1000000000}.data());
  }
  wpg_test::expectInputError([&] { read(huge); }, huge,
                             {plan + ":samples: expected an integer in [1, 200]"});

  const std::string short_com = copy("short_plan.h5");
  declareRows(short_com, plan + "/com", 39, 2);
  wpg_test::expectInputError([&] { read(short_com); }, short_com,
                             {plan + "/com has 39 rows, expected 640"});

  const std::string declared = copy("declared_plan.h5");
  declareRows(declared, plan + "/cop", 200000000, 2);
  wpg_test::expectInputError([&] { read(declared); }, declared,
                             {plan + "/cop declares 200000000 rows: expected at most 640"});

  const std::string nan = copy("nan_plan.h5");
  writeDoubleAt(nan, plan + "/steps", 7, 2, std::nan(""));
  wpg_test::expectInputError([&] { read(nan); }, nan, {plan + "/steps row 7 column 2"});
}

// Attributes read into one value must hold one (an array would be written past it).
TEST_F(HostileFiles, ArrayAttributesWhereOneValueIsExpectedAreRefused) {
  const std::string file = copy("array_success.h5");
  {
    H5::H5File f(file, H5F_ACC_RDWR);
    H5::Group run = f.openGroup("/runs/walk_forward");
    run.removeAttr("success");
    const hsize_t dims[1] = {1000};
    const std::vector<int> ones(dims[0], 1);
    run.createAttribute("success", H5::PredType::NATIVE_INT, H5::DataSpace(1, dims))
        .write(H5::PredType::NATIVE_INT, ones.data());
  }
  wpg_test::expectInputError([&] { read(file); }, file,
                             {"/runs/walk_forward:success", "expected one value, got 1000"});

  const std::string text = copy("array_scenario.h5");
  {
    H5::H5File f(text, H5F_ACC_RDWR);
    f.removeAttr("scenario");
    const H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
    const hsize_t dims[1] = {2};
    const char* values[2] = {"name: a", "name: b"};
    f.createAttribute("scenario", type, H5::DataSpace(1, dims)).write(type, values);
  }
  wpg_test::expectInputError([&] { read(text); }, text,
                             {"/:scenario", "expected one value, got 2"});
}

// `wpg diff` walks every group: a cycle of hard links (or a soft link to an ancestor) made it
// recurse until the stack overflowed.
TEST_F(HostileFiles, DiffFollowsALinkCycleOnce) {
  const std::string a = copy("cycle_a.h5");
  const std::string b = copy("cycle_b.h5");
  for (const std::string& file : {a, b}) {
    H5::H5File f(file, H5F_ACC_RDWR);
    f.link(H5L_TYPE_HARD, "/runs", "/runs/walk_forward/mpc/back_to_runs");
    f.link(H5L_TYPE_SOFT, "/", "/runs/walk_forward/to_root");
  }
  const wpg::datasets::DatasetDiff diff = wpg::datasets::diffDatasets(a, b, {});
  EXPECT_TRUE(diff.differences.empty());
  EXPECT_GT(diff.datasets_compared, 20u);
}

TEST_F(HostileFiles, DiffRefusesDeclaredSizesBeyondTheLimit) {
  const std::string a = copy("diff_a.h5");
  const std::string b = copy("diff_b.h5");
  declareRows(b, "/runs/walk_forward/com", 200000000, 3);
  const auto start = std::chrono::steady_clock::now();
  wpg_test::expectInputError([&] { wpg::datasets::diffDatasets(a, b, {}); }, b,
                             {"dataset /runs/walk_forward/com declares 200000000 x 3 elements"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST_F(HostileFiles, DiffRefusesGroupsNestedBeyondTheLimit) {
  const std::string a = copy("deep_a.h5");
  const std::string b = copy("deep_b.h5");
  for (const std::string& file : {a, b}) {
    H5::H5File f(file, H5F_ACC_RDWR);
    std::string path;
    for (int level = 0; level < wpg::datasets::kMaxGroupDepth + 2; ++level) {
      path += "/g";
      f.createGroup(path);
    }
  }
  wpg_test::expectInputError([&] { wpg::datasets::diffDatasets(a, b, {}); }, a,
                             {"levels deep", "expected at most"});
}

// A batch file's summary table (`wpg batch` summary.csv, `--resume`) declaring 2e8 rows.
TEST_F(HostileFiles, BatchSummaryDeclaringHugeColumnsIsRefused) {
  const std::string file = (directory_ / "batch.h5").string();
  {
    H5::H5File f(file, H5F_ACC_TRUNC);
    const H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
    f.createAttribute("study_name", type, H5::DataSpace(H5S_SCALAR)).write(type, std::string("s"));
    f.createGroup("/batch");
    H5::Group table = f.createGroup("/batch/summary");
    const hsize_t one[1] = {1};
    const char* columns[1] = {"index"};
    table.createAttribute("columns", type, H5::DataSpace(1, one)).write(type, columns);
  }
  declareRows(file, "/batch/summary/index", 200000000, 0);
  wpg_test::expectInputError([&] { wpg::datasets::readBatchSummary(file); }, file,
                             {"dataset /batch/summary/index declares 200000000 elements"});
}

// `wpg batch --resume` on a file whose study name is an array of strings: HDF5's C++ API read
// them all into one pointer (writing past it) before.
TEST_F(HostileFiles, ResumeRefusesAnArrayStudyName) {
  const fs::path study_file = directory_ / "two.yaml";
  std::ofstream(study_file) << "name: two\nbase: walk_forward\nsweep:\n  grid: {robot_mass: [50.0, 55.0]}\n";
  const wpg::datasets::Study study = wpg::datasets::loadStudy(
      study_file.string(),
      [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
      wpg_test::kRobotsDir);
  const std::vector<wpg::datasets::SummaryColumn> columns = {{"distance", "m", "distance", false}};
  const std::string file = (directory_ / "batch.h5").string();
  wpg::datasets::BatchDatasetWriter::create(file, study, columns)->close();
  {
    H5::H5File f(file, H5F_ACC_RDWR);
    f.removeAttr("study_name");
    const H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
    const hsize_t dims[1] = {64};
    const std::vector<const char*> names(dims[0], "two");
    f.createAttribute("study_name", type, H5::DataSpace(1, dims)).write(type, names.data());
  }
  wpg_test::expectInputError(
      [&] { wpg::datasets::BatchDatasetWriter::resume(file, study, columns); }, file,
      {"/:study_name", "expected one value, got 64"});
}

}  // namespace
