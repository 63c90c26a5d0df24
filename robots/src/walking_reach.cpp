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
  if (!(step > 0.0)) throw std::invalid_argument("walkable CoM heights: step must be positive");
  const RobotModel& model = ik.model();
  const double top = 2.0 * std::max(straightLegLength(model, ik.settings().left_sole_frame),
                                    straightLegLength(model, ik.settings().right_sole_frame));
  WalkingIkTarget target;
  target.left_foot << 0.0, 0.5 * foot_separation, 0.0, 0.0;
  target.right_foot << 0.0, -0.5 * foot_separation, 0.0, 0.0;
  Eigen::VectorXd q(model.nq());
  // Heights k step, k = 1 .. last.
  const int last = static_cast<int>(std::floor(top / step + 1e-9));
  const auto ok = [&](int k) {
    target.com << 0.0, 0.0, k * step;
    return reached(ik, target, q);
  };
  // Every kCoarse-th height first; then, from the lowest and the highest of those reached,
  // every height outwards until kCoarse in a row are not reached (the coarse ones beyond are
  // known not to be). The same as a scan of every height unless kCoarse or more heights in a
  // row are not reached between two reached ones: the numerical IK, started from the
  // reference posture, misses some heights inside the range and near its ends (on a 7-joint
  // leg: 0.286 m reached, 0.287 to 0.295 m not, 0.296 m reached), never 16 in a row on
  // HRP-2's legs, analytic and numerical (test_walking_reach.cpp), nor on the 7-joint leg of
  // tests/cli/third_robot.sh. Why: an unreached height costs the IK its whole iteration
  // budget; on that 7-joint leg `wpg robot check` took 13.5 s of CPU with the scan of all 847
  // heights, 2.2 s with this (the same heights, 0.286 to 0.512 m).
  constexpr int kCoarse = 16;
  int low = 0, high = 0;
  for (int k = kCoarse; k <= last; k += kCoarse) {
    if (!ok(k)) continue;
    if (low == 0) low = k;
    high = k;
  }
  if (low == 0) {  // none on the coarse grid: an interval narrower than kCoarse steps, or none
    for (int k = 1; k <= last; ++k) {
      if (k % kCoarse == 0 || !ok(k)) continue;
      if (low == 0) low = k;
      high = k;
    }
    return low == 0 ? ComHeightRange{} : ComHeightRange{low * step, high * step};
  }
  // The furthest reached height from `end` in `direction` (-1 down, +1 up) with fewer than
  // kCoarse unreached ones in a row before it.
  const auto widen = [&](int end, int direction) {
    for (int k = end + direction, misses = 0; k >= 1 && k <= last && misses < kCoarse;
         k += direction) {
      if (k % kCoarse != 0 && ok(k)) {
        end = k;
        misses = 0;
      } else {
        ++misses;
      }
    }
    return end;
  };
  return {widen(low, -1) * step, widen(high, +1) * step};
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
