// The closed loop of the paper's Fig. 3, online (online_filter_loop.hpp).
#include "wpg/robots/online_filter_loop.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "wpg/dynamic_filter.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/robots/momentum_zmp.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "zmp_error_statistics.hpp"

namespace wpg::robots {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

enum Stage { kWpg = 0, kIk = 1, kZmp = 2, kFilter = 3 };

// The multibody ZMP only (no joint torques): the replay welds the upper body the IK holds.
MultibodyReplaySettings zmpReplaySettings(const WalkingParameters& w) {
  MultibodyReplaySettings s;
  s.gravity = w.gravity;
  s.joint_torques = false;
  return s;
}


// The controller around the WPG, called by the walk loop (runWalkLoop: generateWalk or the walk
// to a goal) around every control period.
class FilterLoop : public ControlLoopObserver {
 public:
  FilterLoop(const RobotModel& model, const WalkingParameters& w,
             const OnlineFilterLoopSettings& settings)
      : model_(model),
        w_(w),
        settings_(settings),
        ik_(model, settings.ik),
        controller_(w.control_period, w.com_height, w.gravity, settings.preview),
        filter_(controller_),
        momentum_(model, w.gravity),
        sub_samples_(static_cast<int>(std::lround(w.sampling_period / w.control_period))),
        // The error at offsets 0 .. sub_samples - 1 of the window and NL rows of preview after
        // each; one more row so that the last one used is not the window's extrapolated end.
        window_rows_(sub_samples_ + controller_.previewLength() + 1),
        q_(model.nq()) {
    window_error_.resize(window_rows_, 2);
    window_zmp_.resize(window_rows_, 2);
    window_com_.resize(window_rows_, 3);
  }

  // Room for a walk of `samples` samples (no allocation per control period for the records).
  void reserve(std::size_t samples) {
    q_columns_.resize(model_.nq(), static_cast<Eigen::Index>(samples));
    com_filtered_.reserve(samples);
    zmp_before_.reserve(samples);
    stages_.reserve(samples);
    nmpc_.reserve(samples);
  }

  void beforeStep(OnlineWalkingGenerator& generator) override {
    const Clock::time_point start = Clock::now();
    // Fig. 3: the WPG restarts from the corrected state (its CoM + the filter's correction),
    // which the correction then no longer needs to carry.
    if ((settings_.reinitialize_wpg || settings_.closed_loop) && generator.atSamplingInstant() &&
        generator.time() > 0.0) {
      Eigen::Vector3d absorbed_x, absorbed_y;
      if (settings_.closed_loop) {
        filter_.absorbIncrement(absorbed_x, absorbed_y);
      } else {
        filter_.absorbCorrection(absorbed_x, absorbed_y);
      }
      generator.reinitializeCom(generator.comStateX() + absorbed_x,
                                generator.comStateY() + absorbed_y);
    }
    step_start_ = Clock::now();
    reinit_time_ = seconds(start, step_start_);
  }

  void afterStep(OnlineWalkingGenerator& generator, const ControlSample& sample) override {
    Clock::time_point mark = Clock::now();
    std::array<double, 4> stage{};
    stage[kWpg] = seconds(step_start_, mark);
    stage[kFilter] = reinit_time_;
    if (sample.nmpc_sample || window_offset_ >= sub_samples_) previewError(generator, sample, stage, mark);

    // One period of the preview controller on the error it knows now.
    const Eigen::Vector3d correction(filter_.sentCorrectionX()(0), filter_.sentCorrectionY()(0),
                                     0.0);
    const Eigen::Vector3d com = sample.com_position + correction;
    zmp_before_.push_back(window_zmp_.row(window_offset_).transpose());
    filter_.step(window_error_.bottomRows(window_rows_ - window_offset_));
    ++window_offset_;
    Clock::time_point now = Clock::now();
    stage[kFilter] += seconds(mark, now);
    mark = now;

    // The IK of the corrected motion: the configuration sent to the robot.
    solveOutput(sample.left_foot, sample.right_foot, com, sample.free_flyer_yaw);
    now = Clock::now();
    stage[kIk] += seconds(mark, now);
    com_filtered_.push_back(com);
    stages_.push_back(stage);
    nmpc_.push_back(sample.nmpc_sample ? 1 : 0);
  }

