// PatternGenerator::previewPlan: the prediction of the last NMPC iteration over its horizon
// (nmpc_plan.hpp), computed on demand from the solver's plan so that the iteration itself
// pays nothing for it.
#include <algorithm>

#include "wpg/lipm_prediction.hpp"
#include "wpg/pattern_generator.hpp"

namespace wpg {

int PatternGenerator::maxPreviewSamples() const {
  int longest = 0;
  for (const auto& cadence : cadences_)
    longest = std::max(longest, cadence->model.layout().horizon);
  return longest;
}

void PatternGenerator::previewPlan(NmpcPlan& out) const {
  const NmpcModel& model = *model_;
  const NmpcLayout& L = model.layout();
  const PhaseStructure& phase = problem_->phase;
  const double T = model.parameters().sampling_period;
  if (out.capacity() < maxPreviewSamples() || out.step_pose.rows() != L.steps ||
      out.active_rows.size() != model.familyCount()) {
    out.resize(maxPreviewSamples(), L.steps, model.familyCount());
  }
  out.clear(time_);
  out.sampling_period = T;
  out.samples = L.horizon;
  const Eigen::VectorXd& U = solver_->plan();
  // Eq. (2) sample by sample with the plan's jerks, from the state the iteration solved from
  // (the problem's, after any re-initialisation by the dynamic filter); eq. (3) for the CoP.
  // The same polynomial the online generator integrates period by period (integrateJerk).
  const double h_over_g = model.prediction().height_over_gravity;
  Eigen::Vector3d state[2] = {problem_->com_x, problem_->com_y};
  for (int j = 0; j < L.horizon; ++j) {
    for (int axis = 0; axis < 2; ++axis) {
      const double jerk = U((axis == 0 ? L.jerkX() : L.jerkY()) + j);
      integrateJerk(state[axis], jerk, T);
      out.jerk(j, axis) = jerk;
      out.com_position(j, axis) = state[axis](0);
      out.com_velocity(j, axis) = state[axis](1);
      out.com_acceleration(j, axis) = state[axis](2);
      out.cop(j, axis) = state[axis](0) - h_over_g * state[axis](2);
    }
  }
  // Step i becomes the support at the first sample whose CoP stands on it (row_step, eq. 4):
  // r samples remain on the current support, then S per step (the swing's touchdown for i =
  // 0, as readPlan's landing_time). Standing: no step within the horizon.
  const int S = model.parameters().stepSamples();
  const bool walking = phase.pattern != model.standingPattern();
  for (int i = 0; i < L.steps; ++i) {
    out.step_pose(i, 0) = U(L.stepX() + i);
    out.step_pose(i, 1) = U(L.stepY() + i);
    out.step_pose(i, 2) = U(L.stepYaw() + i);
    if (walking) out.step_landing_time(i) = time_ + (phase.pattern + i * S) * T;
    out.step_side(i) = static_cast<int>(phase.stepSide(i));
  }
  const int* active = solver_->activeRows();
  for (int k = 0; k < solver_->activeCount(); ++k) {
    const int family = model.familyOfRow(active[k]);
    if (family >= 0) ++out.active_rows(family);
  }
}

}  // namespace wpg
