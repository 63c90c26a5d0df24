// What one generated walk did (run_summary.hpp).
#include "wpg/analysis/run_summary.hpp"

#include <map>

#include "wpg/analysis/sample_statistics.hpp"

namespace wpg::analysis {

double walkDuration(const WalkTrajectory& trajectory) {
  return trajectory.time.empty() ? 0.0 : trajectory.time.back() - trajectory.time.front();
}

RunSummary summarizeRun(const WalkTrajectory& trajectory) {
  RunSummary summary;
  const std::vector<Eigen::Vector3d>& com = trajectory.com;
  for (std::size_t i = 1; i < com.size(); ++i) {
    summary.path_length += (com[i].head<2>() - com[i - 1].head<2>()).norm();
  }
  if (!com.empty()) summary.displacement = (com.back().head<2>() - com.front().head<2>()).norm();
  // The two initial feet are the first two footsteps; every other one is a step taken.
  summary.steps = trajectory.footsteps.size() > 2 ? trajectory.footsteps.size() - 2 : 0;
  summary.duration = walkDuration(trajectory);

  summary.nmpc_iterations = trajectory.mpc.size();
  std::map<int, std::size_t> counts;  // ordered by status code
  Eigen::VectorXd solve_time(static_cast<Eigen::Index>(trajectory.mpc.size()));
  for (std::size_t i = 0; i < trajectory.mpc.size(); ++i) {
    const MpcIterationLog& log = trajectory.mpc[i];
    ++counts[static_cast<int>(log.status)];
    solve_time[static_cast<Eigen::Index>(i)] = log.solve_time;
  }
  for (const auto& [code, count] : counts) {
    summary.status_counts.push_back({static_cast<IterationStatus>(code), count});
  }
  if (solve_time.size() > 0) {
    summary.median_solve_time = median(solve_time);
    summary.max_solve_time = solve_time.maxCoeff();
  }
  return summary;
}

}  // namespace wpg::analysis
