#include "wpg/preview_control.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

namespace wpg {

PreviewController::PreviewController(double dt, double com_height, double gravity,
                                     const PreviewControlSettings& settings) {
  if (!(dt > 0.0) || !(com_height > 0.0) || !(gravity > 0.0))
    throw std::invalid_argument("preview control: period, CoM height and gravity must be > 0");
  if (!(settings.error_weight > 0.0) || !(settings.input_weight > 0.0) ||
      !(settings.preview_time > 0.0))
    throw std::invalid_argument("preview control: weights and preview time must be > 0");
  A_ << 1.0, dt, dt * dt / 2.0, 0.0, 1.0, dt, 0.0, 0.0, 1.0;
  B_ << dt * dt * dt / 6.0, dt * dt / 2.0, dt;
  C_ << 1.0, 0.0, -com_height / gravity;

  // Augmented system on (e_k = p_k - pref_k, dx_k = x_k - x_{k-1}) (Katayama 1985):
  //   [e; dx]+ = At [e; dx] + Bt du + It dpref,  At = [1 CA; 0 A], Bt = [CB; B].
  Eigen::Matrix4d At = Eigen::Matrix4d::Zero();
  At(0, 0) = 1.0;
  At.block<1, 3>(0, 1) = C_ * A_;
  At.block<3, 3>(1, 1) = A_;
  Eigen::Vector4d Bt;
  Bt(0) = C_ * B_;
  Bt.tail<3>() = B_;
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();
  Q(0, 0) = settings.error_weight;
  const double R = settings.input_weight;

  // Riccati iteration to the fixed point P = Q + At'P At - At'P Bt (R + Bt'P Bt)^-1 Bt'P At.
  Eigen::Matrix4d P = Q;
  double change = 1.0;
  int iterations = 0;
  for (; iterations < 200000 && change > 1e-13 * std::max(1.0, P.cwiseAbs().maxCoeff());
       ++iterations) {
    const double s = R + Bt.dot(P * Bt);
    const Eigen::RowVector4d K = (Bt.transpose() * P * At) / s;
    Eigen::Matrix4d next = Q + At.transpose() * P * At - (At.transpose() * P * Bt) * K;
    next = 0.5 * (next + next.transpose());
    change = (next - P).cwiseAbs().maxCoeff();
    P = next;
  }
  if (!(change <= 1e-13 * std::max(1.0, P.cwiseAbs().maxCoeff())) || !P.allFinite())
    throw std::runtime_error("preview control: the Riccati iteration did not converge");
  riccati_ = P;
  const double s = R + Bt.dot(P * Bt);
  const Eigen::Matrix4d dare =
      Q + At.transpose() * P * At - (At.transpose() * P * Bt) * (Bt.transpose() * P * At) / s;
  riccati_residual_ = (dare - P).cwiseAbs().maxCoeff();

  const Eigen::RowVector4d K = (Bt.transpose() * P * At) / s;  // du = -K [e; dx] - preview
  gain_integral_ = K(0);
  gain_state_ = K.tail<3>();
  const Eigen::Matrix4d Ac = At - Bt * K;
  spectral_radius_ = Ac.eigenvalues().cwiseAbs().maxCoeff();

  // Preview gains: Gd_1 = -Gi, Gd_j = (R + Bt'P Bt)^-1 Bt' X_{j-1}, X_j = Ac' X_{j-1},
  // X_1 = -Ac' P It with It = [1; 0; 0; 0] (Kajita 2003, eq. 11).
  const int length = std::max(1, static_cast<int>(std::lround(settings.preview_time / dt)));
  gain_preview_.resize(length);
  gain_preview_(0) = -gain_integral_;
  Eigen::Vector4d X = -Ac.transpose() * P.col(0);
  for (int j = 1; j < length; ++j) {
    gain_preview_(j) = Bt.dot(X) / s;
    X = Ac.transpose() * X;
  }
}

void PreviewController::track(const Eigen::Ref<const Eigen::VectorXd>& reference,
                              const Eigen::Vector3d& initial, Eigen::Ref<Eigen::MatrixXd> states,
                              Eigen::Ref<Eigen::VectorXd> zmp) const {
  const Eigen::Index n = reference.size();
  const int length = previewLength();
  Eigen::Vector3d x = initial;
  double error_sum = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    states.row(k) = x.transpose();
    const double p = C_ * x;
    zmp(k) = p;
    error_sum += p - reference(k);
    // sum over j = 1..length of Gd_j r(min(k + j, n - 1)): the window inside the reference (one
    // vectorized dot product), then the last reference value held past its end.
    const Eigen::Index inside = std::min<Eigen::Index>(length, n - 1 - k);
    double preview = gain_preview_.head(inside).dot(reference.segment(k + 1, inside));
    if (inside < length) preview += gain_preview_.tail(length - inside).sum() * reference(n - 1);
    const double u = -gain_integral_ * error_sum - gain_state_.dot(x) - preview;
    x = A_ * x + B_ * u;
  }
}

}  // namespace wpg
