// The constraint families behind one interface (wpg/nmpc/constraint_family.hpp): each built-in
// family against central differences on its own rows, a family added by a test (one class and
// one registration, as a new family of the library is one file and one line), and the staged
// relaxation of infeasible QPs with one slack per family, forced by families that cannot hold.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../common/obstacle_fields.hpp"
#include "../common/paper_gait.hpp"
#include "nmpc_test_problems.hpp"
#include "test_constraint_families.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/pattern_generator.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::ConstraintFamily;
using wpg::IterationStatus;
using wpg::JacobianRows;
using wpg::NmpcLayout;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::NmpcSolver;
using wpg::RelaxationGroup;
using wpg::WalkingParameters;
using namespace wpg_test;

// The model stacks the families in registration order, each from the row where the one before
// it ends; each family's row count comes from the model (horizon, steps, polygon edges, slots,
// landing rates).
TEST(ConstraintFamilies, ModelAssignsEachFamilyItsRows) {
  const NmpcModel model(WalkingParameters(), 3);
  const NmpcLayout& L = model.layout();
  ASSERT_EQ(model.familyCount(), 6);  // swing_reach is registered only when on
  const char* names[6] = {"cop",      "step_feasibility", "yaw_bound",
                          "obstacle", "landing_bound",    "landing_yaw_bound"};
  const int edges = model.feasibilityPolygon(wpg::FootSide::kLeft).edgeCount();
  // The landing bounds are off by default: no rows.
  const int rows[6] = {4 * L.horizon, edges * L.steps, 2 * L.steps, 3 * L.steps, 0, 0};
  int first = 0;
  for (int k = 0; k < 6; ++k) {
    EXPECT_STREQ(model.family(k).name(), names[k]);
    EXPECT_EQ(model.findFamily(names[k]), k);
    EXPECT_EQ(model.familyFirstRow(k), first) << names[k];
    EXPECT_EQ(model.familyRowCount(k), rows[k]) << names[k];
    for (int r = 0; r < rows[k]; ++r) EXPECT_EQ(model.familyOfRow(first + r), k);
    first += rows[k];
  }
  EXPECT_EQ(model.inequalityCount(), first);
  EXPECT_EQ(model.familyOfRow(first), -1);
  EXPECT_EQ(model.findFamily("no_such_family"), -1);
  EXPECT_EQ(wpg::CopRows::count(model), rows[0]);
  EXPECT_EQ(wpg::StepFeasibilityRows::of(model).count(model), rows[1]);
  EXPECT_EQ(wpg::YawBoundRows::count(model), rows[2]);
  EXPECT_EQ(wpg::ObstacleRows::of(model).count(model), rows[3]);
  // Each landing bound has its rows when its rate is on.
  WalkingParameters bounded;
  bounded.max_landing_speed = 0.4;
  EXPECT_EQ(NmpcModel(bounded, 3).familyRowCount(4), wpg::LandingBoundRows::kRows);
  EXPECT_EQ(NmpcModel(bounded, 3).familyRowCount(5), 0);
  bounded.max_landing_yaw_rate = 1.5;
  const NmpcModel both(bounded, 3);
  EXPECT_EQ(both.familyRowCount(5), wpg::LandingYawBoundRows::kRows);
  EXPECT_EQ(both.familyFirstRow(5), both.familyFirstRow(4) + wpg::LandingBoundRows::kRows);
  EXPECT_EQ(both.familyFirstRow(5) + both.familyRowCount(5), both.inequalityCount());
  EXPECT_EQ(model.family(0).group(), RelaxationGroup::kBalance);
  EXPECT_EQ(model.family(1).group(), RelaxationGroup::kKinematics);
  EXPECT_EQ(model.family(2).group(), RelaxationGroup::kKinematics);
  EXPECT_EQ(model.family(3).group(), RelaxationGroup::kObstacle);
  EXPECT_EQ(model.family(4).group(), RelaxationGroup::kKinematics);
  EXPECT_EQ(model.family(5).group(), RelaxationGroup::kKinematics);
  EXPECT_STREQ(model.family(2).unit(), "rad");
  EXPECT_STREQ(model.family(4).unit(), "m");
  EXPECT_STREQ(model.family(5).unit(), "rad");
}

