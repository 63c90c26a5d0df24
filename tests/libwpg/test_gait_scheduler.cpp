// GaitScheduler, the walking phase bookkeeping, on its own: start (starting double support,
// first swing side), steps (swing, landing, completion), stop (free step, side-by-side step,
// standing), stepping in place, steps started by a push, and the PhaseStructure it gives each
// sample.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <utility>

#include "wpg/gait_scheduler.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using wpg::FootSide;
using wpg::GaitScheduler;
using wpg::SupportState;
using wpg::WalkingParameters;

TEST(GaitScheduler, StandsUntilANonZeroCommand) {
  const WalkingParameters w;
  GaitScheduler gait(w);
  gait.reset(Vector3d(1.0, 2.0, 0.0));
  EXPECT_TRUE(gait.standing());
  EXPECT_EQ(gait.footPose(FootSide::kLeft), Vector3d(1.0, 2.095, 0.0));
  EXPECT_EQ(gait.footPose(FootSide::kRight), Vector3d(1.0, 1.905, 0.0));
  // The first sample after a reset has a new structure; standing on does not.
  EXPECT_TRUE(gait.beginSample(Vector3d::Zero(), Vector2d(1.0, 2.0)).structure_changed);
  const GaitScheduler::SampleStart still = gait.beginSample(Vector3d::Zero(), Vector2d(1.0, 2.0));
  EXPECT_FALSE(still.structure_changed);
  EXPECT_FALSE(still.started);
  EXPECT_EQ(gait.supportState(), SupportState::kDouble);
  wpg::NmpcModel model(w);
  wpg::NmpcProblem problem = model.makeProblem();
  gait.fillPhase(model, problem.phase);
  EXPECT_EQ(problem.phase.pattern, model.standingPattern());
  EXPECT_EQ(problem.phase.support_pose, Vector3d(1.0, 2.0, 0.0));
  EXPECT_NEAR(problem.phase.support_half_width, 0.095 + w.copHalfWidth(), 1e-12);
  EXPECT_EQ(problem.phase.step_fixed.sum(), w.previewed_steps);
}

TEST(GaitScheduler, FirstSwingIsOnTheSideOfTheMotion) {
  const WalkingParameters w;
  for (const auto& [command, side] :
       {std::pair{Vector3d(0.2, 0.0, 0.0), FootSide::kLeft},
        std::pair{Vector3d(0.0, 0.1, 0.0), FootSide::kLeft},
        std::pair{Vector3d(0.2, -0.1, 0.0), FootSide::kRight},
        std::pair{Vector3d(0.2, 0.0, -0.1), FootSide::kRight}}) {
    GaitScheduler gait(w);
    const GaitScheduler::SampleStart start = gait.beginSample(command, Vector2d::Zero());
    EXPECT_TRUE(start.started);
    EXPECT_TRUE(start.structure_changed);
    EXPECT_EQ(start.first_swing, side) << command.transpose();
  }
}

