// The paper's two obstacle experiments (Sec. V, Fig. 8) as shipped scenarios, run as `wpg run`
// does (FCL world as the obstacle distance) and checked on the data: where the robot goes,
// how it turns, and the clearance of every footstep measured with FCL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/planning/world.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

struct Experiment {
  wpg::datasets::Scenario scenario;
  wpg::WalkResult result;
  wpg::planning::FootstepObstacleReport steps;
};

Experiment run(const std::string& name, const std::vector<std::string>& overrides = {}) {
  Experiment e;
  e.scenario = wpg::datasets::loadScenario(kSource + "/datasets/scenarios/" + name + ".yaml",
                                           overrides, kSource + "/robots");
  const wpg::planning::World world(e.scenario.request.obstacles);
  e.result = wpg::generateWalk(e.scenario.walking, e.scenario.request);
  e.steps = wpg::planning::checkFootsteps(world, e.scenario.walking, e.result.trajectory);
  return e;
}

// Every step centre stays beyond radius + margin + obstacle_foot_radius (the constraint the
// NMPC enforces: centre clearance >= 0), so the whole sole stays out of the margin (FCL:
// positive clearance). `blocked`: the walk ends blocked (wpg/progress_monitor.hpp), and
// nothing else fails it.
void expectEveryStepClear(const Experiment& e, bool blocked = false) {
  ASSERT_EQ(e.result.blocked, blocked) << e.result.message;
  ASSERT_TRUE(e.result.success ||
              (blocked && e.result.message.rfind("the robot is blocked: ", 0) == 0))
      << e.result.message;
  EXPECT_GE(e.steps.min_centre_clearance, -1e-9)
      << "step " << e.steps.min_centre_clearance_step;
  EXPECT_GT(e.steps.min_clearance, 0.0) << "step " << e.steps.min_clearance_step;
  for (const wpg::MpcIterationLog& log : e.result.trajectory.mpc)
    EXPECT_TRUE(log.status == wpg::IterationStatus::kSolved ||
                log.status == wpg::IterationStatus::kRelaxedObstacle)
        << "t = " << log.time;
}

// Index of the first trajectory sample at or after t.
std::size_t sampleAt(const wpg::WalkTrajectory& t, double time) {
  std::size_t i = 0;
  while (i + 1 < t.time.size() && t.time[i] < time - 1e-9) ++i;
  return i;
}

TEST(PaperExperimentA, GetsPastAnObstacleOnThePathAndWalksOn) {
  const Experiment e = run("paper_experiment_a");
  expectEveryStepClear(e);
  const wpg::Obstacle& obstacle = e.scenario.request.obstacles.at(0);
  const wpg::WalkTrajectory& t = e.result.trajectory;
  // The obstacle is on the path: the straight CoM line y = 0 crosses the obstacle itself.
  ASSERT_LT(std::abs(obstacle.center.y()), obstacle.radius);
  // Past it, by more than a metre beyond the far side of its margin ...
  const double far_side = obstacle.center.x() + obstacle.radius + obstacle.margin;
  EXPECT_GT(t.com.back().x(), far_side + 1.0);
  // ... walking on along the commanded heading at close to the commanded speed over the last
  // 5 s (two whole steps of 0.8 s are 1.6 s: average over 4.8 s).
  const std::size_t a = sampleAt(t, t.time.back() - 4.8);
  const double speed = (t.com.back().x() - t.com[a].x()) / (t.time.back() - t.time[a]);
  EXPECT_NEAR(speed, 0.2, 0.03);
  EXPECT_LT(std::abs(t.free_flyer_yaw.back()), 0.05);
  RecordProperty("final_com_x", std::to_string(t.com.back().x()));
}

// Time from reaching the obstacle to the CoM passing the far side of the margin circle; negative
// when either never happens. Reaching it: the first step that comes within 0.1 m of the NMPC's
// circle (radius + margin + obstacle_foot_radius), or, with `com_reach`, the CoM within
// radius + margin + 0.5 m of the centre (docs/obstacle_passing.md's definition: a border that
// turns the robot aside early may keep every step further than 0.1 m from the circle).
struct PassTimes {
  double reach = -1.0, pass = -1.0;
};
PassTimes passTimes(const Experiment& e, bool com_reach = false) {
  PassTimes p;
  const wpg::WalkTrajectory& t = e.result.trajectory;
  const wpg::Obstacle& margin_circle = e.scenario.request.obstacles.at(0);
  if (com_reach) {
    for (std::size_t i = 0; i < t.time.size(); ++i) {
      if ((t.com[i].head<2>() - margin_circle.center).norm() <=
          margin_circle.radius + margin_circle.margin + 0.5) {
        p.reach = t.time[i];
        break;
      }
    }
  } else {
    for (std::size_t i = 2; i < t.footsteps.size(); ++i) {  // the two initial feet skipped
      if (e.steps.centre_clearance[i] <= 0.1) {
        p.reach = t.footsteps[i].landing_time;
        break;
      }
    }
  }
  const wpg::Obstacle& obstacle = e.scenario.request.obstacles.at(0);
  const double far_side = obstacle.center.x() + obstacle.radius + obstacle.margin;
  for (std::size_t i = 0; i < t.time.size(); ++i) {
    if (t.com[i].x() >= far_side) {
      p.pass = t.time[i];
      break;
    }
  }
  return p;
}