  // The samples the walk loop recorded after the last control period (the closing sample, at
  // the end or at a fall): the correction held, no timing (they are not control periods).
  void closeWalk(const WalkTrajectory& walk) {
    const std::size_t ticks = com_filtered_.size();
    for (std::size_t i = ticks; i < walk.size(); ++i) {
      const Eigen::Vector3d com =
          walk.com[i] +
          Eigen::Vector3d(filter_.sentCorrectionX()(0), filter_.sentCorrectionY()(0), 0.0);
      const Eigen::Index row = std::min<Eigen::Index>(window_offset_, window_rows_ - 1);
      zmp_before_.push_back(window_zmp_.row(row).transpose());
      solveOutput(walk.left_foot[i], walk.right_foot[i], com, walk.free_flyer_yaw[i]);
      com_filtered_.push_back(com);
    }
  }

  MultibodyValidation validation(const WalkTrajectory& walk, const WalkRequest& request) const {
    const Eigen::Index n = static_cast<Eigen::Index>(walk.size());
    MultibodyValidation out;
    out.configuration_names = {"base_x", "base_y", "base_z", "base_qw", "base_qx", "base_qy",
                               "base_qz"};
    for (const std::string& joint : model_.jointNames()) out.configuration_names.push_back(joint);
    out.q.resize(n, model_.nq());
    out.com_filtered.resize(n, 3);
    out.zmp_multibody.resize(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      out.q.row(i) = q_columns_.col(i).transpose();
      out.com_filtered.row(i) = com_filtered_[k].transpose();
      out.zmp_multibody.row(i) = zmp_before_[k].transpose();
    }
    out.ik_failures = ik_failures_;
    out.max_ik_com_error = max_com_error_;
    out.max_ik_foot_error = max_foot_error_;
    out.samples_with_limit_violations = samples_with_limit_violations_;
    out.max_limit_violation = max_limit_violation_;
    for (int j = 0; j < 64 && j < static_cast<int>(model_.jointNames().size()); ++j)
      if (limit_violations_ & (std::uint64_t{1} << j))
        out.violated_joints.push_back(model_.jointNames()[static_cast<std::size_t>(j)]);

    // Validation (not part of the loop): the motion sent to the robot replayed as a whole.
    Eigen::MatrixXd com_force(n, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector2d a = request.pushAccelerationAt(walk.time[static_cast<std::size_t>(i)]);
      com_force.row(i) << request.robot_mass * a.x(), request.robot_mass * a.y(), 0.0;
    }
    MultibodyReplay validation_replay(model_, zmpReplaySettings(w_));
    out.zmp_multibody_filtered = validation_replay.run(out.q, w_.control_period, com_force).zmp;
    out.before = detail::zmpErrorStatistics(walk, out.zmp_multibody);
    out.after = detail::zmpErrorStatistics(walk, out.zmp_multibody_filtered);

    // Timings: per control period, and summed per NMPC iteration (chain_time, as before).
    const Eigen::Index ticks = static_cast<Eigen::Index>(stages_.size());
    out.tick_stage_time.resize(ticks, 4);
    for (Eigen::Index i = 0; i < ticks; ++i)
      for (int s = 0; s < 4; ++s) out.tick_stage_time(i, s) = stages_[static_cast<std::size_t>(i)][s];
    out.tick_nmpc = nmpc_;
    out.tick_stages_measured = true;
    const Eigen::Index iterations = std::max<Eigen::Index>(1, walk.mpc.size());
    out.chain_stage_time = Eigen::MatrixXd::Zero(iterations, 4);
    Eigen::Index iteration = -1;
    for (Eigen::Index i = 0; i < ticks; ++i) {
      if (nmpc_[static_cast<std::size_t>(i)]) ++iteration;
      if (iteration >= 0 && iteration < iterations)
        out.chain_stage_time.row(iteration) += out.tick_stage_time.row(i);
    }
    for (Eigen::Index k = iteration + 1; k < static_cast<Eigen::Index>(walk.mpc.size()); ++k)
      out.chain_stage_time(k, 0) = walk.mpc[static_cast<std::size_t>(k)].solve_time;
    out.chain_time = out.chain_stage_time.rowwise().sum();
    out.filter_mode = dynamicFilterModeName(settings_.closed_loop ? DynamicFilterMode::kClosedLoop
                                                                  : DynamicFilterMode::kOnline);
    out.wpg_reinitialized = settings_.reinitialize_wpg || settings_.closed_loop;
    return out;
  }

