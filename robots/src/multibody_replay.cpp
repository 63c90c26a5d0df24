// MultibodyReplay without Simbody: input checks, finite differences, the loop over samples.
// The Simbody part (construction, one sample of inverse dynamics) is simbody_dynamics.cpp.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "wpg/robots/multibody_replay.hpp"

namespace wpg::robots {
namespace {

// Free-flyer orientation of row k (w x y z in columns 3..6), normalized.
Eigen::Quaterniond rowOrientation(const Eigen::Ref<const Eigen::MatrixXd>& q, Eigen::Index k) {
  return Eigen::Quaterniond(q(k, 3), q(k, 4), q(k, 5), q(k, 6)).normalized();
}

// World-frame rotation vector of R1 R0', i.e. log(R1 R0').
Eigen::Vector3d rotationVector(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  Eigen::Quaterniond d = b * a.conjugate();
  if (d.w() < 0.0) d.coeffs() = -d.coeffs();
  const double s = d.vec().norm();
  const double factor = s > 1e-12 ? 2.0 * std::atan2(s, d.w()) / s : 2.0 / d.w();
  return factor * d.vec();
}

// Mid-point velocity between configurations k and k + 1 (velocity layout).
void midpointVelocity(const Eigen::Ref<const Eigen::MatrixXd>& q, Eigen::Index k, double dt,
                      Eigen::Ref<Eigen::VectorXd> out) {
  const int nj = static_cast<int>(q.cols()) - RobotModel::kFreeFlyerConfigurationSize;
  out.head<3>() = (q.row(k + 1).head<3>() - q.row(k).head<3>()).transpose() / dt;
  out.segment<3>(3) = rotationVector(rowOrientation(q, k), rowOrientation(q, k + 1)) / dt;
  out.tail(nj) = (q.row(k + 1).tail(nj) - q.row(k).tail(nj)).transpose() / dt;
}

// Fills rows `end` of m by polynomial extrapolation from the interior rows next to it.
void extrapolateEnd(Eigen::MatrixXd& m, Eigen::Index end, Eigen::Index step, Eigen::Index interior) {
  const Eigen::Index r1 = end + step, r2 = end + 2 * step, r3 = end + 3 * step;
  if (interior >= 3) {
    m.row(end) = 3.0 * m.row(r1) - 3.0 * m.row(r2) + m.row(r3);  // quadratic
  } else if (interior == 2) {
    m.row(end) = 2.0 * m.row(r1) - m.row(r2);  // linear
  } else {
    m.row(end) = m.row(r1);  // constant
  }
}

}  // namespace

void MultibodyReplay::differentiate(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                    Eigen::MatrixXd& velocity,
                                    Eigen::MatrixXd& acceleration) const {
  const Eigen::Index n = q.rows();
  const int nv = model_.nv();
  if (q.cols() != model_.nq() || n < 3) {
    throw std::invalid_argument("multibody replay: q of size " + std::to_string(n) + " x " +
                                std::to_string(q.cols()) + ", expected n x " +
                                std::to_string(model_.nq()) + " with n >= 3");
  }
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("multibody replay: dt must be finite and > 0");
  }
  velocity.resize(n, nv);
  acceleration.resize(n, nv);
  Eigen::VectorXd before(nv), after(nv);
  midpointVelocity(q, 0, dt, before);
  for (Eigen::Index k = 1; k + 1 < n; ++k) {
    midpointVelocity(q, k, dt, after);
    velocity.row(k) = 0.5 * (before + after).transpose();
    acceleration.row(k) = ((after - before) / dt).transpose();
    before.swap(after);
  }
  const Eigen::Index interior = n - 2;
  // a: polynomial extrapolation; v: from the nearest interior velocity and that acceleration
  // model, i.e. the same extrapolation (consistent to second order).
  extrapolateEnd(acceleration, 0, 1, interior);
  extrapolateEnd(acceleration, n - 1, -1, interior);
  if (interior == 1) {
    velocity.row(0) = velocity.row(1) - dt * acceleration.row(1);
    velocity.row(n - 1) = velocity.row(n - 2) + dt * acceleration.row(n - 2);
  } else {
    extrapolateEnd(velocity, 0, 1, interior);
    extrapolateEnd(velocity, n - 1, -1, interior);
  }
}

