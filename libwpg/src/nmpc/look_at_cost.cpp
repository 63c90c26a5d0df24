// The look-at cost term (wpg/nmpc/builtin_extensions.hpp): each previewed step's yaw towards
// a point.
#include <cmath>
#include <sstream>

#include "wpg/nmpc/builtin_extensions.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

// The angle in [-pi, pi).
double wrapAngle(double angle) {
  return angle - 2.0 * M_PI * std::floor((angle + M_PI) / (2.0 * M_PI));
}

class LookAtCost final : public CostTerm {
 public:
  LookAtCost(double x, double y, double weight, double least_distance)
      : x_(x), y_(y), scale_(std::sqrt(weight)), least_distance_(least_distance) {}
  const char* name() const override { return "look_at"; }
  int residualCount(const NmpcModel& model) const override { return model.layout().steps; }

  // e_i = theta_i - phi_i, phi_i = atan2(y - F_y, x - F_x): with d = (x - F_x, y - F_y),
  // dphi/dF_x = d_y / |d|^2 and dphi/dF_y = -d_x / |d|^2.
  void evaluate(const NmpcModel& model, const NmpcProblem&,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                Eigen::Ref<Eigen::MatrixXd>* jacobian) const override {
    const NmpcLayout& L = model.layout();
    for (int i = 0; i < L.steps; ++i) {
      const double dx = x_ - U(L.stepX() + i), dy = y_ - U(L.stepY() + i);
      const double squared = dx * dx + dy * dy;
      if (squared < least_distance_ * least_distance_) {
        r(i) = 0.0;  // on the point: no heading towards it
        continue;
      }
      r(i) = scale_ * wrapAngle(U(L.stepYaw() + i) - std::atan2(dy, dx));
      if (!jacobian) continue;
      (*jacobian)(i, L.stepYaw() + i) = scale_;
      (*jacobian)(i, L.stepX() + i) = -scale_ * dy / squared;
      (*jacobian)(i, L.stepY() + i) = scale_ * dx / squared;
    }
  }

 private:
  double x_, y_, scale_, least_distance_;
};

}  // namespace

std::unique_ptr<CostTerm> makeLookAtCost(double x, double y, double weight) {
  return std::make_unique<LookAtCost>(x, y, weight, WalkingParameters().foot_length);
}

CostTermSpec lookAtCostSpec() {
  CostTermSpec spec;
  spec.name = "look_at";
  spec.description = "each previewed step's yaw towards the point (x, y) (world)";
  spec.parameters = {{"x", "m", "the world x of the point to face", true, 0.0},
                     {"y", "m", "the world y of the point to face", true, 0.0},
                     {"weight", "1/rad^2", "the weight of the squared yaw error", false, 100.0}};
  spec.check = [](const ExtensionArguments& a, const ExtensionContext& context) {
    if (!(a.at("weight") > 0.0)) throw ExtensionError("weight", "expected a positive weight");
    const double distance = std::hypot(a.at("x") - context.start_pose.x(),
                                       a.at("y") - context.start_pose.y());
    const double least = context.walking.foot_length;
    if (!(distance >= least)) {
      std::ostringstream text;
      text << "expected a point at least the sole length " << least
           << " m from the walk's start (" << context.start_pose.x() << ", "
           << context.start_pose.y() << "): no heading faces a point under the robot, got "
           << distance << " m away";
      throw ExtensionError("x", text.str());
    }
  };
  spec.make = [](const ExtensionArguments& a, const ExtensionContext& context) {
    return std::shared_ptr<const CostTerm>(std::make_shared<LookAtCost>(
        a.at("x"), a.at("y"), a.at("weight"), context.walking.foot_length));
  };
  return spec;
}

}  // namespace wpg
