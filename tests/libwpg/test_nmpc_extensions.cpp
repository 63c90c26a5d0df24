// The NMPC's extension points (wpg/nmpc/extension_registry.hpp, cost_term.hpp) and wpg's own
// extensions (builtin_extensions.hpp): the corridor's and the look-at cost's Jacobians against
// central differences (the harness of the built-in families, numdiff.hpp), the Gauss-Newton
// treatment of a cost term against the same cost written into the paper's terms, and the
// registry's checks (names, parameters, the robot).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <string>

#include "nmpc_test_problems.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/pattern_generator.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using wpg::ExtensionArguments;
using wpg::ExtensionContext;
using wpg::ExtensionError;
using wpg::GeneratorSettings;
using wpg::JacobianCheck;
using wpg::NmpcLayout;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::NmpcSolver;
using wpg::WalkingParameters;
using namespace wpg_test;

TEST(CorridorFamily, JacobianMatchesCentralDifferencesAndRowsAreTheWalls) {
  NmpcModel model{WalkingParameters()};
  model.addConstraintFamily(wpg::makeCorridorConstraint(0.25, -0.35));
  const int family = model.findFamily("corridor");
  ASSERT_GE(family, 0);
  const NmpcLayout& L = model.layout();
  ASSERT_EQ(model.familyRowCount(family), wpg::CorridorRows::count(L.horizon, L.steps));
  Rng rng(7);
  int points = 0;
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (FixedMode mode : {FixedMode::kNone, FixedMode::kFirst, FixedMode::kRandom}) {
      const NmpcProblem problem = randomProblem(model, pattern, wpg::FootSide::kLeft, mode, rng);
      const VectorXd U = randomU(model, problem, rng);
      const JacobianCheck check = wpg::checkConstraintJacobian(model, problem, U, family);
      EXPECT_LE(check.worst, 1e-6) << "pattern " << pattern << ": row " << check.worst_row
                                   << ", column " << check.worst_column;
      ++points;
      // The rows are the signed distances past the walls, by direct geometry.
      VectorXd g(model.familyRowCount(family));
      model.family(family).evaluate(model, problem, U, g, nullptr);
      const wpg::LipmPrediction& P = model.prediction();
      for (int j = 0; j < L.horizon; ++j) {
        const double zy = (P.cop_state * problem.com_y + P.cop_jerk * U.segment(L.jerkY(),
                                                                                L.horizon))(j);
        // the CoP held kCorridorCopMargin inside the walls
        constexpr double m = wpg::kCorridorCopMargin;
        EXPECT_NEAR(g(wpg::CorridorRows::copRow(j, true)), zy - (0.25 - m), 1e-12);
        EXPECT_NEAR(g(wpg::CorridorRows::copRow(j, false)), -0.35 + m - zy, 1e-12);
      }
      for (int i = 0; i < L.steps; ++i) {
        const double y = U(L.stepY() + i);
        const bool fixed = problem.phase.step_fixed(i) != 0;
        EXPECT_EQ(g(wpg::CorridorRows::stepRow(L.horizon, i, true)), fixed ? -1.0 : y - 0.25);
        EXPECT_EQ(g(wpg::CorridorRows::stepRow(L.horizon, i, false)), fixed ? -1.0 : -0.35 - y);
      }
    }
  }
  EXPECT_GE(points, 20);
}

TEST(LookAtCost, JacobianMatchesCentralDifferences) {
  NmpcModel model{WalkingParameters()};
  model.addCostTerm(wpg::makeLookAtCost(3.0, 1.0, 50.0));
  ASSERT_EQ(model.residualCount(), model.layout().steps);
  Rng rng(11);
  int points = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const NmpcProblem problem =
        randomProblem(model, trial % model.patternCount(), wpg::FootSide::kRight,
                      FixedMode::kNone, rng);
    VectorXd U = randomU(model, problem, rng);
    const NmpcLayout& L = model.layout();
    // Away from the wrap of the angle (+-pi), where the residual jumps by 2 pi sqrt(weight).
    bool near_wrap = false;
    for (int i = 0; i < L.steps; ++i) {
      const double heading =
          std::atan2(1.0 - U(L.stepY() + i), 3.0 - U(L.stepX() + i));
      const double e = std::remainder(U(L.stepYaw() + i) - heading, 2.0 * M_PI);
      near_wrap = near_wrap || std::abs(e) > M_PI - 1e-3;
    }
    if (near_wrap) continue;
    const JacobianCheck check = wpg::checkCostJacobian(model, problem, U);
    EXPECT_LE(check.worst, 1e-6) << "trial " << trial << ": residual " << check.worst_row
                                 << ", column " << check.worst_column;
    ++points;
    // Facing the point exactly: a zero residual.
    for (int i = 0; i < L.steps; ++i)
      U(L.stepYaw() + i) = std::atan2(1.0 - U(L.stepY() + i), 3.0 - U(L.stepX() + i));
    VectorXd r(model.residualCount());
    wpg::evaluateCostTerms(model, problem, U, r, nullptr);
    EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_GE(points, 30);
}

