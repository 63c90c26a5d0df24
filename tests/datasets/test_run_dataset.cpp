// Run datasets: a hand-made WalkResult written to HDF5 reads back identical with the HDF5 C++
// API (no code of ours in the reader), with the contract's names, units and attributes; the
// write is atomic and cleans up after itself.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <H5Cpp.h>

#include "hdf5_read.hpp"
#include "hand_made_run.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

#include "wpg/datasets/storage/provenance.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/version.hpp"

namespace fs = std::filesystem;
using wpg::datasets::Scenario;
using wpg::datasets::writeRunDataset;

namespace {

// --- a hand-made run (no generateWalk: libwpg's NMPC is not needed here) ---------------------

using wpg_test::handMadeResult;

Scenario handMadeScenario() {
  Scenario scenario;
  scenario.name = "hand_made";
  scenario.robot = "hrp2";
  scenario.source_path = "nowhere.yaml";
  scenario.request.generator.algorithm = wpg::GeneratorAlgorithm::kNmpc;
  return scenario;
}

// --- reading with the plain HDF5 C++ API -----------------------------------------------------

using namespace wpg_test;  // HDF5 readers (hdf5_read.hpp)

class RunDatasetFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  RunDatasetFiles() : ScratchDirectoryTest("wpg_test_run_dataset") {}

  // Files whose name holds ".tmp-" anywhere below the test directory.
  std::vector<std::string> temporaryFiles() const {
    std::vector<std::string> found;
    for (const auto& item : fs::recursive_directory_iterator(directory_)) {
      if (item.path().filename().string().find(".tmp-") != std::string::npos) {
        found.push_back(item.path().string());
      }
    }
    return found;
  }
};

// Compares a Vector-of-Eigen column block with what was read.
template <typename Rows>
void expectRows(const Rows& rows, const std::vector<double>& read, std::size_t columns) {
  ASSERT_EQ(read.size(), rows.size() * columns);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < columns; ++j) {
      EXPECT_EQ(read[i * columns + j], rows[i][static_cast<Eigen::Index>(j)])
          << "row " << i << " column " << j;
    }
  }
}

