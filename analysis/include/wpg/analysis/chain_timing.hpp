#pragma once
// The timing profile of the control chain per NMPC iteration, the paper's Sec. V-C table
// (Fig. 3: NMPC, IK of the WPG motion, its multibody ZMP, the preview filter), from the
// timings that the multibody replay records (MultibodyValidation::chain_time and
// chain_stage_time), and the real-time factor of a replay.
#include <array>
#include <cstddef>

#include "wpg/analysis/sample_statistics.hpp"
#include "wpg/multibody_validation.hpp"

namespace wpg::analysis {

// The stages of the chain, in the column order of MultibodyValidation::chain_stage_time.
enum class ChainStage : std::size_t { kNmpc = 0, kIk = 1, kMultibodyZmp = 2, kFilter = 3 };
constexpr std::size_t kChainStageCount = 4;

struct ChainTiming {
  // The whole chain's time per NMPC iteration [s]: average, standard deviation, min, max; its
  // count is the number of NMPC iterations.
  SampleStatistics per_iteration;
  // The median over the NMPC iterations of each stage's time [s], indexed by ChainStage; 0 for
  // a stage the replay did not time.
  std::array<double, kChainStageCount> stage_median{};

  double stageMedian(ChainStage stage) const { return stage_median[static_cast<std::size_t>(stage)]; }
};

// The chain timing of a replay (all zero when the replay recorded no timing).
ChainTiming chainTiming(const MultibodyValidation& validation);

// The paper's unit (Sec. V-C): one control period (5 ms tick) of the loop, from
// MultibodyValidation::tick_stage_time. The paper's table counts only the ticks that contain
// an NMPC iteration ("only counts the iteration when the NMPC is computed").
struct TickTiming {
  SampleStatistics nmpc_ticks;  // [s] the whole tick (sum of its stages), NMPC ticks only
  SampleStatistics all_ticks;   // [s] the whole tick, every control period
  // Per stage (ChainStage order; the first is the WPG's step), over the NMPC ticks and over
  // every tick [s].
  std::array<SampleStatistics, kChainStageCount> stage_nmpc_ticks{};
  std::array<SampleStatistics, kChainStageCount> stage_all_ticks{};
  // true when each stage was measured in its own tick (the online loop); false for the
  // offline pass, whose multibody ZMP and filter are whole-walk times spread evenly.
  bool measured = false;
};
TickTiming tickTiming(const MultibodyValidation& validation);

// How many times faster than real time a computation ran: walk_duration / wall_time (both
// [s]); 0 when wall_time is not positive (nothing measured).
double realTimeFactor(double walk_duration, double wall_time);

}  // namespace wpg::analysis
