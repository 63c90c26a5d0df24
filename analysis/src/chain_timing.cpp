// The control chain's timing profile, paper Sec. V-C (chain_timing.hpp).
#include "wpg/analysis/chain_timing.hpp"

#include <cstdint>

namespace wpg::analysis {

ChainTiming chainTiming(const MultibodyValidation& validation) {
  ChainTiming timing;
  timing.per_iteration = describeSample(validation.chain_time);
  const Eigen::MatrixXd& stages = validation.chain_stage_time;
  for (std::size_t stage = 0; stage < kChainStageCount; ++stage) {
    const Eigen::Index column = static_cast<Eigen::Index>(stage);
    if (column < stages.cols()) timing.stage_median[stage] = median(stages.col(column));
  }
  return timing;
}

TickTiming tickTiming(const MultibodyValidation& validation) {
  TickTiming timing;
  const Eigen::MatrixXd& stages = validation.tick_stage_time;
  const Eigen::Index ticks = stages.rows();
  if (ticks == 0 || stages.cols() != static_cast<Eigen::Index>(kChainStageCount) ||
      static_cast<Eigen::Index>(validation.tick_nmpc.size()) != ticks)
    return timing;
  timing.measured = validation.tick_stages_measured;
  Eigen::Index nmpc_count = 0;
  for (std::uint8_t flag : validation.tick_nmpc) nmpc_count += flag ? 1 : 0;
  Eigen::MatrixXd nmpc_stages(nmpc_count, stages.cols());
  for (Eigen::Index i = 0, k = 0; i < ticks; ++i)
    if (validation.tick_nmpc[static_cast<std::size_t>(i)]) nmpc_stages.row(k++) = stages.row(i);
  timing.all_ticks = describeSample(stages.rowwise().sum());
  timing.nmpc_ticks = describeSample(nmpc_stages.rowwise().sum());
  for (std::size_t stage = 0; stage < kChainStageCount; ++stage) {
    const Eigen::Index column = static_cast<Eigen::Index>(stage);
    timing.stage_all_ticks[stage] = describeSample(stages.col(column));
    timing.stage_nmpc_ticks[stage] = describeSample(nmpc_stages.col(column));
  }
  return timing;
}

double realTimeFactor(double walk_duration, double wall_time) {
  return wall_time > 0.0 ? walk_duration / wall_time : 0.0;
}

}  // namespace wpg::analysis
