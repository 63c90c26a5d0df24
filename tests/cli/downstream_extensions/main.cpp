// Extends the NMPC from outside wpg (docs/extending.md): a `lane` constraint family (footstep
// centres and CoP samples between two walls parallel to the world x axis) and a `face_point`
// cost term (each previewed step's yaw towards a point), registered by name, their Jacobians
// checked by central differences, then one walk with both. Exits 1 on any failed check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <wpg/nmpc.hpp>
#include <wpg/walk_generator.hpp>

namespace {

// g = z_y - left <= 0, right - z_y <= 0 per CoP sample j (z = Pzs c_hat + Pzu jerk, eq. 3);
// then F_y - left <= 0, right - F_y <= 0 per free previewed step.
class Lane final : public wpg::NamedConstraintFamily {
 public:
  Lane(double left, double right)
      : NamedConstraintFamily("lane", "m", wpg::RelaxationGroup::kObstacle),
        left_(left), right_(right) {}
  int rowCount(const wpg::NmpcModel& model) const override {
    return 2 * model.layout().horizon + 2 * model.layout().steps;
  }
  void evaluate(const wpg::NmpcModel& model, const wpg::NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                wpg::JacobianRows* jacobian) const override {
    const wpg::NmpcLayout& L = model.layout();
    const wpg::LipmPrediction& P = model.prediction();
    for (int j = 0; j < L.horizon; ++j) {
      const double zy = P.cop_state.row(j).dot(problem.com_y) +
                        P.cop_jerk.row(j).head(j + 1).dot(U.segment(L.jerkY(), j + 1));
      g(2 * j) = zy - left_;
      g(2 * j + 1) = right_ - zy;
      for (int k = 0; jacobian && k <= j; ++k) {
        (*jacobian)(2 * j, L.jerkY() + k) = P.cop_jerk(j, k);
        (*jacobian)(2 * j + 1, L.jerkY() + k) = -P.cop_jerk(j, k);
      }
    }
    for (int i = 0; i < L.steps; ++i) {
      const int row = 2 * L.horizon + 2 * i;
      if (problem.phase.step_fixed(i)) {  // fixed by equality: inactive
        g(row) = g(row + 1) = -1.0;
        continue;
      }
      g(row) = U(L.stepY() + i) - left_;
      g(row + 1) = right_ - U(L.stepY() + i);
      if (!jacobian) continue;
      (*jacobian)(row, L.stepY() + i) = 1.0;
      (*jacobian)(row + 1, L.stepY() + i) = -1.0;
    }
  }
  int jerkSamplesOfRow(const wpg::NmpcModel& model, int row) const override {
    return row < 2 * model.layout().horizon ? row / 2 + 1 : 0;
  }
  int shiftedRow(const wpg::NmpcModel& model, int row, bool step_completed) const override {
    const int N = model.layout().horizon;
    if (row < 2 * N) return row < 2 ? -1 : row - 2;         // sample j -> j - 1
    if (!step_completed) return row;                       // the same step
    return row < 2 * N + 2 ? -1 : row - 2;                 // step i -> i - 1
  }

 private:
  double left_, right_;
};

// r_i = sqrt(weight) (theta_i - atan2(y - F_y, x - F_x)), wrapped to [-pi, pi).
class FacePoint final : public wpg::CostTerm {
 public:
  FacePoint(double x, double y, double weight) : x_(x), y_(y), scale_(std::sqrt(weight)) {}
  const char* name() const override { return "face_point"; }
  int residualCount(const wpg::NmpcModel& model) const override { return model.layout().steps; }
  void evaluate(const wpg::NmpcModel& model, const wpg::NmpcProblem&,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                Eigen::Ref<Eigen::MatrixXd>* jacobian) const override {
    const wpg::NmpcLayout& L = model.layout();
    for (int i = 0; i < L.steps; ++i) {
      const double dx = x_ - U(L.stepX() + i), dy = y_ - U(L.stepY() + i);
      const double d2 = dx * dx + dy * dy;
      r(i) = scale_ * std::remainder(U(L.stepYaw() + i) - std::atan2(dy, dx), 2.0 * M_PI);
      if (!jacobian) continue;
      (*jacobian)(i, L.stepYaw() + i) = scale_;
      (*jacobian)(i, L.stepX() + i) = -scale_ * dy / d2;
      (*jacobian)(i, L.stepY() + i) = scale_ * dx / d2;
    }
  }