// Each family on its own rows (wpg::checkConstraintJacobian), at random points of every
// walking pattern, with obstacles in three of four slots.
TEST(ConstraintFamilies, EachFamilyMatchesFiniteDifferences) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  w.max_landing_speed = 0.4;  // landing bound on (off by default)
  w.max_landing_yaw_rate = 1.5;
  w.max_swing_speed = 2.0;  // swing reach on (off in WalkingParameters' defaults)
  const NmpcModel model(w, 4);
  const NmpcLayout& L = model.layout();
  const wpg::ObstacleSet obstacles(wpg_test::threeObstacles());
  Rng rng(77);
  int points = 0;
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (FixedMode mode : {FixedMode::kNone, FixedMode::kFirst, FixedMode::kRandom}) {
      NmpcProblem problem = randomProblem(model, pattern, FootSide::kLeft, mode, rng);
      problem.obstacles = &obstacles;
      problem.obstacle_slot << 2, -1, 0, 1;
      problem.landing_bounded = true;
      problem.previous_landing = Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      problem.landing_time_left = 0.3;
      problem.swing_reach_bounded = true;
      for (int k = 0; k < problem.swing_reach_lower.size(); ++k) {
        problem.swing_reach_lower(k) = rng.uniform(-1, 0);
        problem.swing_reach_upper(k) = rng.uniform(0, 1);
      }
      VectorXd U = randomU(model, problem, rng);
      for (int i = 0; i < L.steps; ++i) {  // steps 2 cm clear of every obstacle boundary
        for (int attempt = 0;; ++attempt) {
          ASSERT_LT(attempt, 1000);
          const Vector2d F(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
          bool clear = true;
          for (int o = 0; o < 3; ++o)
            if (std::abs(obstacles.signedDistance(o, F, nullptr)) < 0.02) clear = false;
          if (!clear) continue;
          U(L.stepX() + i) = F.x();
          U(L.stepY() + i) = F.y();
          break;
        }
      }
      for (int k = 0; k < model.familyCount(); ++k) {
        const wpg::JacobianCheck check = wpg::checkConstraintJacobian(model, problem, U, k);
        EXPECT_LE(check.worst, 1e-6) << model.family(k).name() << ", pattern " << pattern
                                     << ": row " << check.worst_row << ", column "
                                     << check.worst_column;
        ++points;
      }
    }
  }
  ASSERT_EQ(model.familyCount(), 7);  // the six and swing_reach
  EXPECT_EQ(points, 7 * 3 * model.patternCount());
}

// A new family is one class and one registration: its rows come after the built-in ones, the
// finite-difference checker works on it, and the SQP to convergence satisfies it.
TEST(ConstraintFamilies, AddedFamilyIsEnforced) {
  // The paper's gait: with the default yaw bound (0.17 rad) full-step Gauss-Newton with this
  // extra family cycles at one sample of the walk (50 iterations, no convergence; measured),
  // and this test is about the family's interface, not about the SQP's globalization.
  const WalkingParameters w = paperGait();
  NmpcModel model(w, wpg::GeneratorSettings().max_obstacles_in_qp);  // the generator's slots
  // Compatible with the feasibility polygon (the next step lands 0.2 m to 0.4 m aside) but
  // tighter: at 0.3 m/s the step after next wants to land ~0.5 m ahead of the support.
  const double reach = 0.3;
  model.addConstraintFamily(std::make_shared<StepReach>(reach));
  ASSERT_EQ(model.familyCount(), 7);
  EXPECT_EQ(model.familyFirstRow(6), model.familyFirstRow(5) + model.familyRowCount(5));
  EXPECT_EQ(model.inequalityCount(), model.familyFirstRow(6) + w.previewed_steps);
  Rng rng(5);
  for (int trial = 0; trial < 10; ++trial) {
    const NmpcProblem problem = randomProblem(model, trial % 8, FootSide::kRight, FixedMode::kNone, rng);
    const VectorXd U = randomU(model, problem, rng);
    EXPECT_LE(wpg::checkConstraintJacobian(model, problem, U, 6).worst, 1e-6);
  }

  // Walk forward with the paper's families, then solve the same samples with the added one.
  wpg::GeneratorSettings settings;
  wpg::PatternGenerator generator(w, settings);
  settings.sqp_iterations = 8;  // Gauss-Newton iterations: the nonlinear rows themselves hold
  NmpcSolver solver(model);
  VectorXd g(model.inequalityCount());
  int binding = 0;
  for (int k = 0; k < 40; ++k) {
    generator.update(k * w.sampling_period, Vector3d(0.3, 0.0, 0.0));
    if (!generator.standing() && !generator.starting()) {
      solver.plan() = generator.solver().plan();
      solver.clearActiveSet();
      const wpg::NmpcSolveResult result = solver.solve(generator.problem(), settings);
      ASSERT_EQ(result.status, IterationStatus::kSolved) << "sample " << k;
      wpg::evaluateConstraints(model, generator.problem(), solver.plan(), g, nullptr);
      const auto rows = g.segment(model.familyFirstRow(6), model.familyRowCount(6));
      EXPECT_LE(rows.maxCoeff(), 1e-8) << "sample " << k;
      if (rows.maxCoeff() > -1e-8) ++binding;
      EXPECT_LE(g.maxCoeff(), 1e-8) << "sample " << k;
    }
    Vector3d cx = generator.comX(), cy = generator.comY();
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(cx, generator.plan().jerk_x, w.control_period);
      wpg::integrateJerk(cy, generator.plan().jerk_y, w.control_period);
    }
    generator.advance(cx, cy);
  }
  EXPECT_GT(binding, 10);
}

