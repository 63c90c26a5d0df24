// Checks and finite differences of a replayed joint trajectory (finite_differences.hpp).
#include "finite_differences.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace wpg::robots::detail {
namespace {

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

}  // namespace

void checkTrajectorySize(const RobotModel& model, const Eigen::Ref<const Eigen::MatrixXd>& q,
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

void checkComForce(const Eigen::Ref<const Eigen::MatrixXd>& q,
                   const Eigen::Ref<const Eigen::MatrixXd>& com_force) {
  if (com_force.rows() != q.rows() || com_force.cols() != 3 || !com_force.allFinite()) {
    throw std::invalid_argument("multibody replay: CoM force of size " +
                                std::to_string(com_force.rows()) + " x " +
                                std::to_string(com_force.cols()) + ", expected " +
                                std::to_string(q.rows()) + " x 3, finite");
  }
}

void checkedTranspose(const RobotModel& model, const Eigen::Ref<const Eigen::MatrixXd>& q,
                      double dt, Eigen::MatrixXd& qt) {
  checkTrajectorySize(model, q, dt);
  if (!q.allFinite()) throw std::invalid_argument("multibody replay: q has non-finite entries");
  qt = q.transpose();
  for (Eigen::Index k = 0; k < qt.cols(); ++k) {
    const double norm = qt.col(k).segment<4>(3).norm();
    if (std::abs(norm - 1.0) > 1e-6) {
      throw std::invalid_argument("multibody replay: sample " + std::to_string(k) +
                                  ": free-flyer quaternion norm " + std::to_string(norm) +
                                  ", expected 1");
    }
  }
}

void differentiateSamples(const Eigen::MatrixXd& qt, double dt, Eigen::MatrixXd& vt,
                          Eigen::MatrixXd& at, Eigen::VectorXd& before, Eigen::VectorXd& after) {
  const Eigen::Index n = qt.cols();
  const Eigen::Index nv = qt.rows() - 1;  // the quaternion's 4 coordinates, 3 velocities
  vt.resize(nv, n);
  at.resize(nv, n);
  before.resize(nv);
  after.resize(nv);
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

}  // namespace wpg::robots::detail
