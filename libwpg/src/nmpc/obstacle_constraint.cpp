// Obstacle avoidance, paper eq. (18)-(19): one row per previewed step and obstacle slot (the
// obstacles near the steps, chosen at every sample), with libwpg's exact 2-D distances. The
// bound is WalkingParameters::obstacle_distance_form's: the whole sole out of the margin
// (default) or the paper's R^2 + m^2 as written. A row is either eq. (18) itself (a circle's
// (F - c)^2 >= r^2, a box's or polygon's signed distance), which the solver linearizes at the
// step (the paper's linearization), or, when the problem carries a normal for its slot
// (obstacle_linearization: command_tangent, wpg/obstacle_tangent.hpp), the supporting
// half-plane of that normal on the same grown shape.
#include <cmath>

#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

class ObstacleConstraint final : public NamedConstraintFamily {
 public:
  ObstacleConstraint() : NamedConstraintFamily("obstacle", "m", RelaxationGroup::kObstacle) {}
  int rowCount(const NmpcModel& model) const override {
    return ObstacleRows::of(model).count(model);
  }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const ObstacleRows rows = ObstacleRows::of(model);
    if (jacobian) nmpc_internal::clearStepColumns(*jacobian, L);  // rewritesJacobianRows
    for (int i = 0; i < L.steps; ++i) {
      for (int k = 0; k < rows.slots; ++k) {
        const int row = rows.row(i, k);
        const int index = problem.obstacle_slot(k);
        if (index < 0 || !problem.obstacles || problem.phase.step_fixed(i)) {
          g(row) = -1.0;  // empty slot, or a step that can no longer move
          continue;
        }
        const Obstacle& obstacle = problem.obstacles->obstacle(index);
        const Eigen::Vector2d F(U(L.stepX() + i), U(L.stepY() + i));
        const WalkingParameters& w = model.parameters();
        Eigen::Vector2d dg;
        // The next landing's own half-plane, when it has one (obstacle_landing_linearization:
        // step, facing the planned landing); else the sample's border.
        const bool own = i == 0 && !problem.obstacle_landing_normal.col(k).isZero();
        const auto normal =
            own ? problem.obstacle_landing_normal.col(k) : problem.obstacle_normal.col(k);
        if (!normal.isZero()) {
          // command_tangent linearization (wpg/obstacle_tangent.hpp): the supporting
          // half-plane n.F >= h(n) + radius of the obstacle (or group) grown by the
          // step-centre margin, n and the offset fixed for the sample: g = offset - n.F <= 0,
          // linear in F (metres, the distance missing to the border), inside eq. (18)'s set,
          // for every shape.
          g(row) = (own ? problem.obstacle_landing_offset(k) : problem.obstacle_offset(k)) -
                   normal.dot(F);
          dg = -normal;
        } else if (obstacle.type == ObstacleType::kCircle) {
          // r^2 is R^2 + m^2 in the paper's form (eq. 18 as written, the step a point),
          // (R + m + obstacle_foot_radius)^2 in the default sole_clearance form (the whole sole
          // out of the margin circle).
          const Eigen::Vector2d d = F - obstacle.center;
          const double R = obstacle.radius, m = obstacle.margin;
          const double r_squared = w.obstacle_distance_form == ObstacleDistanceForm::kPaper
                                       ? R * R + m * m
                                       : (R + m + w.obstacle_foot_radius) *
                                             (R + m + w.obstacle_foot_radius);
          const double r = std::sqrt(r_squared);
          // eq. (18): (F - c)^2 >= r^2, written (r^2 - |F - c|^2) / (2 r) <= 0: the same
          // feasible set and linearization up to a positive factor, in metres (to first
          // order the distance missing to the circle), so that the relaxation slack of this
          // family has one unit whatever the shapes.
          g(row) = (r_squared - d.squaredNorm()) / (2.0 * r);
          dg = -d / r;
        } else {
          // d(F) >= margin (+ obstacle_foot_radius in the sole_clearance form)  <=>
          // g = stepCentreMargin - d(F) <= 0, with d the signed distance to the convex shape
          Eigen::Vector2d gradient;
          g(row) = stepCentreMargin(obstacle, w) -
                   problem.obstacles->signedDistance(index, F, &gradient);
          dg = -gradient;
        }
        if (jacobian) {
          (*jacobian)(row, L.stepX() + i) = dg.x();
          (*jacobian)(row, L.stepY() + i) = dg.y();
        }
      }
    }
  }

  bool rewritesJacobianRows() const override { return true; }

  // Step i becomes step i - 1 when a step was completed (step 0 has landed: its rows leave);
  // slot k stays slot k (it keeps its obstacle only approximately: the selection is redone at
  // every sample, a warm-start guess is a guess).
  int jerkSamplesOfRow(const NmpcModel&, int) const override { return 0; }  // steps only

  int shiftedRow(const NmpcModel& model, int row, bool step_completed) const override {
    const ObstacleRows rows = ObstacleRows::of(model);
    if (!step_completed || rows.slots == 0) return rows.slots == 0 ? -1 : row;
    const int step = row / rows.slots, slot = row % rows.slots;
    return step == 0 ? -1 : rows.row(step - 1, slot);
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeObstacleConstraint() {
  return std::make_unique<ObstacleConstraint>();
}

}  // namespace wpg