// Collects the samples of a forward walk (problems and the generator's shifted plans).
struct Samples {
  std::vector<NmpcProblem> problems;
  std::vector<VectorXd> guesses;
};

Samples walkingSamples(const WalkingParameters& w, int count) {
  wpg::PatternGenerator generator(w, wpg::GeneratorSettings());
  Samples samples;
  for (int k = 0; k < 30 + count; ++k) {
    const VectorXd guess = generator.solver().plan();
    generator.update(k * w.sampling_period, Vector3d(0.2, 0.0, 0.0));
    if (k >= 30) {
      samples.problems.push_back(generator.problem());
      samples.guesses.push_back(guess);
    }
    Vector3d cx = generator.comX(), cy = generator.comY();
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(cx, generator.plan().jerk_x, w.control_period);
      wpg::integrateJerk(cy, generator.plan().jerk_y, w.control_period);
    }
    generator.advance(cx, cy);
  }
  return samples;
}

// Infeasible QPs relax in stages (obstacle, kinematics, balance), one slack per family: a family
// that cannot hold in group G gets slack 1, every other family slack 0 and its rows satisfied,
// and the status names G.
TEST(ConstraintFamilies, StagedRelaxationNamesTheGroupThatGaveWay) {
  const WalkingParameters w;
  const Samples samples = walkingSamples(w, 8);
  const struct {
    RelaxationGroup group;
    IterationStatus status;
  } cases[] = {{RelaxationGroup::kObstacle, IterationStatus::kRelaxedObstacle},
               {RelaxationGroup::kKinematics, IterationStatus::kRelaxedKinematics},
               {RelaxationGroup::kBalance, IterationStatus::kRelaxedBalance}};
  for (const auto& c : cases) {
    NmpcModel model(w, wpg::GeneratorSettings().max_obstacles_in_qp);
    model.addConstraintFamily(std::make_shared<NeverHolds>(c.group));
    const int never = model.familyCount() - 1;
    NmpcSolver solver(model);
    for (std::size_t i = 0; i < samples.problems.size(); ++i) {
      solver.plan() = samples.guesses[i];
      const wpg::NmpcSolveResult result =
          solver.solve(samples.problems[i], wpg::GeneratorSettings());
      SCOPED_TRACE(std::string(wpg::relaxationGroupName(c.group)) + " sample " + std::to_string(i));
      EXPECT_EQ(result.status, c.status);
      EXPECT_EQ(result.relaxed_families, 1u << never);
      EXPECT_NEAR(result.slack[never], 1.0, 1e-9);
      for (int k = 0; k < never; ++k) EXPECT_LE(result.slack[k], 1e-12) << model.family(k).name();
      // The paper's rows hold in the QP that was solved (their linearization at the sample,
      // eq. 21b): the relaxation gave up only the family that cannot hold.
      const wpg::NmpcWorkspace& ws = solver.workspace();
      const int rows = model.familyFirstRow(never);  // the paper's families' rows
      const VectorXd residual = ws.jacobian.topRows(rows) * solver.plan() - ws.upper.head(rows);
      EXPECT_LE(residual.maxCoeff(), 1e-9);
    }
  }
}

// Obstacle rows give way before the others: an obstacle family that cannot hold is relaxed at
// the first stage, with the balance and kinematics rows kept hard.
TEST(ConstraintFamilies, ObstacleRowsRelaxFirst) {
  const WalkingParameters w;
  const Samples samples = walkingSamples(w, 4);
  NmpcModel model(w, wpg::GeneratorSettings().max_obstacles_in_qp);
  model.addConstraintFamily(std::make_shared<NeverHolds>(RelaxationGroup::kObstacle));
  model.addConstraintFamily(std::make_shared<StepReach>(0.3));  // binding, kinematics
  NmpcSolver solver(model);
  for (std::size_t i = 0; i < samples.problems.size(); ++i) {
    solver.plan() = samples.guesses[i];
    const wpg::NmpcSolveResult result =
        solver.solve(samples.problems[i], wpg::GeneratorSettings());
    EXPECT_EQ(result.status, IterationStatus::kRelaxedObstacle) << i;
    const int never = model.familyCount() - 2, reach = model.familyCount() - 1;
    EXPECT_EQ(result.relaxed_families, 1u << never) << i;
    EXPECT_LE(result.slack[reach], 1e-12) << i;
    for (int k = 0; k < never; ++k) EXPECT_LE(result.slack[k], 1e-12) << i;
  }
}