// One walk through the phases: start, steps with a landing each, stop, standing.
TEST(GaitScheduler, StartsStepsAndStops) {
  const WalkingParameters w;
  const int S = w.stepSamples();
  wpg::NmpcModel model(w);
  wpg::NmpcProblem problem = model.makeProblem();
  GaitScheduler gait(w);
  const Vector3d forward(0.2, 0.0, 0.0);
  double t = 0.0;
  bool starting = false, swinging = false;  // during the sample
  auto sample = [&](const Vector3d& command, const Vector3d& landing) {
    const GaitScheduler::SampleStart start = gait.beginSample(command, Vector2d::Zero());
    gait.fillPhase(model, problem.phase);
    starting = gait.starting();
    swinging = gait.swinging();
    t += w.sampling_period;
    return std::make_pair(start, gait.endSample(landing, t));
  };
  // Starting double support: start_double_support_samples samples without a swing, the CoP
  // on both feet in all but the last (on the first support foot, as at a step's end).
  for (int k = 0; k < w.start_double_support_samples; ++k) {
    const auto [start, end] = sample(forward, Vector3d::Zero());
    EXPECT_EQ(start.started, k == 0);
    EXPECT_EQ(starting, k + 1 < w.start_double_support_samples) << "sample " << k;
    EXPECT_FALSE(swinging);
    EXPECT_FALSE(end.landed);
    EXPECT_EQ(end.step_completed, k + 1 == w.start_double_support_samples);
  }
  // Steps: swing S-1 samples (left first), land at the end of the last, complete at the next.
  FootSide swing = FootSide::kLeft;
  for (int step = 0; step < 3; ++step, swing = wpg::otherSide(swing)) {
    const Vector3d landing(0.15 * (step + 1), swing == FootSide::kLeft ? 0.1 : -0.1, 0.0);
    for (int m = 0; m < S; ++m) {
      const auto [start, end] = sample(forward, landing);
      EXPECT_FALSE(start.structure_changed);
      EXPECT_EQ(problem.phase.pattern, S - 1 - m);
      EXPECT_EQ(swinging, m < S - 1);
      EXPECT_EQ(problem.phase.first_step_side, swing);
      EXPECT_EQ(end.landed, m == S - 2) << "step " << step << " sample " << m;
      EXPECT_EQ(end.step_completed, m == S - 1);
      if (end.landed) {
        EXPECT_EQ(gait.footPose(swing), landing);
        EXPECT_EQ(gait.lastLanding().pose, landing);
        EXPECT_EQ(gait.lastLanding().side, swing);
        EXPECT_DOUBLE_EQ(gait.lastLanding().landing_time, t);
      }
    }
  }
  // Stop: a zero command at a step start twice makes the second step the side-by-side one.
  int samples_to_stand = 0;
  bool fixed_side_by_side = false;
  while (!gait.standing() && samples_to_stand < 4 * S) {
    const Vector3d support = gait.footPose(gait.supportSide());
    sample(Vector3d::Zero(), gait.footPose(wpg::otherSide(gait.supportSide())));
    // Before it lands (pattern > 0), a fixed first step is the final side-by-side one.
    if (!gait.standing() && problem.phase.pattern > 0 && problem.phase.step_fixed(0) == 1) {
      const double side = problem.phase.first_step_side == FootSide::kLeft ? 1.0 : -1.0;
      const Vector3d expected(support.x(), support.y() + side * w.stop_foot_separation, support.z());
      EXPECT_TRUE(problem.phase.fixed_step_pose.col(0).isApprox(expected, 1e-12));
      fixed_side_by_side = true;
    }
    ++samples_to_stand;
  }
  EXPECT_TRUE(fixed_side_by_side);
  EXPECT_TRUE(gait.standing());
  EXPECT_LE(samples_to_stand, 2 * S + 1);
}

// At a landing, the capture point's offset from the landed ankle is read along the landed
// foot's own lateral axis (its yaw), positive towards the foot that lifts next, whichever side
// that is; the component along the foot does not count.
TEST(GaitScheduler, CaptureOffsetAtALandingPointsTowardsTheLiftingFoot) {
  const WalkingParameters w;
  const int S = w.stepSamples();
  GaitScheduler gait(w);
  const Vector3d forward(0.2, 0.0, 0.0);
  for (int k = 0; k + 1 < w.start_double_support_samples; ++k) {  // the start (as above)
    gait.beginSample(forward, Vector2d::Zero());
    gait.endSample(Vector3d::Zero(), 0.0);
  }
  // The end of a start is a step boundary where no swing foot landed.
  EXPECT_TRUE(gait.atLanding());
  EXPECT_FALSE(gait.atSwingLanding());
  gait.beginSample(forward, Vector2d::Zero());
  gait.endSample(Vector3d::Zero(), 0.0);
  const Vector3d landings[2] = {Vector3d(0.15, 0.1, 0.3), Vector3d(0.3, -0.1, -0.2)};
  for (const Vector3d& landing : landings) {
    const FootSide swing = wpg::otherSide(gait.supportSide());
    for (int m = 0; m < S - 1; ++m) {
      EXPECT_FALSE(gait.atLanding());
      gait.beginSample(forward, Vector2d::Zero());
      gait.endSample(landing, 0.0);
    }
    ASSERT_TRUE(gait.atSwingLanding());
    ASSERT_EQ(gait.footPose(swing), landing);
    EXPECT_EQ(gait.supportSide(), wpg::otherSide(swing));  // the foot that lifts next
    const Vector2d along(std::cos(landing.z()), std::sin(landing.z()));
    const Vector2d left(-std::sin(landing.z()), std::cos(landing.z()));
    // The lifting foot is on the landed foot's right when the left foot landed.
    const Vector2d towards_lifting = swing == FootSide::kLeft ? Vector2d(-left) : left;
    const Vector2d ankle = landing.head<2>();
    EXPECT_NEAR(gait.captureOffsetTowardsLiftingFoot(ankle + 0.05 * towards_lifting + 0.1 * along),
                0.05, 1e-12);
    EXPECT_NEAR(gait.captureOffsetTowardsLiftingFoot(ankle - 0.02 * towards_lifting - 0.3 * along),
                -0.02, 1e-12);
    gait.beginSample(forward, Vector2d::Zero());
    gait.endSample(landing, 0.0);  // the step completes: the landed foot becomes the support
  }
}

