#include "wpg/robots/numerical_leg_ik.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "wpg/robots/walking_reach.hpp"

namespace wpg::robots {
namespace {

// The rotation vector (axis x angle) of r, in (-pi, pi].
Eigen::Vector3d rotationVector(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

}  // namespace

NumericalLegIk::NumericalLegIk(const RobotModel& model, const std::string& sole_frame,
                               NumericalLegIkSettings settings, std::vector<int> locked)
    : model_(model), settings_(settings) {
  const Frame& frame = model_.frames()[model_.frameIndex(sole_frame)];
  joints_ = jointsToFrame(model_, sole_frame);
  if (joints_.size() < 6 || joints_.size() > static_cast<std::size_t>(kMaxLegJoints)) {
    throw std::invalid_argument("numerical leg IK: the leg of " + sole_frame + " has " +
                                std::to_string(joints_.size()) + " joints, expected 6 to " +
                                std::to_string(kMaxLegJoints));
  }
  if (!(settings_.damping >= 0.0) || settings_.max_iterations < 1) {
    throw std::invalid_argument("numerical leg IK: settings must be positive");
  }
  for (const int k : joints_) between_.push_back(model_.joints()[k].origin);
  locked_.assign(joints_.size(), false);
  for (const int i : locked) {
    if (i < 0 || i >= static_cast<int>(joints_.size()) || locked_[static_cast<std::size_t>(i)])
      throw std::invalid_argument("numerical leg IK: bad locked joint " + std::to_string(i));
    locked_[static_cast<std::size_t>(i)] = true;
  }
  if (joints_.size() - locked.size() < 6)
    throw std::invalid_argument("numerical leg IK: fewer than six joints left free");
  sole_ = frame.placement;
}

Pose NumericalLegIk::evaluate(
    const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles,
    Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxLegJoints>* jacobian, Pose* bodies) const {
  const int n = jointCount();
  Eigen::Vector3d axes[kMaxLegJoints], origins[kMaxLegJoints];
  bool prismatic[kMaxLegJoints];
  Pose pose = root;
  for (int i = 0; i < n; ++i) {
    const Joint& joint = model_.joints()[joints_[i]];
    pose = pose * between_[i];
    axes[i] = pose.rotation * joint.axis;
    origins[i] = pose.position;
    prismatic[i] = joint.type == JointType::kPrismatic;
    if (prismatic[i]) {
      pose.position += axes[i] * angles(i);
    } else {
      pose.rotation = pose.rotation * Eigen::AngleAxisd(angles(i), joint.axis).toRotationMatrix();
    }
    if (bodies != nullptr) bodies[i] = pose;
  }
  const Pose sole = pose * sole_;
  if (jacobian != nullptr) {
    jacobian->resize(6, n);
    for (int i = 0; i < n; ++i) {
      if (prismatic[i]) {
        jacobian->col(i) << axes[i], Eigen::Vector3d::Zero();
      } else {
        jacobian->col(i) << axes[i].cross(sole.position - origins[i]), axes[i];
      }
    }
  }
  return sole;
}

Pose NumericalLegIk::forwardKinematics(const Pose& root,
                                       const Eigen::Ref<const Eigen::VectorXd>& angles) const {
  if (angles.size() != jointCount())
    throw std::invalid_argument("numerical leg IK: " + std::to_string(angles.size()) +
                                " angles for a leg of " + std::to_string(jointCount()));
  return evaluate(root, angles, nullptr);
}

Pose NumericalLegIk::forwardKinematics(const Pose& root,
                                       const Eigen::Ref<const Eigen::VectorXd>& angles,
                                       Pose* bodies) const {
  if (angles.size() != jointCount())
    throw std::invalid_argument("numerical leg IK: " + std::to_string(angles.size()) +
                                " angles for a leg of " + std::to_string(jointCount()));
  return evaluate(root, angles, nullptr, bodies);
}

Eigen::Matrix<double, 6, Eigen::Dynamic> NumericalLegIk::jacobian(
    const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles) const {
  if (angles.size() != jointCount())
    throw std::invalid_argument("numerical leg IK: " + std::to_string(angles.size()) +
                                " angles for a leg of " + std::to_string(jointCount()));
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxLegJoints> out;
  evaluate(root, angles, &out);
  return out;
}

NumericalLegIkResult NumericalLegIk::solve(const Pose& root, const Pose& sole,
                                           Eigen::Ref<Eigen::VectorXd> angles) const {
  const int n = jointCount();
  if (angles.size() != n)
    throw std::invalid_argument("numerical leg IK: " + std::to_string(angles.size()) +
                                " angles for a leg of " + std::to_string(n));
  const Eigen::VectorXd& lower = model_.jointLowerLimits();
  const Eigen::VectorXd& upper = model_.jointUpperLimits();
  for (int i = 0; i < n; ++i) angles(i) = std::clamp(angles(i), lower(joints_[i]), upper(joints_[i]));

  NumericalLegIkResult result;
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxLegJoints> jacobian;
  Eigen::Matrix<double, 6, 1> error, candidate_error;
  using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLegJoints, kMaxLegJoints>;
  Square normal;
  Angles gradient, step, candidate;
  bool held[kMaxLegJoints];
  const auto soleError = [&](const Pose& reached, Eigen::Matrix<double, 6, 1>& e) {
    e << sole.position - reached.position,
        rotationVector(sole.rotation * reached.rotation.transpose());
  };
  soleError(evaluate(root, angles, &jacobian), error);
  double lambda = settings_.damping * error.norm();
  for (;;) {
    result.position_error = error.head<3>().norm();
    result.rotation_error = error.tail<3>().norm();
    if (result.position_error <= settings_.position_tolerance &&
        result.rotation_error <= settings_.rotation_tolerance) {
      result.converged = true;
      return result;
    }
    if (result.iterations >= settings_.max_iterations) return result;
    ++result.iterations;
    // Solve with every joint free, then hold at its limit each joint the step pushes beyond
    // it, and solve again, until the held set no longer changes (at most n rounds).
    for (int i = 0; i < n; ++i) held[i] = locked_[static_cast<std::size_t>(i)];
    for (int round = 0; round <= n; ++round) {
      normal.noalias() = jacobian.transpose() * jacobian;
      normal.diagonal().array() += lambda * lambda;
      gradient.noalias() = jacobian.transpose() * error;
      for (int i = 0; i < n; ++i) {
        if (!held[i]) continue;
        normal.row(i).setZero();
        normal.col(i).setZero();
        normal(i, i) = 1.0;
        gradient(i) = 0.0;
      }
      step = normal.ldlt().solve(gradient);
      bool changed = false;
      for (int i = 0; i < n; ++i) {
        const double next = angles(i) + step(i);
        if (!held[i] && (next < lower(joints_[i]) || next > upper(joints_[i]))) {
          held[i] = true;
          changed = true;
        }
      }
      if (!changed) break;
    }
    candidate = angles;
    for (int i = 0; i < n; ++i)
      candidate(i) = std::clamp(angles(i) + step(i), lower(joints_[i]), upper(joints_[i]));
    soleError(evaluate(root, candidate, nullptr), candidate_error);
    // Levenberg-Marquardt: a step that does not reduce the error is refused and the damping
    // raised (the straight knee's singularity pulls Gauss-Newton's steps too far); an accepted
    // one lowers it back towards damping x |e|, Gauss-Newton's near the solution.
    if (candidate_error.norm() < error.norm()) {
      angles = candidate;
      soleError(evaluate(root, angles, &jacobian), error);
      lambda = std::max(0.25 * lambda, settings_.damping * error.norm());
    } else {
      lambda = std::max(4.0 * lambda, 1e-6);
    }
  }
}

}  // namespace wpg::robots