// A QP stopped by its iteration limit is not executed: the plan stays the shifted previous one.
TEST(ConstraintFamilies, CappedQpKeepsTheShiftedPlan) {
  // The paper's gait, whose cold QPs need more than two working-set updates (the defaults'
  // need at most two on this walk).
  const WalkingParameters w = paperGait();
  const Samples samples = walkingSamples(w, 8);
  const NmpcModel model(w, wpg::GeneratorSettings().max_obstacles_in_qp);
  NmpcSolver solver(model);
  wpg::GeneratorSettings settings;
  settings.max_qp_iterations = 2;
  int capped = 0;
  for (std::size_t i = 0; i < samples.problems.size(); ++i) {
    solver.plan() = samples.guesses[i];
    solver.clearActiveSet();  // cold: the QP needs more than two working-set updates
    const wpg::NmpcSolveResult result = solver.solve(samples.problems[i], settings);
    if (result.status != IterationStatus::kIterationLimit) {
      EXPECT_EQ(result.status, IterationStatus::kSolved) << i;
      continue;
    }
    ++capped;
    EXPECT_EQ((solver.plan() - samples.guesses[i]).cwiseAbs().maxCoeff(), 0.0) << i;
    EXPECT_GE(result.qp_iterations, settings.max_qp_iterations) << i;
    EXPECT_TRUE(std::isfinite(result.cost));
  }
  EXPECT_GE(capped, 2);
}

// Public entry points check sizes and say which field was wrong.
TEST(ConstraintFamilies, EntryPointsCheckSizes) {
  const NmpcModel model(WalkingParameters(), 2);
  NmpcSolver solver(model);
  const wpg::GeneratorSettings settings;
  auto message = [](auto call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  NmpcProblem problem = model.makeProblem();
  problem.velocity_x.resize(3);
  EXPECT_NE(message([&] { solver.solve(problem, settings); }).find("'velocity_x'"),
            std::string::npos);
  problem = model.makeProblem();
  problem.obstacle_slot(1) = 0;  // no obstacles given
  EXPECT_NE(message([&] { solver.solve(problem, settings); }).find("obstacle_slot[1]"),
            std::string::npos);
  problem = model.makeProblem();
  problem.phase.pattern = model.patternCount();
  EXPECT_NE(message([&] { solver.solveLmpc(problem, settings); }).find("phase.pattern"),
            std::string::npos);
  const NmpcModel other(WalkingParameters(), 3);  // a problem of another model: 3 slots
  EXPECT_NE(message([&] { solver.solve(other.makeProblem(), settings); }).find("'obstacle_slot'"),
            std::string::npos);
  VectorXd g(5);
  const VectorXd U = VectorXd::Zero(model.layout().variableCount());
  EXPECT_NE(message([&] { wpg::evaluateConstraints(model, model.makeProblem(), U, g, nullptr); })
                .find("evaluateConstraints"),
            std::string::npos);
  EXPECT_THROW(wpg::evaluateCost(model, model.makeProblem(), VectorXd::Zero(3)),
               std::invalid_argument);
  VectorXd gradient(4);
  EXPECT_THROW(wpg::buildCostGradient(model, model.makeProblem(), gradient), std::invalid_argument);
  // the right sizes go through (standing problem: every step fixed)
  problem = model.makeProblem();
  problem.phase.pattern = model.standingPattern();
  EXPECT_EQ(message([&] { solver.solve(problem, settings); }), "no exception");
}

TEST(ConstraintFamilies, RegistrationIsChecked) {
  NmpcModel model{WalkingParameters()};
  EXPECT_THROW(model.addConstraintFamily(nullptr), std::invalid_argument);
  for (int k = model.familyCount(); k < wpg::kMaxConstraintFamilies; ++k)
    model.addConstraintFamily(std::make_shared<StepReach>(0.3));
  EXPECT_THROW(model.addConstraintFamily(std::make_shared<StepReach>(0.3)), std::invalid_argument);
}

}  // namespace
