#pragma once
// The command_tangent linearization of the obstacle rows (eq. 18-19,
// ObstacleLinearization::kCommandTangent): which half-plane stands for "outside the obstacle"
// in the QP of one sample, for any convex obstacle and any number of them.
//
// Every obstacle is a convex core grown by a radius: a circle is its centre grown by
// R + the step-centre margin, a box or polygon its vertices grown by the step-centre margin
// (the set of step centres eq. 18 forbids). For any unit n, the supporting half-plane
//     n.F >= h(n) + radius,   h(n) = max over the core's points v of n.v
// lies inside the allowed set (a point beyond the supporting line of the grown shape is outside
// it), so any choice of n keeps every step out; the choice decides where the robot can go. The
// paper linearizes eq. (18) at the previewed step (Sec. III-E), which faces the step: with an
// obstacle on the path the border is square to the command, progress needs lateral steps that
// J1 charges, and the QP's optimum is to mark time in front of it for good
// (docs/formulation.md, "Obstacles on the path"). The paper's Fig. 2 describes the constraint
// as "a linearization at a point of the obstacle boundary": this rule picks that point from the
// CoM, the command and a passing side instead of from the step.
//
// The normal. Those whose border passes at least `clearance` beside the CoM,
//     n.(com - v) >= radius + clearance for every core point v,
// form one arc of directions (the intersection of one arc per point, each within
// acos((radius + clearance) / |com - v|) of the direction from v to the CoM; non-empty exactly
// when the CoM is at least radius + clearance from the core). The border starts from the
// normal facing the CoM (the distance's gradient) and turns, through the passing side, towards
// the command's direction d as far as that arc allows:
//  - an obstacle ahead: the border slants towards the passing side, `clearance` beside the CoM,
//    and J1's reference slides along it (turnReferenceAlongBorders);
//  - an obstacle abreast: the border along the command, then past it, n -> d: behind the robot,
//    the border frees the space ahead and across, where the next obstacle may send the robot
//    (a slalom: a border kept along the command would forbid coming back across the path);
//  - closer to the core than radius + clearance: the border facing the CoM (turning it while
//    the CoM is that close, with less clearance, leaves the previewed steps, which are ahead of
//    the CoM, on the wrong side: measured with half the CoM's room as the clearance, the
//    staggered pair, the tight slalom and narrow doorways fell after relaxed rows).
// The normal depends on the sample's data only (CoM, command, side, the border of the samples
// before: ObstacleSelector keeps it and lets it turn only towards d), not on the QP's
// variables: the row is linear in the step, its Jacobian exact and constant. Every obstacle in
// the QP gets its own border the same way; one mechanism for circles, boxes and polygons, alone
// or several at once.
#include <vector>

#include <Eigen/Core>

