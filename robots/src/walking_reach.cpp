#include "wpg/robots/walking_reach.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wpg::robots {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool reached(const WalkingIk& ik, const WalkingIkTarget& target, Eigen::VectorXd& q) {
  const WalkingIkResult r = ik.solve(target, q);
  return r.status == WalkingIkStatus::kSolved && r.limit_violations == 0;
}

}  // namespace

std::vector<int> jointsToFrame(const RobotModel& model, const std::string& frame) {
  std::vector<int> joints;
  for (int body = model.frames()[model.frameIndex(frame)].body; body > 0;
       body = model.bodies()[body].parent) {
    joints.push_back(model.bodies()[body].joint);
  }
  std::reverse(joints.begin(), joints.end());
  return joints;
}

double straightLegLength(const RobotModel& model, const std::string& sole_frame) {
  const std::vector<int> joints = jointsToFrame(model, sole_frame);
  if (joints.empty()) throw std::invalid_argument("no joint between the root and " + sole_frame);
  const Eigen::VectorXd q = model.neutralConfiguration();
  std::vector<Pose> poses;
  model.forwardKinematics(q, poses);
  const Joint& first = model.joints()[joints.front()];
  const Pose& parent = poses[model.bodies()[first.body].parent];
  const Eigen::Vector3d hip = parent * first.origin.position;
  return (model.framePose(q, sole_frame).position - hip).norm();
}

ComHeightRange walkableComHeights(const WalkingIk& ik, double foot_separation, double step) {
  const RobotModel& model = ik.model();
  const double top = 2.0 * std::max(straightLegLength(model, ik.settings().left_sole_frame),
                                    straightLegLength(model, ik.settings().right_sole_frame));
  WalkingIkTarget target;
  target.left_foot << 0.0, 0.5 * foot_separation, 0.0, 0.0;
  target.right_foot << 0.0, -0.5 * foot_separation, 0.0, 0.0;
  Eigen::VectorXd q(model.nq());
  ComHeightRange range;
  bool any = false;
  for (double z = step; z <= top; z += step) {
    target.com << 0.0, 0.0, z;
    if (!reached(ik, target, q)) continue;
    if (!any) range.lowest = z;
    range.highest = z;
    any = true;
  }
  return range;
}

bool stepReachable(const WalkingIk& ik, const Eigen::Vector2d& step, double com_height) {
  WalkingIkTarget target;
  target.right_foot.setZero();
  target.left_foot << step.x(), step.y(), 0.0, 0.0;
  target.com << 0.5 * step.x(), 0.5 * step.y(), com_height;
  Eigen::VectorXd q(ik.model().nq());
  return reached(ik, target, q);
}

std::vector<Eigen::Vector2d> reachableStepPolygon(const WalkingIk& ik, double com_height,
                                                  const Eigen::Vector2d& centre, int rays,
                                                  double min_lateral, double max_distance) {
  const auto ok = [&](const Eigen::Vector2d& p) {
    return p.y() >= min_lateral && stepReachable(ik, p, com_height);
  };
  std::vector<Eigen::Vector2d> polygon;
  if (!ok(centre)) return polygon;
  for (int i = 0; i < rays; ++i) {
    const double angle = 2.0 * kPi * i / rays;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double inside = 0.0, outside = max_distance;
    if (ok(centre + max_distance * direction)) {
      polygon.push_back(centre + max_distance * direction);
      continue;
    }
    while (outside - inside > 1e-3) {
      const double middle = 0.5 * (inside + outside);
      (ok(centre + middle * direction) ? inside : outside) = middle;
    }
    polygon.push_back(centre + inside * direction);
  }
  return polygon;
}

}  // namespace wpg::robots
