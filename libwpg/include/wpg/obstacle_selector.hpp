#pragma once
// The obstacles a walk avoids (eq. 18-19), owned with libwpg's exact 2-D distances
// (ObstacleSet: what the NMPC's obstacle rows read, allocation-free), and the choice at each
// sample of the few that enter the QP (the nearest ones, one per obstacle slot of the model).
#include <algorithm>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "wpg/obstacles.hpp"

namespace wpg {

class ObstacleSelector {
 public:
  // Takes the obstacles (validated by Obstacle::validate, key "obstacles[i]"; throws
  // std::invalid_argument and changes nothing then). An empty list removes every obstacle.
  // Allocates.
  void set(std::vector<Obstacle> obstacles);

  bool empty() const { return obstacles_.empty(); }
  const std::vector<Obstacle>& obstacles() const { return obstacles_.obstacles(); }
  // The obstacles with their distances, as the constraints use them; null without obstacles.
  const ObstacleSet* distance() const { return obstacles_.empty() ? nullptr : &obstacles_; }

  // Slot k of `slots` <- the index of the k-th nearest obstacle (bounding circle grown by its
  // margin) within `reach` of `support` [m], -1 for the rest. Does not allocate.
  void select(const Eigen::Vector2d& support, double reach, Eigen::Ref<Eigen::VectorXi> slots);

  // command_tangent linearization (obstacle_tangent.hpp): column k of `normals` and entry k
  // of `offsets` <- the border n.F >= offset of the obstacle in slot k (any shape, grown by its
  // step-centre margin, stepCentreMargin of `parameters`), from the CoM, the command's world
  // `direction` and the obstacle's passing side; zero for an empty slot. Every obstacle in the
  // slots gets a border the same way, taken in the order the robot meets them along the
  // command: each keeps the point where the robot will pass the one before it clear (the route
  // round them). Obstacles whose gap is narrower than the robot's least step width
  // (WalkingParameters::leastStepWidth: no walk fits between them) are one obstacle for this
  // rule, the convex hull of their grown shapes: the slot of the first one met carries the
  // group's border, the others' slots are emptied (set to -1). The side is chosen from
  // `feet_middle` when the obstacle (the group's first) comes within reach (select()) and kept
  // while it stays there, so that the robot does not change its mind half-way round; the
  // border only turns towards the command while it stays (borderProgress). An obstacle (or
  // group) whose way round on its passing side lies more than `max_detour` [m] aside of the
  // CoM is a wall (GeneratorSettings::max_detour): its border faces the CoM, and its slide
  // (slides()) is zero. Does not allocate.
  void borderNormals(const Eigen::Vector2d& com, const Eigen::Vector2d& feet_middle,
                     const Eigen::Vector2d& direction, const WalkingParameters& parameters,
                     double clearance, double max_detour, Eigen::Ref<Eigen::VectorXi> slots,
                     Eigen::Ref<Eigen::Matrix2Xd> normals, Eigen::Ref<Eigen::VectorXd> offsets);
  // The row of the next landing (the previewed step 0, the foot in the air), per slot left by
  // the last borderNormals: column k of `normals` and entry k of
  // `offsets` <- the supporting half-plane n.F >= offset of the same shape (the obstacle, or
  // its group's hull) whose normal faces `landing`, the landing planned at the previous
  // sample: the paper's linearization of eq. (18) at the step (Sec. III-E), given the
  // group's hull. Zero for an empty slot, and for every slot when borderNormals had no
  // command. Why: the border of borderNormals slants across the robot's way to steer it round
  // the obstacle (a half-plane kept as the CoM walks on, `clearance` beside the CoM when it
  // was chosen, less after); the step that catches a push forward must land beyond it,
  // where the obstacle is not (docs/obstacle_scenes.md, "Pushes while avoiding"); the
  // generator uses it only when it must (PatternGenerator::placeObstacles). The later steps
  // keep the border: they steer. Does not allocate.
  void landingRows(const Eigen::Vector2d& landing, const WalkingParameters& parameters,
                   const Eigen::Ref<const Eigen::VectorXi>& slots,
                   Eigen::Ref<Eigen::Matrix2Xd> normals, Eigen::Ref<Eigen::VectorXd> offsets);
  // Column k: the unit tangent of slot k's border towards its passing side (borderSlide), as
  // the last borderNormals left them; zero for an empty slot.
  const Eigen::Matrix2Xd& slides() const { return slides_; }
  // Forgets the passing sides (a new walk).
  void forgetSides() { std::fill(side_.begin(), side_.end(), 0); }

 private:
  ObstacleSet obstacles_;
  std::vector<std::pair<double, int>> order_;  // scratch, sized once per set()
  std::vector<std::pair<double, int>> route_;  // scratch: slots along the command, per set()
  std::vector<int> side_;  // per obstacle: passing side +1 / -1, 0 = not chosen (out of reach)
  Eigen::Matrix2Xd slides_;  // per slot, sized at the first borderNormals of a slot count
  std::vector<Eigen::Vector2d> normal_;  // per obstacle: its border so far (valid when side_ != 0)
  // scratch, sized once per set(): the route position of each slot's group's first member, and
  // the points and radii of the group whose border is being computed
  std::vector<int> leader_;
  // the obstacle of each route position, and how many the last borderNormals placed (-1: none,
  // no command)
  std::vector<int> route_obstacle_;
  int route_count_ = -1;
  std::vector<Eigen::Vector2d> group_points_;
  std::vector<double> group_radii_;

  double radiusOf(int index, const WalkingParameters& parameters) const;
  // group_points_, group_radii_ <- the core points and radii of the route positions r..count-1
  // led by route position r; returns the furthest of their positions along the command.
  double gatherGroup(int r, int count, const WalkingParameters& parameters);
};

}  // namespace wpg
