// The multibody fields of a run dataset (replay and dynamic filter, SCHEMA.md) read back
// identical with the plain HDF5 C++ API, with units, descriptions and the summary attributes;
// inconsistent sizes are rejected before writing; and readRunDataset gives back the walk that
// was written, or a one-line InputError for a bad file.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <H5Cpp.h>

#include "hdf5_read.hpp"
#include "hand_made_run.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"

namespace fs = std::filesystem;
using wpg::datasets::ChainTimeSummary;
using wpg::datasets::InputError;
using wpg::datasets::MultibodyRecord;
using wpg::datasets::readRunDataset;
using wpg::datasets::Scenario;
using wpg::datasets::writeRunDataset;

namespace {

Scenario handMadeScenario() {
  Scenario scenario;
  scenario.name = "hand_made";
  scenario.robot = "hrp2";
  scenario.filter_settings.input_weight = 1e-5;
  scenario.filter_settings.preview_time = 0.665;
  return scenario;
}

// Distinct values everywhere (hand_made_run.hpp), five footsteps, a failed walk.
wpg::WalkResult handMadeResult(std::size_t samples, std::size_t iterations) {
  wpg::WalkResult result = wpg_test::handMadeResult(samples, 5, iterations);
  result.success = false;
  result.message = "iteration 2: fallback";
  return result;
}

wpg::MultibodyValidation handMadeValidation(Eigen::Index samples, Eigen::Index iterations,
                                            bool filtered) {
  wpg::MultibodyValidation v;
  v.configuration_names = {"base_x", "base_y", "base_z", "base_qw", "base_qx", "base_qy",
                           "base_qz", "JOINT_A", "JOINT_B"};
  const Eigen::Index nq = static_cast<Eigen::Index>(v.configuration_names.size());
  v.q.resize(samples, nq);
  for (Eigen::Index i = 0; i < samples; ++i)
    for (Eigen::Index j = 0; j < nq; ++j) v.q(i, j) = 100.0 * i + j;
  v.zmp_multibody = Eigen::MatrixXd::Random(samples, 2);
  if (filtered) {
    v.com_filtered = Eigen::MatrixXd::Random(samples, 3);
    v.zmp_multibody_filtered = Eigen::MatrixXd::Random(samples, 2);
  }
  v.before = {0.0177, 0.035};
  v.after = filtered ? wpg::ZmpErrorStatistics{0.0019, 0.0042} : v.before;
  v.ik_failures = 2;
  v.max_ik_com_error = 1e-12;
  v.max_ik_foot_error = 2e-15;
  v.samples_with_limit_violations = 3;
  v.max_limit_violation = 0.02;
  v.violated_joints = {"JOINT_B", "JOINT_A"};
  v.chain_stage_time = Eigen::MatrixXd::Random(iterations, 4).cwiseAbs();
  v.chain_time = v.chain_stage_time.rowwise().sum();
  return v;
}

// The chain timing's summary comes from the caller (analysis/ computes it): distinct values,
// written as given.
constexpr ChainTimeSummary kChainTimeSummary{0.0021, 0.0003, 0.0015, 0.0042};

using namespace wpg_test;  // HDF5 readers (hdf5_read.hpp)

void expectMatrix(const Eigen::MatrixXd& expected, const H5::Group& group,
                  const std::string& name) {
  SCOPED_TRACE(name);
  std::vector<hsize_t> dims;
  const std::vector<double> read = readDoubles(group, name, &dims);
  const std::vector<hsize_t> shape =
      expected.cols() == 1 ? std::vector<hsize_t>{hsize_t(expected.rows())}
                           : std::vector<hsize_t>{hsize_t(expected.rows()), hsize_t(expected.cols())};
  ASSERT_EQ(dims, shape);
  for (Eigen::Index i = 0; i < expected.rows(); ++i)
    for (Eigen::Index j = 0; j < expected.cols(); ++j)
      EXPECT_EQ(read[static_cast<std::size_t>(i * expected.cols() + j)], expected(i, j))
          << "row " << i << " column " << j;
}


class MultibodyDatasetFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  MultibodyDatasetFiles() : ScratchDirectoryTest("wpg_test_multibody_dataset") {}
  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  // Loading `file` must throw one InputError line holding the file and `part`.
  static void expectBadFile(const std::string& file, const std::string& part) {
    wpg_test::expectInputError([&] { readRunDataset(file); }, file, {part});
  }
};