TEST_F(RunDatasetFiles, WritesTheSchemaAndReadsBackTheSameNumbers) {
  const Scenario scenario = handMadeScenario();
  wpg::WalkResult result = handMadeResult(250, 7, 11);
  result.success = false;
  result.message = "iteration 3: fallback";
  const std::string path = (directory_ / "new" / "sub" / "run.h5").string();  // parent missing
  writeRunDataset(path, scenario, result);
  ASSERT_TRUE(fs::is_regular_file(path));
  EXPECT_TRUE(temporaryFiles().empty());

  const H5::H5File file(path, H5F_ACC_RDONLY);
  EXPECT_EQ(intAttribute(file, "schema_version"), 2);  // 2: step_centre_clearance redefined
  EXPECT_EQ(stringAttribute(file, "wpg_version"), WPG_VERSION_STRING);
  EXPECT_EQ(stringAttribute(file, "scenario"), resolvedScenarioText(scenario));
  EXPECT_EQ(stringAttribute(file, "created_by"), "wpg");
  // Provenance (provenance.hpp): the configured commit, this host, a UTC date of this year.
  EXPECT_EQ(stringAttribute(file, "wpg_commit"), wpg::datasets::buildCommit());
  EXPECT_EQ(stringAttribute(file, "created_on"), wpg::datasets::currentProvenance().machine);
  EXPECT_EQ(stringAttribute(file, "created_at").size(), 20u);  // 2025-11-25T16:03:00Z
  EXPECT_EQ(stringAttribute(file, "created_at").substr(0, 4), wpg::datasets::currentProvenance().date.substr(0, 4));

  const H5::Group run = file.openGroup("/runs/hand_made");
  EXPECT_EQ(stringAttribute(run, "algorithm"),
            wpg::generatorAlgorithmName(wpg::GeneratorAlgorithm::kNmpc));
  EXPECT_EQ(intAttribute(run, "success"), 0);
  EXPECT_EQ(stringAttribute(run, "message"), "iteration 3: fallback");

  const wpg::WalkTrajectory& t = result.trajectory;
  std::vector<hsize_t> dims;
  EXPECT_EQ(readDoubles(run, "time", &dims), t.time);
  EXPECT_EQ(dims, std::vector<hsize_t>({250}));
  expectRows(t.com, readDoubles(run, "com", &dims), 3);
  EXPECT_EQ(dims, std::vector<hsize_t>({250, 3}));
  expectRows(t.com_vel, readDoubles(run, "com_vel", &dims), 3);
  expectRows(t.com_acc, readDoubles(run, "com_acc", &dims), 3);
  expectRows(t.cop, readDoubles(run, "cop", &dims), 2);
  EXPECT_EQ(dims, std::vector<hsize_t>({250, 2}));
  expectRows(t.left_foot, readDoubles(run, "left_foot", &dims), 4);
  EXPECT_EQ(dims, std::vector<hsize_t>({250, 4}));
  expectRows(t.right_foot, readDoubles(run, "right_foot", &dims), 4);
  EXPECT_EQ(readDoubles(run, "free_flyer_yaw", &dims), t.free_flyer_yaw);

  const std::vector<std::uint8_t> support =
      readAll<std::uint8_t>(run, "support", H5::PredType::NATIVE_UINT8, &dims);
  ASSERT_EQ(support.size(), 250u);
  for (std::size_t i = 0; i < support.size(); ++i) {
    EXPECT_EQ(support[i], static_cast<std::uint8_t>(t.support[i]));
  }
  EXPECT_EQ(run.openDataSet("support").getDataType(), H5::PredType::STD_U8LE);

  const std::vector<double> footsteps = readDoubles(run, "footsteps", &dims);
  EXPECT_EQ(dims, std::vector<hsize_t>({7, 4}));
  const std::vector<std::uint8_t> sides =
      readAll<std::uint8_t>(run, "footstep_side", H5::PredType::NATIVE_UINT8, &dims);
  ASSERT_EQ(sides.size(), 7u);
  for (std::size_t j = 0; j < 7; ++j) {
    EXPECT_EQ(footsteps[4 * j + 0], t.footsteps[j].landing_time);
    EXPECT_EQ(footsteps[4 * j + 1], t.footsteps[j].pose.x());
    EXPECT_EQ(footsteps[4 * j + 2], t.footsteps[j].pose.y());
    EXPECT_EQ(footsteps[4 * j + 3], t.footsteps[j].pose.z());
    EXPECT_EQ(sides[j], static_cast<std::uint8_t>(t.footsteps[j].side));
  }

  const H5::Group mpc = run.openGroup("mpc");
  const std::vector<double> mpc_time = readDoubles(mpc, "time", &dims);
  const std::vector<double> solve_time = readDoubles(mpc, "solve_time", &dims);
  const std::vector<double> cost = readDoubles(mpc, "cost", &dims);
  const std::vector<double> slack = readDoubles(mpc, "slack", &dims);
  EXPECT_EQ(dims[1], 4u);  // one column per constraint family
  EXPECT_EQ(stringAttribute(mpc.openDataSet("slack"), "columns"),
            "cop, step_feasibility, yaw_bound, obstacle");
  EXPECT_EQ(stringAttribute(mpc.openDataSet("slack"), "groups"),
            "balance, kinematics, kinematics, obstacle");
  const std::vector<std::uint8_t> relaxed =
      readAll<std::uint8_t>(mpc, "relaxed_families", H5::PredType::NATIVE_UINT8, &dims);
  const std::vector<int> qp =
      readAll<int>(mpc, "qp_iterations", H5::PredType::NATIVE_INT, &dims);
  const std::vector<int> sqp =
      readAll<int>(mpc, "sqp_iterations", H5::PredType::NATIVE_INT, &dims);
  const std::vector<std::uint8_t> status =
      readAll<std::uint8_t>(mpc, "status", H5::PredType::NATIVE_UINT8, &dims);
  ASSERT_EQ(mpc_time.size(), 11u);
  ASSERT_EQ(status.size(), 11u);
  for (std::size_t m = 0; m < 11; ++m) {
    EXPECT_EQ(mpc_time[m], t.mpc[m].time);
    EXPECT_EQ(solve_time[m], t.mpc[m].solve_time);
    EXPECT_EQ(cost[m], t.mpc[m].cost);
    for (std::size_t f = 0; f < 4; ++f) EXPECT_EQ(slack[4 * m + f], t.mpc[m].slack[f]);
    EXPECT_EQ(relaxed[m], t.mpc[m].relaxed_families);
    EXPECT_EQ(qp[m], t.mpc[m].qp_iterations);
    EXPECT_EQ(sqp[m], t.mpc[m].sqp_iterations);
    EXPECT_EQ(status[m], static_cast<std::uint8_t>(t.mpc[m].status));
  }
  // The code -> name mapping is there (its text belongs to libwpg).
  EXPECT_FALSE(stringAttribute(mpc.openDataSet("status"), "codes").empty());
  EXPECT_FALSE(stringAttribute(run.openDataSet("support"), "codes").empty());
}

