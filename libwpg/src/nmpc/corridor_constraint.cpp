// The corridor constraint family (wpg/nmpc/builtin_extensions.hpp): CoP samples and step
// centres between two walls y = right and y = left.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "wpg/nmpc/builtin_extensions.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

class CorridorConstraint final : public NamedConstraintFamily {
 public:
  CorridorConstraint(double left, double right, double cop_margin)
      : NamedConstraintFamily("corridor", "m", RelaxationGroup::kObstacle),
        left_(left),
        right_(right),
        cop_margin_(cop_margin) {}

  int rowCount(const NmpcModel& model) const override {
    return CorridorRows::count(model.layout().horizon, model.layout().steps);
  }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const LipmPrediction& P = model.prediction();
    const auto jerk_y = U.segment(L.jerkY(), L.horizon);
    for (int j = 0; j < L.horizon; ++j) {
      // z_y of sample j (eq. 3): lower triangular in the jerks
      const double zy = P.cop_state.row(j).dot(problem.com_y) +
                        P.cop_jerk.row(j).head(j + 1).dot(jerk_y.head(j + 1));
      g(CorridorRows::copRow(j, true)) = zy - (left_ - cop_margin_);
      g(CorridorRows::copRow(j, false)) = right_ + cop_margin_ - zy;
      if (!jacobian) continue;
      for (int k = 0; k <= j; ++k) {
        (*jacobian)(CorridorRows::copRow(j, true), L.jerkY() + k) = P.cop_jerk(j, k);
        (*jacobian)(CorridorRows::copRow(j, false), L.jerkY() + k) = -P.cop_jerk(j, k);
      }
    }
    for (int i = 0; i < L.steps; ++i) {
      const int upper = CorridorRows::stepRow(L.horizon, i, true);
      const int lower = CorridorRows::stepRow(L.horizon, i, false);
      if (problem.phase.step_fixed(i)) {  // fixed by equality: nothing to decide
        g(upper) = g(lower) = -1.0;
        continue;
      }
      const double y = U(L.stepY() + i);
      g(upper) = y - left_;
      g(lower) = right_ - y;
      if (!jacobian) continue;
      (*jacobian)(upper, L.stepY() + i) = 1.0;
      (*jacobian)(lower, L.stepY() + i) = -1.0;
    }
  }

  int jerkSamplesOfRow(const NmpcModel& model, int row) const override {
    return row < 2 * model.layout().horizon ? row / 2 + 1 : 0;
  }

  // A CoP sample's rows become the sample before's; a step's the step before's once a step is
  // completed (step 0's leave the horizon).
  int shiftedRow(const NmpcModel& model, int row, bool step_completed) const override {
    const int N = model.layout().horizon;
    const bool left = row % 2 == 0;
    if (row < 2 * N) {
      const int sample = row / 2;
      return sample == 0 ? -1 : CorridorRows::copRow(sample - 1, left);
    }
    const int step = (row - 2 * N) / 2;
    if (!step_completed) return row;
    return step == 0 ? -1 : CorridorRows::stepRow(N, step - 1, left);
  }

 private:
  double left_, right_;  // [m] world y of the walls
  // [m] how far inside the walls the CoP samples are held: the rows bound the CoP at the NMPC
  // samples only, and between two samples (a cubic of the jerk held over the period) it bulges
  // past the line through them: by 1.3 mm on corridor.yaml with no margin.
  double cop_margin_;
};

std::string metres(double value) {
  std::ostringstream text;
  text << value << " m";
  return text.str();
}

// The walls must leave room for the first step of either foot: the feet start
// initial_foot_separation apart, which may be less than the least step width (HRP-2: 0.19 m
// against 0.2 m), so a corridor just wider than leastStepWidth can still hold no first step
// (both feet would have to move out before either may land). Which foot swings first
// depends on the command and on pushes, so both must fit. A step lands in the feasibility
// polygon of the support foot's frame, the start yaw here; its lowest (left step) or highest
// (right step) world y is at one of the polygon's vertices, the polygon being convex.
void checkFirstStepFits(double left, double right, const ExtensionContext& context) {
  const WalkingParameters& w = context.walking;
  const double yaw = context.start_pose.z();
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double half = 0.5 * w.initial_foot_separation;
  // Start feet (world y): the left foot at +half along the robot's y axis.
  const double left_foot = context.start_pose.y() + c * half;
  const double right_foot = context.start_pose.y() - c * half;
  double left_step_lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& v : w.feasibilityVertices(FootSide::kLeft)) {
    left_step_lowest = std::min(left_step_lowest, right_foot + s * v.x() + c * v.y());
  }
  double right_step_highest = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& v : w.feasibilityVertices(FootSide::kRight)) {
    right_step_highest = std::max(right_step_highest, left_foot + s * v.x() + c * v.y());
  }
  constexpr double kRounding = 1e-9;  // metres: 0.2 - 0.095 is not 0.105 in doubles
  if (left < left_step_lowest - kRounding) {
    throw ExtensionError("left", "expected a left wall at y >= " + metres(left_step_lowest) +
                                     ": the first step of the left foot lands there at the "
                                     "nearest (the feet start " +
                                     metres(w.initial_foot_separation) + " apart), got " +
                                     metres(left));
  }
  if (right > right_step_highest + kRounding) {
    throw ExtensionError("right", "expected a right wall at y <= " +
                                      metres(right_step_highest) +
                                      ": the first step of the right foot lands there at the "
                                      "nearest (the feet start " +
                                      metres(w.initial_foot_separation) + " apart), got " +
                                      metres(right));
  }
}

}  // namespace

std::unique_ptr<ConstraintFamily> makeCorridorConstraint(double left, double right,
                                                         double cop_margin) {
  return std::make_unique<CorridorConstraint>(left, right, cop_margin);
}

ConstraintFamilySpec corridorConstraintSpec() {
  ConstraintFamilySpec spec;
  spec.name = "corridor";
  spec.description = "step centres and CoP between the walls y = right and y = left (world)";
  spec.parameters = {{"left", "m", "the world y of the left wall", true, 0.0},
                     {"right", "m", "the world y of the right wall", true, 0.0},
                     {"cop_margin", "m",
                      "how far inside the walls the CoP is held at the NMPC samples, so that "
                      "it stays between them from one sample to the next",
                      false, kCorridorCopMargin}};
  spec.check = [](const ExtensionArguments& a, const ExtensionContext& context) {
    const double width = a.at("left") - a.at("right");
    const double least = context.walking.leastStepWidth();
    if (!(width >= least)) {
      throw ExtensionError("left", "expected left - right of at least " + metres(least) +
                                       " (two feet side by side: the least step width of the "
                                       "robot's feasibility polygon; its sole is " +
                                       metres(context.walking.foot_width) + " wide), got " +
                                       metres(width));
    }
    const double margin = a.at("cop_margin");
    if (!(margin >= 0.0 && margin < 0.5 * width)) {
      throw ExtensionError("cop_margin", "expected a margin >= 0 m and below half the "
                                         "corridor's width, got " + metres(margin));
    }
    const double y = context.start_pose.y();
    if (!(y < a.at("left") && y > a.at("right"))) {
      throw ExtensionError("left", "expected walls on either side of the walk's start (y = " +
                                       metres(y) + ")");
    }
    checkFirstStepFits(a.at("left"), a.at("right"), context);
  };
  spec.make = [](const ExtensionArguments& a, const ExtensionContext&) {
    return std::shared_ptr<const ConstraintFamily>(
        makeCorridorConstraint(a.at("left"), a.at("right"), a.at("cop_margin")));
  };
  return spec;
}

}  // namespace wpg