// Experiment A as the paper runs it: on the path and 0.2 m off it, the robot passes the obstacle
// within 10 s of first reaching it (the CoM within half a metre of the margin circle), never
// steps in its margin, and walks on along +x.
TEST(PaperExperimentA, PassesWithinTenSecondsOfReachingTheMarginOnAndOffThePath) {
  for (const char* centre : {"[3.0,0.0]", "[3.0,-0.2]"}) {
    const Experiment e = run("paper_experiment_a", {std::string("obstacles[0].center=") + centre});
    SCOPED_TRACE(centre);
    expectEveryStepClear(e);
    const PassTimes p = passTimes(e, /*com_reach=*/true);
    ASSERT_GT(p.reach, 0.0) << "never came near the margin";
    ASSERT_GT(p.pass, 0.0) << "never got past";
    EXPECT_LE(p.pass - p.reach, 10.0);
    EXPECT_LT(std::abs(e.result.trajectory.free_flyer_yaw.back()), 0.05);
    RecordProperty(std::string("pass_after_reach_") + centre, std::to_string(p.pass - p.reach));
  }
}

TEST(PaperExperimentA, ThePapersLiteralFormulationStaysBlockedInFront) {
  // The paper's cost and linearization (eq. 18 linearized at the step, J1 instantaneous, the
  // support foot's heading, alpha on J2): the robot walks up to the margin and marks time
  // there, never entering it (docs/formulation.md, "Obstacles on the path"): the walk ends
  // blocked, since the window that starts at 13.0 s.
  const Experiment e = run("paper_experiment_a", {"walking.obstacle_linearization=step",
                                                  "walking.velocity_tracking=instantaneous",
                                                  "walking.heading_reference=support_foot",
                                                  "walking.weight_yaw=2.5"});
  expectEveryStepClear(e, /*blocked=*/true);
  EXPECT_NEAR(e.result.blocked_since, 13.0, 1e-9);
  const wpg::Obstacle& obstacle = e.scenario.request.obstacles.at(0);
  EXPECT_LT(e.result.trajectory.com.back().x(), obstacle.center.x());
  EXPECT_GT(passTimes(e).reach, 0.0);  // it did reach the margin
}

TEST(PaperExperimentA, TheStepLinearizationOffThePathIsNeverEntered) {
  const Experiment e = run("paper_experiment_a", {"obstacles[0].center=[3.0,-0.2]",
                                                  "walking.obstacle_linearization=step"});
  expectEveryStepClear(e);
}

// The passing side (wpg/obstacle_tangent.hpp): the side of the command's line through the
// centre on which the point between the feet lies. An obstacle 0.2 m to the left of the path
// is passed on the right, and the robot never crosses to the other side.
TEST(PaperExperimentA, CommandTangentPassesOnTheSideTheFeetAreOn) {
  const Experiment e = run("paper_experiment_a", {"obstacles[0].center=[3.0,0.2]"});
  expectEveryStepClear(e);
  double y_min = 0.0, y_max = 0.0;
  for (const Eigen::Vector3d& c : e.result.trajectory.com) {
    y_min = std::min(y_min, c.y());
    y_max = std::max(y_max, c.y());
  }
  EXPECT_LT(y_min, -0.4);
  EXPECT_LT(y_max, 0.1);  // the gait's sway only
}

