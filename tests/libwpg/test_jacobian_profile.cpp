// The model's Jacobian profile (NmpcModel::jacobianProfile, ConstraintFamily::jerkSamplesOfRow)
// covers every entry the families write, whatever the problem and the plan, so that the
// solver's products that skip the rest skip zeros only; and it does skip: a CoP row of sample
// j reaches the jerks up to j only.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>

#include "wpg/nmpc.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/obstacles.hpp"
#include "../common/obstacle_fields.hpp"
#include "nmpc_test_problems.hpp"

namespace {

using Eigen::MatrixXd;
using namespace wpg_test;

// A caller's family that says nothing of its jerks (the default jerkSamplesOfRow): one row,
// the last sample's x jerk below 1.
class LastJerkBound final : public wpg::NamedConstraintFamily {
 public:
  LastJerkBound() : NamedConstraintFamily("last_jerk", "m/s^3", wpg::RelaxationGroup::kBalance) {}
  int rowCount(const NmpcModel&) const override { return 1; }
  void evaluate(const NmpcModel& model, const NmpcProblem&, const Eigen::Ref<const VectorXd>& U,
                Eigen::Ref<VectorXd> g, wpg::JacobianRows* jacobian) const override {
    const int column = model.layout().jerkX() + model.layout().horizon - 1;
    g(0) = U(column) - 1.0;
    if (jacobian) (*jacobian)(0, column) = 1.0;
  }
  int shiftedRow(const NmpcModel&, int, bool) const override { return -1; }
};

TEST(JacobianProfile, CoversEveryJacobianTheFamiliesWrite) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  w.max_landing_speed = 0.8;
  w.max_landing_yaw_rate = 1.5;
  w.max_swing_speed = 1.0;  // swing_reach registered
  NmpcModel model(w, 3);
  model.addConstraintFamily(std::make_shared<LastJerkBound>());
  const wpg::ObstacleSet obstacles(wpg_test::threeObstacles());
  const int m = model.inequalityCount(), n = model.layout().variableCount();
  const wpg::qp::ColumnProfile& profile = model.jacobianProfile();
  ASSERT_EQ(profile.rows(), m);
  ASSERT_EQ(profile.cols(), n);
  Rng rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    const int pattern = static_cast<int>(rng.uniform(0.0, model.patternCount() - 1e-9));
    NmpcProblem problem =
        randomProblem(model, pattern, rng.chance(0.5) ? FootSide::kLeft : FootSide::kRight,
                      rng.chance(0.5) ? FixedMode::kRandom : FixedMode::kNone, rng);
    problem.obstacles = &obstacles;
    for (int k = 0; k < model.obstacleSlots(); ++k) problem.obstacle_slot(k) = k;
    problem.landing_bounded = rng.chance(0.7);
    problem.swing_reach_bounded = rng.chance(0.7);
    problem.swing_reach_lower.setConstant(-0.5);
    problem.swing_reach_upper.setConstant(0.5);
    const VectorXd U = randomU(model, problem, rng);
    VectorXd g(m);
    MatrixXd J = MatrixXd::Zero(m, n);
    wpg::evaluateConstraints(model, problem, U, g, &J);
    ASSERT_TRUE(profile.covers(J)) << "trial " << trial;
  }
}

TEST(JacobianProfile, SkipsTheJerksACopRowDoesNotReach) {
  const WalkingParameters w;
  NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const int cop = model.findFamily("cop");
  ASSERT_GE(cop, 0);
  const int m = model.inequalityCount();
  // The jerk of sample k is in the CoP rows of samples k..N-1 only, on both axes: J with ones
  // there and on the step columns is covered; a one in the CoP row of sample k - 1 is not.
  MatrixXd J = MatrixXd::Zero(m, L.variableCount());
  J.middleCols(L.stepX(), L.steps).setOnes();
  J.middleCols(L.stepY(), 2 * L.steps).setOnes();
  for (int k = 0; k < L.horizon; ++k) {
    for (int row = wpg::CopRows::row(k, 0); row < wpg::CopRows::count(model); ++row) {
      J(model.familyFirstRow(cop) + row, L.jerkX() + k) = 1.0;
      J(model.familyFirstRow(cop) + row, L.jerkY() + k) = 1.0;
    }
  }
  EXPECT_TRUE(model.jacobianProfile().covers(J));
  for (int k = 1; k < L.horizon; ++k) {
    for (int column : {L.jerkX() + k, L.jerkY() + k}) {
      MatrixXd outside = J;
      outside(model.familyFirstRow(cop) + wpg::CopRows::row(k - 1, 3), column) = 1.0;
      EXPECT_FALSE(model.jacobianProfile().covers(outside)) << "sample " << k;
    }
  }
  // No other family's row reaches a jerk.
  MatrixXd below = J;
  below(model.familyFirstRow(cop) + wpg::CopRows::count(model), L.jerkX()) = 1.0;
  EXPECT_FALSE(model.jacobianProfile().covers(below));

  // A family without jerkSamplesOfRow is taken to reach every jerk.
  model.addConstraintFamily(std::make_shared<LastJerkBound>());
  MatrixXd with_row = MatrixXd::Zero(m + 1, L.variableCount());
  with_row.topRows(m) = J;
  with_row.row(m).setOnes();
  EXPECT_TRUE(model.jacobianProfile().covers(with_row));
}

}  // namespace
