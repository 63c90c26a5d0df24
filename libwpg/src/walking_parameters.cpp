#include "wpg/walking_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "value_checks.hpp"
#include "wpg/convex_polygon.hpp"

namespace wpg {
namespace {

void require(bool ok, const char* field, const std::string& expected, double got) {
  detail::requireValue(ok, "walking parameter ", field, expected, got);
}

void requirePositive(double value, const char* field) {
  require(std::isfinite(value) && value > 0.0, field, "a positive finite number", value);
}

void requireNonNegative(double value, const char* field) {
  require(std::isfinite(value) && value >= 0.0, field, "a finite number >= 0", value);
}

}  // namespace

bool parseHeadingReference(const std::string& name, HeadingReference* out) {
  if (name == "support_foot") {
    *out = HeadingReference::kSupportFoot;
  } else if (name == "command") {
    *out = HeadingReference::kCommand;
  } else {
    return false;
  }
  return true;
}

const char* headingReferenceName(HeadingReference reference) {
  return reference == HeadingReference::kCommand ? "command" : "support_foot";
}

bool parseVelocityTracking(const std::string& name, VelocityTracking* out) {
  if (name == "instantaneous") {
    *out = VelocityTracking::kInstantaneous;
  } else if (name == "window") {
    *out = VelocityTracking::kWindow;
  } else if (name == "with_sway") {
    *out = VelocityTracking::kWithSway;
  } else {
    return false;
  }
  return true;
}

const char* velocityTrackingName(VelocityTracking tracking) {
  switch (tracking) {
    case VelocityTracking::kInstantaneous: return "instantaneous";
    case VelocityTracking::kWindow: return "window";
    case VelocityTracking::kWithSway: return "with_sway";
  }
  return "unknown";
}

bool parseStepTiming(const std::string& name, StepTiming* out) {
  if (name == "fixed") {
    *out = StepTiming::kFixed;
  } else if (name == "adaptive") {
    *out = StepTiming::kAdaptive;
  } else {
    return false;
  }
  return true;
}

const char* stepTimingName(StepTiming timing) {
  return timing == StepTiming::kFixed ? "fixed" : "adaptive";
}

bool parseZeroCommandGait(const std::string& name, ZeroCommandGait* out) {
  if (name == "stop") {
    *out = ZeroCommandGait::kStop;
  } else if (name == "step_in_place") {
    *out = ZeroCommandGait::kStepInPlace;
  } else {
    return false;
  }
  return true;
}

const char* zeroCommandGaitName(ZeroCommandGait gait) {
  return gait == ZeroCommandGait::kStepInPlace ? "step_in_place" : "stop";
}

bool parseStandingPushResponse(const std::string& name, StandingPushResponse* out) {
  if (name == "step") {
    *out = StandingPushResponse::kStep;
  } else if (name == "stand") {
    *out = StandingPushResponse::kStand;
  } else {
    return false;
  }
  return true;
}

const char* standingPushResponseName(StandingPushResponse response) {
  return response == StandingPushResponse::kStand ? "stand" : "step";
}

bool parseObstacleDistanceForm(const std::string& name, ObstacleDistanceForm* out) {
  if (name == "sole_clearance") {
    *out = ObstacleDistanceForm::kSoleClearance;
  } else if (name == "paper") {
    *out = ObstacleDistanceForm::kPaper;
  } else {
    return false;
  }
  return true;
}

const char* obstacleDistanceFormName(ObstacleDistanceForm form) {
  return form == ObstacleDistanceForm::kPaper ? "paper" : "sole_clearance";
}

bool parseObstacleLinearization(const std::string& name, ObstacleLinearization* out) {
  if (name == "step") {
    *out = ObstacleLinearization::kStep;
  } else if (name == "command_tangent") {
    *out = ObstacleLinearization::kCommandTangent;
  } else {
    return false;
  }
  return true;
}

const char* obstacleLinearizationName(ObstacleLinearization linearization) {
  return linearization == ObstacleLinearization::kStep ? "step" : "command_tangent";
}

void WalkingParameters::validate() const {
  requirePositive(com_height, "com_height");
  requirePositive(gravity, "gravity");
  requirePositive(sampling_period, "sampling_period");
  require(sampling_period >= 1e-3 && sampling_period <= 10.0, "sampling_period",
          "a duration in [0.001, 10] s", sampling_period);
  require(horizon_length >= 2 && horizon_length <= 200, "horizon_length", "an integer in [2, 200]",
          horizon_length);
  // Bounded before any product of them (no signed overflow).
  require(single_support_samples >= 1 && single_support_samples <= 1000,
          "single_support_samples", "an integer in [1, 1000]", single_support_samples);
  // The phase bookkeeping follows the paper (Sec. III-C1): NMPC samples never fall inside a
  // double support phase, which lasts exactly one sampling period.
  require(double_support_samples == 1, "double_support_samples",
          "1 (double support lasts one sampling period, paper Sec. III-C1)",
          double_support_samples);
  require(previewed_steps >= 1 && previewed_steps <= 10, "previewed_steps", "an integer in [1, 10]",
          previewed_steps);
  // Every previewed step must own at least one CoP sample and no sample may fall beyond the
  // last previewed step: N = nf * (samples per step), as the paper's N = 16, nf = 2.
  require(static_cast<long long>(horizon_length) ==
              static_cast<long long>(previewed_steps) * stepSamples(),
          "horizon_length",
          "previewed_steps * (single_support_samples + double_support_samples) = " +
              std::to_string(previewed_steps * stepSamples()),
          horizon_length);
  require(min_single_support_samples >= 1 &&
              min_single_support_samples <= single_support_samples,
          "min_single_support_samples", "an integer in [1, single_support_samples]",
          min_single_support_samples);
  requireNonNegative(push_step_capture_offset, "push_step_capture_offset");
  requireNonNegative(push_step_capture_jump, "push_step_capture_jump");
  require(push_step_single_support_samples >= min_single_support_samples &&
              push_step_single_support_samples <= single_support_samples,
          "push_step_single_support_samples",
          "an integer in [min_single_support_samples, single_support_samples]",
          push_step_single_support_samples);
  require(start_double_support_samples >= 1 && start_double_support_samples <= stepSamples(),
          "start_double_support_samples",
          "an integer in [1, single_support_samples + double_support_samples]",
          start_double_support_samples);
  require(push_start_double_support_samples >= 1 &&
              push_start_double_support_samples <= stepSamples(),
          "push_start_double_support_samples",
          "an integer in [1, single_support_samples + double_support_samples]",
          push_start_double_support_samples);
  require(push_step_swing_samples >= 1 && push_step_swing_samples <= single_support_samples,
          "push_step_swing_samples", "an integer in [1, single_support_samples]",
          push_step_swing_samples);
  requirePositive(control_period, "control_period");
  // At most 1000 control periods per sample: the ratio is converted to an integer.
  const double ratio = sampling_period / control_period;
  require(ratio >= 1.0 && ratio <= 1000.0 && std::abs(ratio - std::round(ratio)) < 1e-9,
          "control_period", "a divisor of sampling_period, at least sampling_period / 1000",
          control_period);
  requirePositive(foot_length, "foot_length");
  requirePositive(foot_width, "foot_width");
  requireNonNegative(ankle_height, "ankle_height");
  requireNonNegative(cop_margin_x, "cop_margin_x");
  requireNonNegative(cop_margin_y, "cop_margin_y");
  require(copHalfLength() > 0.0, "cop_margin_x", "less than half the foot length", cop_margin_x);
  require(copHalfWidth() > 0.0, "cop_margin_y", "less than half the foot width", cop_margin_y);
  requirePositive(initial_foot_separation, "initial_foot_separation");
  requirePositive(stop_foot_separation, "stop_foot_separation");
  requireNonNegative(obstacle_foot_radius, "obstacle_foot_radius");
  for (int i = 0; i < 5; ++i) {
    require(std::isfinite(feasibility_x[i]), "feasibility_x", "finite numbers", feasibility_x[i]);
    require(std::isfinite(feasibility_y[i]), "feasibility_y", "finite numbers", feasibility_y[i]);
  }
  ConvexPolygon polygon;
  std::string why;
  if (!polygon.setVertices(feasibilityVertices(FootSide::kLeft), &why)) {
    throw std::invalid_argument("walking parameter 'feasibility_x/feasibility_y': expected a convex "
                                "polygon, got one that is " + why);
  }
  const Eigen::Vector2d stop_step(0.0, stop_foot_separation);
  require(polygon.contains(stop_step, 1e-12), "stop_foot_separation",
          "a side-by-side step inside the feasibility polygon", stop_foot_separation);
  requirePositive(max_step_yaw_change, "max_step_yaw_change");
  requireNonNegative(max_landing_speed, "max_landing_speed");
  requireNonNegative(max_landing_yaw_rate, "max_landing_yaw_rate");
  requireNonNegative(max_swing_speed, "max_swing_speed");
  requireNonNegative(max_swing_acceleration, "max_swing_acceleration");
  requirePositive(weight_velocity, "weight_velocity");
  requirePositive(weight_yaw, "weight_yaw");
  require(velocity_window_samples >= 1 && velocity_window_samples <= horizon_length,
          "velocity_window_samples", "an integer in [1, horizon_length]", velocity_window_samples);
  requirePositive(weight_cop, "weight_cop");
  requirePositive(weight_jerk, "weight_jerk");
  requireNonNegative(step_height, "step_height");
  requireNonNegative(max_forward_velocity, "max_forward_velocity");
  requireNonNegative(max_lateral_velocity, "max_lateral_velocity");
  requireNonNegative(max_angular_velocity, "max_angular_velocity");
}

WalkingParameters WalkingParameters::withSingleSupport(int single_support) const {
  WalkingParameters w = *this;
  w.single_support_samples = single_support;
  w.horizon_length = previewed_steps * w.stepSamples();
  w.start_double_support_samples = std::min(start_double_support_samples, w.stepSamples());
  w.push_start_double_support_samples =
      std::min(push_start_double_support_samples, w.stepSamples());
  w.push_step_swing_samples = std::min(push_step_swing_samples, single_support);
  w.push_step_single_support_samples = std::min(push_step_single_support_samples, single_support);
  w.velocity_window_samples = std::min(velocity_window_samples, w.horizon_length);
  return w;
}

std::vector<Eigen::Vector2d> WalkingParameters::feasibilityVertices(FootSide side) const {
  std::vector<Eigen::Vector2d> vertices;
  const double sign = side == FootSide::kLeft ? 1.0 : -1.0;
  for (int i = 0; i < 5; ++i) vertices.emplace_back(feasibility_x[i], sign * feasibility_y[i]);
  return vertices;
}

double WalkingParameters::gaitSidewaysSpeed() const {
  const auto [narrowest, widest] = std::minmax_element(feasibility_y.begin(), feasibility_y.end());
  return (*widest - *narrowest) / (2.0 * stepDuration());
}

double WalkingParameters::leastStepWidth() const {
  double least = std::abs(feasibility_y[0]);
  for (const double y : feasibility_y) least = std::min(least, std::abs(y));
  return least;
}

}  // namespace wpg
