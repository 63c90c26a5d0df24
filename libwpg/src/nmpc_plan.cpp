// One NMPC iteration's prediction and a walk's log of them (nmpc_plan.hpp).
#include "wpg/nmpc_plan.hpp"

namespace wpg {
namespace {

// What fills the rows beyond an iteration's samples and a standing robot's landing times:
// zero, so that every stored number is finite (datasets/SCHEMA.md); the counts say what holds.
constexpr double kNone = 0.0;

void appendRows(const Eigen::Matrix<double, Eigen::Dynamic, 2>& from, int samples, int width,
                std::vector<double>& to) {
  for (int j = 0; j < width; ++j) {
    const bool in = j < samples && j < from.rows();
    to.push_back(in ? from(j, 0) : kNone);
    to.push_back(in ? from(j, 1) : kNone);
  }
}

}  // namespace

void NmpcPlan::resize(int max_samples, int steps, int families) {
  for (auto* m : {&com_position, &com_velocity, &com_acceleration, &cop, &jerk})
    m->resize(max_samples, 2);
  step_pose.resize(steps, 3);
  step_landing_time.resize(steps);
  step_side.resize(steps);
  active_rows.resize(families);
  clear(0.0);
}

void NmpcPlan::clear(double t) {
  time = t;
  samples = 0;
  for (auto* m : {&com_position, &com_velocity, &com_acceleration, &cop, &jerk})
    m->setConstant(kNone);
  step_pose.setConstant(kNone);
  step_landing_time.setConstant(kNone);
  step_side.setZero();
  active_rows.setZero();
}

void PlanLog::reserve(int max_samples_, int steps_, int families_, double sampling_period_,
                      std::size_t iterations) {
  max_samples = max_samples_;
  steps = steps_;
  families = families_;
  sampling_period = sampling_period_;
  const std::size_t per_sample = iterations * static_cast<std::size_t>(2 * max_samples);
  samples.reserve(iterations);
  for (auto* v : {&com_position, &com_velocity, &com_acceleration, &jerk, &cop})
    v->reserve(per_sample);
  step.reserve(iterations * static_cast<std::size_t>(4 * steps));
  step_side.reserve(iterations * static_cast<std::size_t>(steps));
  active_rows.reserve(iterations * static_cast<std::size_t>(families));
}

void PlanLog::append(const NmpcPlan& plan) {
  samples.push_back(plan.samples);
  appendRows(plan.com_position, plan.samples, max_samples, com_position);
  appendRows(plan.com_velocity, plan.samples, max_samples, com_velocity);
  appendRows(plan.com_acceleration, plan.samples, max_samples, com_acceleration);
  appendRows(plan.jerk, plan.samples, max_samples, jerk);
  appendRows(plan.cop, plan.samples, max_samples, cop);
  for (int s = 0; s < steps; ++s) {
    const bool in = s < plan.step_pose.rows();
    step.push_back(in ? plan.step_landing_time(s) : kNone);
    for (int c = 0; c < 3; ++c) step.push_back(in ? plan.step_pose(s, c) : kNone);
    step_side.push_back(in ? static_cast<std::uint8_t>(plan.step_side(s)) : 0);
  }
  for (int f = 0; f < families; ++f)
    active_rows.push_back(f < plan.active_rows.size() ? plan.active_rows(f) : 0);
}

}  // namespace wpg
