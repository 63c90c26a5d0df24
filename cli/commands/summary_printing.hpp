#pragma once
// The summary lines that `wpg run` and `wpg replay` print: formatting only (the numbers come
// from analysis/ and the engine's run result, wpg/engine/scenario_run.hpp).
#include <iosfwd>
#include <string>

#include "wpg/analysis/run_summary.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/pipeline_stages.hpp"

namespace wpg::cli {

// "%.<digits>f" of value, without the sign of a value that rounds to zero ("0.000", never
// "-0.000").
std::string fixed(double value, int digits);
// A clearance [m] as fixed(), but one inside a margin (below -analysis::kMarginTolerance) that
// would round to zero in two significant digits ("-1.1e-05"): a failure is never shown as 0.
std::string clearanceText(double value, int digits);

// scenario, walked, status and solve lines of `wpg run`.
void printRunSummary(std::ostream& out, const datasets::Scenario& scenario,
                     const analysis::RunSummary& summary);

// The line about the least clearances of the footsteps to the obstacles.
void printObstacleClearances(std::ostream& out, const engine::ObstacleClearances& clearances);

// The line of a walk to a goal: reached or not (and why), the first route's length, the
// replans and the planner's time over all plans.
void printGoalSummary(std::ostream& out, const engine::WalkOutcome& walk);

// The summary lines of a replay: ZMP error before/after, IK status, timing of the chain.
void printMultibodySummary(std::ostream& out, const engine::ReplayOutcome& outcome);

// The last lines of `wpg run` and `wpg replay`: the dataset, and when `plot` its figure next to
// it (a figure that cannot be drawn is a warning: the dataset is complete).
void reportDatasetAndFigure(const std::string& dataset_path, const std::string& figure_path,
                            bool plot);

}  // namespace wpg::cli