 private:
  // At an NMPC iteration: the error the filter previews until the next one, from the motion
  // the NMPC plans (this sample, then OnlineWalkingGenerator::previewReference).
  void previewError(const OnlineWalkingGenerator& generator, const ControlSample& sample,
                    std::array<double, 4>& stage, Clock::time_point& mark) {
    generator.previewReference(static_cast<int>(window_rows_ - 1), preview_);
    window_.time.assign(1, sample.time);
    window_.com.assign(1, sample.com_position);
    window_.cop.assign(1, sample.cop);
    window_.left_foot.assign(1, sample.left_foot);
    window_.right_foot.assign(1, sample.right_foot);
    window_.free_flyer_yaw.assign(1, sample.free_flyer_yaw);
    window_.time.insert(window_.time.end(), preview_.time.begin(), preview_.time.end());
    window_.com.insert(window_.com.end(), preview_.com.begin(), preview_.com.end());
    window_.cop.insert(window_.cop.end(), preview_.cop.begin(), preview_.cop.end());
    window_.left_foot.insert(window_.left_foot.end(), preview_.left_foot.begin(),
                             preview_.left_foot.end());
    window_.right_foot.insert(window_.right_foot.end(), preview_.right_foot.begin(),
                              preview_.right_foot.end());
    window_.free_flyer_yaw.insert(window_.free_flyer_yaw.end(), preview_.free_flyer_yaw.begin(),
                                  preview_.free_flyer_yaw.end());
    Clock::time_point now = Clock::now();
    stage[kWpg] += seconds(mark, now);  // the preview is the WPG's interpolation
    mark = now;
    for (Eigen::Index i = 0; i < window_rows_; ++i)
      window_com_.row(i) = window_.com[static_cast<std::size_t>(i)].transpose();
    ik_.solveTrajectory(window_, window_com_, window_ik_, /*timed=*/false);  // timed as a stage
    now = Clock::now();
    stage[kIk] += seconds(mark, now);
    mark = now;
    // Pushes are not previewed (nobody knows them in advance): the reference motion's ZMP,
    // from the momentum rate of its kinematics (Simbody's inverse dynamics within 1e-9 m,
    // momentum_zmp.hpp), which allocates nothing here.
    const Eigen::MatrixXd& zmp = momentum_.run(window_ik_.q, w_.control_period).zmp;
    now = Clock::now();
    stage[kZmp] += seconds(mark, now);
    mark = now;
    for (Eigen::Index i = 0; i < window_rows_; ++i) {
      window_zmp_.row(i) = zmp.row(i);
      const Eigen::Vector2d e = window_.cop[static_cast<std::size_t>(i)] - zmp.row(i).transpose();
      window_error_.row(i) = e.allFinite() ? Eigen::RowVector2d(e.transpose())
                                           : Eigen::RowVector2d::Zero();
    }
    window_offset_ = 0;
    now = Clock::now();
    stage[kFilter] += seconds(mark, now);
    mark = now;
  }

