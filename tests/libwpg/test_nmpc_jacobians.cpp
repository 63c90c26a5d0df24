// Tests of the NMPC constraints g(U) <= 0 (paper eq. 9-17) and of their exact Jacobian:
// central finite differences at random points of every walking phase, the CoM-state term of
// the yaw derivative of the CoP rows, and g itself against a direct geometric computation.
#include <gtest/gtest.h>

#include <initializer_list>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/walking_parameters.hpp"
#include "../common/obstacle_fields.hpp"
#include "nmpc_test_problems.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;

using namespace wpg_test;

using wpg::JacobianCheck;

// Every family at once (the stacked g of the model) against central differences
// (wpg::checkConstraintJacobian); evaluateConstraints must also set every Jacobian entry.
JacobianCheck compareWithFiniteDifferences(const NmpcModel& model, const NmpcProblem& problem,
                                           const VectorXd& U) {
  const NmpcLayout& L = model.layout();
  VectorXd g(model.inequalityCount());
  MatrixXd J = MatrixXd::Constant(model.inequalityCount(), L.variableCount(), 12345.0);
  wpg::evaluateConstraints(model, problem, U, g, &J);
  EXPECT_LT(J.cwiseAbs().maxCoeff(), 12345.0) << "an entry of the Jacobian was not written";
  return wpg::checkConstraintJacobian(model, problem, U);
}

// "<family> row <r>": the family owning a row of the stacked g, and its own row number.
std::string describeRow(const NmpcModel& model, int row) {
  const int family = model.familyOfRow(row);
  if (row < 0 || family < 0) return "none";
  return std::string(model.family(family).name()) + " row " +
         std::to_string(row - model.familyFirstRow(family));
}


// Every previewed step of U at a random point of [-1.2, 1.2]^2 at least 2 cm from the listed
// obstacles (their signed distances are not smooth on the boundary).
void placeStepsClearOf(const NmpcLayout& L, const wpg::AnalyticObstacleDistance& distance,
                       std::initializer_list<int> obstacles, Rng& rng, VectorXd& U) {
  for (int i = 0; i < L.steps; ++i) {
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 1000);
      const Vector2d F(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
      bool clear = true;
      for (const int o : obstacles)
        if (distance.signedDistance(o, F, nullptr) < 0.02) clear = false;
      if (!clear) continue;
      U(L.stepX() + i) = F.x();
      U(L.stepY() + i) = F.y();
      break;
    }
  }
}

TEST(NmpcJacobian, MatchesCentralFiniteDifferencesEverywhere) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  ASSERT_EQ(model.patternCount(), w.stepSamples() + 1);
  Rng rng(2024);
  int points = 0;
  double worst = 0.0;
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (FootSide side : {FootSide::kLeft, FootSide::kRight}) {
      for (FixedMode mode : {FixedMode::kNone, FixedMode::kFirst, FixedMode::kRandom}) {
        for (int trial = 0; trial < 4; ++trial) {
          const NmpcProblem problem = randomProblem(model, pattern, side, mode, rng);
          const VectorXd U = randomU(model, problem, rng);
          const JacobianCheck check = compareWithFiniteDifferences(model, problem, U);
          ++points;
          worst = std::max(worst, check.worst);
          EXPECT_LE(check.worst, 1e-6)
              << "pattern " << pattern << " side " << static_cast<int>(side) << " mode "
              << static_cast<int>(mode) << " trial " << trial << ": row " << check.worst_row
              << " (" << describeRow(model, check.worst_row) << "), column " << check.worst_column;
        }
      }
    }
  }
  EXPECT_GE(points, 200);
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

// Obstacle rows (eq. 18-19): circles in the squared form, a box and a polygon through the
// analytic signed distance; steps kept away from the obstacle boundaries and from the
// polygon's medial axis regions where the distance is not differentiable (outside only). Both
// forms of the bound (WalkingParameters::obstacle_distance_form): the default sole_clearance,
// |F - c|^2 >= (R + m + obstacle_foot_radius)^2, and the paper's eq. (18) as written,
// |F - c|^2 >= R^2 + m^2.
class ObstacleRows : public ::testing::TestWithParam<wpg::ObstacleDistanceForm> {};

