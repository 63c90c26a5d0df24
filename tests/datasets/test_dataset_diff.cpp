// wpg::datasets::diffDatasets on small hand-written files: the tolerance test at its boundary,
// NaN and infinities, the first differing sample's row and column, shapes that differ, text
// compared line by line, wall times and provenance left out, and bad input.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/storage/dataset_diff.hpp"

namespace {

using wpg::datasets::DatasetDiff;
using wpg::datasets::DiffSettings;
using wpg::datasets::diffDatasets;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class DatasetDiffTest : public wpg_test::ScratchDirectoryTest {
 protected:
  DatasetDiffTest() : ScratchDirectoryTest("wpg_dataset_diff") {}

  // A minimal wpg dataset: root attributes schema_version, scenario, wpg_version; the run
  // group /runs/r with a (rows, 2) `com` (columns "x, y") and mpc/solve_time.
  std::string write(const std::string& name, const std::vector<double>& com,
                    const std::string& scenario = "name: r\nduration: 1\n",
                    const std::string& version = "0.1.0", double solve_time = 1e-5) {
    const std::string path = (directory_ / name).string();
    H5::H5File file(path, H5F_ACC_TRUNC);
    const H5::DataSpace scalar;
    file.createAttribute("schema_version", H5::PredType::NATIVE_INT, scalar)
        .write(H5::PredType::NATIVE_INT, &kSchemaVersion);
    const H5::StrType text(H5::PredType::C_S1, H5T_VARIABLE);
    file.createAttribute("scenario", text, scalar).write(text, scenario);
    file.createAttribute("wpg_version", text, scalar).write(text, version);
    H5::Group run = file.createGroup("runs").createGroup("r");
    const hsize_t dims[2] = {com.size() / 2, 2};
    H5::DataSet dataset = run.createDataSet("com", H5::PredType::NATIVE_DOUBLE, H5::DataSpace(2, dims));
    if (!com.empty()) dataset.write(com.data(), H5::PredType::NATIVE_DOUBLE);
    dataset.createAttribute("columns", text, scalar).write(text, std::string("x, y"));
    const hsize_t one[1] = {1};
    run.createGroup("mpc")
        .createDataSet("solve_time", H5::PredType::NATIVE_DOUBLE, H5::DataSpace(1, one))
        .write(&solve_time, H5::PredType::NATIVE_DOUBLE);
    return path;
  }

  static constexpr int kSchemaVersion = 2;
};

TEST_F(DatasetDiffTest, ToleranceIsInclusiveAndScalesWithTheLargerValue) {
  DiffSettings settings;
  settings.rtol = 0.0;
  settings.atol = 0.5;
  const std::string unit = write("unit.h5", {1.0, 2.0});
  // |a - b| = atol exactly agrees (<=); one ulp more does not.
  EXPECT_TRUE(diffDatasets(unit, write("edge.h5", {1.5, 2.0}), settings).differences.empty());
  EXPECT_EQ(diffDatasets(unit, write("over.h5", {std::nextafter(1.5, 2.0), 2.0}), settings)
                .differences.size(), 1u);

  settings.rtol = 1e-3;
  settings.atol = 0.0;
  const std::string a = write("a.h5", {1.0, 2.0, 1000.0, 4.0});
  // 1000 vs 1000.5 at rtol 4.999e-4: 0.5 <= 4.999e-4 * 1000.5 (the larger value) but not
  // <= 4.999e-4 * 1000 (the smaller): the tolerance takes the larger.
  const std::string same = write("same.h5", {1.0, 2.0, 1000.5, 4.0});
  settings.rtol = 4.999e-4;
  EXPECT_TRUE(diffDatasets(a, same, settings).differences.empty());
  EXPECT_TRUE(diffDatasets(same, a, settings).differences.empty());
  // 2.0 vs 2.0025 is beyond 1e-3 * 2.0025.
  settings.rtol = 1e-3;
  const std::string beyond = write("beyond.h5", {1.0, 2.0025, 1000.5, 4.0});
  const DatasetDiff diff = diffDatasets(a, beyond, settings);
  ASSERT_EQ(diff.differences.size(), 1u);
  const auto& d = diff.differences[0];
  EXPECT_EQ(d.path, "/runs/r/com");
  EXPECT_TRUE(d.has_sample);
  EXPECT_EQ(d.row, 0u);
  EXPECT_EQ(d.column, 1u);
  EXPECT_EQ(d.column_name, "y");
  EXPECT_EQ(d.a, 2.0);
  EXPECT_EQ(d.b, 2.0025);
  EXPECT_DOUBLE_EQ(d.tolerance, 1e-3 * 2.0025);
  EXPECT_EQ(d.differing_samples, 1u);
  EXPECT_EQ(d.compared_samples, 4u);
  EXPECT_NEAR(d.max_relative, 0.0025 / 2.0025, 1e-15);
}

TEST_F(DatasetDiffTest, NanAndInfinitiesAgreeOnlyWithThemselves) {
  DiffSettings settings;
  settings.rtol = 1.0;  // generous: only non-finite values can differ
  settings.atol = 1.0;
  const std::string a = write("a.h5", {kNaN, kInf, -kInf, 1.0});
  EXPECT_TRUE(diffDatasets(a, write("same.h5", {kNaN, kInf, -kInf, 1.0}), settings).differences.empty());
  for (const auto& [name, values] :
       std::vector<std::pair<std::string, std::vector<double>>>{{"nan.h5", {0.0, kInf, -kInf, 1.0}},
                                                                {"inf.h5", {kNaN, -kInf, -kInf, 1.0}},
                                                                {"one.h5", {kNaN, kInf, -kInf, kNaN}}}) {
    const DatasetDiff diff = diffDatasets(a, write(name, values), settings);
    ASSERT_EQ(diff.differences.size(), 1u) << name;
    EXPECT_EQ(diff.differences[0].differing_samples, 1u) << name;
  }
}

TEST_F(DatasetDiffTest, LongerWalkReportsShapeAndFirstDifferenceInTheCommonRows) {
  const std::string a = write("a.h5", {1.0, 2.0, 3.0, 4.0});
  const DatasetDiff diff =
      diffDatasets(a, write("b.h5", {1.0, 2.0, 3.5, 4.0, 5.0, 6.0}), DiffSettings{});
  ASSERT_EQ(diff.differences.size(), 1u);
  EXPECT_EQ(diff.differences[0].what, "shape (2, 2) vs (3, 2)");
  EXPECT_TRUE(diff.differences[0].has_sample);
  EXPECT_EQ(diff.differences[0].row, 1u);
  EXPECT_EQ(diff.differences[0].column, 0u);
}

TEST_F(DatasetDiffTest, ScenarioTextNamesTheFirstDifferingLine) {
  const std::string a = write("a.h5", {1.0, 2.0}, "name: r\nduration: 1\nweight: 2\n");
  const DatasetDiff diff =
      diffDatasets(a, write("b.h5", {1.0, 2.0}, "name: r\nduration: 2\nweight: 2\n"), DiffSettings{});
  ASSERT_EQ(diff.differences.size(), 1u);
  EXPECT_EQ(diff.differences[0].path, "/@scenario");
  EXPECT_EQ(diff.differences[0].line, 2u);
  EXPECT_EQ(diff.differences[0].text_a, "duration: 1");
  EXPECT_EQ(diff.differences[0].text_b, "duration: 2");
}

TEST_F(DatasetDiffTest, WallTimesAndProvenanceAreLeftOutUnlessAsked) {
  const std::string a = write("a.h5", {1.0, 2.0}, "s", "0.1.0", 1e-5);
  const std::string b = write("b.h5", {1.0, 2.0}, "s", "0.2.0", 3e-5);
  const DatasetDiff ignored = diffDatasets(a, b, DiffSettings{});
  EXPECT_TRUE(ignored.differences.empty());
  EXPECT_EQ(ignored.ignored.size(), 2u);  // /@wpg_version, /runs/r/mpc/solve_time
  DiffSettings settings;
  settings.ignore_wall_time = false;
  const DatasetDiff compared = diffDatasets(a, b, settings);
  ASSERT_EQ(compared.differences.size(), 1u);
  EXPECT_EQ(compared.differences[0].path, "/runs/r/mpc/solve_time");
  settings.ignore_patterns = {"*/mpc/*"};
  EXPECT_TRUE(diffDatasets(a, b, settings).differences.empty());

  EXPECT_TRUE(wpg::datasets::isWallTimeField("/runs/x/mpc/solve_time"));
  EXPECT_TRUE(wpg::datasets::isWallTimeField("/runs/x/timing"));
  EXPECT_TRUE(wpg::datasets::isWallTimeField("/runs/x/plans/planning_time"));
  EXPECT_TRUE(wpg::datasets::isWallTimeField("/runs/x/plans/simplification_time"));
  EXPECT_TRUE(wpg::datasets::isWallTimeField("/batch/summary/nmpc_time_p99"));
  EXPECT_FALSE(wpg::datasets::isWallTimeField("/runs/x/mpc/time"));
  EXPECT_FALSE(wpg::datasets::isWallTimeField("/runs/x/plans/time"));
  EXPECT_FALSE(wpg::datasets::isWallTimeField("/runs/x/time"));
}

// Every HDF5 identifier the comparison opens is released: a diff of two 10^4-run studies
// opens several per dataset, and identifiers left behind (the C++ API's wrappers built from an
// id HDF5 handed over take a reference of their own) accumulate for the process's life and
// slow every later lookup of HDF5's identifier tables.
TEST_F(DatasetDiffTest, LeavesNoHdf5IdentifierBehind) {
  const std::string a = write("a.h5", {1.0, 2.0, 3.0, 4.0});
  const std::string b = write("b.h5", {1.0, 2.0, 3.0, 5.0});
  for (const std::string& path : {a, b}) {  // a variable-length string dataset in each
    H5::H5File file(path, H5F_ACC_RDWR);
    const hsize_t two[1] = {2};
    const H5::StrType text(H5::PredType::C_S1, H5T_VARIABLE);
    const char* names[2] = {"left", "right"};
    file.openGroup("runs/r").createDataSet("names", text, H5::DataSpace(1, two))
        .write(names, text);
  }
  // HDF5 numbers the identifiers of each kind in sequence: those handed out between a
  // marker made before the comparison and one made after it must all be closed again.
  struct Kind {
    const char* name;
    hid_t (*make)();
    herr_t (*close)(hid_t);
  };
  const Kind kinds[] = {
      {"datatype", [] { return H5Tcopy(H5T_NATIVE_INT); }, H5Tclose},
      {"dataspace", [] { return H5Screate(H5S_SCALAR); }, H5Sclose},
      {"property list", [] { return H5Pcreate(H5P_DATASET_XFER); }, H5Pclose}};
  std::vector<hid_t> before;
  for (const Kind& kind : kinds) {
    before.push_back(kind.make());
    kind.close(before.back());
  }
  EXPECT_EQ(diffDatasets(a, b, DiffSettings{}).differences.size(), 1u);
  for (std::size_t k = 0; k < before.size(); ++k) {
    const hid_t after = kinds[k].make();
    int left = 0;
    for (hid_t id = before[k] + 1; id < after; ++id) left += H5Iis_valid(id) > 0;
    EXPECT_GT(after - before[k], 1) << kinds[k].name << ": the comparison opened none";
    EXPECT_EQ(left, 0) << kinds[k].name << " identifiers left open by the comparison";
    kinds[k].close(after);
  }
}


TEST_F(DatasetDiffTest, BadInputIsOneInputErrorNamingTheFile) {
  const std::string a = write("a.h5", {1.0, 2.0});
  const std::string missing = (directory_ / "missing.h5").string();
  EXPECT_THROW(diffDatasets(a, missing, DiffSettings{}), wpg::datasets::InputError);
  const std::string other = (directory_ / "other.h5").string();
  H5::H5File(other, H5F_ACC_TRUNC).createGroup("runs");  // no schema_version
  try {
    diffDatasets(other, a, DiffSettings{});
    FAIL() << "no exception";
  } catch (const wpg::datasets::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(other), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