  void solveOutput(const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                   const Eigen::Vector3d& com, double yaw) {
    WalkingIkTarget target;
    target.left_foot = left;
    target.right_foot = right;
    target.com = com;
    target.waist_yaw = yaw;
    // Newton from the previous ticks' solutions (5 ms apart, as solveTrajectory's samples).
    const WalkingIkResult r = ik_.solveNext(target, q_, output_warm_start_);
    if (r.status != WalkingIkStatus::kSolved) ++ik_failures_;
    max_com_error_ = std::max(max_com_error_, r.com_error);
    max_foot_error_ = std::max(max_foot_error_, r.foot_position_error);
    if (r.limit_violations) {
      ++samples_with_limit_violations_;
      limit_violations_ |= r.limit_violations;
      max_limit_violation_ = std::max(max_limit_violation_, r.max_limit_violation);
    }
    const Eigen::Index column = static_cast<Eigen::Index>(com_filtered_.size());
    if (column >= q_columns_.cols())  // more samples than reserved (never for a whole walk)
      q_columns_.conservativeResize(Eigen::NoChange, 2 * column + 1);
    q_columns_.col(column) = q_;
  }

  const RobotModel& model_;
  const WalkingParameters& w_;
  OnlineFilterLoopSettings settings_;
  WalkingIk ik_;
  PreviewController controller_;
  OnlineDynamicFilter filter_;
  MomentumZmp momentum_;  // the window's multibody ZMP
  int sub_samples_;
  Eigen::Index window_rows_;
  Eigen::VectorXd q_;

  WalkTrajectory preview_, window_;
  Eigen::MatrixXd window_com_;             // window_.com as a matrix, for the IK
  WalkingIkTrajectory window_ik_;          // buffers reused at every NMPC iteration
  WalkingIk::WarmStart output_warm_start_;  // the IK of the corrected motion, tick after tick
  Eigen::MatrixXd window_error_, window_zmp_;
  Eigen::Index window_offset_ = std::numeric_limits<int>::max();
  Clock::time_point step_start_;
  double reinit_time_ = 0.0;

  // Per sample (the output) and per control period (the timings).
  Eigen::MatrixXd q_columns_;  // the configurations sent, one per column (reserved)
  std::vector<Eigen::Vector3d> com_filtered_;
  std::vector<Eigen::Vector2d> zmp_before_;
  std::vector<std::array<double, 4>> stages_;
  std::vector<std::uint8_t> nmpc_;
  int ik_failures_ = 0, samples_with_limit_violations_ = 0;
  double max_com_error_ = 0.0, max_foot_error_ = 0.0, max_limit_violation_ = 0.0;
  std::uint64_t limit_violations_ = 0;
};

}  // namespace

PreviewControlSettings onlinePreviewSettings(const PreviewControlSettings& filter_settings,
                                             const DynamicFilterLoopSettings& loop) {
  PreviewControlSettings out = filter_settings;
  out.input_weight = loop.online_input_weight;
  return out;
}

OnlineFilterRun runOnlineFilterLoop(const RobotModel& model, const WalkingParameters& parameters,
                                    const WalkRequest& request,
                                    const OnlineFilterLoopSettings& settings,
                                    const ObservedWalk& walk) {
  parameters.validate();
  if (settings.closed_loop && settings.reinitialize_wpg)
    throw std::invalid_argument("online filter: closed_loop and reinitialize_wpg are two forms "
                                "of the re-initialisation, choose one");
  FilterLoop loop(model, parameters, settings);
  // A walk to a goal may end before its duration: the duration bounds every walk's samples.
  loop.reserve(static_cast<std::size_t>(std::lround(request.duration / parameters.control_period)) + 2);
  OnlineFilterRun run;
  run.walk = walk(loop);
  if (run.walk.trajectory.size() < 3)
    throw std::runtime_error("online filter: the walk has fewer than 3 samples to replay");
  loop.closeWalk(run.walk.trajectory);
  run.validation = loop.validation(run.walk.trajectory, request);
  return run;
}

OnlineFilterRun runOnlineFilterLoop(const RobotModel& model, const WalkingParameters& parameters,
                                    const WalkRequest& request,
                                    const OnlineFilterLoopSettings& settings,
                                    const ConstraintFamilies& extra_families) {
  return runOnlineFilterLoop(model, parameters, request, settings,
                             [&](ControlLoopObserver& observer) {
                               return generateWalk(parameters, request, extra_families, &observer);
                             });
}

}  // namespace wpg::robots