TEST_P(ObstacleRows, MatchFiniteDifferencesAndTheirForm) {
  const bool paper = GetParam() == wpg::ObstacleDistanceForm::kPaper;
  WalkingParameters w;
  w.obstacle_distance_form = GetParam();
  const int slots = 4;
  const NmpcModel model(w, slots);
  const NmpcLayout& L = model.layout();
  ASSERT_EQ(model.obstacleSlots(), slots);
  // The landing bounds are off by default: no rows.
  ASSERT_EQ(model.inequalityCount(), 4 * L.horizon + feasibilityEdges(model) * L.steps +
                                         2 * L.steps + slots * L.steps);
  const std::vector<wpg::Obstacle> obstacles = wpg_test::threeObstacles();
  const wpg::AnalyticObstacleDistance distance(obstacles);
  Rng rng(31);
  int points = 0;
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (int trial = 0; trial < 6; ++trial) {
      NmpcProblem problem = randomProblem(model, pattern, trial % 2 ? FootSide::kLeft : FootSide::kRight,
                                          trial < 2 ? FixedMode::kNone : FixedMode::kRandom, rng);
      problem.phase.support_pose.head<2>().setZero();
      problem.obstacles = &distance;
      problem.obstacle_slot.resize(slots);
      problem.obstacle_slot << 0, 1, -1, 2;
      VectorXd U = randomU(model, problem, rng);
      // Steps at least 2 cm away from every obstacle boundary.
      placeStepsClearOf(L, distance, {0, 1, 2}, rng, U);
      const JacobianCheck check = compareWithFiniteDifferences(model, problem, U);
      ++points;
      EXPECT_LE(check.worst, 1e-6) << "pattern " << pattern << " trial " << trial << ": row "
                                   << check.worst_row << " (" << describeRow(model, check.worst_row)
                                   << "), column " << check.worst_column;
      // The obstacle family alone (family 3), as every family's own check does.
      EXPECT_LE(wpg::checkConstraintJacobian(model, problem, U, 3).worst, 1e-6);
      // Values: the circle's squared form, the others' margin - distance; -1 for the empty
      // slot and for fixed steps.
      VectorXd g(model.inequalityCount());
      wpg::evaluateConstraints(model, problem, U, g, nullptr);
      for (int i = 0; i < L.steps; ++i) {
        const Vector2d F(U(L.stepX() + i), U(L.stepY() + i));
        if (problem.phase.step_fixed(i)) {
          for (int k = 0; k < slots; ++k) EXPECT_EQ(g(obstacleRow(model, i, k)), -1.0);
          continue;
        }
        // sole_clearance: margins grown by the sole radius (obstacle_foot_radius); the
        // paper's form: point steps
        const double foot = paper ? 0.0 : model.parameters().obstacle_foot_radius;
        const double R = obstacles[0].radius, m = obstacles[0].margin;
        const double bound = paper ? R * R + m * m : (R + m + foot) * (R + m + foot);
        // bound - |F - c|^2 (eq. 18: the paper's R^2 + m^2, or (R + m + r_sole)^2), scaled by
        // 1 / (2 sqrt(bound)) to metres
        const double row = g(obstacleRow(model, i, 0)) * 2.0 * std::sqrt(bound);
        EXPECT_NEAR(row, bound - (F - obstacles[0].center).squaredNorm(), 1e-12);
        EXPECT_NEAR(g(obstacleRow(model, i, 1)), 0.05 + foot - distance.signedDistance(1, F, nullptr), 1e-12);
        EXPECT_EQ(g(obstacleRow(model, i, 2)), -1.0);
        EXPECT_NEAR(g(obstacleRow(model, i, 3)), 0.02 + foot - distance.signedDistance(2, F, nullptr), 1e-12);
      }
    }
  }
  EXPECT_GE(points, 50);
}