Eigen::Vector2d MultibodyReplay::zmpOfWrench(const Eigen::Matrix<double, 6, 1>& wrench) {
  const double fz = wrench(5);
  if (!(fz > 0.0)) {
    return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return {-wrench(1) / fz, wrench(0) / fz};
}

const MultibodyReplayResult& MultibodyReplay::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                                  double dt) {
  return runImpl(q, dt, nullptr);
}

const MultibodyReplayResult& MultibodyReplay::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                                  double dt,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& com_force) {
  if (com_force.rows() != q.rows() || com_force.cols() != 3 || !com_force.allFinite()) {
    throw std::invalid_argument("multibody replay: CoM force of size " +
                                std::to_string(com_force.rows()) + " x " +
                                std::to_string(com_force.cols()) + ", expected " +
                                std::to_string(q.rows()) + " x 3, finite");
  }
  return runImpl(q, dt, &com_force);
}

const MultibodyReplayResult& MultibodyReplay::runImpl(
    const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
    const Eigen::Ref<const Eigen::MatrixXd>* com_force) {
  const Eigen::Index n = q.rows();
  if (q.cols() != model_.nq() || n < 3) {
    throw std::invalid_argument("multibody replay: q of size " + std::to_string(n) + " x " +
                                std::to_string(q.cols()) + ", expected n x " +
                                std::to_string(model_.nq()) + " with n >= 3");
  }
  if (!q.allFinite()) throw std::invalid_argument("multibody replay: q has non-finite entries");
  for (Eigen::Index k = 0; k < n; ++k) {
    const double norm = q.row(k).segment<4>(3).norm();
    if (std::abs(norm - 1.0) > 1e-6) {
      throw std::invalid_argument("multibody replay: sample " + std::to_string(k) +
                                  ": free-flyer quaternion norm " + std::to_string(norm) +
                                  ", expected 1");
    }
  }
  result_.dt = dt;
  differentiate(q, dt, result_.velocity, result_.acceleration);
  result_.base_wrench.resize(n, 6);
  Simbody& simbody = simbodyFor(q);
  result_.joint_torques.resize(settings_.joint_torques ? n : 0, model_.jointCount());
  result_.zmp.resize(n, 2);
  result_.com.resize(n, 3);
  InverseDynamicsSample sample;
  for (Eigen::Index k = 0; k < n; ++k) {
    q_ = q.row(k).transpose();
    v_ = result_.velocity.row(k).transpose();
    a_ = result_.acceleration.row(k).transpose();
    sampleDynamics(simbody, q_, v_, a_, sample, tau_);
    if (com_force != nullptr) {  // the ground's share: minus the wrench of the force at the CoM
      const Eigen::Vector3d force = com_force->row(k).transpose();
      sample.base_wrench.head<3>() -= sample.com.cross(force);
      sample.base_wrench.tail<3>() -= force;
      sample.zmp = zmpOfWrench(sample.base_wrench);
    }
    result_.base_wrench.row(k) = sample.base_wrench.transpose();
    if (settings_.joint_torques) result_.joint_torques.row(k) = tau_.transpose();
    result_.zmp.row(k) = sample.zmp.transpose();
    result_.com.row(k) = sample.com.transpose();
  }
  return result_;
}

InverseDynamicsSample MultibodyReplay::inverseDynamics(const Eigen::Ref<const Eigen::VectorXd>& q,
                                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                                       const Eigen::Ref<const Eigen::VectorXd>& a,
                                                       Eigen::VectorXd* joint_torques) {
  model_.checkConfiguration(q);
  if (v.size() != model_.nv() || a.size() != model_.nv() || !v.allFinite() || !a.allFinite()) {
    throw std::invalid_argument("multibody replay: v and a must have " +
                                std::to_string(model_.nv()) + " finite entries");
  }
  InverseDynamicsSample out;
  sampleDynamics(*simbody_, q, v, a, out, tau_);
  if (joint_torques != nullptr) *joint_torques = tau_;
  return out;
}

}  // namespace wpg::robots
