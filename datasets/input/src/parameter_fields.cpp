// The parameter tables of parameter_fields.hpp and their readers and emitters.
#include "parameter_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::datasets::detail {
namespace {

// The values of a choice, from its `expected` text ("a, b or c").
std::vector<std::string> choiceNames(const WalkingChoice& choice) {
  std::vector<std::string> names;
  std::string text = choice.expected;
  for (std::size_t at; (at = text.find(" or ")) != std::string::npos;) text.replace(at, 4, ", ");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(", ", start), text.size());
    names.push_back(text.substr(start, end - start));
    start = end + 2;
  }
  return names;
}

WalkingField numberField(const char* name, double WalkingParameters::*member) {
  return {name, member, nullptr, nullptr, nullptr};
}
WalkingField integerField(const char* name, int WalkingParameters::*member) {
  return {name, nullptr, member, nullptr, nullptr};
}
WalkingField polygonField(const char* name, std::array<double, 5> WalkingParameters::*member) {
  return {name, nullptr, nullptr, member, nullptr};
}
WalkingField choiceField(const char* name, const WalkingChoice* choice) {
  return {name, nullptr, nullptr, nullptr, choice};
}

const WalkingChoice kHeadingReference{
    "support_foot or command",
    [](const std::string& name, WalkingParameters* p) {
      return parseHeadingReference(name, &p->heading_reference);
    },
    [](const WalkingParameters& p) { return headingReferenceName(p.heading_reference); }};

const WalkingChoice kVelocityTracking{
    "instantaneous, window or with_sway",
    [](const std::string& name, WalkingParameters* p) {
      return parseVelocityTracking(name, &p->velocity_tracking);
    },
    [](const WalkingParameters& p) { return velocityTrackingName(p.velocity_tracking); }};

const WalkingChoice kObstacleDistanceForm{
    "sole_clearance or paper",
    [](const std::string& name, WalkingParameters* p) {
      return parseObstacleDistanceForm(name, &p->obstacle_distance_form);
    },
    [](const WalkingParameters& p) { return obstacleDistanceFormName(p.obstacle_distance_form); }};

const WalkingChoice kObstacleLinearization{
    "step or command_tangent",
    [](const std::string& name, WalkingParameters* p) {
      return parseObstacleLinearization(name, &p->obstacle_linearization);
    },
    [](const WalkingParameters& p) { return obstacleLinearizationName(p.obstacle_linearization); }};

const WalkingChoice kObstacleLandingLinearization{
    "step or command_tangent",
    [](const std::string& name, WalkingParameters* p) {
      return parseObstacleLinearization(name, &p->obstacle_landing_linearization);
    },
    [](const WalkingParameters& p) {
      return obstacleLinearizationName(p.obstacle_landing_linearization);
    }};

const WalkingChoice kZeroCommandGait{
    "stop or step_in_place",
    [](const std::string& name, WalkingParameters* p) {
      return parseZeroCommandGait(name, &p->zero_command);
    },
    [](const WalkingParameters& p) { return zeroCommandGaitName(p.zero_command); }};

const WalkingChoice kStepTiming{
    "fixed or adaptive",
    [](const std::string& name, WalkingParameters* p) {
      return parseStepTiming(name, &p->step_timing);
    },
    [](const WalkingParameters& p) { return stepTimingName(p.step_timing); }};

const WalkingChoice kStandingPushResponse{
    "step or stand",
    [](const std::string& name, WalkingParameters* p) {
      return parseStandingPushResponse(name, &p->standing_push_response);
    },
    [](const WalkingParameters& p) { return standingPushResponseName(p.standing_push_response); }};

}  // namespace

void emitNumbers(YAML::Emitter& out, const double* values, int count) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < count; ++i) emitScalar(out, formatNumber(values[i]));
  out << YAML::EndSeq;
}