TEST_F(MultibodyDatasetFiles, FilteredReplayReadsBackWithUnitsAndSummary) {
  const wpg::WalkResult result = handMadeResult(40, 6);
  const wpg::MultibodyValidation v = handMadeValidation(40, 6, true);
  const MultibodyRecord record{v, kChainTimeSummary};
  writeRunDataset(path("run.h5"), handMadeScenario(), result, nullptr, &record);
  const H5::H5File file(path("run.h5"), H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/hand_made");

  expectMatrix(v.q, run, "q");
  expectMatrix(v.zmp_multibody, run, "zmp_multibody");
  expectMatrix(v.com_filtered, run, "com_filtered");
  expectMatrix(v.zmp_multibody_filtered, run, "zmp_multibody_filtered");
  const H5::DataSet q = run.openDataSet("q");
  EXPECT_EQ(stringListAttribute(q, "names"), v.configuration_names);
  EXPECT_EQ(stringAttribute(q, "columns"),
            "base_x, base_y, base_z, base_qw, base_qx, base_qy, base_qz, JOINT_A, JOINT_B");
  EXPECT_EQ(stringAttribute(q, "units"), "m, m, m, 1, 1, 1, 1, rad, rad");
  for (const char* name : {"q", "zmp_multibody", "com_filtered", "zmp_multibody_filtered"}) {
    SCOPED_TRACE(name);
    const H5::DataSet dataset = run.openDataSet(name);
    EXPECT_FALSE(stringAttribute(dataset, "description").empty());
    EXPECT_EQ(stringAttribute(dataset, "frame"), "world");
    if (std::string(name) != "q") EXPECT_EQ(stringAttribute(dataset, "units"), "m");
  }

  const H5::Group multibody = run.openGroup("multibody");
  EXPECT_EQ(intAttribute(multibody, "filtered"), 1);
  EXPECT_EQ(doubleAttribute(multibody, "zmp_error_rms_before"), 0.0177);
  EXPECT_EQ(doubleAttribute(multibody, "zmp_error_max_before"), 0.035);
  EXPECT_EQ(doubleAttribute(multibody, "zmp_error_rms_after"), 0.0019);
  EXPECT_EQ(doubleAttribute(multibody, "zmp_error_max_after"), 0.0042);
  EXPECT_EQ(intAttribute(multibody, "ik_failures"), 2);
  EXPECT_EQ(doubleAttribute(multibody, "max_ik_com_error"), 1e-12);
  EXPECT_EQ(doubleAttribute(multibody, "max_ik_foot_error"), 2e-15);
  EXPECT_EQ(intAttribute(multibody, "samples_with_limit_violations"), 3);
  EXPECT_EQ(doubleAttribute(multibody, "max_limit_violation"), 0.02);
  EXPECT_EQ(stringListAttribute(multibody, "violated_joints"), v.violated_joints);
  EXPECT_EQ(doubleAttribute(multibody, "filter_error_weight"), 1.0);
  EXPECT_EQ(doubleAttribute(multibody, "filter_input_weight"), 1e-5);
  EXPECT_EQ(doubleAttribute(multibody, "filter_preview_time"), 0.665);

  const H5::Group timing = run.openGroup("timing");
  expectMatrix(v.chain_time, timing, "chain_time");
  expectMatrix(v.chain_stage_time, timing, "chain_stage_time");
  EXPECT_EQ(stringAttribute(timing.openDataSet("chain_stage_time"), "columns"),
            "nmpc, ik, multibody_zmp, filter");
  for (const char* name : {"chain_time", "chain_stage_time"}) {
    EXPECT_EQ(stringAttribute(timing.openDataSet(name), "units"), "s");
    EXPECT_FALSE(stringAttribute(timing.openDataSet(name), "description").empty());
  }
  EXPECT_EQ(doubleAttribute(timing, "chain_time_average"), kChainTimeSummary.average);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_std"), kChainTimeSummary.std_dev);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_min"), kChainTimeSummary.min);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_max"), kChainTimeSummary.max);
}