namespace wpg {

// Passing side of an obstacle centred at `center`: +1 = to the left of the command's
// `direction` (world), -1 = to the right; the side of that line through the centre on which
// `robot` lies (the point between the feet, which does not sway), ties (within 1 cm) to the
// left. A zero direction gives +1.
int obstacleSide(const Eigen::Vector2d& center, const Eigen::Vector2d& robot,
                 const Eigen::Vector2d& direction);

// How far the border of `normal` has turned from the command's world `direction` (any
// nonzero length) on the passing `side`: -pi for the border square to the command in front of
// the robot (n = -d), -pi/2 along it on the passing side, 0 behind the robot (n = d), up to
// pi/2 beyond; a turn towards d increases it. The cut (-pi/2 from d on the side away from the
// passing side) is the one direction a border never takes on the way round.
double borderProgress(const Eigen::Vector2d& normal, const Eigen::Vector2d& direction, int side);

// Unit normal n of the border n.F >= h(n) + radius (see above) of the obstacle whose core is
// `core` (a circle's centre, a polygon's vertices) grown by `radius` [m], for the CoM `com`,
// the command's world `direction` (any length; zero: the border facing the CoM), the passing
// `side` (+1/-1), the CoM's `clearance` from the border [m] and `facing`, the unit gradient of
// the core's distance at the CoM (the normal when the arc is empty). Does not allocate.
Eigen::Vector2d borderNormal(const std::vector<Eigen::Vector2d>& core, double radius,
                             const Eigen::Vector2d& com, const Eigen::Vector2d& direction,
                             int side, double clearance, const Eigen::Vector2d& facing);

// The same for a group of obstacles taken as one (ObstacleSelector: a gap between them that no
// step fits through): the convex hull of the discs (points[i], radii[i]), every member's core
// points with its own radius. Its support h(n) is the largest of the members', so the border
// keeps every step out of every member, and the way between them is closed.
Eigen::Vector2d borderNormal(const std::vector<Eigen::Vector2d>& points,
                             const std::vector<double>& radii, const Eigen::Vector2d& com,
                             const Eigen::Vector2d& direction, int side, double clearance,
                             const Eigen::Vector2d& facing);

// The unit normal of the hull of the discs (points[i], radii[i]) facing `point`: the gradient
// of the point's distance to it (the `facing` of a group). Does not allocate.
Eigen::Vector2d hullFacing(const std::vector<Eigen::Vector2d>& points,
                           const std::vector<double>& radii, const Eigen::Vector2d& point);

// The unit tangent of the border of `normal` that points to the passing `side` (+1 left of the
// command's `direction`, -1 right): the way J1's reference slides along it.
Eigen::Vector2d borderSlide(const Eigen::Vector2d& normal, const Eigen::Vector2d& direction,
                            int side);

// The right-hand side h(n) + radius of the border n.F >= h(n) + radius of the core `core`
// grown by `radius`, for a unit n.
double borderOffset(const std::vector<Eigen::Vector2d>& core, double radius,
                    const Eigen::Vector2d& normal);
double borderOffset(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& radii,
                    const Eigen::Vector2d& normal);

// The distance between two convex cores (a circle's centre, a polygon's vertices in order):
// the least distance between their edges (a one-point core is one degenerate edge), 0 when
// they cross or one holds the other. The gap between the two obstacles grown by radii r_a and
// r_b is this minus r_a + r_b.
double coreDistance(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b);

// J1's world reference per sample (vx, vy), turned into the directions that drive into none of
// the borders of `normals` (columns; zero columns ignored; a border is driven into when n.v <
// 0): the reference projected onto that cone of directions (the nearest direction of it; no
// change when it drives into none), and scaled back to its own speed, so that it slides along
// the borders instead of asking the robot to walk through them. A reference (nearly) square
// into a border (a box's face met head on) has no projection of its own along it: it slides
// towards the obstacle's passing side, column k of `slides` (the unit tangent of border k that
// way); a zero column is a wall (no way round within the generator's max_detour): along it the
// reference keeps only its own part, no faster, so that the robot stops. When the cone holds no
// direction within a right angle of the reference (borders facing each other across it) the
// reference is left as it is: the QP holds the steps. Scaled back no faster than leaves its
// part across the robot's heading within `max_sideways_speed` [m/s] (<= 0: no limit), the
// heading of sample j being (heading_cos(j), heading_sin(j)): the gait walks sideways at most
// at the feasibility polygon's lateral reach per gait cycle (0.125 m/s for HRP-2,
// gaitSidewaysSpeed), in the robot's frame, and forward much faster; asked for more along a
// steep border, the QP lengthens the outward step, which the polygon's slanted edges pay for in
// sideways reach, and the robot slides slower (docs/obstacle_passing.md, "Sliding along a steep
// border"). When no direction along the borders drives into none of the others (two borders
// nearly facing each other across a strip that narrows far ahead), a direction counts that
// reaches none of them within the preview: room(k) [m] is how far the CoM is inside border k,
// walked at the reference's speed for `preview_time` [s]. Does not allocate.
void turnReferenceAlongBorders(const Eigen::Ref<const Eigen::Matrix2Xd>& normals,
                               const Eigen::Ref<const Eigen::Matrix2Xd>& slides,
                               const Eigen::Ref<const Eigen::VectorXd>& heading_cos,
                               const Eigen::Ref<const Eigen::VectorXd>& heading_sin,
                               double max_sideways_speed,
                               const Eigen::Ref<const Eigen::VectorXd>& room,
                               double preview_time, Eigen::Ref<Eigen::VectorXd> velocity_x,
                               Eigen::Ref<Eigen::VectorXd> velocity_y);

}  // namespace wpg