INSTANTIATE_TEST_SUITE_P(NmpcJacobian, ObstacleRows,
                         ::testing::Values(wpg::ObstacleDistanceForm::kSoleClearance,
                                           wpg::ObstacleDistanceForm::kPaper));

// The bound of each form at a step centre (stepCentreMargin, stepCentreClearance: what the
// post-run checks measure), against the paper's eq. (18) written out.
TEST(ObstacleDistanceForm, StepCentreBoundIsTheFormsExpression) {
  WalkingParameters w;
  const std::vector<wpg::Obstacle> obstacles = wpg_test::threeObstacles();
  const wpg::AnalyticObstacleDistance distance(obstacles);
  const wpg::Obstacle& circle = obstacles[0];
  const double R = circle.radius, m = circle.margin;
  const Vector2d f = circle.center + Vector2d(0.3, -0.4);  // 0.5 m from the centre
  EXPECT_EQ(w.obstacle_distance_form, wpg::ObstacleDistanceForm::kSoleClearance);
  EXPECT_NEAR(wpg::stepCentreMargin(circle, w), m + w.obstacle_foot_radius, 1e-15);
  EXPECT_NEAR(wpg::stepCentreClearance(distance, 0, circle, w, f),
              0.5 - (R + m + w.obstacle_foot_radius), 1e-12);
  EXPECT_STREQ(wpg::stepCentreBoundName(w), "margin + obstacle_foot_radius");
  w.obstacle_distance_form = wpg::ObstacleDistanceForm::kPaper;
  // eq. (18): (f - c)^2 >= R^2 + m^2, so the clearance is |f - c| - sqrt(R^2 + m^2), which is
  // larger than |f - c| - (R + m): the paper's circle lies inside the margin circle.
  EXPECT_NEAR(wpg::stepCentreClearance(distance, 0, circle, w, f), 0.5 - std::sqrt(R * R + m * m),
              1e-12);
  EXPECT_LT(std::sqrt(R * R + m * m), R + m);
  // Not in the paper: boxes and polygons keep the point step the margin away.
  EXPECT_NEAR(wpg::stepCentreMargin(obstacles[1], w), obstacles[1].margin, 1e-15);
  EXPECT_NEAR(wpg::stepCentreMargin(obstacles[2], w), obstacles[2].margin, 1e-15);
  EXPECT_NE(std::string(wpg::stepCentreBoundName(w)).find("R^2 + m^2"), std::string::npos);
  // The names of the key's values.
  wpg::ObstacleDistanceForm form = wpg::ObstacleDistanceForm::kSoleClearance;
  EXPECT_TRUE(wpg::parseObstacleDistanceForm("paper", &form));
  EXPECT_EQ(form, wpg::ObstacleDistanceForm::kPaper);
  EXPECT_TRUE(wpg::parseObstacleDistanceForm("sole_clearance", &form));
  EXPECT_EQ(form, wpg::ObstacleDistanceForm::kSoleClearance);
  EXPECT_FALSE(wpg::parseObstacleDistanceForm("points", &form));
  EXPECT_STREQ(wpg::obstacleDistanceFormName(wpg::ObstacleDistanceForm::kPaper), "paper");
}