// A term r_i = sqrt(w) (theta_i - a) beside J2 = weight_yaw/2 |theta - theta_ref|^2 is J2
// with weight weight_yaw + w and reference (weight_yaw theta_ref + w a) / (weight_yaw + w),
// up to a constant: the solver's Gauss-Newton terms (Hessian Q + R'R, linear term
// p + R'(r - R U0)) must give that problem's plan.
class YawPull final : public wpg::CostTerm {
 public:
  YawPull(double weight, double target) : scale_(std::sqrt(weight)), target_(target) {}
  const char* name() const override { return "yaw_pull"; }
  int residualCount(const NmpcModel& model) const override { return model.layout().steps; }
  void evaluate(const NmpcModel& model, const NmpcProblem&,
                const Eigen::Ref<const VectorXd>& U, Eigen::Ref<VectorXd> r,
                Eigen::Ref<MatrixXd>* jacobian) const override {
    const NmpcLayout& L = model.layout();
    for (int i = 0; i < L.steps; ++i) {
      r(i) = scale_ * (U(L.stepYaw() + i) - target_);
      if (jacobian) (*jacobian)(i, L.stepYaw() + i) = scale_;
    }
  }

 private:
  double scale_, target_;
};

TEST(CostTerms, GaussNewtonTermEqualsTheSameCostInThePapersTerms) {
  WalkingParameters w;
  const double pull = 60.0, target = 0.3;
  NmpcModel with_term(w);
  with_term.addCostTerm(std::make_shared<YawPull>(pull, target));
  WalkingParameters merged = w;
  merged.weight_yaw = w.weight_yaw + pull;
  const NmpcModel plain(merged);
  Rng rng(5);
  GeneratorSettings settings;
  settings.sqp_iterations = 0;  // to convergence: the fixed point of both
  int compared = 0;
  for (int trial = 0; trial < 8; ++trial) {
    NmpcProblem problem = randomProblem(with_term, trial, wpg::FootSide::kLeft,
                                        FixedMode::kNone, rng);
    // A feasible start: the current support under the CoM at rest.
    problem.com_x = Eigen::Vector3d(problem.phase.support_pose.x(), 0.0, 0.0);
    problem.com_y = Eigen::Vector3d(problem.phase.support_pose.y(), 0.0, 0.0);
    problem.phase.support_pose.z() = 0.0;
    problem.yaw_reference.setConstant(0.1);
    NmpcProblem merged_problem = problem;
    merged_problem.yaw_reference.setConstant((w.weight_yaw * 0.1 + pull * target) /
                                             (w.weight_yaw + pull));
    NmpcSolver a(with_term), b(plain);
    a.plan().setZero();
    b.plan().setZero();
    const wpg::NmpcSolveResult ra = a.solve(problem, settings);
    const wpg::NmpcSolveResult rb = b.solve(merged_problem, settings);
    ASSERT_EQ(ra.status, rb.status);
    // A relaxed QP's plan is the same optimum too; a fallback keeps the start.
    if (ra.status == wpg::IterationStatus::kFallback ||
        ra.status == wpg::IterationStatus::kIterationLimit)
      continue;
    EXPECT_LE((a.plan() - b.plan()).cwiseAbs().maxCoeff(), 1e-8) << "trial " << trial;
    ++compared;
  }
  EXPECT_GE(compared, 6);
}

TEST(ExtensionRegistry, ListsWpgsOwnWithTheirParametersAndUnits) {
  bool corridor = false, look_at = false;
  for (const auto& spec : wpg::registeredConstraintFamilies()) {
    if (spec.name != "corridor") continue;
    corridor = true;
    ASSERT_EQ(spec.parameters.size(), 3u);
    EXPECT_EQ(spec.parameters[0].name, "left");
    EXPECT_EQ(spec.parameters[0].unit, "m");
    EXPECT_EQ(spec.parameters[2].name, "cop_margin");
    EXPECT_FALSE(spec.parameters[2].required);
  }
  for (const auto& spec : wpg::registeredCostTerms()) {
    if (spec.name != "look_at") continue;
    look_at = true;
    ASSERT_EQ(spec.parameters.size(), 3u);
    EXPECT_EQ(spec.parameters[2].name, "weight");
    EXPECT_FALSE(spec.parameters[2].required);
  }
  EXPECT_TRUE(corridor);
  EXPECT_TRUE(look_at);
}

// The parameter an ExtensionError names, and its message.
std::pair<std::string, std::string> errorOf(const std::string& name,
                                            const ExtensionArguments& arguments,
                                            bool constraint = true) {
  ExtensionContext context;
  try {
    if (constraint) {
      wpg::checkConstraintFamily(name, arguments, context);
    } else {
      wpg::checkCostTerm(name, arguments, context);
    }
  } catch (const ExtensionError& error) {
    return {error.parameter(), error.what()};
  }
  return {"<none>", ""};
}