TEST_F(MultibodyDatasetFiles, ReplayWithoutFilterHasNoFilteredDatasets) {
  const wpg::MultibodyValidation v = handMadeValidation(20, 3, false);
  const MultibodyRecord record{v, kChainTimeSummary};
  writeRunDataset(path("run.h5"), handMadeScenario(), handMadeResult(20, 3), nullptr, &record);
  const H5::H5File file(path("run.h5"), H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/hand_made");
  EXPECT_TRUE(run.nameExists("q"));
  EXPECT_TRUE(run.nameExists("zmp_multibody"));
  EXPECT_FALSE(run.nameExists("com_filtered"));
  EXPECT_FALSE(run.nameExists("zmp_multibody_filtered"));
  EXPECT_EQ(intAttribute(run.openGroup("multibody"), "filtered"), 0);
}

TEST_F(MultibodyDatasetFiles, WithoutReplayThereIsNoMultibodyData) {
  writeRunDataset(path("run.h5"), handMadeScenario(), handMadeResult(20, 3));
  const H5::H5File file(path("run.h5"), H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/hand_made");
  for (const char* name : {"q", "zmp_multibody", "multibody", "timing"}) {
    EXPECT_FALSE(run.nameExists(name)) << name;
  }
}

TEST_F(MultibodyDatasetFiles, InconsistentSizesAreRejectedBeforeWriting) {
  const wpg::WalkResult result = handMadeResult(20, 3);
  const auto rejected = [&](const wpg::MultibodyValidation& v) {
    const MultibodyRecord record{v, kChainTimeSummary};
    EXPECT_THROW(writeRunDataset(path("bad.h5"), handMadeScenario(), result, nullptr, &record),
                 std::invalid_argument);
    EXPECT_FALSE(fs::exists(path("bad.h5")));
  };
  wpg::MultibodyValidation v = handMadeValidation(19, 3, true);  // one row short
  rejected(v);
  v = handMadeValidation(20, 3, true);
  v.configuration_names.pop_back();  // q has a column without a name
  rejected(v);
  v = handMadeValidation(20, 3, true);
  v.zmp_multibody_filtered.resize(0, 0);  // com_filtered without its ZMP
  rejected(v);
  v = handMadeValidation(20, 3, false);
  v.zmp_multibody_filtered = Eigen::MatrixXd::Zero(20, 2);  // a filtered ZMP without com_filtered
  rejected(v);
  v = handMadeValidation(20, 3, true);
  v.chain_time.resize(2);
  rejected(v);
  v = handMadeValidation(20, 3, true);
  v.zmp_multibody.resize(20, 3);
  rejected(v);
}

TEST_F(MultibodyDatasetFiles, ReaderGivesBackTheWalk) {
  const wpg::WalkResult written = handMadeResult(33, 4);
  const wpg::MultibodyValidation v = handMadeValidation(33, 4, true);
  const MultibodyRecord record{v, kChainTimeSummary};
  writeRunDataset(path("run.h5"), handMadeScenario(), written, nullptr, &record);
  const wpg::datasets::StoredRun stored = readRunDataset(path("run.h5"));
  EXPECT_EQ(stored.name, "hand_made");
  EXPECT_EQ(stored.robot, "hrp2");
  EXPECT_EQ(stored.scenario_yaml, resolvedScenarioText(handMadeScenario()));
  EXPECT_EQ(stored.result.success, written.success);
  EXPECT_EQ(stored.result.message, written.message);
  const wpg::WalkTrajectory& a = written.trajectory;
  const wpg::WalkTrajectory& b = stored.result.trajectory;
  EXPECT_EQ(b.time, a.time);
  EXPECT_EQ(b.com, a.com);
  EXPECT_EQ(b.com_vel, a.com_vel);
  EXPECT_EQ(b.com_acc, a.com_acc);
  EXPECT_EQ(b.cop, a.cop);
  EXPECT_EQ(b.left_foot, a.left_foot);
  EXPECT_EQ(b.right_foot, a.right_foot);
  EXPECT_EQ(b.free_flyer_yaw, a.free_flyer_yaw);
  EXPECT_EQ(b.support, a.support);
  ASSERT_EQ(b.footsteps.size(), a.footsteps.size());
  for (std::size_t j = 0; j < a.footsteps.size(); ++j) {
    EXPECT_EQ(b.footsteps[j].landing_time, a.footsteps[j].landing_time);
    EXPECT_EQ(b.footsteps[j].pose, a.footsteps[j].pose);
    EXPECT_EQ(b.footsteps[j].side, a.footsteps[j].side);
  }
  ASSERT_EQ(b.mpc.size(), a.mpc.size());
  for (std::size_t m = 0; m < a.mpc.size(); ++m) {
    EXPECT_EQ(b.mpc[m].time, a.mpc[m].time);
    EXPECT_EQ(b.mpc[m].solve_time, a.mpc[m].solve_time);
    EXPECT_EQ(b.mpc[m].qp_iterations, a.mpc[m].qp_iterations);
    EXPECT_EQ(b.mpc[m].sqp_iterations, a.mpc[m].sqp_iterations);
    EXPECT_EQ(b.mpc[m].status, a.mpc[m].status);
    EXPECT_EQ(b.mpc[m].cost, a.mpc[m].cost);
    EXPECT_EQ(b.mpc[m].slack, a.mpc[m].slack);
    EXPECT_EQ(b.mpc[m].relaxed_families, a.mpc[m].relaxed_families);
  }
  ASSERT_EQ(b.constraint_families.size(), a.constraint_families.size());
  for (std::size_t f = 0; f < a.constraint_families.size(); ++f) {
    EXPECT_EQ(b.constraint_families[f].name, a.constraint_families[f].name);
    EXPECT_EQ(b.constraint_families[f].unit, a.constraint_families[f].unit);
    EXPECT_EQ(b.constraint_families[f].group, a.constraint_families[f].group);
  }
  // Written again from what was read: the same file content (the walk round-trips).
  writeRunDataset(path("again.h5"), handMadeScenario(), stored.result, nullptr, &record);
  const wpg::datasets::StoredRun again = readRunDataset(path("again.h5"), "hand_made");
  EXPECT_EQ(again.result.trajectory.com, a.com);
}

TEST_F(MultibodyDatasetFiles, ReaderRejectsBadFilesInOneLine) {
  expectBadFile(path("missing.h5"), "no such file");
  std::ofstream(path("text.h5")) << "not an HDF5 file\n";
  expectBadFile(path("text.h5"), "not an HDF5 file");
  fs::create_directories(path("folder.h5"));
  expectBadFile(path("folder.h5"), "directory");

  writeRunDataset(path("run.h5"), handMadeScenario(), handMadeResult(10, 2));
  try {
    readRunDataset(path("run.h5"), "other");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("no run /runs/other (runs: hand_made)"),
              std::string::npos)
        << error.what();
  }
  // A dataset of the schema removed, or of the wrong shape.
  {
    H5::H5File file(path("run.h5"), H5F_ACC_RDWR);
    file.unlink("/runs/hand_made/com_vel");
  }
  expectBadFile(path("run.h5"), "dataset /runs/hand_made/com_vel is missing");
  writeRunDataset(path("run.h5"), handMadeScenario(), handMadeResult(10, 2));
  {
    H5::H5File file(path("run.h5"), H5F_ACC_RDWR);
    file.unlink("/runs/hand_made/cop");
    const hsize_t dims[2] = {10, 3};
    file.createDataSet("/runs/hand_made/cop", H5::PredType::IEEE_F64LE, H5::DataSpace(2, dims));
  }
  expectBadFile(path("run.h5"), "/runs/hand_made/cop has the wrong shape");
  writeRunDataset(path("run.h5"), handMadeScenario(), handMadeResult(10, 2));
  {
    H5::H5File file(path("run.h5"), H5F_ACC_RDWR);
    file.unlink("/runs/hand_made/free_flyer_yaw");
    const hsize_t dims[1] = {9};
    file.createDataSet("/runs/hand_made/free_flyer_yaw", H5::PredType::IEEE_F64LE,
                       H5::DataSpace(1, dims));
  }
  expectBadFile(path("run.h5"), "/runs/hand_made/free_flyer_yaw has 9 rows, expected 10");
  // An HDF5 file that is not a run dataset.
  { H5::H5File file(path("other.h5"), H5F_ACC_TRUNC); }
  expectBadFile(path("other.h5"), "'scenario' is missing");
}

}  // namespace
