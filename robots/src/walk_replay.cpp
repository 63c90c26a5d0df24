#include "wpg/robots/walk_replay.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <future>
#include <stdexcept>
#include <system_error>

#include "wpg/dynamic_filter.hpp"
#include "wpg/robots/momentum_zmp.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "zmp_error_statistics.hpp"

namespace wpg::robots {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// IK of every sample (WalkingIk::solveTrajectory); each sample's solve time goes to its NMPC
// iteration (stage column 1). `record` keeps the IK statistics (of the motion finally sent to
// the robot).
Eigen::MatrixXd solveIk(const WalkingIk& ik, const RobotModel& model, const WalkTrajectory& walk,
                        const Eigen::MatrixXd& com, int per_iteration, MultibodyValidation& out,
                        bool record) {
  WalkingIkTrajectory result = ik.solveTrajectory(walk, com);
  for (std::size_t i = 0; i < result.solve_time.size(); ++i) {
    if (static_cast<Eigen::Index>(i) < out.tick_stage_time.rows())
      out.tick_stage_time(static_cast<Eigen::Index>(i), 1) += result.solve_time[i];
    const Eigen::Index k = std::min<Eigen::Index>(static_cast<Eigen::Index>(i) / per_iteration,
                                                  out.chain_stage_time.rows() - 1);
    out.chain_stage_time(k, 1) += result.solve_time[i];
  }
  if (record) {
    out.ik_failures = result.failures;
    out.max_ik_com_error = result.max_com_error;
    out.max_ik_foot_error = result.max_foot_position_error;
    out.samples_with_limit_violations = result.samples_with_limit_violations;
    out.max_limit_violation = result.max_limit_violation;
    out.violated_joints.clear();
    for (int j = 0; j < 64 && j < static_cast<int>(model.jointNames().size()); ++j)
      if (result.limit_violations & (std::uint64_t{1} << j))
        out.violated_joints.push_back(model.jointNames()[j]);
  }
  return std::move(result.q);
}


}  // namespace

