#pragma once
// What the multibody replay and the dynamic filter (paper Sec. IV, Fig. 3 and 6) add to a
// walk: plain data, filled by robots/ (Simbody) and written by datasets/ (HDF5), so that
// neither of the two depends on the other.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wpg {

struct ZmpErrorStatistics {
  double rms = 0.0;  // [m], sqrt(mean |reference CoP - multibody ZMP|^2) over the samples
  double max = 0.0;  // [m]
};

struct MultibodyValidation {
  std::vector<std::string> configuration_names;  // nq column names of q
  Eigen::MatrixXd q;                       // n x nq, the motion sent to the robot (filtered
                                           // when the filter ran), RobotModel's layout
  Eigen::MatrixXd zmp_multibody;           // n x 2, ZMP of the WPG's motion (before the filter)
  Eigen::MatrixXd com_filtered;            // n x 3, WPG CoM + filter correction (empty: no filter)
  Eigen::MatrixXd zmp_multibody_filtered;  // n x 2, ZMP after the filter (empty: no filter)
  ZmpErrorStatistics before, after;        // vs. the reference CoP
  int ik_failures = 0;                     // samples the IK did not solve
  double max_ik_com_error = 0.0;           // [m]
  double max_ik_foot_error = 0.0;          // [m]
  int samples_with_limit_violations = 0;
  double max_limit_violation = 0.0;        // [rad]
  std::vector<std::string> violated_joints;
  // Timing profile per NMPC iteration of the control chain, as the paper's Sec. V-C table
  // (Fig. 3: NMPC, IK of the WPG motion, its multibody ZMP, the preview filter, IK of the
  // corrected CoM; the validation replay is not part of the chain): k entries [s].
  Eigen::VectorXd chain_time;
  Eigen::MatrixXd chain_stage_time;        // k x 4: NMPC, IK, multibody ZMP, preview filter [s]

  // The same per control period (5 ms tick, the unit of the paper's Sec. V-C table): one row
  // per step() of the generator (the closing sample of a walk is not one), columns as
  // chain_stage_time, the first being the WPG's step() (the NMPC when it runs, plus the
  // interpolation) [s].
  Eigen::MatrixXd tick_stage_time;
  std::vector<std::uint8_t> tick_nmpc;  // 1 when the NMPC ran in that control period
  // true: every stage measured in its own tick (the online loop); false: the offline pass,
  // where the IK is measured per sample but the multibody ZMP and the filter run over the
  // whole walk and are spread evenly over the ticks (and the WPG's interpolation is not timed).
  bool tick_stages_measured = false;

  std::string filter_mode;        // "online", "offline" (dynamicFilterModeName); empty: no filter
  bool wpg_reinitialized = false;  // online: the WPG re-initialised from the filter every NMPC iteration
  // filter_mode "both": the offline pass over the open-loop walk, for comparison.
  bool has_offline_comparison = false;
  ZmpErrorStatistics offline_before, offline_after;
};

}  // namespace wpg
