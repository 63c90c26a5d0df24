#pragma once
// The command_tangent linearization of a circle obstacle's row (eq. 18-19,
// ObstacleLinearization::kCommandTangent): which half-plane of the plane stands for "outside
// the circle" in the QP of one sample.
//
// Any unit n gives a half-plane n.(F - c) >= r inside the feasible set of eq. (18)
// (|F - c| >= n.(F - c) >= r), so any choice keeps every step out of the grown circle; the
// choice decides where the robot can go. The paper linearizes eq. (18) at the previewed step
// (Sec. III-E), which faces the step: with an obstacle on the path the border is perpendicular
// to the command, progress needs lateral steps that J1 charges, and the QP's optimum is to mark
// time in front of it for good (docs/formulation.md, "Obstacles on the path"). The paper's
// Fig. 2 describes the constraint as "a linearization at a point of the obstacle boundary": this
// rule picks that point from the CoM and the command instead of from the step:
//  - the border is a tangent of the circle turned towards the command's direction as far as
//    the CoM allows: parallel to the command when the command's line from the CoM clears the
//    circle (then the row does not hinder walking straight on), else the tangent that passes
//    `clearance` beside the CoM on the robot's passing side, so that the robot slides along it round the obstacle;
//  - closer to the centre than r + clearance, the tangent facing the CoM.
// The normal depends on the sample's data only (CoM, command, side, the border of the samples
// before: ObstacleSelector keeps it and lets it turn only towards the command), not on the QP's
// variables: the row is linear in the step, its Jacobian exact and constant.
// J1's reference is turned along the borders the command drives into
// (turnReferenceAlongBorders): without it the instantaneous J1 charges every lateral step and
// the robot hardly slides.
#include <Eigen/Core>

namespace wpg {

// Passing side of an obstacle centred at `center`: +1 = to the left of the command's
// `direction` (world), -1 = to the right; the side of that line through the centre on which
// `robot` lies (the point between the feet, which does not sway), ties (within 1 cm) to the
// left. A zero direction gives +1.
int obstacleSide(const Eigen::Vector2d& center, const Eigen::Vector2d& robot,
                 const Eigen::Vector2d& direction);

// Unit normal n of the command_tangent half-plane n.(F - center) >= radius (see above), for a
// circle of `radius` (grown by margin and sole radius) [m], the CoM `com`, the command's
// world `direction` (any length; zero: the tangent facing the CoM), the passing `side` (+1/-1)
// and the CoM's `clearance` from the border [m].
Eigen::Vector2d commandTangentNormal(const Eigen::Vector2d& center, double radius,
                                     const Eigen::Vector2d& com, const Eigen::Vector2d& direction,
                                     int side, double clearance);

// J1's world reference per sample (vx, vy), for each border of `normals` (columns; zero
// columns ignored) it drives into (n.v < 0): its component into the border removed, and the
// result scaled back to the commanded speed, so that the reference slides along the border
// instead of asking the robot to walk through it; but no faster than leaves its part across the
// command within `max_sideways_speed` [m/s] (<= 0: no limit). The gait walks sideways at most
// at the feasibility polygon's lateral reach per gait cycle (0.125 m/s for HRP-2,
// gaitSidewaysSpeed); asked for more along a steep border, the QP lengthens the outward step,
// which the polygon's slanted edges pay for in sideways reach, and the robot slides slower
// (docs/obstacle_passing.md, "Sliding along a steep border"). References that drive into no
// border are left as they are. PatternGenerator passes the limit for straight commands (zero
// yaw rate) only. Does not allocate.
void turnReferenceAlongBorders(const Eigen::Ref<const Eigen::Matrix2Xd>& normals,
                               double max_sideways_speed, Eigen::Ref<Eigen::VectorXd> velocity_x,
                               Eigen::Ref<Eigen::VectorXd> velocity_y);

}  // namespace wpg
