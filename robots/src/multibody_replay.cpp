// MultibodyReplay without Simbody: input checks, finite differences, the loop over samples.
// The Simbody part (construction, one sample of inverse dynamics) is simbody_dynamics.cpp.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "wpg/robots/multibody_replay.hpp"

namespace wpg::robots {
namespace {

// The loops below work on transposed trajectories (one sample per column, contiguous): a row of
// an n x nq matrix is strided across n, and reading it between two Simbody calls misses the
// caches on every entry.

// Free-flyer orientation of sample k (w x y z in rows 3..6), normalized.
Eigen::Quaterniond sampleOrientation(const Eigen::MatrixXd& qt, Eigen::Index k) {
  return Eigen::Quaterniond(qt(3, k), qt(4, k), qt(5, k), qt(6, k)).normalized();
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
void midpointVelocity(const Eigen::MatrixXd& qt, Eigen::Index k, double dt,
                      Eigen::Ref<Eigen::VectorXd> out) {
  const Eigen::Index nj = qt.rows() - RobotModel::kFreeFlyerConfigurationSize;
  out.head<3>() = (qt.col(k + 1).head<3>() - qt.col(k).head<3>()) / dt;
  out.segment<3>(3) = rotationVector(sampleOrientation(qt, k), sampleOrientation(qt, k + 1)) / dt;
  out.tail(nj) = (qt.col(k + 1).tail(nj) - qt.col(k).tail(nj)) / dt;
}

// Fills sample (column) `end` of m by polynomial extrapolation from the interior samples next
// to it.
void extrapolateEnd(Eigen::MatrixXd& m, Eigen::Index end, Eigen::Index step, Eigen::Index interior) {
  const Eigen::Index r1 = end + step, r2 = end + 2 * step, r3 = end + 3 * step;
  if (interior >= 3) {
    m.col(end) = 3.0 * m.col(r1) - 3.0 * m.col(r2) + m.col(r3);  // quadratic
  } else if (interior == 2) {
    m.col(end) = 2.0 * m.col(r1) - m.col(r2);  // linear
  } else {
    m.col(end) = m.col(r1);  // constant
  }
}

// The checks of differentiate() and run().
void checkTrajectory(const RobotModel& model, const Eigen::Ref<const Eigen::MatrixXd>& q,
                     double dt) {
  if (q.cols() != model.nq() || q.rows() < 3) {
    throw std::invalid_argument("multibody replay: q of size " + std::to_string(q.rows()) + " x " +
                                std::to_string(q.cols()) + ", expected n x " +
                                std::to_string(model.nq()) + " with n >= 3");
  }
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("multibody replay: dt must be finite and > 0");
  }
}

}  // namespace

void MultibodyReplay::differentiate(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                    Eigen::MatrixXd& velocity,
                                    Eigen::MatrixXd& acceleration) const {
  checkTrajectory(model_, q, dt);
  const Eigen::MatrixXd qt = q.transpose();
  Eigen::MatrixXd vt, at;
  differentiateSamples(qt, dt, vt, at);
  velocity = vt.transpose();
  acceleration = at.transpose();
}

void MultibodyReplay::differentiateSamples(const Eigen::MatrixXd& qt, double dt,
                                           Eigen::MatrixXd& vt, Eigen::MatrixXd& at) const {
  const Eigen::Index n = qt.cols();
  const int nv = model_.nv();
  vt.resize(nv, n);
  at.resize(nv, n);
  Eigen::VectorXd before(nv), after(nv);
  midpointVelocity(qt, 0, dt, before);
  for (Eigen::Index k = 1; k + 1 < n; ++k) {
    midpointVelocity(qt, k, dt, after);
    vt.col(k) = 0.5 * (before + after);
    at.col(k) = (after - before) / dt;
    before.swap(after);
  }
  const Eigen::Index interior = n - 2;
  // a: polynomial extrapolation; v: from the nearest interior velocity and that acceleration
  // model, i.e. the same extrapolation (consistent to second order).
  extrapolateEnd(at, 0, 1, interior);
  extrapolateEnd(at, n - 1, -1, interior);
  if (interior == 1) {
    vt.col(0) = vt.col(1) - dt * at.col(1);
    vt.col(n - 1) = vt.col(n - 2) + dt * at.col(n - 2);
  } else {
    extrapolateEnd(vt, 0, 1, interior);
    extrapolateEnd(vt, n - 1, -1, interior);
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
  checkTrajectory(model_, q, dt);
  const Eigen::Index n = q.rows();
  if (!q.allFinite()) throw std::invalid_argument("multibody replay: q has non-finite entries");
  qt_ = q.transpose();
  for (Eigen::Index k = 0; k < n; ++k) {
    const double norm = qt_.col(k).segment<4>(3).norm();
    if (std::abs(norm - 1.0) > 1e-6) {
      throw std::invalid_argument("multibody replay: sample " + std::to_string(k) +
                                  ": free-flyer quaternion norm " + std::to_string(norm) +
                                  ", expected 1");
    }
  }
  result_.dt = dt;
  differentiateSamples(qt_, dt, vt_, at_);
  result_.velocity = vt_.transpose();
  result_.acceleration = at_.transpose();
  result_.base_wrench.resize(n, 6);
  Simbody& simbody = simbodyFor(q);
  result_.joint_torques.resize(settings_.joint_torques ? n : 0, model_.jointCount());
  result_.zmp.resize(n, 2);
  result_.com.resize(n, 3);
  InverseDynamicsSample sample;
  for (Eigen::Index k = 0; k < n; ++k) {
    sampleDynamics(simbody, qt_.col(k), vt_.col(k), at_.col(k), sample, tau_);
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