// command_tangent linearization (wpg/obstacle_tangent.hpp): a circle's row with a normal n in
// its slot is the half-plane r - n.(F - c) <= 0, linear in the step; the box and polygon of the
// other slots keep their signed distance (a zero normal column).
TEST(NmpcJacobian, CommandTangentObstacleRowsMatchFiniteDifferences) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const int slots = 3;
  const NmpcModel model(w, slots);
  const NmpcLayout& L = model.layout();
  const std::vector<wpg::Obstacle> obstacles = wpg_test::threeObstacles();
  const wpg::AnalyticObstacleDistance distance(obstacles);
  Rng rng(57);
  int points = 0;
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (int trial = 0; trial < 4; ++trial) {
      NmpcProblem problem = randomProblem(model, pattern, trial % 2 ? FootSide::kLeft : FootSide::kRight,
                                          trial < 2 ? FixedMode::kNone : FixedMode::kRandom, rng);
      problem.obstacles = &distance;
      problem.obstacle_slot << 0, 1, 2;
      const double angle = rng.uniform(-3.0, 3.0);
      problem.obstacle_normal.col(0) = Vector2d(std::cos(angle), std::sin(angle));
      // the circle's supporting half-plane n.F >= n.c + r (borderOffset of its one-point core)
      const double r = obstacles[0].radius + obstacles[0].margin + w.obstacle_foot_radius;
      problem.obstacle_offset(0) = problem.obstacle_normal.col(0).dot(obstacles[0].center) + r;
      VectorXd U = randomU(model, problem, rng);
      placeStepsClearOf(L, distance, {1, 2}, rng, U);  // the box and polygon: non-smooth inside
      const JacobianCheck check = compareWithFiniteDifferences(model, problem, U);
      ++points;
      EXPECT_LE(check.worst, 1e-6) << "pattern " << pattern << " trial " << trial << ": row "
                                   << check.worst_row << " (" << describeRow(model, check.worst_row)
                                   << "), column " << check.worst_column;
      VectorXd g(model.inequalityCount());
      MatrixXd J(model.inequalityCount(), L.variableCount());
      wpg::evaluateConstraints(model, problem, U, g, &J);
      for (int i = 0; i < L.steps; ++i) {
        if (problem.phase.step_fixed(i)) continue;
        const Vector2d F(U(L.stepX() + i), U(L.stepY() + i));
        const Vector2d n = problem.obstacle_normal.col(0);
        EXPECT_NEAR(g(obstacleRow(model, i, 0)), r - n.dot(F - obstacles[0].center), 1e-12);
        EXPECT_EQ(J(obstacleRow(model, i, 0), L.stepX() + i), -n.x());
        EXPECT_EQ(J(obstacleRow(model, i, 0), L.stepY() + i), -n.y());
        // inside eq. (18)'s feasible set: a satisfied row keeps the step out of the circle
        if (g(obstacleRow(model, i, 0)) <= 0.0) EXPECT_GE((F - obstacles[0].center).norm(), r - 1e-12);
        EXPECT_NEAR(g(obstacleRow(model, i, 1)), 0.05 + w.obstacle_foot_radius -
                                                distance.signedDistance(1, F, nullptr), 1e-12);
      }
    }
  }
  EXPECT_GE(points, 30);
}

TEST(NmpcJacobian, FixedStepRowsAreInactive) {
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  Rng rng(5);
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    const NmpcProblem problem = randomProblem(model, pattern, FootSide::kRight, FixedMode::kFirst, rng);
    const VectorXd U = randomU(model, problem, rng);
    VectorXd g(model.inequalityCount());
    MatrixXd J(model.inequalityCount(), L.variableCount());
    J.setConstant(7.0);
    wpg::evaluateConstraints(model, problem, U, g, &J);
    for (int e = 0; e < feasibilityEdges(model); ++e) {
      EXPECT_EQ(g(feasibilityRow(model, 0, e)), -1.0);
      EXPECT_EQ(J.row(feasibilityRow(model, 0, e)).cwiseAbs().maxCoeff(), 0.0);
    }
    for (bool upper : {true, false}) {
      EXPECT_EQ(g(yawRow(model, 0, upper)), -1.0);
      EXPECT_EQ(J.row(yawRow(model, 0, upper)).cwiseAbs().maxCoeff(), 0.0);
    }
    // Step 2 stays free: its rows are active and depend on step 1's pose (its predecessor).
    EXPECT_NE(J(yawRow(model, 1, true), L.stepYaw() + 0), 0.0);
    EXPECT_NE(J(yawRow(model, 1, true), L.stepYaw() + 1), 0.0);
  }
}