// The paper's experiment B: the obstacle's margin lies across the commanded circle. With the
// paper's J1 and linearization (one set of keys away) the robot is blocked in translation,
// turns on the spot, then resumes its circle (the paper's Fig. 8, bottom).
TEST(PaperExperimentB, BlockedInTranslationItTurnsOnTheSpotThenResumesItsCircle) {
  for (const std::vector<std::string>& keys : std::vector<std::vector<std::string>>{
           {"walking.velocity_tracking=instantaneous", "walking.obstacle_linearization=step"}}) {
    const Experiment e = run("paper_experiment_b", keys);
    SCOPED_TRACE("the paper's J1 and linearization");
    expectEveryStepClear(e);
    const wpg::WalkTrajectory& t = e.result.trajectory;
    // A stretch of 2.5 s with (almost) no translation while the yaw keeps turning (measured
    // 0.55 rad for less than 3 cm of CoM until 11.9 s with the defaults, 0.53 rad from 9.5 s
    // with the paper's keys) ...
    const std::size_t window = sampleAt(t, 2.5);
    std::size_t blocked_end = 0;
    double blocked_turn = 0.0;
    for (std::size_t i = 0; i + window < t.time.size(); i += 10) {
      const double moved = (t.com[i + window] - t.com[i]).head<2>().norm();
      const double turned = std::abs(t.free_flyer_yaw[i + window] - t.free_flyer_yaw[i]);
      if (moved < 0.03 && turned > blocked_turn) {
        blocked_turn = turned;
        blocked_end = i + window;
      }
    }
    EXPECT_GT(blocked_turn, 0.3) << "no blocked stretch in which the robot turns";
    // ... in front of the obstacle's margin ...
    const wpg::Obstacle& obstacle = e.scenario.request.obstacles.at(0);
    EXPECT_LT((t.com[blocked_end].head<2>() - obstacle.center).norm(),
              obstacle.radius + obstacle.margin + 0.4);
    // ... then the circle resumes: more than a metre of walking afterwards.
    EXPECT_GT((t.com.back() - t.com[blocked_end]).head<2>().norm(), 1.0);
    RecordProperty("blocked_turn_rad_paper",
                   std::to_string(blocked_turn));
  }
}

// With the defaults the border of the obstacle turns the robot aside before its margin: it is
// never held, and walks round the commanded circle (a robot that is not blocked has no need to
// turn on the spot).
TEST(PaperExperimentB, WithTheDefaultsItGoesRoundTheMarginWithoutBeingHeld) {
  const Experiment e = run("paper_experiment_b", {});
  expectEveryStepClear(e);
  const wpg::WalkTrajectory& t = e.result.trajectory;
  // over every 2.5 s from the first step on, the CoM moves more than 0.15 m
  const std::size_t window = sampleAt(t, 2.5);
  double least = 1e9;
  for (std::size_t i = sampleAt(t, 2.5); i + window < t.time.size(); i += 10)
    least = std::min(least, (t.com[i + window] - t.com[i]).head<2>().norm());
  EXPECT_GT(least, 0.15);
  // 29 s of 0.2 rad/s: 5.8 rad commanded
  EXPECT_NEAR(t.free_flyer_yaw.back(), 0.2 * 29.0, 0.3);
  RecordProperty("least_motion_in_2_5_s_m", std::to_string(least));
  RecordProperty("final_yaw_rad", std::to_string(t.free_flyer_yaw.back()));
}

// With the default J1 (velocity_tracking: with_sway) but the paper's linearization at the step,
// the robot can step aside: it slides along the margin on the inside of its circle without
// stopping, and turns the whole circle.
TEST(PaperExperimentB, AtTheStepTheDefaultJ1SlidesAlongTheMarginWithoutStopping) {
  const Experiment e = run("paper_experiment_b", {"walking.obstacle_linearization=step"});
  expectEveryStepClear(e);
  const wpg::WalkTrajectory& t = e.result.trajectory;
  const wpg::Obstacle& obstacle = e.scenario.request.obstacles.at(0);
  // Never held: over every 2.5 s from the first step on, the CoM moves more than 0.15 m
  // (measured at least 0.27 m; 0.5 m at 0.2 m/s).
  const std::size_t window = sampleAt(t, 2.5);
  double least = 1e9;
  for (std::size_t i = sampleAt(t, 2.5); i + window < t.time.size(); i += 10)
    least = std::min(least, (t.com[i + window] - t.com[i]).head<2>().norm());
  EXPECT_GT(least, 0.15);
  // It came to the margin (a step centre within 5 cm of the NMPC's circle) ...
  EXPECT_LT(e.steps.min_centre_clearance, 0.05);
  // ... and walked round the circle: 29 s of 0.2 rad/s, 5.8 rad commanded (measured 5.79).
  EXPECT_NEAR(t.free_flyer_yaw.back(), 0.2 * 29.0, 0.3);
  // Where it came nearest the obstacle, its CoM was inside the commanded circle (centre
  // (0, 1), radius 1 m), between the circle's centre and the obstacle (1.36 m from it).
  const Eigen::Vector2d centre(0.0, 1.0);
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < t.com.size(); ++i)
    if ((t.com[i].head<2>() - obstacle.center).norm() <
        (t.com[nearest].head<2>() - obstacle.center).norm())
      nearest = i;
  EXPECT_LT((t.com[nearest].head<2>() - centre).norm(), 1.0);
  RecordProperty("least_motion_in_2_5_s_m", std::to_string(least));
}

}  // namespace
