#include "wpg/obstacle_selector.hpp"

#include <algorithm>
#include <limits>

#include "wpg/obstacle_tangent.hpp"

namespace wpg {
namespace {

// [m] how far on the other side of an obstacle's centre line the feet must be for the robot to
// pass it on that side instead: a little more than a step's sway, so that the feet of a robot
// that walks along the line do not switch sides at every step.
constexpr double kSideSwitch = 0.1;

}  // namespace

void ObstacleSelector::set(std::vector<Obstacle> obstacles) {
  ObstacleSet validated(std::move(obstacles));  // throws before anything changes
  obstacles_ = std::move(validated);
  order_.assign(obstacles_.obstacleCount(), {0.0, 0});
  route_.assign(obstacles_.obstacleCount(), {0.0, 0});
  side_.assign(obstacles_.obstacleCount(), 0);
  normal_.assign(obstacles_.obstacleCount(), Eigen::Vector2d::Zero());
  leader_.assign(obstacles_.obstacleCount(), 0);
  route_obstacle_.assign(obstacles_.obstacleCount(), -1);
  route_count_ = -1;
  std::size_t points = 0;
  for (int i = 0; i < obstacles_.obstacleCount(); ++i) points += obstacles_.core(i).size();
  group_points_.clear();
  group_points_.reserve(points);  // a group holds every obstacle at most
  group_radii_.clear();
  group_radii_.reserve(points);
}

void ObstacleSelector::select(const Eigen::Vector2d& support, double reach,
                              Eigen::Ref<Eigen::VectorXi> slots) {
  slots.setConstant(-1);
  const int slot_count = static_cast<int>(slots.size());
  if (slot_count == 0 || obstacles_.empty()) return;
  int candidates = 0;
  for (int i = 0; i < obstacles_.obstacleCount(); ++i) {
    const Eigen::Vector3d& circle = obstacles_.reachCircle(i);
    const double gap = (circle.head<2>() - support).norm() - circle.z();
    if (gap < reach) {
      order_[candidates++] = {gap, i};
    } else {
      side_[i] = 0;  // out of reach: its side is chosen afresh when it comes back
    }
  }
  const int kept = std::min(candidates, slot_count);
  std::partial_sort(order_.begin(), order_.begin() + kept, order_.begin() + candidates);
  for (int k = 0; k < kept; ++k) slots(k) = order_[k].second;
}

void ObstacleSelector::borderNormals(const Eigen::Vector2d& com,
                                     const Eigen::Vector2d& feet_middle,
                                     const Eigen::Vector2d& direction,
                                     const WalkingParameters& parameters, double clearance,
                                     double max_detour, Eigen::Ref<Eigen::VectorXi> slots,
                                     Eigen::Ref<Eigen::Matrix2Xd> normals,
                                     Eigen::Ref<Eigen::VectorXd> offsets) {
  normals.setZero();
  offsets.setZero();
  if (slides_.cols() != slots.size()) slides_.resize(2, slots.size());  // once per slot count
  slides_.setZero();
  route_count_ = -1;
  const double length = direction.norm();
  if (length <= 1e-12) {  // no command: each border faces the CoM
    for (int k = 0; k < slots.size(); ++k) {
      if (slots(k) < 0) continue;
      Eigen::Vector2d facing;
      obstacles_.signedDistance(slots(k), com, &facing);
      normals.col(k) = facing;
      offsets(k) = borderOffset(obstacles_.core(slots(k)), radiusOf(slots(k), parameters), facing);
    }
    return;
  }
  const Eigen::Vector2d d = direction / length;
  const Eigen::Vector2d left(-d.y(), d.x());
  // The slots in the order the robot meets their obstacles along the command (the centres'
  // positions along d); an insertion sort of at most max_obstacles_in_qp slots.
  int count = 0;
  for (int k = 0; k < slots.size(); ++k) {
    if (slots(k) < 0) continue;
    const double along = (obstacles_.reachCircle(slots(k)).head<2>() - com).dot(d);
    int at = count++;
    for (; at > 0 && route_[at - 1].first > along; --at) route_[at] = route_[at - 1];
    route_[at] = {along, k};
  }
  for (int r = 0; r < count; ++r) route_obstacle_[r] = slots(route_[r].second);
  route_count_ = count;
  // Groups: obstacles whose grown shapes leave a gap narrower than the least step width between
  // them have no way between them; each is joined to the group of the first one met (the
  // group's leader, by route position), transitively.
  const double least_width = parameters.leastStepWidth();
  for (int r = 0; r < count; ++r) leader_[r] = r;
  for (int r = 1; r < count; ++r) {
    const int index = slots(route_[r].second);
    for (int before = 0; before < r; ++before) {
      if (leader_[before] == leader_[r]) continue;
      const int other = slots(route_[before].second);
      // Far apart by their enclosing circles (each grown as the shape is): no need for the
      // exact gap. Measured: the exact gap of every pair at every sample made the NMPC
      // iteration among three obstacles 16 % slower than before this rule, this test 11 %.
      const auto enclosing = [&](int member) {
        return obstacles_.reachCircle(member).z() - obstacles_.obstacle(member).margin +
               stepCentreMargin(obstacles_.obstacle(member), parameters);
      };
      const double apart = (obstacles_.reachCircle(index).head<2>() -
                            obstacles_.reachCircle(other).head<2>()).norm();
      if (apart - enclosing(index) - enclosing(other) >= least_width) continue;
      const double gap = coreDistance(obstacles_.core(index), obstacles_.core(other)) -
                         radiusOf(index, parameters) - radiusOf(other, parameters);
      if (gap >= least_width) continue;
      // Not when the joined group's hull comes closer to the CoM than its members do, by more
      // than the clearance: the robot is then in the pocket between them (inside a U of walls
      // that touch, the hull of two of them covers the room in front of the robot; a ring of
      // boxes round it, their hull holds it; measured: every enclosure of obstacle_scenes.yaml
      // fell or failed on relaxed rows). Seen from outside (a doorway from in front, a
      // staggered pair from its side), the hull is as near as the nearest member.
      // the joined group keeps the leader met first (the smaller route position)
      const int into = std::min(leader_[r], leader_[before]);
      const int joined = std::max(leader_[r], leader_[before]);
      group_points_.clear();
      group_radii_.clear();
      double nearest = std::numeric_limits<double>::infinity();
      for (int m = 0; m <= r; ++m) {
        if (leader_[m] != joined && leader_[m] != into) continue;
        const int member = slots(route_[m].second);
        const std::vector<Eigen::Vector2d>& core = obstacles_.core(member);
        group_points_.insert(group_points_.end(), core.begin(), core.end());
        group_radii_.insert(group_radii_.end(), core.size(), radiusOf(member, parameters));
        nearest = std::min(nearest, obstacles_.signedDistance(member, com, nullptr) -
                                        stepCentreMargin(obstacles_.obstacle(member), parameters));
      }
      const Eigen::Vector2d facing = hullFacing(group_points_, group_radii_, com);
      if (facing.dot(com) - borderOffset(group_points_, group_radii_, facing) < nearest - clearance)
        continue;
      for (int m = 0; m <= r; ++m)
        if (leader_[m] == joined) leader_[m] = into;
    }
  }
  // The route: the CoM, then the point beside each obstacle not yet passed where the robot
  // will pass it. Each obstacle's border is turned as far as keeps the route point before it
  // `clearance` inside the free side: the next obstacle's border leaves the way round the
  // current one open (a border turned from the CoM alone may cut across it: a staggered
  // pair then closes in a wedge in front of the robot). An obstacle whose centre the CoM has
  // passed turns its border from the CoM (on towards the command, behind the robot).
  Eigen::Vector2d route_point = com;
  bool route_started = false;  // route_point is the way round an obstacle before
  for (int r = 0; r < count; ++r) {
    const int k = route_[r].second, index = slots(k);
    if (leader_[r] != r) continue;  // a member of an earlier group: its slot is emptied below
    // The shape: the obstacle's core grown by its radius, or the group's members' together
    // (the convex hull of their grown shapes, through the support function).
    // The group is passed once its last centre is.
    const double furthest = gatherGroup(r, count, parameters);
    const bool grouped = group_points_.size() > obstacles_.core(index).size();
    const bool passed = furthest < 0.0;
    const bool after_another = !passed && route_started;
    const Eigen::Vector2d& from = after_another ? route_point : com;
    const Eigen::Vector2d centre = obstacles_.reachCircle(index).head<2>();
    // The side: where the feet are when the obstacle comes within reach, kept until they are
    // clearly (kSideSwitch) on the other side of its centre line. Other obstacles may push the
    // robot across that line (the way round the one before it): going back across to keep a
    // side chosen from afar would be a detour, or, along a border square to the command in
    // front of it, no way at all (measured on a staggered pair: 15 s sliding sideways). Taken
    // for an obstacle behind another from where the robot will pass that one, the side passed
    // two staggered boxes 1.2 m apart (6 scenes more of obstacle_scenes.yaml) but turned the
    // walks to a goal against their route when the path follower's command turns (one fall in
    // each of two worlds of planners.yaml). Those boxes are now one group (their gap is
    // narrower than a step), passed on the side of the first.
    const int previous_side = side_[index];
    if (side_[index] * left.dot(feet_middle - centre) < -kSideSwitch) side_[index] = 0;
    if (side_[index] == 0) side_[index] = obstacleSide(centre, feet_middle, d);
    const int side = side_[index];
    const bool fresh = side != previous_side;
    // The normal of the shape (or the group's hull) facing `point`: the distance's gradient.
    const auto facingFrom = [&](const Eigen::Vector2d& point) {
      Eigen::Vector2d facing;
      if (grouped) {
        facing = hullFacing(group_points_, group_radii_, point);
      } else {
        obstacles_.signedDistance(index, point, &facing);
      }
      return facing;
    };
    const auto borderFrom = [&](const Eigen::Vector2d& point) {
      return borderNormal(group_points_, group_radii_, point, d, side, clearance,
                          facingFrom(point));
    };
    const auto offsetOf = [&](const Eigen::Vector2d& n) {
      return borderOffset(group_points_, group_radii_, n);
    };
    // How far inside the free side of the border of n the CoM is.
    const auto comInside = [&](const Eigen::Vector2d& n) { return n.dot(com) - offsetOf(n); };
    // The way round on the passing side: further aside of the CoM than max_detour, the
    // obstacle is a wall for a velocity command (a 6 m wall across the path at 0.1 m/s was
    // slid along for 3.3 m and passed round its end after 53-68 s; docs/obstacle_scenes.md).
    // Its border faces the CoM (the paper's linearization at the CoM), with no slide: J1's
    // reference keeps its own part along it (turnReferenceAlongBorders), and the robot stops.
    const Eigen::Vector2d out = side * left;
    const bool wall = !passed && offsetOf(out) - out.dot(com) + clearance > max_detour;
    if (wall) {
      normal_[index] = facingFrom(com);
    } else {
      // A border turned from a route point ahead must leave the robot where it is with room for a
      // step (half the clearance) on its free side; else it is turned from the CoM.
      Eigen::Vector2d candidate = borderFrom(from);
      if (after_another && comInside(candidate) < 0.5 * clearance) candidate = borderFrom(com);
      // The border only ever turns towards the command (a ratchet): recomputed beside a CoM that
      // walked straight on, it would recede in front of the robot at every sample, and the robot
      // would walk up to the obstacle instead of sliding along the border. A kept border is given
      // up once the CoM has crossed it, or, for a border turned from the way round another
      // obstacle (a forecast of where the robot will be), once the CoM comes closer to it than
      // the clearance. Measured on obstacle_scenes.yaml and obstacle_passing.yaml (with the sides
      // of an earlier version, taken from the route points): given up at half the clearance for
      // every border, the robot slid slower (the obstacle dead ahead met at 1 m at 0.2 m/s passed
      // 0.6 s over the 10 s allowed; 292 scenes correct); only once crossed, for every border, a
      // border kept from the way round the first circle of a slalom was crossed by a CoM that
      // hugged that circle, and the sudden new border made the robot fall (300 correct, 10
      // failed); as here, 304 correct, 4 failed, 540 of 540 passed.
      const double keep = after_another ? clearance : 0.0;
      if (fresh || comInside(normal_[index]) < keep ||
          borderProgress(candidate, d, side) >= borderProgress(normal_[index], d, side))
        normal_[index] = candidate;
    }
    normals.col(k) = normal_[index];
    offsets(k) = offsetOf(normal_[index]);
    slides_.col(k) = wall ? Eigen::Vector2d::Zero() : borderSlide(normal_[index], d, side);
    for (int m = r + 1; m < count; ++m) {
      if (leader_[m] != r) continue;
      side_[slots(route_[m].second)] = side;  // kept if the group parts
      slots(route_[m].second) = -1;
    }
    if (!passed) {
      // abreast of the centre, `clearance` beyond the grown shape on the passing side
      const double beside = offsetOf(out) - out.dot(centre) + clearance;
      route_point = centre + beside * out;
      route_started = true;
    }
  }
}

double ObstacleSelector::radiusOf(int index, const WalkingParameters& parameters) const {
  return obstacles_.coreRadius(index) + stepCentreMargin(obstacles_.obstacle(index), parameters);
}

double ObstacleSelector::gatherGroup(int r, int count, const WalkingParameters& parameters) {
  group_points_.clear();
  group_radii_.clear();
  double furthest = route_[r].first;
  for (int m = r; m < count; ++m) {
    if (leader_[m] != r) continue;
    const std::vector<Eigen::Vector2d>& core = obstacles_.core(route_obstacle_[m]);
    group_points_.insert(group_points_.end(), core.begin(), core.end());
    group_radii_.insert(group_radii_.end(), core.size(), radiusOf(route_obstacle_[m], parameters));
    furthest = std::max(furthest, route_[m].first);
  }
  return furthest;
}

void ObstacleSelector::landingRows(const Eigen::Vector2d& landing,
                                   const WalkingParameters& parameters,
                                   const Eigen::Ref<const Eigen::VectorXi>& slots,
                                   Eigen::Ref<Eigen::Matrix2Xd> normals,
                                   Eigen::Ref<Eigen::VectorXd> offsets) {
  normals.setZero();
  offsets.setZero();
  for (int r = 0; r < route_count_; ++r) {
    const int k = route_[r].second;
    if (leader_[r] != r || slots(k) < 0) continue;  // a member of a group: no row of its own
    gatherGroup(r, route_count_, parameters);
    const Eigen::Vector2d facing = hullFacing(group_points_, group_radii_, landing);
    normals.col(k) = facing;
    offsets(k) = borderOffset(group_points_, group_radii_, facing);
  }
}

}  // namespace wpg