// The yaw derivative of a CoP row, dg/dtheta = a' R'(theta) (z_j - f), depends on the whole
// CoP z_j = Pzs c_hat + Pzu jerks, including the current CoM state term Pzs c_hat.
TEST(NmpcJacobian, CopYawDerivativeIncludesTheComStateTerm) {
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const wpg::LipmPrediction& P = model.prediction();
  Rng rng(9);
  NmpcProblem problem = randomProblem(model, 0, FootSide::kLeft, FixedMode::kNone, rng);
  VectorXd U = randomU(model, problem, rng);
  const double yaw = 0.7;
  U(L.stepYaw() + 0) = yaw;  // pattern 0: sample 1 is on step 1
  ASSERT_EQ(problem.phase.row_step(0), 1);
  const int m = model.inequalityCount(), n = L.variableCount();
  VectorXd g(m);
  MatrixXd J0(m, n), J1(m, n), J2(m, n);
  wpg::evaluateConstraints(model, problem, U, g, &J0);

  const int col = L.stepYaw() + 0;
  const int j = 0;  // first CoP sample
  const double s = std::sin(yaw), c = std::cos(yaw);
  // Edge 0 (normal +x in the foot frame): g = c dx + s dy - b, dg/dtheta = -s dx + c dy.
  const double delta = 0.1;
  NmpcProblem moved_x = problem;
  moved_x.com_x(0) += delta;  // z_j moves by Pzs(j, 0) delta = delta along x
  wpg::evaluateConstraints(model, moved_x, U, g, &J1);
  const double change_x = J1(copRow(model, j, 0), col) - J0(copRow(model, j, 0), col);
  EXPECT_GT(std::abs(change_x), 0.05) << "the yaw column ignores the CoM position";
  EXPECT_NEAR(change_x, -s * P.cop_state(j, 0) * delta, 1e-12);

  NmpcProblem moved_y = problem;
  moved_y.com_y(1) += delta;  // a CoM velocity change moves z_j by Pzs(j, 1) delta along y
  wpg::evaluateConstraints(model, moved_y, U, g, &J2);
  const double change_y = J2(copRow(model, j, 0), col) - J0(copRow(model, j, 0), col);
  EXPECT_GT(std::abs(change_y), 1e-3) << "the yaw column ignores the CoM velocity";
  EXPECT_NEAR(change_y, c * P.cop_state(j, 1) * delta, 1e-12);

  // And the full value: a' R'(theta) (Pzs c_hat + Pzu jerks - f) on every edge of every sample
  // on step 1.
  for (int jj = 0; jj < L.horizon; ++jj) {
    if (problem.phase.row_step(jj) != 1) continue;
    const double zx = P.cop_state.row(jj).dot(problem.com_x) +
                      P.cop_jerk.row(jj).dot(U.segment(L.jerkX(), L.horizon));
    const double zy = P.cop_state.row(jj).dot(problem.com_y) +
                      P.cop_jerk.row(jj).dot(U.segment(L.jerkY(), L.horizon));
    const double dx = zx - U(L.stepX()), dy = zy - U(L.stepY());
    // Foot-frame coordinates (lx, ly) = R(theta)(d); edges +lx, -lx, +ly, -ly.
    const double dlx = -s * dx + c * dy, dly = -c * dx - s * dy;
    const double expected[4] = {dlx, -dlx, dly, -dly};
    for (int e = 0; e < 4; ++e)
      EXPECT_NEAR(J0(copRow(model, jj, e), col), expected[e], 1e-12) << "sample " << jj << " edge " << e;
    // Without the state term the value would differ (the state term is not small here).
    const double zx_jerk_only = P.cop_jerk.row(jj).dot(U.segment(L.jerkX(), L.horizon));
    const double zy_jerk_only = P.cop_jerk.row(jj).dot(U.segment(L.jerkY(), L.horizon));
    const double wrong = -s * (zx_jerk_only - U(L.stepX())) + c * (zy_jerk_only - U(L.stepY()));
    EXPECT_GT(std::abs(J0(copRow(model, jj, 0), col) - wrong), 1e-3);
  }
}

