#pragma once
// ZMP preview control on the cart-table model (Kajita et al., "Biped walking pattern
// generation by using preview control of zero-moment point", ICRA 2003), used by the dynamic
// filter of the paper (Sec. IV): at the control period dt, one horizontal axis,
//   x = [c, c', c''],  x+ = A x + B u (u = jerk),  p = C x = c - h/g c''  (the ZMP),
// and the optimal servo with integral action on the ZMP error and a preview of the reference:
//   u_k = -Gi sum_{i<=k} (p_i - pref_i) - Gx x_k - sum_{j=1}^{NL} Gd_j pref_{k+j}
// from the discrete algebraic Riccati equation of the augmented system (error, state
// increments) with weights Qe on the error and R on the input (Katayama et al. 1985).
#include <Eigen/Core>

namespace wpg {

struct PreviewControlSettings {
  double error_weight = 1.0;   // Qe
  double input_weight = 1e-6;  // R (the authors' code: 1e-5)
  double preview_time = 1.6;   // NL * dt [s] (the authors' code: 0.665 s)
};

class PreviewController {
 public:
  // Throws std::invalid_argument on non-positive weights, periods or heights, and
  // std::runtime_error when the Riccati iteration does not converge.
  PreviewController(double control_period, double com_height, double gravity,
                    const PreviewControlSettings& settings = PreviewControlSettings());

  double integralGain() const { return gain_integral_; }           // Gi
  const Eigen::RowVector3d& stateGain() const { return gain_state_; }  // Gx
  const Eigen::VectorXd& previewGains() const { return gain_preview_; }  // Gd_1 .. Gd_NL
  const Eigen::Matrix4d& riccati() const { return riccati_; }       // P of the augmented DARE
  double riccatiResidual() const { return riccati_residual_; }     // |DARE(P) - P|_max
  double closedLoopSpectralRadius() const { return spectral_radius_; }
  int previewLength() const { return static_cast<int>(gain_preview_.size()); }

  const Eigen::Matrix3d& A() const { return A_; }
  const Eigen::Vector3d& B() const { return B_; }
  const Eigen::RowVector3d& C() const { return C_; }

  // Runs the servo over a whole reference (one axis, sampled at dt; the reference is held at
  // its last value beyond the end). Writes the state trajectory (n x 3) and the ZMP (n).
  void track(const Eigen::Ref<const Eigen::VectorXd>& reference, const Eigen::Vector3d& initial,
             Eigen::Ref<Eigen::MatrixXd> states, Eigen::Ref<Eigen::VectorXd> zmp) const;

 private:
  Eigen::Matrix3d A_;
  Eigen::Vector3d B_;
  Eigen::RowVector3d C_;
  double gain_integral_ = 0.0;
  Eigen::RowVector3d gain_state_;
  Eigen::VectorXd gain_preview_;
  Eigen::Matrix4d riccati_;
  double riccati_residual_ = 0.0;
  double spectral_radius_ = 0.0;
};

}  // namespace wpg
