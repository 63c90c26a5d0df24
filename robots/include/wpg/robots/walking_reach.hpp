#pragma once
// What a robot's legs can do for the pattern generator, measured by the walking IK (what
// `wpg robot check` prints beside the walking file's declared values, docs/robots.md):
// the leg length, the CoM heights the robot can stand at, and the step polygon the legs reach.
// Reachable means: the IK solves (feet on their targets, CoM within its tolerance) with every
// joint within its URDF limits. Kinematic only: no self-collision, no torque limit.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace wpg::robots {

// The actuated joints (configuration indices k, root first) from the root to `frame`.
std::vector<int> jointsToFrame(const RobotModel& model, const std::string& frame);

// Hip to sole, leg straight (every leg joint at 0): the distance from the first joint's origin
// of the chain to the sole frame [m].
double straightLegLength(const RobotModel& model, const std::string& sole_frame);

// The feet side by side (ankles `foot_separation` apart, soles on z = 0), the CoM above their
// middle: the lowest and highest CoM heights the IK reaches on the grid k x `step` (k >= 1) up
// to 2 x the straight leg length (0, 0 when none is reached): a coarse grid, refined at its
// ends (walking_reach.cpp says when that differs from a scan of every height).
struct ComHeightRange {
  double lowest = 0.0, highest = 0.0;  // [m]
};
ComHeightRange walkableComHeights(const WalkingIk& ik, double foot_separation,
                                  double step = 1e-3);

// The step polygon reached (a left step in the right support foot's frame, the paper's Fig. 5),
// sampled along `rays` directions from `centre`: on each ray, the furthest point (bisection to
// 1 mm, within `max_distance`) where the IK reaches both feet, yaw 0, with the CoM at their
// middle at `com_height` and the soles at least `min_lateral` apart (not overlapping). Empty
// when `centre` itself is not reached. The polygon is the star-shaped boundary seen from
// `centre`.
std::vector<Eigen::Vector2d> reachableStepPolygon(const WalkingIk& ik, double com_height,
                                                  const Eigen::Vector2d& centre, int rays,
                                                  double min_lateral, double max_distance = 1.0);

// One double-support stance of reachableStepPolygon: right sole at the origin, left sole at
// `step`, CoM at their middle at `com_height`.
bool stepReachable(const WalkingIk& ik, const Eigen::Vector2d& step, double com_height);

}  // namespace wpg::robots