// g(U) against a straightforward computation: the CoP from the prediction matrices, rotated
// into the support foot frame, compared with the rectangle; the step in the previous foot's
// frame compared with the feasibility polygon; the yaw difference with its bound.
TEST(NmpcConstraints, ValuesMatchDirectGeometry) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const wpg::LipmPrediction& P = model.prediction();
  wpg::ConvexPolygon feasibility[2];
  ASSERT_TRUE(feasibility[0].setVertices(w.feasibilityVertices(FootSide::kLeft)));
  ASSERT_TRUE(feasibility[1].setVertices(w.feasibilityVertices(FootSide::kRight)));
  Rng rng(77);
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    for (FootSide side : {FootSide::kLeft, FootSide::kRight}) {
      const NmpcProblem problem = randomProblem(model, pattern, side, FixedMode::kNone, rng);
      const VectorXd U = randomU(model, problem, rng);
      VectorXd g(model.inequalityCount());
      wpg::evaluateConstraints(model, problem, U, g, nullptr);
      const auto& phase = problem.phase;
      const VectorXd zx = P.cop_state * problem.com_x + P.cop_jerk * U.segment(L.jerkX(), L.horizon);
      const VectorXd zy = P.cop_state * problem.com_y + P.cop_jerk * U.segment(L.jerkY(), L.horizon);
      for (int j = 0; j < L.horizon; ++j) {
        const int step = phase.row_step(j) - 1;
        const Vector3d foot = step < 0 ? phase.support_pose
                                       : Vector3d(U(L.stepX() + step), U(L.stepY() + step),
                                                  U(L.stepYaw() + step));
        const double hl = step < 0 ? phase.support_half_length : w.copHalfLength();
        const double hw = step < 0 ? phase.support_half_width : w.copHalfWidth();
        const Eigen::Rotation2Dd R(foot.z());
        const Vector2d local = R.inverse() * (Vector2d(zx(j), zy(j)) - foot.head<2>());
        const double expected[4] = {local.x() - hl, -local.x() - hl, local.y() - hw, -local.y() - hw};
        for (int e = 0; e < 4; ++e)
          EXPECT_NEAR(g(copRow(model, j, e)), expected[e], 1e-12)
              << "pattern " << pattern << " sample " << j << " edge " << e;
        // Inside the rectangle iff every row is <= 0.
        const bool inside = std::abs(local.x()) <= hl && std::abs(local.y()) <= hw;
        const double worst = g.segment(copRow(model, j, 0), 4).maxCoeff();
        EXPECT_EQ(inside, worst <= 0.0);
      }
      for (int i = 0; i < L.steps; ++i) {
        const Vector3d prev = i == 0 ? phase.support_pose
                                     : Vector3d(U(L.stepX() + i - 1), U(L.stepY() + i - 1),
                                                U(L.stepYaw() + i - 1));
        const Vector3d step(U(L.stepX() + i), U(L.stepY() + i), U(L.stepYaw() + i));
        const Eigen::Rotation2Dd R(prev.z());
        const Vector2d local = R.inverse() * (step.head<2>() - prev.head<2>());
        const auto& polygon = feasibility[phase.stepSide(i) == FootSide::kLeft ? 0 : 1];
        ASSERT_EQ(polygon.edgeCount(), feasibilityEdges(model));
        double worst = -1e300;
        for (int e = 0; e < feasibilityEdges(model); ++e) worst = std::max(worst, g(feasibilityRow(model, i, e)));
        EXPECT_NEAR(worst, polygon.violation(local), 1e-12) << "pattern " << pattern << " step " << i;
        const double change = step.z() - prev.z();
        EXPECT_NEAR(g(yawRow(model, i, true)), change - w.max_step_yaw_change, 1e-12);
        EXPECT_NEAR(g(yawRow(model, i, false)), -change - w.max_step_yaw_change, 1e-12);
      }
    }
  }
}

