// The batch file (wpg/datasets/storage/batch_dataset.hpp), read back with the HDF5 C++ API: run
// groups with their scenario and swept values, the summary table filled row by row, prepared
// (chunks compressed off the writer) and direct writes giving the same data, --resume's checks.
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "hand_made_run.hpp"
#include "hdf5_read.hpp"
#include "test_support.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"

namespace fs = std::filesystem;
using namespace wpg::datasets;  // NOLINT: the API under test
using namespace wpg_test;       // NOLINT: HDF5 readers

namespace {

class BatchFiles : public ScratchDirectoryTest {
 protected:
  BatchFiles() : ScratchDirectoryTest("wpg_test_batch") {}

  Study load(const std::string& name, const std::string& grid) {
    const fs::path path = directory_ / (name + ".yaml");
    std::ofstream(path) << "name: " << name << "\nbase: walk_forward\nsweep:\n  grid: " << grid
                        << "\n";
    return loadStudy(
        path.string(), [](const std::string& base) { return kScenariosDir + "/" + base + ".yaml"; },
        kRobotsDir);
  }

  std::string bytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
  }
};

const std::vector<SummaryColumn> kColumns = {{"distance", "m", "distance walked", false},
                                            {"steps", "1", "steps taken", true}};

}  // namespace

TEST_F(BatchFiles, RunsAndSummaryRowsAsTheyFinish) {
  const Study study = load("three", "{robot_mass: [50.0, 55.0, 60.0]}");
  const std::string path = (directory_ / "batch.h5").string();
  const wpg::WalkResult direct = handMadeResult(300, 4, 6, 0.0);
  const wpg::WalkResult prepared_result = handMadeResult(300, 4, 6, 0.0);
  {
    auto writer = BatchDatasetWriter::create(path, study, kColumns);
    BatchRunRecord record;
    const StudyRun run0 = study.runs[0], run2 = study.runs[2];
    record.run = &run0;
    record.result = &direct;
    record.values = {1.5, 3.0};
    writer->write(record);
    record.run = &run2;
    record.result = &prepared_result;
    record.exit_status = 1;
    record.values = {2.5, 7.0};
    const PreparedRun prepared = BatchDatasetWriter::prepare(record);
    writer->write(record, &prepared);
    writer->close();
  }
  H5::H5File file(path, H5F_ACC_RDONLY);
  EXPECT_EQ(stringAttribute(file, "study_name"), "three");
  EXPECT_EQ(intAttribute(file, "run_count"), 3);
  const H5::Group runs = file.openGroup("runs");
  ASSERT_EQ(runs.getNumObjs(), 2u);
  const H5::Group run0 = runs.openGroup("three_0");
  EXPECT_EQ(intAttribute(run0, "batch_index"), 0);
  EXPECT_DOUBLE_EQ(doubleAttribute(run0, "sweep.robot_mass"), 50.0);
  EXPECT_NE(stringAttribute(run0, "scenario").find("name: three_0"), std::string::npos);
  // the prepared run's chunks hold the same values as the direct write
  const H5::Group run2 = runs.openGroup("three_2");
  for (const char* name : {"com", "cop", "left_foot", "time"}) {
    EXPECT_EQ(readDoubles(run0, name), readDoubles(run2, name)) << name;
  }
  EXPECT_EQ(readDoubles(run0, "mpc/cost"), readDoubles(run2, "mpc/cost"));
  EXPECT_DOUBLE_EQ(doubleAttribute(run2, "sweep.robot_mass"), 60.0);

  const H5::Group table = file.openGroup("batch/summary");
  EXPECT_EQ(readInts(table, "index"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(readInts(table, "exit_status"), (std::vector<int>{0, -1, 1}));
  EXPECT_EQ(readInts(table, "steps"), (std::vector<int>{3, -1, 7}));
  const std::vector<double> distance = readDoubles(table, "distance");
  EXPECT_DOUBLE_EQ(distance[0], 1.5);
  EXPECT_TRUE(std::isnan(distance[1]));
  EXPECT_DOUBLE_EQ(distance[2], 2.5);
  EXPECT_EQ(readDoubles(table, "sweep.robot_mass"), (std::vector<double>{50.0, 55.0, 60.0}));
  file.close();

  // read back as runs
  EXPECT_EQ(listRuns(path), (std::vector<std::string>{"three_0", "three_2"}));
  const StoredRun stored = readRunDataset(path, "three_2");
  EXPECT_NE(stored.scenario_yaml.find("robot_mass: 60.0"), std::string::npos);
  EXPECT_EQ(stored.result.trajectory.time.size(), 300u);
  const BatchSummaryTable summary = readBatchSummary(path);
  EXPECT_EQ(summary.rows, 3u);
  EXPECT_EQ(summary.column_names.front(), "index");
}

// The engine's run result holds the run's checks (computeDatasetChecks): the writer takes them
// from the record, prepared or not, rather than computing them a second time.
TEST_F(BatchFiles, ChecksOfTheRecordAreTheOnesWritten) {
  const Study study = load("two", "{robot_mass: [50.0, 55.0]}");
  const std::string path = (directory_ / "batch.h5").string();
  const wpg::WalkResult result = handMadeResult(100, 4, 5);
  DatasetChecks checks;  // values the hand-made walk's own checks cannot have
  checks.walk.landed_steps = 4242;
  checks.walk.max_step_yaw_change = 12.5;
  {
    auto writer = BatchDatasetWriter::create(path, study, kColumns);
    BatchRunRecord record;
    record.result = &result;
    record.checks = &checks;
    record.values = {1.0, 1.0};
    const StudyRun run0 = study.runs[0], run1 = study.runs[1];
    record.run = &run0;
    writer->write(record);
    record.run = &run1;
    const PreparedRun prepared = BatchDatasetWriter::prepare(record);
    writer->write(record, &prepared);
    writer->close();
  }
  const H5::H5File file(path, H5F_ACC_RDONLY);
  for (const char* name : {"two_0", "two_1"}) {
    SCOPED_TRACE(name);
    const H5::Group group = file.openGroup(std::string("runs/") + name + "/checks");
    EXPECT_EQ(intAttribute(group, "landed_steps"), 4242);
    EXPECT_EQ(doubleAttribute(group, "max_step_yaw_change"), 12.5);
  }
}

TEST_F(BatchFiles, ResumeKnowsTheDoneRunsAndRefusesAnotherStudy) {
  const Study study = load("three", "{robot_mass: [50.0, 55.0, 60.0]}");
  const std::string path = (directory_ / "batch.h5").string();
  const wpg::WalkResult result = handMadeResult(50, 3, 2);
  {
    auto writer = BatchDatasetWriter::create(path, study, kColumns);
    BatchRunRecord record;
    const StudyRun run1 = study.runs[1];
    record.run = &run1;
    record.result = &result;
    record.values = {1.0, 1.0};
    writer->write(record);
  }
  {
    auto writer = BatchDatasetWriter::resume(path, study, kColumns);
    EXPECT_EQ((std::vector<bool>{writer->done(0), writer->done(1), writer->done(2)}),
              (std::vector<bool>{false, true, false}));
  }
  const std::string before = bytes(path);
  const Study other = load("three", "{robot_mass: [50.0, 55.0, 61.0]}");  // same name
  EXPECT_THROW(BatchDatasetWriter::resume(path, other, kColumns), InputError);
  const Study renamed = load("four", "{robot_mass: [50.0, 55.0, 60.0]}");
  EXPECT_THROW(BatchDatasetWriter::resume(path, renamed, kColumns), InputError);
  std::vector<SummaryColumn> more = kColumns;
  more.push_back({"extra", "1", "", false});
  EXPECT_THROW(BatchDatasetWriter::resume(path, study, more), InputError);
  EXPECT_EQ(bytes(path), before);  // refused without a change
}
