// Steps that pushes call for: a robot stepping in place (zero_command:
// step_in_place, the situation of the paper's on-the-spot pushes, Sec. V-B) and a standing
// robot whose capture point a push carries out of its CoP's reach (standing_push_response).
// Whole walks through generateWalk; the forces are those the acceptance names and the
// docs/formulation.md table measures.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using wpg::IterationStatus;
using wpg::SupportState;
using wpg::WalkingParameters;
using wpg::WalkRequest;
using wpg::WalkResult;
using wpg::WalkTrajectory;

WalkRequest standStill(double duration) {
  WalkRequest request;
  request.duration = duration;
  request.reference = {{0.0, Vector3d::Zero()}};
  return request;
}

WalkingParameters steppingInPlace() {
  WalkingParameters w;
  w.zero_command = wpg::ZeroCommandGait::kStepInPlace;
  return w;
}

// Every CoP sample inside the support it is assigned to: the walk is dynamically balanced,
// not merely "not fallen". Double support: inside the rectangle hull of the two soles (the
// feet are parallel or nearly so here); single support: inside the support sole.
void expectCopOnTheSoles(const WalkTrajectory& tr, const WalkingParameters& w) {
  const double tolerance = 1e-6;
  for (std::size_t i = 0; i < tr.size(); i += 4) {
    const Vector2d cop = tr.cop[i];
    auto inside = [&](const Eigen::Vector4d& foot, double extra_half_width) {
      const double c = std::cos(foot(3)), s = std::sin(foot(3));
      const Vector2d d = cop - foot.head<2>();
      return std::abs(c * d.x() + s * d.y()) <= 0.5 * w.foot_length + tolerance &&
             std::abs(-s * d.x() + c * d.y()) <= 0.5 * w.foot_width + extra_half_width + tolerance;
    };
    if (tr.support[i] == SupportState::kLeft) {
      EXPECT_TRUE(inside(tr.left_foot[i], 0.0)) << "t = " << tr.time[i];
    } else if (tr.support[i] == SupportState::kRight) {
      EXPECT_TRUE(inside(tr.right_foot[i], 0.0)) << "t = " << tr.time[i];
    } else {
      // Convex hull of the two soles, checked as the segment between the ankles grown by a
      // sole: the CoP lies within half a sole of some point of that segment.
      const Vector2d a = tr.left_foot[i].head<2>(), b = tr.right_foot[i].head<2>();
      const double t = std::clamp((cop - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const Vector2d nearest = a + t * (b - a);
      EXPECT_LE((cop - nearest).norm(),
                0.5 * std::hypot(w.foot_length, w.foot_width) + tolerance)
          << "t = " << tr.time[i];
    }
  }
}

int stepsTaken(const WalkTrajectory& tr) { return static_cast<int>(tr.footsteps.size()) - 2; }

// --- stepping in place ---------------------------------------------------------------------

TEST(StepInPlace, KeepsSteppingOnTheSpotWithAZeroCommand) {
  const WalkingParameters w = steppingInPlace();
  const WalkResult r = wpg::generateWalk(w, standStill(8.0));
  ASSERT_TRUE(r.success) << r.message;
  const WalkTrajectory& tr = r.trajectory;
  // Starting double support (0.8 s), then one landing per step duration to the end.
  const int expected = static_cast<int>(
      std::floor((8.0 - w.start_double_support_samples * w.sampling_period) / w.stepDuration()));
  EXPECT_GE(stepsTaken(tr), expected - 1);
  // In place: the feet stay about where they started.
  for (std::size_t k = 2; k < tr.footsteps.size(); ++k)
    EXPECT_LT(std::abs(tr.footsteps[k].pose.x()), 0.05) << "step " << k;
  EXPECT_LT(tr.com.back().head<2>().norm(), 0.1);
  expectCopOnTheSoles(tr, w);
  // The paper's default (stop) never starts on a zero command.
  const WalkResult still = wpg::generateWalk(WalkingParameters(), standStill(8.0));
  ASSERT_TRUE(still.success) << still.message;
  EXPECT_EQ(stepsTaken(still.trajectory), 0);
}

// A 100 ms push of +-100 N sagittal while stepping in place, at the phases of a step where
// the swing still has time to catch it (docs/formulation.md, "Pushes: stepping in place").
TEST(StepInPlace, SurvivesSagittalPushesOf100N) {
  const WalkingParameters w = steppingInPlace();
  for (const double force : {100.0, -100.0}) {
    for (const double t : {3.3, 3.5, 3.7}) {
      WalkRequest request = standStill(8.0);
      request.pushes.push_back({t, Vector2d(force, 0.0), 0.1});
      const WalkResult r = wpg::generateWalk(w, request);
      EXPECT_TRUE(r.success) << force << " N at t = " << t << ": " << r.message;
      EXPECT_NEAR(r.trajectory.time.back(), 8.0, 1e-9);
      expectCopOnTheSoles(r.trajectory, w);
    }
  }
}

// --- a standing robot pushed ---------------------------------------------------------------

TEST(StandingPush, SteppingRecoversFrom60NSagittalAndStandsAgain) {
  const WalkingParameters w;
  for (const double force : {60.0, -60.0}) {
    WalkRequest request = standStill(6.0);
    request.pushes.push_back({1.0, Vector2d(force, 0.0), 0.1});
    const WalkResult r = wpg::generateWalk(w, request);
    ASSERT_TRUE(r.success) << force << " N: " << r.message;
    const WalkTrajectory& tr = r.trajectory;
    for (const auto& m : tr.mpc) EXPECT_EQ(m.status, IterationStatus::kSolved) << m.time;
    // It stepped in the push's direction ...
    ASSERT_GE(stepsTaken(tr), 1) << force;
    EXPECT_GT(tr.footsteps[2].pose.x() * force, 0.0);
    EXPECT_GT(tr.footsteps[2].landing_time, 1.0);
    // Seen at the first sample after the push began (1.1 s), then the short start and swing.
    EXPECT_LE(tr.footsteps[2].landing_time,
              1.1 + w.sampling_period * (w.push_start_double_support_samples +
                                         w.push_step_swing_samples) + 1e-9);
    // ... and stands again, at rest, for the last second.
    for (std::size_t i = tr.size() - 200; i < tr.size(); ++i)
      ASSERT_EQ(tr.support[i], SupportState::kDouble) << "t = " << tr.time[i];
    EXPECT_LT(tr.com_vel.back().head<2>().norm(), 0.02);
    expectCopOnTheSoles(tr, w);
  }
}

TEST(StandingPush, WithoutStepsTheSamePushFalls) {
  WalkingParameters w;
  w.standing_push_response = wpg::StandingPushResponse::kStand;
  WalkRequest request = standStill(6.0);
  request.pushes.push_back({1.0, Vector2d(60.0, 0.0), 0.1});
  const WalkResult r = wpg::generateWalk(w, request);
  EXPECT_FALSE(r.success);
  ASSERT_FALSE(r.trajectory.mpc.empty());
  EXPECT_EQ(r.trajectory.mpc.back().status, IterationStatus::kFallen);
  EXPECT_EQ(stepsTaken(r.trajectory), 0);
}

TEST(StandingPush, AStandingRobotLeftAloneNeverSteps) {
  // Standing at rest, and after a stop: the capture point stays in the standing rectangle
  // (or the stop would be followed by stray steps).
  WalkRequest request;
  request.duration = 10.0;
  request.reference = {{0.0, Vector3d::Zero()}, {1.0, Vector3d(0.2, 0, 0)}, {6.0, Vector3d::Zero()}};
  const WalkResult r = wpg::generateWalk(WalkingParameters(), request);
  ASSERT_TRUE(r.success) << r.message;
  WalkingParameters stand;
  stand.standing_push_response = wpg::StandingPushResponse::kStand;
  const WalkResult reference = wpg::generateWalk(stand, request);
  ASSERT_EQ(r.trajectory.footsteps.size(), reference.trajectory.footsteps.size());
  EXPECT_EQ(r.trajectory.com.back(), reference.trajectory.com.back());
}

}  // namespace
