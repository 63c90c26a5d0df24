// WalkingIk's legs (walking_ik.hpp): which leg is solved in closed form, and the numerical
// legs' IK with their mass.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/SVD>

#include "wpg/robots/walking_ik.hpp"
#include "wpg/robots/walking_reach.hpp"

namespace wpg::robots {
namespace {

constexpr double kStructureTolerance = 1e-12;

bool isIdentity(const Eigen::Matrix3d& r) {
  return (r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= kStructureTolerance;
}

}  // namespace

WalkingIk::Leg WalkingIk::makeLeg(const std::string& sole_frame) const {
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("walking IK: the leg of frame " + sole_frame + " of robot " +
                                model_.name() + " " + why);
  };
  const Frame& frame = model_.frames()[model_.frameIndex(sole_frame)];
  const std::vector<int> chain = jointsToFrame(model_, sole_frame);
  if (chain.size() < 6 || chain.size() > static_cast<std::size_t>(NumericalLegIk::kMaxLegJoints)) {
    fail("has " + std::to_string(chain.size()) + " joints between the root and the sole, " +
         "expected 6 to " + std::to_string(NumericalLegIk::kMaxLegJoints));
  }
  Leg leg;
  for (const int k : chain) {
    leg.chain_body.push_back(model_.joints()[k].body);
    leg.chain_q.push_back(RobotModel::kFreeFlyerConfigurationSize + k);
  }
  // Nothing but the next leg body may hang from a leg body (its mass would not be counted).
  const int n = static_cast<int>(leg.chain_body.size());
  for (std::size_t b = 1; b < model_.bodies().size(); ++b) {
    const int parent = model_.bodies()[b].parent;
    for (int i = 0; i < n; ++i) {
      if (parent == leg.chain_body[i] && (i == n - 1 || static_cast<int>(b) != leg.chain_body[i + 1])) {
        fail("has a branch at body " + model_.bodies()[parent].name);
      }
    }
  }
  std::string why;
  leg.analytic = !settings_.numerical_legs && makeAnalyticLeg(frame, leg, why);
  return leg;
}

bool WalkingIk::makeAnalyticLeg(const Frame& frame, Leg& leg, std::string& why) const {
  if (leg.chain_body.size() != 6) return (why = "not six joints", false);
  if (!isIdentity(frame.placement.rotation)) return (why = "a rotated sole frame", false);
  leg.sole = frame.placement.position;
  for (int i = 0; i < 6; ++i) leg.body[i] = leg.chain_body[i];
  const Eigen::Vector3d expected_axes[6] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY(),
                                            Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX()};
  Eigen::Vector3d origins[6];
  for (int i = 0; i < 6; ++i) {
    const Joint& joint = model_.joints()[model_.bodies()[leg.body[i]].joint];
    if (joint.type == JointType::kPrismatic) return (why = "a prismatic joint", false);
    leg.axis[i] = i == 0 ? 2 : (i == 1 || i == 5) ? 0 : 1;  // index of expected_axes[i]
    if ((joint.axis - expected_axes[i]).norm() > kStructureTolerance)
      return (why = "axes other than z x y y y x", false);
    if (!isIdentity(joint.origin.rotation)) return (why = "a rotated joint frame", false);
    origins[i] = joint.origin.position;
    leg.q_index[i] = leg.chain_q[i];
  }
  if (origins[1].norm() > kStructureTolerance || origins[2].norm() > kStructureTolerance ||
      origins[5].norm() > kStructureTolerance) {
    return (why = "hip or ankle axes that do not intersect", false);
  }
  if (std::abs(origins[3].x()) > kStructureTolerance ||
      std::abs(origins[4].x()) > kStructureTolerance || !(origins[3].z() < 0.0) ||
      !(origins[4].z() < 0.0)) {
    return (why = "a knee or ankle offset along x, or not below the hip", false);
  }
  for (int i = 0; i < 6; ++i) leg.origin[i] = origins[i];
  leg.hip = origins[0];
  leg.thigh = -origins[3].z();
  leg.shank = -origins[4].z();
  leg.lateral = origins[3].y() + origins[4].y();
  return true;
}

std::vector<int> WalkingIk::lockedLegJoints(const NumericalLegIk& leg,
                                            const Eigen::VectorXd& reference) {
  // Greedy: drop, one at a time, the joint whose column leaves the remaining Jacobian (at the
  // reference posture, root at the origin) with the largest smallest singular value.
  const Eigen::Matrix<double, 6, Eigen::Dynamic> full = leg.jacobian(Pose{}, reference);
  std::vector<int> free(static_cast<std::size_t>(leg.jointCount()));
  for (int i = 0; i < leg.jointCount(); ++i) free[static_cast<std::size_t>(i)] = i;
  std::vector<int> locked;
  while (free.size() > 6) {
    double best = -1.0;
    std::size_t best_index = 0;
    for (std::size_t drop = 0; drop < free.size(); ++drop) {
      Eigen::Matrix<double, 6, Eigen::Dynamic> kept(6, static_cast<Eigen::Index>(free.size() - 1));
      for (std::size_t j = 0, c = 0; j < free.size(); ++j)
        if (j != drop) kept.col(static_cast<Eigen::Index>(c++)) = full.col(free[j]);
      const double smallest = Eigen::JacobiSVD<Eigen::MatrixXd>(kept).singularValues().minCoeff();
      if (smallest > best) {
        best = smallest;
        best_index = drop;
      }
    }
    locked.push_back(free[best_index]);
    free.erase(free.begin() + static_cast<std::ptrdiff_t>(best_index));
  }
  return locked;
}

bool WalkingIk::solveNumericalLeg(Side side, const Pose& waist, const Pose& sole,
                                  LegSolution& out, Eigen::Vector3d& moment, Pose& reached) const {
  const NumericalLegIk& ik = *numerical_[side];
  // Always from the reference posture: the angles are a function of the waist and sole poses
  // (Newton's finite differences on the waist position need one), the knee bent as it is.
  out.numeric = numerical_start_[side];
  const NumericalLegIkResult result = ik.solve(waist, sole, out.numeric);
  Pose bodies[NumericalLegIk::kMaxLegJoints];
  reached = ik.forwardKinematics(waist, out.numeric, bodies);
  const std::vector<LegMassPoint>& mass = leg_mass_[side];
  for (std::size_t i = 0; i < mass.size(); ++i) moment += mass[i].mass * (bodies[i] * mass[i].com);
  return result.converged;
}

}  // namespace wpg::robots