TEST(ExtensionRegistry, ChecksNamesParametersAndTheRobot) {
  auto [parameter, message] = errorOf("coridor", {});
  EXPECT_EQ(parameter, "");
  EXPECT_NE(message.find("did you mean 'corridor'"), std::string::npos) << message;
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.25}});
  EXPECT_EQ(parameter, "right");
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.25}, {"rigth", -0.3}});
  EXPECT_EQ(parameter, "rigth");
  EXPECT_NE(message.find("did you mean 'right'"), std::string::npos) << message;
  // HRP-2's feet need 0.2 m across (its feasibility polygon); its sole is 0.138 m wide.
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.05}, {"right", -0.05}});
  EXPECT_EQ(parameter, "left");
  EXPECT_NE(message.find("at least 0.2 m"), std::string::npos) << message;
  // Wide enough for two feet, but not for the first step: the feet start 0.19 m apart
  // (initial_foot_separation), so a left step from the right foot lands at y >= 0.105 m and a
  // right step from the left foot at y <= -0.105 m. Either foot may be the first to swing
  // (the command, a push), so both must fit. [-0.1, 0.1] used to be accepted and the robot
  // fell; [-0.1, 0.11] walks only while the left foot swings first.
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.1}, {"right", -0.1}});
  EXPECT_EQ(parameter, "left");
  EXPECT_NE(message.find("first step"), std::string::npos) << message;
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.11}, {"right", -0.1}});
  EXPECT_EQ(parameter, "right");
  EXPECT_NE(message.find("first step"), std::string::npos) << message;
  std::tie(parameter, message) = errorOf("corridor", {{"left", 0.105}, {"right", -0.105}});
  EXPECT_EQ(parameter, "<none>") << message;
  {
    // Turned a quarter turn the feet stand along x: a step may go either way across, so a
    // corridor of the least width holds the first step whichever foot takes it.
    ExtensionContext turned;
    turned.start_pose = Eigen::Vector3d(0.0, 0.0, M_PI / 2);
    EXPECT_NO_THROW(wpg::checkConstraintFamily("corridor", {{"left", 0.1}, {"right", -0.1}},
                                               turned));
  }
  std::tie(parameter, message) = errorOf("look_at", {{"x", 0.05}, {"y", 0.0}}, false);
  EXPECT_EQ(parameter, "x");
  EXPECT_NE(message.find("sole length"), std::string::npos) << message;
  std::tie(parameter, message) =
      errorOf("look_at", {{"x", 2.0}, {"y", 0.0}, {"weight", -1.0}}, false);
  EXPECT_EQ(parameter, "weight");
  const ExtensionArguments filled = wpg::checkCostTerm("look_at", {{"x", 2.0}, {"y", 0.0}}, {});
  EXPECT_EQ(filled.at("weight"), 100.0);
}

TEST(ExtensionRegistry, RegistersNewOnesOnceByName) {
  wpg::CostTermSpec spec;
  spec.name = "test_yaw_pull";
  spec.parameters = {{"weight", "1/rad^2", "the pull's weight", true, 0.0},
                     {"target", "rad", "the yaw pulled to", true, 0.0}};
  spec.make = [](const ExtensionArguments& a, const ExtensionContext&) {
    return std::shared_ptr<const wpg::CostTerm>(
        std::make_shared<YawPull>(a.at("weight"), a.at("target")));
  };
  wpg::registerCostTerm(spec);
  EXPECT_THROW(wpg::registerCostTerm(spec), std::invalid_argument);
  const auto term = wpg::makeCostTerm({"test_yaw_pull", {{"weight", 4.0}, {"target", 1.0}}}, {});
  ASSERT_TRUE(term);
  EXPECT_STREQ(term->name(), "yaw_pull");
  // Used by name through the generator's settings: its model holds the term.
  GeneratorSettings settings;
  settings.costs = {{"test_yaw_pull", {{"weight", 4.0}, {"target", 1.0}}}};
  wpg::PatternGenerator generator(WalkingParameters(), settings);
  EXPECT_EQ(generator.model().costTermCount(), 1);
  EXPECT_EQ(generator.model().residualCount(), generator.model().layout().steps);
  // The LMPC baseline plans the yaws before the positions: a cost term on the steps would
  // move them instead of turning them, so the generator refuses it.
  settings.algorithm = wpg::GeneratorAlgorithm::kLmpc;
  EXPECT_THROW(wpg::PatternGenerator(WalkingParameters(), settings), std::invalid_argument);
  settings.costs.clear();
  EXPECT_NO_THROW(wpg::PatternGenerator(WalkingParameters(), settings));
}

}  // namespace