// zero_command: step_in_place: a zero command starts a standing robot (normal starting double
// support) and never stops it.
TEST(GaitScheduler, StepInPlaceStartsAndNeverStops) {
  WalkingParameters w;
  w.zero_command = wpg::ZeroCommandGait::kStepInPlace;
  GaitScheduler gait(w);
  const GaitScheduler::SampleStart start = gait.beginSample(Vector3d::Zero(), Vector2d::Zero());
  EXPECT_TRUE(start.started);
  EXPECT_EQ(start.first_swing, FootSide::kLeft);
  int landings = 0;
  for (int k = 0; k < w.start_double_support_samples + 6 * w.stepSamples(); ++k) {
    if (k > 0) EXPECT_FALSE(gait.beginSample(Vector3d::Zero(), Vector2d::Zero()).started);
    EXPECT_FALSE(gait.standing()) << "sample " << k;
    const Vector3d in_place = gait.footPose(wpg::otherSide(gait.supportSide()));
    landings += gait.endSample(in_place, 0.1 * (k + 1)).landed ? 1 : 0;
  }
  EXPECT_EQ(landings, 6);
}

// standing_push_response: step: a capture point inside the standing rectangle changes nothing;
// out of it the robot starts after push_start_double_support_samples, the foot on the capture
// point's side first; a zero command then stops it again (free step, side-by-side step).
TEST(GaitScheduler, PushedStandingRobotStepsThenStops) {
  const WalkingParameters w;
  const double half_length = w.copHalfLength();
  const double half_width = 0.5 * w.initial_foot_separation + w.copHalfWidth();
  {
    GaitScheduler gait(w);
    gait.reset(Vector3d(1.0, 2.0, 0.5));
    EXPECT_FALSE(gait.outsideStandingSupport(Vector2d(1.0, 2.0)));
    // Just inside / just outside along the rotated axes (yaw 0.5).
    const Vector2d along(std::cos(0.5), std::sin(0.5)), across(-std::sin(0.5), std::cos(0.5));
    EXPECT_FALSE(gait.outsideStandingSupport(Vector2d(1.0, 2.0) + 0.99 * half_length * along));
    EXPECT_TRUE(gait.outsideStandingSupport(Vector2d(1.0, 2.0) + 1.01 * half_length * along));
    EXPECT_FALSE(gait.outsideStandingSupport(Vector2d(1.0, 2.0) - 0.99 * half_width * across));
    EXPECT_TRUE(gait.outsideStandingSupport(Vector2d(1.0, 2.0) - 1.01 * half_width * across));
    EXPECT_FALSE(gait.beginSample(Vector3d::Zero(), Vector2d(1.0, 2.0)).started);
    const GaitScheduler::SampleStart pushed =
        gait.beginSample(Vector3d::Zero(), Vector2d(1.0, 2.0) - 1.5 * half_width * across);
    EXPECT_TRUE(pushed.started);
    EXPECT_EQ(pushed.first_swing, FootSide::kRight);  // pushed to the right
  }
  {
    WalkingParameters stand = w;
    stand.standing_push_response = wpg::StandingPushResponse::kStand;
    GaitScheduler gait(stand);
    EXPECT_FALSE(gait.beginSample(Vector3d::Zero(), Vector2d(0.1, 0.0)).started);
    EXPECT_TRUE(gait.standing());
  }
  GaitScheduler gait(w);
  const Vector2d ahead(2.0 * half_length, 0.0);  // a sagittal push: ties go to the left foot
  const GaitScheduler::SampleStart start = gait.beginSample(Vector3d::Zero(), ahead);
  ASSERT_TRUE(start.started);
  EXPECT_EQ(start.first_swing, FootSide::kLeft);
  // push_start_double_support_samples, then a swing of push_step_swing_samples; the zero
  // command does not cancel the start, and after the side-by-side step the robot stands again.
  int samples = 0, landings = 0, first_swing_sample = -1, first_landing_sample = -1;
  double t = 0.0;
  while (samples < 10 * w.stepSamples()) {
    if (samples > 0) gait.beginSample(Vector3d::Zero(), Vector2d::Zero());
    if (gait.standing()) break;
    if (gait.swinging() && first_swing_sample < 0) first_swing_sample = samples;
    const Vector3d support = gait.footPose(gait.supportSide());
    const double side = gait.supportSide() == FootSide::kLeft ? -1.0 : 1.0;
    t += w.sampling_period;
    const bool landed = gait.endSample(support + Vector3d(0.05, side * 0.2, 0.0), t).landed;
    if (landed && first_landing_sample < 0) first_landing_sample = samples;
    landings += landed ? 1 : 0;
    ++samples;
  }
  EXPECT_TRUE(gait.standing());
  EXPECT_EQ(first_swing_sample, w.push_start_double_support_samples);
  EXPECT_EQ(first_landing_sample - first_swing_sample + 1, w.push_step_swing_samples);
  EXPECT_EQ(landings, 2);  // the step that catches the push (the free step), the final step
}

}  // namespace
