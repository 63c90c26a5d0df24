#include "wpg/walk_generator.hpp"

#include <cmath>
#include <stdexcept>

#include "wpg/pattern_generator.hpp"
#include "wpg/swing_foot_trajectory.hpp"

namespace wpg {

WalkResult generateWalk(const WalkingParameters& parameters, const WalkRequest& request) {
  parameters.validate();
  request.validate();
  PatternGenerator generator(parameters, request.generator);
  // Obstacle distances: libwpg's exact 2-D ones, as the NMPC's rows see them.
  const ObstacleDistanceOracle* distance = nullptr;
  if (!request.obstacles.empty()) {
    generator.setObstacles(request.obstacles);
    distance = &generator.obstacles();
    // The feet must start clear of every obstacle grown by its margin (and the sole radius).
    for (int o = 0; o < static_cast<int>(request.obstacles.size()); ++o) {
      for (FootSide side : {FootSide::kLeft, FootSide::kRight}) {
        const double clearance =
            distance->signedDistance(o, generator.footPose(side).head<2>(), nullptr) -
            request.obstacles[o].margin - parameters.obstacle_foot_radius;
        if (clearance < 0.0) {
          throw std::invalid_argument(
              "'obstacles[" + std::to_string(o) + "]': expected the obstacle, its margin and " +
              "the sole radius clear of the initial feet, but the " +
              (side == FootSide::kLeft ? "left" : "right") + " foot is " +
              std::to_string(-clearance) + " m inside");
        }
      }
    }
  }
  const double T = parameters.sampling_period;
  const double dt = parameters.control_period;
  const int sub_samples = static_cast<int>(std::lround(T / dt));
  const int iterations = static_cast<int>(std::lround(request.duration / T));
  const double h = parameters.com_height;
  const double h_over_g = parameters.com_height / parameters.gravity;

  WalkResult result;
  WalkTrajectory& out = result.trajectory;
  out.reserve(static_cast<std::size_t>(iterations) * sub_samples + 1, iterations);
  out.constraint_families = generator.model().familyInfo();
  out.footsteps.push_back({0.0, generator.footPose(FootSide::kLeft), FootSide::kLeft});
  out.footsteps.push_back({0.0, generator.footPose(FootSide::kRight), FootSide::kRight});

  SwingFootTrajectory swing;
  bool swing_started = false;
  Eigen::Vector3d com_x = generator.comX(), com_y = generator.comY();
  Eigen::Vector2d push = Eigen::Vector2d::Zero();

  auto record = [&](double t, const PatternGenerator::SamplePlan* plan) {
    out.time.push_back(t);
    out.com.emplace_back(com_x(0), com_y(0), h);
    out.com_vel.emplace_back(com_x(1), com_y(1), 0.0);
    out.com_acc.emplace_back(com_x(2) + push.x(), com_y(2) + push.y(), 0.0);
    // The CoP balances the controlled acceleration only: an external push moves the CoM
    // without passing through the feet (z = c - h/g c'', eq. 3).
    out.cop.emplace_back(com_x(0) - h_over_g * com_x(2), com_y(0) - h_over_g * com_y(2));
    Eigen::Vector4d left, right;
    const Eigen::Vector3d& l = generator.footPose(FootSide::kLeft);
    const Eigen::Vector3d& r = generator.footPose(FootSide::kRight);
    left << l.x(), l.y(), 0.0, l.z();
    right << r.x(), r.y(), 0.0, r.z();
    if (plan && plan->swinging) (plan->swing_side == FootSide::kLeft ? left : right) = swing.poseAt(t);
    out.left_foot.push_back(left);
    out.right_foot.push_back(right);
    out.free_flyer_yaw.push_back(0.5 * (left(3) + right(3)));
    out.support.push_back(plan ? plan->support : SupportState::kDouble);
  };

  const double omega0 = std::sqrt(parameters.gravity / parameters.com_height);
  PatternGenerator::SamplePlan last_plan;  // the final sample closes the last period
  bool planned = false;
  int k = 0;
  for (; k < iterations; ++k) {
    const double t = k * T;
    // Fall: the capture point (where the CoM comes to rest over a fixed CoP) out of reach.
    const Eigen::Vector2d capture(com_x(0) + com_x(1) / omega0, com_y(0) + com_y(1) / omega0);
    const double reach = std::min(
        (capture - generator.footPose(FootSide::kLeft).head<2>()).norm(),
        (capture - generator.footPose(FootSide::kRight).head<2>()).norm());
    if (!(reach <= request.generator.fall_capture_distance)) {
      MpcIterationLog fallen;
      fallen.time = t;
      fallen.status = IterationStatus::kFallen;
      out.mpc.push_back(fallen);
      result.success = false;
      result.message = "the robot fell at t = " + std::to_string(t) + " s: capture point " +
                       std::to_string(reach) + " m from the nearest foot (limit " +
                       std::to_string(request.generator.fall_capture_distance) + " m)";
      break;
    }
    const MpcIterationLog& log = generator.update(t, request.commandAt(t));
    out.mpc.push_back(log);
    if (result.success && (log.status == IterationStatus::kFallback ||
                           log.status == IterationStatus::kIterationLimit)) {
      result.success = false;
      result.message = std::string("NMPC iteration at t = ") + std::to_string(t) +
                       " s ended with status '" + iterationStatusName(log.status) + "'";
    }
    const PatternGenerator::SamplePlan& plan = generator.plan();
    last_plan = plan;
    planned = true;
    if (plan.swinging) {
      if (!swing_started) {
        swing.start(generator.footPose(plan.swing_side), plan.lift_off_time, plan.landing_time,
                    parameters.step_height);
        swing_started = true;
      }
      swing.replan(t, plan.swing_target);
    } else {
      swing_started = false;
    }
    for (int i = 0; i < sub_samples; ++i) {
      const double ti = t + i * dt;
      push = request.pushAccelerationAt(ti);
      record(ti, &plan);
      integrateJerk(com_x, plan.jerk_x, dt, push.x());
      integrateJerk(com_y, plan.jerk_y, dt, push.y());
    }
    if (generator.advance(com_x, com_y)) out.footsteps.push_back(generator.lastLanding());
  }
  // Relaxed obstacle rows (a robot enclosed or pushed into an obstacle) may let a step land in
  // a margin: the walk is then recorded as failed.
  if (result.success && distance) {
    for (const Footstep& step : out.footsteps) {
      if (step.landing_time <= 0.0) continue;
      for (int o = 0; o < static_cast<int>(request.obstacles.size()); ++o) {
        const double clearance = distance->signedDistance(o, step.pose.head<2>(), nullptr) -
                                 request.obstacles[o].margin - parameters.obstacle_foot_radius;
        if (clearance < -1e-6 && result.success) {
          result.success = false;
          result.message = "the step landing at t = " + std::to_string(step.landing_time) +
                           " s is " + std::to_string(-clearance) + " m inside obstacle " +
                           std::to_string(o) + "'s margin (its constraint had to be relaxed)";
        }
      }
    }
  }
  // The sample at the end belongs to the last period: a swing foot still in the air is where
  // its polynomial puts it (not back at its lift-off pose).
  push = request.pushAccelerationAt(k * T);
  record(k * T, planned ? &last_plan : nullptr);
  return result;
}

}  // namespace wpg