TEST_F(RunDatasetFiles, EveryDatasetHasUnitsFrameAndDescription) {
  const std::string path = (directory_ / "run.h5").string();
  writeRunDataset(path, handMadeScenario(), handMadeResult(30, 3, 4));
  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/hand_made");
  struct Expected {
    const char* name;
    const char* units;
    bool world;
  };
  const Expected run_sets[] = {
      {"time", "s", false},
      {"com", "m", true},
      {"com_vel", "m/s", true},
      {"com_acc", "m/s^2", true},
      {"cop", "m", true},
      {"left_foot", "m, m, m, rad", true},
      {"right_foot", "m, m, m, rad", true},
      {"free_flyer_yaw", "rad", true},
      {"support", "1", false},
      {"footsteps", "s, m, m, rad", true},
      {"footstep_side", "1", false},
  };
  for (const Expected& e : run_sets) {
    SCOPED_TRACE(e.name);
    const H5::DataSet dataset = run.openDataSet(e.name);
    EXPECT_EQ(stringAttribute(dataset, "units"), e.units);
    EXPECT_FALSE(stringAttribute(dataset, "description").empty());
    EXPECT_EQ(dataset.attrExists("frame"), e.world);
    if (e.world) {
      EXPECT_EQ(stringAttribute(dataset, "frame"), "world");
    }
    // Chunked and gzip-compressed (rows >= 1).
    const H5::DSetCreatPropList properties = dataset.getCreatePlist();
    EXPECT_EQ(properties.getLayout(), H5D_CHUNKED);
    EXPECT_TRUE(properties.allFiltersAvail());
    bool deflate = false;
    for (int f = 0; f < properties.getNfilters(); ++f) {
      unsigned int flags = 0;
      std::size_t count = 1;
      unsigned int level = 0;
      unsigned int config = 0;
      char filter_name[64];
      if (properties.getFilter(f, flags, count, &level, sizeof(filter_name), filter_name,
                               config) == H5Z_FILTER_DEFLATE) {
        deflate = true;
        EXPECT_EQ(level, 1u);  // the level the chunks are deflated at (hdf5_writing.cpp)
      }
    }
    EXPECT_TRUE(deflate);
  }
  const H5::Group mpc = run.openGroup("mpc");
  const std::pair<const char*, const char*> mpc_sets[] = {
      {"time", "s"}, {"solve_time", "s"}, {"qp_iterations", "1"}, {"sqp_iterations", "1"},
      {"status", "1"}, {"cost", "1"}, {"slack", "m, m, rad, m"}, {"relaxed_families", "1"}};
  for (const auto& [name, units] : mpc_sets) {
    SCOPED_TRACE(name);
    const H5::DataSet dataset = mpc.openDataSet(name);
    EXPECT_EQ(stringAttribute(dataset, "units"), units);
    EXPECT_FALSE(stringAttribute(dataset, "description").empty());
  }
}

