// gaitReach (wpg/gait_reach.hpp), the C++ port of analysis/gait_reach.py: the same lambda as
// the Python for HRP-2's polygon (values printed by analysis/gait_reach.py), and the
// properties of a reach: linear in the command, inversely proportional to the step duration
// when not turning, a regular gait never reaching further than any gait.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "wpg/gait_reach.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using Eigen::Vector2d;

struct Case {
  double vx, vy, omega, step_duration;
  double any, regular;  // gait_reach(...), gait_reach(..., regular=True) of the Python
};

// /usr/bin/python3 -c 'from gait_reach import gait_reach; ...' in analysis/, HRP-2's polygon.
constexpr Case kPython[] = {
    {0.0, 0.15, 0.0, 0.8, 0.8333333333437515, 0.8333333333416666},
    {0.2, -0.1, 0.1, 0.8, 1.0980453978133085, 0.8780817614736544},
    {0.3, 0.05, 0.2, 0.8, 0.9663568335515602, 0.853073388190549},
    {-0.1, 0.15, -0.2, 0.6, 1.0805405734237041, 0.9426041789549713},
    {0.3, -0.15, 0.2, 0.5, 1.182009350377995, 0.9506260210427715},
    {0.1, 0.0, 0.0, 0.8, 3.500000000062499, 3.500000000019999},
    {0.05, 0.1, 0.2, 0.7, 1.4016854903129314, 1.2692497419630289},
};

TEST(GaitReach, MatchesThePythonReach) {
  const wpg::WalkingParameters w;
  for (const Case& c : kPython) {
    const Vector2d v(c.vx, c.vy);
    EXPECT_NEAR(wpg::gaitReach(v, c.omega, c.step_duration, w.feasibility_x, w.feasibility_y),
                c.any, 1e-9)
        << c.vx << " " << c.vy << " " << c.omega << " T " << c.step_duration;
    EXPECT_NEAR(wpg::gaitReach(v, c.omega, c.step_duration, w.feasibility_x, w.feasibility_y,
                               true),
                c.regular, 1e-9)
        << c.vx << " " << c.vy << " " << c.omega << " T " << c.step_duration << " regular";
  }
}

TEST(GaitReach, ClockwisePolygonGivesTheSameReach) {
  const wpg::WalkingParameters w;
  std::array<double, 5> x, y;
  for (int i = 0; i < 5; ++i) x[i] = w.feasibility_x[4 - i], y[i] = w.feasibility_y[4 - i];
  // analysis/gait_reach.py with the reversed vertex lists.
  EXPECT_NEAR(wpg::gaitReach(Vector2d(0.2, 0.05), 0.1, 0.8, x, y), 1.3567657495387904, 1e-9);
  EXPECT_NEAR(wpg::gaitReach(Vector2d(0.2, 0.05), 0.1, 0.8, x, y, true), 1.1677849246256247,
              1e-9);
}

TEST(GaitReach, SidewaysReachIsTheWidthOverACycle) {
  // (0.4 - 0.2) m per two steps: 0.125 m/s at 0.8 s steps, the gait's sideways speed.
  const wpg::WalkingParameters w;
  const double reach = wpg::gaitReach(Vector2d(0.0, 0.125), 0.0, w.stepDuration(),
                                      w.feasibility_x, w.feasibility_y, true);
  EXPECT_NEAR(reach, 1.0, 1e-9);
  EXPECT_NEAR(0.125, w.gaitSidewaysSpeed(), 1e-12);
}

TEST(GaitReach, LinearInTheCommandAndFasterWithShorterSteps) {
  const wpg::WalkingParameters w;
  const Vector2d v(0.2, 0.1);
  for (const bool regular : {false, true}) {
    const double base = wpg::gaitReach(v, 0.0, 0.8, w.feasibility_x, w.feasibility_y, regular);
    EXPECT_NEAR(wpg::gaitReach(2.0 * v, 0.0, 0.8, w.feasibility_x, w.feasibility_y, regular),
                0.5 * base, 1e-9);
    // Not turning, a step covers the same polygon in less time.
    EXPECT_NEAR(wpg::gaitReach(v, 0.0, 0.5, w.feasibility_x, w.feasibility_y, regular),
                base * 0.8 / 0.5, 1e-9);
    for (const double omega : {-0.2, 0.1, 0.2}) {
      EXPECT_LE(wpg::gaitReach(v, omega, 0.8, w.feasibility_x, w.feasibility_y, true),
                wpg::gaitReach(v, omega, 0.8, w.feasibility_x, w.feasibility_y, false) + 1e-12);
    }
  }
}

TEST(GaitReach, ZeroVelocityIsAlwaysReached) {
  const wpg::WalkingParameters w;
  EXPECT_EQ(wpg::gaitReach(Vector2d::Zero(), 0.2, 0.8, w.feasibility_x, w.feasibility_y),
            std::numeric_limits<double>::infinity());
}

}  // namespace

// gaitReachesCommand is gaitReach >= 1, also on the boundary (commands scaled to their reach,
// a rounding either side), in any direction, turning or not, regular or not.
TEST(GaitReach, ReachesCommandIsReachAtLeastOne) {
  const wpg::WalkingParameters w;
  int reached = 0, missed = 0;
  for (int a = 0; a < 24; ++a) {
    const double angle = 2.0 * M_PI * a / 24.0;
    for (const double omega : {0.0, 0.15, -0.3}) {
      for (const bool regular : {false, true}) {
        const Vector2d direction(0.3 * std::cos(angle), 0.2 * std::sin(angle));
        const double lambda =
            wpg::gaitReach(direction, omega, 0.8, w.feasibility_x, w.feasibility_y, regular);
        for (const double scale : {0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.5}) {
          const Vector2d v = scale * lambda * direction;
          const bool reaches =
              wpg::gaitReach(v, omega, 0.8, w.feasibility_x, w.feasibility_y, regular) >= 1.0;
          EXPECT_EQ(
              wpg::gaitReachesCommand(v, omega, 0.8, w.feasibility_x, w.feasibility_y, regular),
              reaches)
              << angle << " " << omega << " " << scale << " " << regular;
          (reaches ? reached : missed) += 1;
        }
      }
    }
  }
  EXPECT_GT(reached, 100);
  EXPECT_GT(missed, 100);
}