const std::vector<WalkingField>& walkingFields() {
  using P = WalkingParameters;
  static const std::vector<WalkingField> fields = {
      numberField("com_height", &P::com_height),
      numberField("gravity", &P::gravity),
      numberField("sampling_period", &P::sampling_period),
      integerField("horizon_length", &P::horizon_length),
      integerField("single_support_samples", &P::single_support_samples),
      integerField("double_support_samples", &P::double_support_samples),
      integerField("previewed_steps", &P::previewed_steps),
      choiceField("step_timing", &kStepTiming),
      integerField("min_single_support_samples", &P::min_single_support_samples),
      numberField("push_step_capture_offset", &P::push_step_capture_offset),
      numberField("push_step_capture_jump", &P::push_step_capture_jump),
      integerField("push_step_single_support_samples", &P::push_step_single_support_samples),
      integerField("start_double_support_samples", &P::start_double_support_samples),
      choiceField("zero_command", &kZeroCommandGait),
      choiceField("standing_push_response", &kStandingPushResponse),
      integerField("push_start_double_support_samples", &P::push_start_double_support_samples),
      integerField("push_step_swing_samples", &P::push_step_swing_samples),
      choiceField("velocity_tracking", &kVelocityTracking),
      integerField("velocity_window_samples", &P::velocity_window_samples),
      choiceField("heading_reference", &kHeadingReference),
      numberField("control_period", &P::control_period),
      numberField("foot_length", &P::foot_length),
      numberField("foot_width", &P::foot_width),
      numberField("ankle_height", &P::ankle_height),
      numberField("cop_margin_x", &P::cop_margin_x),
      numberField("cop_margin_y", &P::cop_margin_y),
      numberField("initial_foot_separation", &P::initial_foot_separation),
      numberField("stop_foot_separation", &P::stop_foot_separation),
      numberField("obstacle_foot_radius", &P::obstacle_foot_radius),
      choiceField("obstacle_distance_form", &kObstacleDistanceForm),
      choiceField("obstacle_linearization", &kObstacleLinearization),
      choiceField("obstacle_landing_linearization", &kObstacleLandingLinearization),
      polygonField("feasibility_x", &P::feasibility_x),
      polygonField("feasibility_y", &P::feasibility_y),
      numberField("max_step_yaw_change", &P::max_step_yaw_change),
      numberField("max_landing_speed", &P::max_landing_speed),
      numberField("max_landing_yaw_rate", &P::max_landing_yaw_rate),
      numberField("max_swing_speed", &P::max_swing_speed),
      numberField("max_swing_acceleration", &P::max_swing_acceleration),
      numberField("weight_velocity", &P::weight_velocity),
      numberField("weight_yaw", &P::weight_yaw),
      numberField("weight_cop", &P::weight_cop),
      numberField("weight_jerk", &P::weight_jerk),
      numberField("step_height", &P::step_height),
      numberField("max_forward_velocity", &P::max_forward_velocity),
      numberField("max_lateral_velocity", &P::max_lateral_velocity),
      numberField("max_angular_velocity", &P::max_angular_velocity),
  };
  return fields;
}

std::vector<std::string> walkingFieldNames() {
  std::vector<std::string> names;
  for (const WalkingField& field : walkingFields()) names.push_back(field.name);
  return names;
}

namespace {

// The walking parameters that are lengths [m]: bounded by kMaxLength (input_limits.hpp).
bool isLengthField(const std::string& name) {
  static const std::set<std::string> names = {
      "com_height",     "foot_length",           "foot_width",           "ankle_height",
      "cop_margin_x",   "cop_margin_y",          "initial_foot_separation",
      "stop_foot_separation", "obstacle_foot_radius", "feasibility_x", "feasibility_y",
      "step_height"};
  return names.count(name) > 0;
}

}  // namespace