// The writer makes each chunk shape's creation properties once (hdf5_writing.cpp) and starts
// again past a few hundred shapes: every dataset of runs of 300+ lengths still gets its own
// chunk shape (the whole dataset up to ~64 KiB of rows) and its values.
TEST_F(RunDatasetFiles, ChunksFollowEachDatasetsShapeOverManyRunLengths) {
  const auto chunkOf = [](const H5::DataSet& dataset) {
    const H5::DSetCreatPropList properties = dataset.getCreatePlist();
    EXPECT_EQ(properties.getLayout(), H5D_CHUNKED);
    std::vector<hsize_t> chunk(static_cast<std::size_t>(dataset.getSpace().getSimpleExtentNdims()));
    properties.getChunk(static_cast<int>(chunk.size()), chunk.data());
    return chunk;
  };
  const auto chunkRows = [](hsize_t rows, hsize_t row_bytes) {
    return std::min<hsize_t>(rows, std::max<hsize_t>(1, 65536 / row_bytes));
  };
  std::vector<std::size_t> lengths;
  for (std::size_t samples = 1; samples <= 300; ++samples) lengths.push_back(samples);
  lengths.insert(lengths.end(), {8191, 8193, 20000});  // longer than one chunk
  const std::string path = (directory_ / "run.h5").string();
  for (const std::size_t samples : lengths) {
    SCOPED_TRACE(samples);
    const wpg::WalkResult result = handMadeResult(samples, 3, 4);
    writeRunDataset(path, handMadeScenario(), result);
    const H5::H5File file(path, H5F_ACC_RDONLY);
    const H5::Group run = file.openGroup("/runs/hand_made");
    const hsize_t n = samples;
    EXPECT_EQ(chunkOf(run.openDataSet("time")), (std::vector<hsize_t>{chunkRows(n, 8)}));
    EXPECT_EQ(chunkOf(run.openDataSet("com")), (std::vector<hsize_t>{chunkRows(n, 24), 3}));
    EXPECT_EQ(chunkOf(run.openDataSet("left_foot")), (std::vector<hsize_t>{chunkRows(n, 32), 4}));
    EXPECT_EQ(chunkOf(run.openDataSet("support")), (std::vector<hsize_t>{chunkRows(n, 1)}));
    EXPECT_EQ(chunkOf(run.openDataSet("footsteps")), (std::vector<hsize_t>{3, 4}));
    EXPECT_EQ(readDoubles(run, "time"), result.trajectory.time);
    expectRows(result.trajectory.left_foot, readDoubles(run, "left_foot"), 4);
  }
}

TEST_F(RunDatasetFiles, EmptyRunHasZeroRowDatasets) {
  const std::string path = (directory_ / "empty.h5").string();
  writeRunDataset(path, handMadeScenario(), handMadeResult(0, 0, 0));
  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/hand_made");
  std::vector<hsize_t> dims;
  EXPECT_TRUE(readDoubles(run, "time", &dims).empty());
  EXPECT_EQ(dims, std::vector<hsize_t>({0}));
  EXPECT_TRUE(readDoubles(run, "com", &dims).empty());
  EXPECT_EQ(dims, std::vector<hsize_t>({0, 3}));
  EXPECT_TRUE(readDoubles(run, "footsteps", &dims).empty());
  EXPECT_EQ(dims, std::vector<hsize_t>({0, 4}));
  EXPECT_TRUE(readDoubles(run.openGroup("mpc"), "cost", &dims).empty());
  EXPECT_EQ(dims, std::vector<hsize_t>({0}));
  EXPECT_EQ(stringAttribute(run.openDataSet("com"), "units"), "m");
}

TEST_F(RunDatasetFiles, MismatchedSizesAreRejectedBeforeWriting) {
  wpg::WalkResult result = handMadeResult(10, 2, 1);
  result.trajectory.cop.pop_back();
  const std::string path = (directory_ / "bad.h5").string();
  EXPECT_THROW(writeRunDataset(path, handMadeScenario(), result), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(temporaryFiles().empty());
  Scenario bad_name = handMadeScenario();
  bad_name.name = "a/b";
  EXPECT_THROW(writeRunDataset(path, bad_name, handMadeResult(1, 0, 0)), std::invalid_argument);
}

TEST_F(RunDatasetFiles, UnwritablePathThrowsAndLeavesNoTemporaryFile) {
  // The parent "directory" is a regular file: it can be neither created nor written into.
  const fs::path blocker = directory_ / "blocker";
  std::ofstream(blocker) << "not a directory";
  const std::string path = (blocker / "run.h5").string();
  EXPECT_THROW(writeRunDataset(path, handMadeScenario(), handMadeResult(5, 2, 1)),
               std::runtime_error);
  EXPECT_TRUE(temporaryFiles().empty());

  // The target is an existing directory: the HDF5 file is written, the rename fails, the
  // temporary file is removed and the directory is untouched.
  const fs::path occupied = directory_ / "occupied.h5";
  fs::create_directories(occupied / "inside");
  EXPECT_THROW(writeRunDataset(occupied.string(), handMadeScenario(), handMadeResult(5, 2, 1)),
               std::runtime_error);
  EXPECT_TRUE(temporaryFiles().empty());
  EXPECT_TRUE(fs::is_directory(occupied / "inside"));
}

TEST_F(RunDatasetFiles, ExistingFileIsReplacedWhole) {
  const std::string path = (directory_ / "run.h5").string();
  writeRunDataset(path, handMadeScenario(), handMadeResult(100, 4, 3, /*offset=*/0.0));
  writeRunDataset(path, handMadeScenario(), handMadeResult(40, 2, 1, /*offset=*/1000.0));
  EXPECT_TRUE(temporaryFiles().empty());
  {
    const H5::H5File file(path, H5F_ACC_RDONLY);
    std::vector<hsize_t> dims;
    const std::vector<double> com = readDoubles(file.openGroup("/runs/hand_made"), "com", &dims);
    EXPECT_EQ(dims, std::vector<hsize_t>({40, 3}));
    EXPECT_EQ(com[0], 1000.1);
  }
  // A failed write leaves the previous file as it was.
  wpg::WalkResult bad = handMadeResult(10, 1, 1);
  bad.trajectory.support.clear();
  EXPECT_THROW(writeRunDataset(path, handMadeScenario(), bad), std::invalid_argument);
  const H5::H5File file(path, H5F_ACC_RDONLY);
  std::vector<hsize_t> dims;
  readDoubles(file.openGroup("/runs/hand_made"), "time", &dims);
  EXPECT_EQ(dims, std::vector<hsize_t>({40}));
}

}  // namespace