MultibodyValidation replayWalk(const RobotModel& model, const WalkingParameters& w,
                               const WalkRequest& request, const WalkTrajectory& walk,
                               const WalkReplaySettings& settings) {
  const Eigen::Index n = static_cast<Eigen::Index>(walk.size());
  if (n < 3 || walk.com.size() != walk.size() || walk.cop.size() != walk.size())
    throw std::invalid_argument("replay: expected a walk of at least 3 consistent samples");
  const double dt = w.control_period;
  const int per_iteration = static_cast<int>(std::lround(w.sampling_period / dt));
  const Eigen::Index iterations = std::max<Eigen::Index>(1, walk.mpc.size());

  MultibodyValidation out;
  out.configuration_names = {"base_x", "base_y", "base_z", "base_qw", "base_qx", "base_qy", "base_qz"};
  for (const std::string& joint : model.jointNames()) out.configuration_names.push_back(joint);
  out.chain_stage_time = Eigen::MatrixXd::Zero(iterations, 4);
  for (Eigen::Index k = 0; k < static_cast<Eigen::Index>(walk.mpc.size()); ++k)
    out.chain_stage_time(k, 0) = walk.mpc[k].solve_time;
  // Per control period (the closing sample is not one): the NMPC at its ticks, the IK per
  // sample; the whole-walk ZMP and filter spread evenly below (tick_stages_measured false).
  const Eigen::Index ticks = n - 1;
  out.tick_stage_time = Eigen::MatrixXd::Zero(ticks, 4);
  out.tick_nmpc.assign(static_cast<std::size_t>(ticks), 0);
  for (Eigen::Index k = 0; k < static_cast<Eigen::Index>(walk.mpc.size()); ++k) {
    const Eigen::Index tick = k * per_iteration;
    if (tick >= ticks) break;
    out.tick_stage_time(tick, 0) = walk.mpc[k].solve_time;
    out.tick_nmpc[static_cast<std::size_t>(tick)] = 1;
  }

  Eigen::MatrixXd com(n, 3), com_force(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    com.row(i) = walk.com[i].transpose();
    const Eigen::Vector2d a = request.pushAccelerationAt(walk.time[i]);
    com_force.row(i) << request.robot_mass * a.x(), request.robot_mass * a.y(), 0.0;
  }
  const WalkingIk ik(model, settings.ik);
  // Simbody validates: the ZMP of the motion sent to the robot (the filtered one, or the WPG's
  // when there is no filter) is its inverse dynamics. Only the ZMP is needed: without joint
  // torques the replay welds the joints the IK holds constant (the upper body in its
  // reference posture), which halves Simbody's work.
  MultibodyReplaySettings replay_settings;
  replay_settings.gravity = w.gravity;
  replay_settings.joint_torques = false;
  replay_settings.threads = settings.threads;
  MultibodyReplay replay(model, replay_settings);

  // The unfiltered motion: IK then its multibody ZMP, the filter's input: the momentum rate of
  // the kinematics (Simbody's within 1e-9 m, tested on the shipped walks, at a twentieth of
  // the cost); without the filter, Simbody's.
  Eigen::MatrixXd q = solveIk(ik, model, walk, com, per_iteration, out, !settings.filter);
  // With the filter, Simbody's systems for the validation are built on another thread while
  // this one computes the corrected motion (its constant joints are the unfiltered motion's:
  // the IK holds the same ones in the reference posture; run() checks and rebuilds if not).
  std::future<void> building;
  if (settings.filter && settings.threads > 1) {
    try {
      building = std::async(std::launch::async, [&] { replay.prepare(q); });
    } catch (const std::system_error&) {  // no thread to spare: run() builds them
    }
  }
  auto start = Clock::now();
  if (settings.filter) {
    MomentumZmp momentum(model, w.gravity);
    out.zmp_multibody = momentum.run(q, dt, com_force).zmp;
  } else {
    out.zmp_multibody = replay.run(q, dt, com_force).zmp;
  }
  const double zmp_time = seconds(start);
  out.before = detail::zmpErrorStatistics(walk, out.zmp_multibody);
  if (!settings.filter) {
    out.q = q;
    out.after = out.before;
  } else {
    // Dynamic filter: preview control on (reference CoP - multibody ZMP), correction added to
    // the WPG's CoM; then IK and replay again (validation, Fig. 6's dashed green curve).
    start = Clock::now();
    const PreviewController controller(dt, w.com_height, w.gravity, settings.preview);
    Eigen::MatrixXd error(n, 2), correction(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector2d e = walk.cop[i] - out.zmp_multibody.row(i).transpose();
      error.row(i) = e.allFinite() ? Eigen::RowVector2d(e.transpose()) : Eigen::RowVector2d::Zero();
    }
    dynamicFilterCorrection(controller, error, correction);
    out.com_filtered = com;
    out.com_filtered.leftCols<2>() += correction;
    const double filter_time = seconds(start);
    out.q = solveIk(ik, model, walk, out.com_filtered, per_iteration, out, true);
    // Its errors (out of memory, Simbody's) are run()'s: they stop the replay as run()'s
    // would.
    if (building.valid()) building.get();
    out.zmp_multibody_filtered = replay.run(out.q, dt, com_force).zmp;
    out.after = detail::zmpErrorStatistics(walk, out.zmp_multibody_filtered);
    // The whole-walk stages are spread evenly over the iterations (per-sample costs). The
    // validation replay of the corrected motion is not part of the control chain.
    out.chain_stage_time.col(3).setConstant(filter_time / iterations);
    out.tick_stage_time.col(3).setConstant(filter_time / ticks);
    out.filter_mode = dynamicFilterModeName(DynamicFilterMode::kOffline);
  }
  out.chain_stage_time.col(2).setConstant(zmp_time / iterations);
  out.tick_stage_time.col(2).setConstant(zmp_time / ticks);
  out.chain_time = out.chain_stage_time.rowwise().sum();
  return out;
}

}  // namespace wpg::robots
