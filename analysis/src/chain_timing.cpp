// The control chain's timing profile, paper Sec. V-C (chain_timing.hpp).
#include "wpg/analysis/chain_timing.hpp"

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

double realTimeFactor(double walk_duration, double wall_time) {
  return wall_time > 0.0 ? walk_duration / wall_time : 0.0;
}

}  // namespace wpg::analysis
