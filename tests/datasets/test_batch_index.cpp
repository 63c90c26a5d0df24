// Shards and their index (wpg/datasets/storage/batch_index.hpp): the slicing rule puts every run in
// exactly one slice; the index takes each run's row and group from the shard that holds it
// (the first when several do), links the groups with paths relative to its folder, reads back
// as a batch file, and is not written when a run is in no shard.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hand_made_run.hpp"
#include "hdf5_read.hpp"
#include "test_support.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"

namespace fs = std::filesystem;
using namespace wpg::datasets;  // NOLINT: the API under test
using namespace wpg_test;       // NOLINT: HDF5 readers

namespace {

class BatchIndexFiles : public ScratchDirectoryTest {
 protected:
  BatchIndexFiles() : ScratchDirectoryTest("wpg_test_batch_index") {}

  void SetUp() override {
    ScratchDirectoryTest::SetUp();
    const fs::path path = directory_ / "masses.yaml";
    std::ofstream(path) << "name: masses\nbase: walk_forward\nsweep:\n  grid: {robot_mass: [50.0, 55.0, 60.0]}\n";
    study_ = loadStudy(
        path.string(), [](const std::string& base) { return kScenariosDir + "/" + base + ".yaml"; },
        kRobotsDir);
  }

  // A shard holding `runs`, each with distance = 10 * index + `offset`.
  std::string shard(const std::string& name, const std::vector<std::size_t>& runs, double offset) {
    const std::string path = (directory_ / "shards" / name).string();
    fs::create_directories(directory_ / "shards");
    auto writer = BatchDatasetWriter::create(path, study_, kColumns, "rank 0 of 2");
    const wpg::WalkResult result = handMadeResult(300, 4, 6, 0.0);
    for (const std::size_t run : runs) {
      BatchRunRecord record;
      const StudyRun made = study_.runs[run];
      record.run = &made;
      record.result = &result;
      record.values = {10.0 * static_cast<double>(run) + offset};
      writer->write(record);
    }
    writer->close();
    return path;
  }

  Study study_;
  const std::vector<SummaryColumn> kColumns = {{"distance", "m", "distance walked", false}};
};

}  // namespace

TEST(ShardSlices, EveryRunInExactlyOneSlice) {
  for (int count = 1; count <= 7; ++count) {
    for (std::size_t run = 0; run < 50; ++run) {
      int slices = 0;
      for (int shard = 0; shard < count; ++shard) slices += inShardSlice(run, shard, count);
      EXPECT_EQ(slices, 1) << "run " << run << " of " << count << " slices";
    }
  }
  EXPECT_TRUE(inShardSlice(7, 1, 3));
  EXPECT_EQ(shardSliceLabel(1, 3), "1/3");
}

TEST_F(BatchIndexFiles, RowsAndLinksFromTheShardHoldingEachRun) {
  const std::string a = shard("a.h5", {0, 2}, 0.0);
  const std::string b = shard("b.h5", {1, 2}, 0.5);  // run 2 also here: taken from a (first)
  const std::string index = (directory_ / "index.h5").string();
  const IndexReport report = writeBatchIndex(index, {a, b}, IndexLayout::kLinks);
  EXPECT_EQ(report.runs, 3u);
  EXPECT_EQ(report.shards_used, 2u);

  H5::H5File file(index, H5F_ACC_RDONLY);
  EXPECT_FALSE(file.attrExists("shard"));
  EXPECT_EQ(stringAttribute(file, "study_name"), "masses");
  const H5::Group table = file.openGroup("batch/summary");
  EXPECT_EQ(readDoubles(table, "distance"), (std::vector<double>{0.0, 10.5, 20.0}));
  EXPECT_EQ(readInts(table, "exit_status"), (std::vector<int>{0, 0, 0}));
  const H5::Group runs = file.openGroup("runs");
  for (const auto& [name, target] : {std::pair<std::string, std::string>{"masses_0", "shards/a.h5"},
                                     {"masses_1", "shards/b.h5"},
                                     {"masses_2", "shards/a.h5"}}) {
    H5L_info_t link;
    ASSERT_GE(H5Lget_info(runs.getId(), name.c_str(), &link, H5P_DEFAULT), 0) << name;
    ASSERT_EQ(link.type, H5L_TYPE_EXTERNAL) << name;
    std::vector<char> value(link.u.val_size);
    ASSERT_GE(H5Lget_val(runs.getId(), name.c_str(), value.data(), value.size(), H5P_DEFAULT), 0);
    const char* file_name = nullptr;
    const char* object = nullptr;
    unsigned flags = 0;
    ASSERT_GE(H5Lunpack_elink_val(value.data(), value.size(), &flags, &file_name, &object), 0);
    EXPECT_EQ(std::string(file_name), target) << name;  // relative to the index's folder
    EXPECT_EQ(std::string(object), "/runs/" + name);
  }
  file.close();
  // Read through the links as any batch file.
  EXPECT_EQ(listRuns(index), (std::vector<std::string>{"masses_0", "masses_1", "masses_2"}));
  EXPECT_EQ(readRunDataset(index, "masses_1").name, "masses_1");
}

TEST_F(BatchIndexFiles, CopyHoldsTheRunsItself) {
  const std::string a = shard("a.h5", {0, 1, 2}, 0.0);
  const std::string index = (directory_ / "flat.h5").string();
  writeBatchIndex(index, {a}, IndexLayout::kCopy);
  fs::remove_all(directory_ / "shards");
  EXPECT_EQ(readRunDataset(index, "masses_2").name, "masses_2");
}

TEST_F(BatchIndexFiles, ARunInNoShardWritesNothing) {
  const std::string a = shard("a.h5", {0, 2}, 0.0);
  const std::string index = (directory_ / "index.h5").string();
  try {
    writeBatchIndex(index, {a}, IndexLayout::kLinks);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("run 1 (1 of 3)"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(index));
  for (const auto& entry : fs::directory_iterator(directory_)) {  // no temporary file left
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "shards" || name == "masses.yaml") << name;
  }
}
