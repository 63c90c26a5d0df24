#pragma once
// The kinematic reach of a steady two-step gait (docs/command_tracking.md, "Which commands a
// robot can walk"; the same computation as analysis/gait_reach.py): for a robot-frame command
// (vx, vy, omega), the largest factor lambda such that lambda (vx, vy) at omega can be walked
// by a periodic gait whose steps all land inside the step feasibility polygon (paper eq. 14,
// Fig. 5) and turn by omega T_step each. The adaptive step timing (walking.step_timing,
// wpg/step_timing.hpp) walks each command at the slowest cadence whose regular gait reaches it.
//
// A stride is a left step p1 in the right foot's frame (yaw 0) and a right step p2 in the left
// foot's frame (yaw delta = omega T_step); it moves the robot's frame (the point between the
// feet at a landing, yaw halfway between them) by tau = R(delta/2) ((R(2 delta) - I) m + p1 +
// R(delta) p2), m = -R(-delta) p2 / 2, and turns it by 2 delta. A constant twist (v, omega) over
// the stride's 2 T_step gives the same motion when v = R(-delta) tau / (2 T_step sinc(delta)):
// v is linear in (p1, p2), and lambda is the largest factor for which v = lambda (vx, vy) with
// p1, p2 in their polygons (a linear program in two 2-D unknowns, solved by clipping polygons
// and bisection on lambda). `regular` also asks both steps to reach equally far forward in
// their frames (p1.x = p2.x): no limping. Kinematics only (no dynamics, CoP or cost); anchored
// at the left or the right step it differs by a few % when turning, and the larger is returned.
// Does not allocate (fixed-size scratch): a few microseconds.
#include <array>

#include <Eigen/Core>

namespace wpg {

// lambda for the robot-frame (vx, vy) = `velocity` [m/s] at `omega` [rad/s] with steps of
// `step_duration` [s]; +infinity for a zero velocity. The polygon is that of a left step in the
// right foot's frame (WalkingParameters::feasibility_x/y), a right step uses its mirror image.
// Capped at 64 (a reach beyond it is returned as about 64).
double gaitReach(const Eigen::Vector2d& velocity, double omega, double step_duration,
                 const std::array<double, 5>& feasibility_x,
                 const std::array<double, 5>& feasibility_y, bool regular = false);

// gaitReach(...) >= 1, the gait walks the whole command, without the bisection (4 of its
// ~130 feasibility tests): what the scenario warnings ask of every command of every run.
bool gaitReachesCommand(const Eigen::Vector2d& velocity, double omega, double step_duration,
                        const std::array<double, 5>& feasibility_x,
                        const std::array<double, 5>& feasibility_y, bool regular = false);

}  // namespace wpg