// Known geometry, to pin the rotation direction: a foot turned by +90 degrees (toes along
// world +y). A CoP 1 cm in front of the ankle (world +y) touches the front edge (+x of the
// foot) and not the side edges; a left step 0.3 m to the foot's left (world -x) is feasible.
TEST(NmpcConstraints, RotationDirectionOnKnownGeometry) {
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  NmpcProblem problem = model.makeProblem();
  auto& phase = problem.phase;
  phase.pattern = 3;
  model.rowStepsOf(3, phase.row_step);
  phase.first_step_side = FootSide::kLeft;
  phase.support_pose = Vector3d(1.0, 2.0, M_PI / 2);
  phase.support_half_length = w.copHalfLength();
  phase.support_half_width = w.copHalfWidth();
  const double offset = 0.01;
  problem.com_x = Vector3d(1.0, 0.0, 0.0);           // at rest: z = c for every sample
  problem.com_y = Vector3d(2.0 + offset, 0.0, 0.0);
  VectorXd U = VectorXd::Zero(L.variableCount());
  U(L.stepX() + 0) = 1.0 - 0.3;  // left step: world -x is the foot's +y
  U(L.stepY() + 0) = 2.0;
  U(L.stepYaw() + 0) = M_PI / 2 + 0.03;
  U(L.stepX() + 1) = 1.0 - 0.3 + 0.01;  // right step from the left one, back next to the first foot
  U(L.stepY() + 1) = 2.0 + 0.15;
  U(L.stepYaw() + 1) = M_PI / 2 + 0.06;
  VectorXd g(model.inequalityCount());
  wpg::evaluateConstraints(model, problem, U, g, nullptr);
  const double hl = w.copHalfLength(), hw = w.copHalfWidth();
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(g(copRow(model, j, 0)), offset - hl, 1e-12);
    EXPECT_NEAR(g(copRow(model, j, 1)), -offset - hl, 1e-12);
    EXPECT_NEAR(g(copRow(model, j, 2)), -hw, 1e-12);
    EXPECT_NEAR(g(copRow(model, j, 3)), -hw, 1e-12);
  }
  for (int e = 0; e < feasibilityEdges(model); ++e) EXPECT_LE(g(feasibilityRow(model, 0, e)), 0.0) << e;
  // The right step, 0.15 m along world +y (the left foot's forward direction) and 0.01 m
  // along world +x, is almost straight ahead of the left foot: outside the right-step polygon.
  double worst1 = -1.0;
  for (int e = 0; e < feasibilityEdges(model); ++e) worst1 = std::max(worst1, g(feasibilityRow(model, 1, e)));
  // local = R(-theta0)(dx, dy) with theta0 = pi/2 + 0.03: about (0.15, -0.01): outside the
  // right-step polygon (y must be <= -0.2).
  EXPECT_GT(worst1, 0.15);
  EXPECT_NEAR(g(yawRow(model, 0, true)), 0.03 - w.max_step_yaw_change, 1e-12);
  EXPECT_NEAR(g(yawRow(model, 1, false)), -0.03 - w.max_step_yaw_change, 1e-12);

  // The same left step on the wrong side (world +x = the foot's -y) is infeasible.
  U(L.stepX() + 0) = 1.0 + 0.3;
  wpg::evaluateConstraints(model, problem, U, g, nullptr);
  double worst0 = -1.0;
  for (int e = 0; e < feasibilityEdges(model); ++e) worst0 = std::max(worst0, g(feasibilityRow(model, 0, e)));
  EXPECT_GT(worst0, 0.4);
}

}  // namespace
