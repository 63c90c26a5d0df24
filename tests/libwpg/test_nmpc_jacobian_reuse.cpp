// The solver hands each family that rewritesJacobianRows() the Jacobian rows of the previous
// sample instead of zeroed ones (ConstraintFamily::rewritesJacobianRows): evaluated over what
// an earlier problem left there, every such family must write exactly, bit for bit, the rows
// it writes into zeros, whatever the two problems' patterns, fixed steps, obstacle slots,
// landing bounds and plans.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "wpg/nmpc.hpp"
#include "wpg/obstacles.hpp"
#include "../common/obstacle_fields.hpp"
#include "nmpc_test_problems.hpp"

namespace {

using Eigen::MatrixXd;
using namespace wpg_test;

// A random problem of the model with random obstacle slots (some empty) and landing bound.
NmpcProblem randomFullProblem(const NmpcModel& model, const wpg::ObstacleSet& obstacles,
                              Rng& rng) {
  const int pattern = static_cast<int>(rng.uniform(0.0, model.patternCount() - 1e-9));
  const FixedMode modes[] = {FixedMode::kNone, FixedMode::kFirst, FixedMode::kRandom,
                             FixedMode::kAll};
  const FixedMode mode = modes[static_cast<int>(rng.uniform(0.0, 4.0 - 1e-9))];
  NmpcProblem problem = randomProblem(
      model, pattern, rng.chance(0.5) ? FootSide::kLeft : FootSide::kRight, mode, rng);
  problem.obstacles = &obstacles;
  for (int k = 0; k < model.obstacleSlots(); ++k)
    problem.obstacle_slot(k) =
        rng.chance(0.3) ? -1
                        : static_cast<int>(rng.uniform(0.0, obstacles.obstacleCount() - 1e-9));
  for (int k = 0; k < model.obstacleSlots(); ++k) {
    if (rng.chance(0.5)) {
      const double angle = rng.uniform(-3.0, 3.0);
      problem.obstacle_normal.col(k) = Eigen::Vector2d(std::cos(angle), std::sin(angle));
      problem.obstacle_offset(k) = rng.uniform(-1.0, 1.0);
    }
  }
  problem.landing_bounded = rng.chance(0.7);
  problem.previous_landing = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.yaw());
  problem.landing_time_left = rng.uniform(0.1, 0.8);
  return problem;
}

TEST(NmpcJacobianReuse, RewritingFamiliesGiveTheRowsOfAZeroedJacobian) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  w.max_landing_speed = 0.8;     // landing_bound and landing_yaw_bound have rows
  w.max_landing_yaw_rate = 1.5;
  const NmpcModel model(w, 3);
  const wpg::ObstacleSet obstacles(wpg_test::threeObstacles());
  const int n = model.layout().variableCount();
  // Every built-in family rewrites its rows: the solver never zeroes the Jacobian.
  for (int k = 0; k < model.familyCount(); ++k) {
    EXPECT_TRUE(model.family(k).rewritesJacobianRows()) << model.family(k).name();
    EXPECT_GT(model.familyRowCount(k), 0) << model.family(k).name();
  }
  Rng rng(77);
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const NmpcProblem before = randomFullProblem(model, obstacles, rng);
    const NmpcProblem after = randomFullProblem(model, obstacles, rng);
    const VectorXd U_before = randomU(model, before, rng);
    const VectorXd U_after = randomU(model, after, rng);
    for (int k = 0; k < model.familyCount(); ++k) {
      const wpg::ConstraintFamily& family = model.family(k);
      if (!family.rewritesJacobianRows()) continue;
      const int rows = model.familyRowCount(k);
      VectorXd g_fresh(rows), g_reused(rows);
      MatrixXd fresh = MatrixXd::Zero(rows, n), reused = MatrixXd::Zero(rows, n);
      wpg::JacobianRows fresh_rows(fresh), reused_rows(reused);
      family.evaluate(model, before, U_before, g_reused, &reused_rows);
      family.evaluate(model, after, U_after, g_reused, &reused_rows);
      family.evaluate(model, after, U_after, g_fresh, &fresh_rows);
      ASSERT_TRUE((fresh.array() == reused.array()).all())
          << family.name() << ", trial " << trial << ": largest difference "
          << (fresh - reused).cwiseAbs().maxCoeff();
      ASSERT_TRUE((g_fresh.array() == g_reused.array()).all()) << family.name();
      ++compared;
    }
  }
  EXPECT_EQ(compared, 400 * model.familyCount());
}

}  // namespace