 private:
  double x_, y_, scale_;
};

void registerExtensions() {
  wpg::ConstraintFamilySpec lane;
  lane.name = "lane";
  lane.description = "footsteps and CoP between y = right and y = left";
  lane.parameters = {{"left", "m", "the left wall's y", true, 0.0},
                     {"right", "m", "the right wall's y", true, 0.0}};
  lane.check = [](const wpg::ExtensionArguments& a, const wpg::ExtensionContext& context) {
    if (!(a.at("left") - a.at("right") >= context.walking.leastStepWidth()))
      throw wpg::ExtensionError("left", "expected a lane wider than two feet");
  };
  lane.make = [](const wpg::ExtensionArguments& a, const wpg::ExtensionContext&) {
    return std::shared_ptr<const wpg::ConstraintFamily>(
        std::make_shared<Lane>(a.at("left"), a.at("right")));
  };
  wpg::registerConstraintFamily(lane);

  wpg::CostTermSpec face;
  face.name = "face_point";
  face.description = "each previewed step's yaw towards (x, y)";
  face.parameters = {{"x", "m", "the point's x", true, 0.0},
                     {"y", "m", "the point's y", true, 0.0},
                     {"weight", "1/rad^2", "the weight", false, 100.0}};
  face.make = [](const wpg::ExtensionArguments& a, const wpg::ExtensionContext&) {
    return std::shared_ptr<const wpg::CostTerm>(
        std::make_shared<FacePoint>(a.at("x"), a.at("y"), a.at("weight")));
  };
  wpg::registerCostTerm(face);
}

bool check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  return ok;
}

}  // namespace

int main() {
  registerExtensions();
  bool ok = true;

  // Central differences of both, at a plan and a problem of the robot's model.
  const wpg::WalkingParameters w;
  const wpg::ExtensionContext context{w, Eigen::Vector3d::Zero()};
  wpg::NmpcModel model(w);
  model.addConstraintFamily(wpg::makeConstraintFamily({"lane", {{"left", 0.3}, {"right", -0.3}}},
                                                      context));
  model.addCostTerm(wpg::makeCostTerm({"face_point", {{"x", 4.0}, {"y", 2.0}}}, context));
  wpg::NmpcProblem problem = model.makeProblem();
  model.rowStepsOf(3, problem.phase.row_step);
  problem.phase.pattern = 3;
  problem.com_y = Eigen::Vector3d(0.05, 0.1, -0.3);
  Eigen::VectorXd U = Eigen::VectorXd::LinSpaced(model.layout().variableCount(), -0.7, 0.9);
  const int lane = model.findFamily("lane");
  ok &= check(lane >= 0 && wpg::checkConstraintJacobian(model, problem, U, lane).worst <= 1e-6,
              "lane's Jacobian matches central differences");
  ok &= check(wpg::checkCostJacobian(model, problem, U).worst <= 1e-6,
              "face_point's Jacobian matches central differences");

  // A walk drifting left (0.05 m/s) between walls 0.2 m left and 0.3 m right, facing a point.
  wpg::WalkRequest request;
  request.duration = 12.0;
  request.reference = {{0.0, Eigen::Vector3d(0.2, 0.05, 0.0)}};
  request.generator.constraints = {{"lane", {{"left", 0.2}, {"right", -0.3}}}};
  request.generator.costs = {{"face_point", {{"x", 10.0}, {"y", 0.0}, {"weight", 50.0}}}};
  const wpg::WalkResult walk = wpg::generateWalk(w, request);
  ok &= check(walk.success, "the walk succeeds");
  double highest = -1.0;
  for (const auto& step : walk.trajectory.footsteps) highest = std::max(highest, step.pose.y());
  // The CoP at the NMPC samples, which the rows constrain (between them the LIPM's CoP may
  // pass the wall by a millimetre, as it may leave the margin-reduced support polygon).
  const std::size_t period = std::lround(w.sampling_period / w.control_period);
  for (std::size_t k = 0; k < walk.trajectory.size(); k += period)
    highest = std::max(highest, walk.trajectory.cop[k].y());
  ok &= check(highest <= 0.2 + 1e-9, "every footstep and NMPC CoP sample right of the left wall");
  ok &= check(walk.trajectory.com.back().x() > 1.5, "the robot walks on along x");
  std::printf("highest y %.4f m, x reached %.2f m\n", highest, walk.trajectory.com.back().x());
  return ok ? 0 : 1;
}