void readWalkingFields(const Entries& entries, const std::string& prefix, bool require_all,
                       const Source& source, WalkingParameters* parameters) {
  for (const WalkingField& field : walkingFields()) {
    const YAML::Node node = entry(entries, field.name);
    const std::string key = childKey(prefix, field.name);
    if (!node.IsDefined()) {
      if (require_all) source.fail(key, "a value (every walking parameter is required here)", node);
      continue;
    }
    if (field.number) {
      parameters->*field.number = isLengthField(field.name)
                                      ? readLength(node, key, "a length in m", source)
                                      : readNumber(node, key, "a number", source);
    } else if (field.integer) {
      parameters->*field.integer =
          readInteger(node, key, std::numeric_limits<int>::min(), "an integer", source);
    } else if (field.choice) {
      // Case ignored (`Command_Tangent`); a value near a known one is named in the message.
      if (!node.IsScalar() || !field.choice->parse(asciiLower(node.Scalar()), parameters)) {
        const std::string near =
            node.IsScalar() ? didYouMean(node.Scalar(), choiceNames(*field.choice)) : "";
        source.failWith(key, std::string("expected ") + field.choice->expected + ", got " +
                                 describe(node) + near);
      }
    } else {
      const Eigen::Matrix<double, 5, 1> values =
          readLengthVector<5>(node, key, "a list of 5 numbers [m]", source);
      for (int i = 0; i < 5; ++i) (parameters->*field.polygon)[i] = values[i];
    }
  }
}

void emitWalkingFields(YAML::Emitter& out, const WalkingParameters& parameters) {
  for (const WalkingField& field : walkingFields()) {
    emitKey(out, field.name);
    if (field.number) {
      emitScalar(out, formatNumber(parameters.*field.number));
    } else if (field.integer) {
      out << parameters.*field.integer;
    } else if (field.choice) {
      emitScalar(out, field.choice->name(parameters));
    } else {
      emitNumbers(out, (parameters.*field.polygon).data(), 5);
    }
  }
}

const std::vector<SettingField<GeneratorSettings>>& generatorSettingFields() {
  using G = GeneratorSettings;
  static const std::vector<SettingField<G>> fields = {
      integerSetting("sqp_iterations", &G::sqp_iterations, 0,
                     "an integer in [0, 1000] (1 = real-time iteration, 0 = to convergence)", 1000),
      integerSetting("max_sqp_iterations", &G::max_sqp_iterations, 1, "an integer in [1, 1000]",
                     1000),
      positiveSetting("sqp_tolerance", &G::sqp_tolerance, "a positive number"),
      integerSetting("max_qp_iterations", &G::max_qp_iterations, 1, "an integer in [1, 100000]",
                     100000),
      positiveSetting("slack_weight", &G::slack_weight, "a positive number"),
      positiveSetting("fall_capture_distance", &G::fall_capture_distance,
                      "a positive distance of at most 1e4 m", kMaxLength),
      integerSetting("max_obstacles_in_qp", &G::max_obstacles_in_qp, 0,
                     "an integer in [0, 32] (obstacles in the QP at each sample)", 32),
      positiveSetting("obstacle_reach", &G::obstacle_reach, "a positive distance of at most 1e4 m",
                      kMaxLength),
      positiveSetting("max_detour", &G::max_detour, "a positive distance of at most 1e4 m",
                      kMaxLength),
      integerSetting("blocked_window_cycles", &G::blocked_window_cycles, 1,
                     "an integer in [1, 100] (gait cycles of the robot's nominal steps)",
                     kMaxBlockedWindowCycles),
      // (0, 1): the largest double below 1 is the bound (a ratio of 1 or more is refused).
      positiveSetting("blocked_progress", &G::blocked_progress, "a ratio in (0, 1)",
                      std::nextafter(1.0, 0.0)),
  };
  return fields;
}

const std::vector<SettingField<PreviewControlSettings>>& filterSettingFields() {
  using F = PreviewControlSettings;
  static const std::vector<SettingField<F>> fields = {
      positiveSetting("error_weight", &F::error_weight, "a positive weight (Qe)"),
      positiveSetting("input_weight", &F::input_weight, "a positive weight (R)"),
      positiveSetting("preview_time", &F::preview_time,
                      "a positive duration of at most 10 seconds", 10.0),
  };
  return fields;
}

}  // namespace wpg::datasets::detail