namespace {

// Every chunked dataset of a file: its path and its stored (shuffled, deflated) chunks.
std::map<std::string, std::vector<std::vector<unsigned char>>> storedChunks(const std::string& path) {
  std::map<std::string, std::vector<std::vector<unsigned char>>> out;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0);
  const auto visit = [](hid_t root, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type != H5O_TYPE_DATASET) return 0;
    auto& chunks = (*static_cast<std::map<std::string, std::vector<std::vector<unsigned char>>>*>(
        data))[name];
    const hid_t dataset = H5Dopen2(root, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    hsize_t count = 0;
    if (H5Dget_num_chunks(dataset, space, &count) >= 0) {
      for (hsize_t i = 0; i < count; ++i) {
        hsize_t offset[2] = {0, 0};
        unsigned filter_mask = 0;
        haddr_t address = 0;
        hsize_t size = 0;
        H5Dget_chunk_info(dataset, space, i, offset, &filter_mask, &address, &size);
        std::vector<unsigned char> bytes(size);
        uint32_t filters = 0;
        H5Dread_chunk(dataset, H5P_DEFAULT, offset, &filters, bytes.data());
        chunks.push_back(std::move(bytes));
      }
    }
    H5Sclose(space);
    H5Dclose(dataset);
    return 0;
  };
  H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &out);
  H5Fclose(file);
  return out;
}

// The walk's datasets compressed ahead, on another thread (prepareWalkDatasets, what `wpg run`
// does while the replay runs), are written as the very chunks the writer would have made; a
// preparation of another walk is refused, and leaves no file.
TEST_F(RunDatasetFiles, APreparedWalkWritesTheSameChunks) {
  const std::string direct = (directory_ / "direct.h5").string();
  const std::string prepared = (directory_ / "prepared.h5").string();
  for (const std::size_t samples : {std::size_t{1}, std::size_t{250}, std::size_t{20000}}) {
    SCOPED_TRACE(samples);
    const Scenario scenario = handMadeScenario();
    const wpg::WalkResult result = handMadeResult(samples, 3, 4);
    writeRunDataset(direct, scenario, result);
    wpg::datasets::PreparedRun walk;
    std::thread preparing([&] { walk = wpg::datasets::prepareWalkDatasets(scenario, result); });
    preparing.join();
    writeRunDataset(prepared, scenario, result, nullptr, nullptr, nullptr, &walk);
    const auto expected = storedChunks(direct);
    EXPECT_GT(expected.size(), 10u);
    EXPECT_EQ(storedChunks(prepared), expected);
  }
  const Scenario scenario = handMadeScenario();
  const wpg::datasets::PreparedRun other =
      wpg::datasets::prepareWalkDatasets(scenario, handMadeResult(250, 3, 4));
  const std::string refused = (directory_ / "refused.h5").string();
  EXPECT_THROW(writeRunDataset(refused, scenario, handMadeResult(251, 3, 4), nullptr, nullptr,
                               nullptr, &other),
               std::logic_error);
  EXPECT_FALSE(fs::exists(refused));
}

}  // namespace
