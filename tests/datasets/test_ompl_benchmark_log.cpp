// The OMPL benchmark log writer (wpg/datasets/storage/ompl_benchmark_log.hpp) against the grammar of
// OMPL's documentation: the preamble lines in order, the status enum, a planner's block, the
// run lines of "value; " items, and refusals of what the format cannot hold.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "wpg/datasets/storage/ompl_benchmark_log.hpp"

namespace {

using wpg::datasets::BenchmarkExperiment;
using wpg::datasets::BenchmarkPlanner;

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

BenchmarkExperiment smallExperiment() {
  BenchmarkExperiment e;
  e.version = "0.1.0";
  e.name = "u trap";  // a space: one word in the log
  e.properties = {{"seeds INTEGER", "2"}};
  e.host = "host";
  e.date = "2025-11-25T16:03:00Z";
  e.setup = "line one\n|>>> not the end\nline three";
  e.cpu_info = "a CPU\n";
  e.seed = 7;
  e.time_limit = 1.0;
  e.runs_per_planner = 2;
  e.total_time = 0.25;
  BenchmarkPlanner planner;
  planner.name = "rrtconnect";
  planner.common = {{"planner.range", "0.5"}};
  planner.properties = {"reached BOOLEAN", "time REAL"};
  planner.runs = {{"1", "0.001"}, {"0", ""}};
  e.planners.push_back(planner);
  return e;
}

TEST(OmplBenchmarkLog, WritesTheDocumentedPreambleAndPlannerBlock) {
  std::ostringstream out;
  wpg::datasets::writeBenchmarkLog(out, smallExperiment());
  const std::vector<std::string> lines = linesOf(out.str());
  const std::vector<std::string> expected = {
      "wpg version 0.1.0",
      "Experiment u_trap",
      "1 experiment properties",
      "seeds INTEGER = 2",
      "Running on host",
      "Starting at 2025-11-25T16:03:00Z",
      "<<<|", "line one", " |>>> not the end", "line three", "|>>>",
      "<<<|", "a CPU", "|>>>",
      "7 is the random seed",
      "1 seconds per run",
      "0 MB per run",
      "2 runs per planner",
      "0.25 seconds spent to collect the data",
      "1 enum type",
      "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|"
      "Approximate solution|Exact solution|Crash|Abort",
      "1 planners",
      "rrtconnect",
      "1 common properties",
      "planner.range = 0.5",
      "2 properties for each run",
      "reached BOOLEAN",
      "time REAL",
      "2 runs",
      "1; 0.001; ",
      "0; ; ",
      ".",
  };
  EXPECT_EQ(lines, expected);
}

TEST(OmplBenchmarkLog, NumbersReadBackExactlyAndNonFiniteAsTheGrammarAllows) {
  for (const double value : {0.1, 1.0 / 3.0, 5.7407e-05, 21.6, -0.023186209657707402, 1e300}) {
    EXPECT_EQ(std::stod(wpg::datasets::benchmarkNumber(value)), value);
  }
  EXPECT_EQ(wpg::datasets::benchmarkNumber(0.1), "0.1");
  EXPECT_EQ(wpg::datasets::benchmarkNumber(std::nan("")), "nan");
  EXPECT_EQ(wpg::datasets::benchmarkNumber(HUGE_VAL), "inf");
  EXPECT_EQ(wpg::datasets::benchmarkNumber(-HUGE_VAL), "nan");  // no "-inf" in the grammar
}

TEST(OmplBenchmarkLog, RefusesWhatTheFormatCannotHold) {
  std::ostringstream out;
  BenchmarkExperiment short_run = smallExperiment();
  short_run.planners[0].runs.push_back({"1"});
  EXPECT_THROW(wpg::datasets::writeBenchmarkLog(out, short_run), std::invalid_argument);
  BenchmarkExperiment broken_name = smallExperiment();
  broken_name.planners[0].name = "two\nlines";
  EXPECT_THROW(wpg::datasets::writeBenchmarkLog(out, broken_name), std::invalid_argument);
  BenchmarkExperiment broken_value = smallExperiment();
  broken_value.planners[0].common[0].second = "a\nb";
  EXPECT_THROW(wpg::datasets::writeBenchmarkLog(out, broken_value), std::invalid_argument);
}

}  // namespace
