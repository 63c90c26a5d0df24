// The engine's study requests (wpg/engine/batch_study_run.hpp, comparison_study_run.hpp):
// every output, side outputs included, is checked before any work whatever the front end, a bad
// value is named as the front end calls it, and an accepted request writes the study file and
// its summaries and tells the observer once.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../datasets/test_support.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/engine/batch_study_run.hpp"
#include "wpg/engine/comparison_study_run.hpp"

namespace fs = std::filesystem;

namespace {

// What the engine told the front end.
class AcceptingObserver : public wpg::engine::StudyObserver {
 public:
  void accepted(const std::string& name, const std::vector<std::string>&) override {
    names.push_back(name);
  }
  void runFinished(bool) override { ++runs; }
  std::vector<std::string> names;
  std::size_t runs = 0;
};

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class StudyRequests : public wpg_test::ScratchDirectoryTest {
 protected:
  StudyRequests() : ScratchDirectoryTest("wpg_test_study_requests") {}
  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  // Two walks of 2 s (a batch); one walk to a goal of 3 s (a comparison).
  void SetUp() override {
    ScratchDirectoryTest::SetUp();
    std::ofstream(path("batch.yaml"))
        << "name: pair\nbase: {robot: hrp2, duration: 2.0, reference: [{t: 0.0, v: [0.2, 0, 0]}]}\n"
           "sweep:\n  grid:\n    walking.weight_cop: [300.0, 3000.0]\n";
    std::ofstream(path("compare.yaml"))
        << "name: onecmp\nbase: {robot: hrp2, duration: 3.0}\nseeds: 1\n"
           "worlds:\n  - {name: trap, u_trap: {}}\nvariants:\n  nmpc_only: {planner.algorithm: none}\n";
  }

  wpg::engine::StudyRequest request(const std::string& study, const std::string& output) const {
    wpg::engine::StudyRequest r;
    r.study = path(study);
    r.output = path(output);
    return r;
  }
};

TEST_F(StudyRequests, ASideOutputOfAnotherKindIsRefusedBeforeAnyWork) {
  const std::string binary("\x00\x01 not a table \x00", 16);
  std::ofstream(path("out.summary.csv"), std::ios::binary) << binary;
  AcceptingObserver observer;
  EXPECT_THROW(wpg::engine::runBatchStudy(request("batch.yaml", "out.h5"), observer),
               wpg::datasets::InputError);
  EXPECT_EQ(contents(path("out.summary.csv")), binary);
  EXPECT_FALSE(fs::exists(path("out.h5")));

  fs::create_directories(path("cmp"));
  std::ofstream(path("cmp/study.h5")) << "notes, not HDF5\n";
  EXPECT_THROW(wpg::engine::runComparisonStudy(request("compare.yaml", "cmp"), observer),
               wpg::datasets::InputError);
  EXPECT_EQ(contents(path("cmp/study.h5")), "notes, not HDF5\n");
  fs::remove(path("cmp/study.h5"));

  // A figure the front end would draw, over a file of another kind: found before any walk.
  std::ofstream(path("cmp/top_trap.png")) << "a figure? no\n";
  wpg::engine::StudyRequest with_figures = request("compare.yaml", "cmp");
  with_figures.figures = true;
  EXPECT_THROW(wpg::engine::runComparisonStudy(with_figures, observer), wpg::datasets::InputError);
  EXPECT_FALSE(fs::exists(path("cmp/study.h5")));
  EXPECT_TRUE(observer.names.empty());
  EXPECT_EQ(observer.runs, 0u);
}

TEST_F(StudyRequests, ABadValueIsNamedAsTheFrontEndCallsIt) {
  AcceptingObserver observer;
  wpg::engine::StudyRequest r = request("batch.yaml", "out.h5");
  r.jobs = 0;
  r.names.jobs = "-j";
  try {
    wpg::engine::runBatchStudy(r, observer);
    FAIL() << "jobs = 0 was accepted";
  } catch (const wpg::datasets::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("-j: expected a number of worker threads >= 1", 0), 0u)
        << e.what();
  }
  r.jobs = 1;
  r.ompl_log = path("logs");
  r.shard = wpg::engine::ShardSlice{0, 2};
  r.study = path("compare.yaml");
  EXPECT_THROW(wpg::engine::runComparisonStudy(r, observer), wpg::datasets::InputError);
  EXPECT_FALSE(fs::exists(path("logs")));
}

TEST_F(StudyRequests, AnAcceptedBatchWritesItsFileAndSummaries) {
  AcceptingObserver observer;
  const wpg::engine::BatchStudyResult result =
      wpg::engine::runBatchStudy(request("batch.yaml", "out.h5"), observer);
  ASSERT_TRUE(result.complete);
  EXPECT_EQ(observer.names, std::vector<std::string>{"pair"});
  EXPECT_EQ(observer.runs, 2u);
  EXPECT_EQ(result.runs, 2u);
  EXPECT_EQ(result.summary.runs, 2u);
  EXPECT_EQ(result.summary.failed_runs, 0u);
  EXPECT_TRUE(result.figure.empty());
  EXPECT_TRUE(fs::is_regular_file(path("out.h5")));
  // A header and one row per run.
  const std::string csv = contents(result.summary.csv);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3) << csv;
  EXPECT_TRUE(fs::is_regular_file(result.summary.markdown));
}

}  // namespace
