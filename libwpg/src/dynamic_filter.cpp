#include "wpg/dynamic_filter.hpp"

#include <algorithm>
#include <stdexcept>

namespace wpg {

void dynamicFilterCorrection(const PreviewController& controller,
                             const Eigen::Ref<const Eigen::MatrixXd>& zmp_error,
                             Eigen::Ref<Eigen::MatrixXd> correction) {
  if (zmp_error.cols() != 2 || correction.cols() != 2 || correction.rows() != zmp_error.rows())
    throw std::invalid_argument("dynamic filter: expected n x 2 ZMP error and correction");
  const Eigen::Index n = zmp_error.rows();
  Eigen::MatrixXd states(n, 3);
  Eigen::VectorXd zmp(n);
  for (int axis = 0; axis < 2; ++axis) {
    controller.track(zmp_error.col(axis), Eigen::Vector3d::Zero(), states, zmp);
    correction.col(axis) = states.col(0);
  }
}

const char* dynamicFilterModeName(DynamicFilterMode mode) {
  switch (mode) {
    case DynamicFilterMode::kOnline: return "online";
    case DynamicFilterMode::kOffline: return "offline";
    case DynamicFilterMode::kBoth: return "both";
    case DynamicFilterMode::kClosedLoop: return "closed_loop";
  }
  return "online";
}

bool parseDynamicFilterMode(const std::string& name, DynamicFilterMode* out) {
  for (DynamicFilterMode mode : {DynamicFilterMode::kOnline, DynamicFilterMode::kOffline,
                                 DynamicFilterMode::kBoth, DynamicFilterMode::kClosedLoop}) {
    if (name == dynamicFilterModeName(mode)) {
      *out = mode;
      return true;
    }
  }
  return false;
}

OnlineDynamicFilter::OnlineDynamicFilter(const PreviewController& controller)
    : controller_(controller) {}

void OnlineDynamicFilter::reset() {
  state_x_.setZero();
  state_y_.setZero();
  error_sum_x_ = error_sum_y_ = 0.0;
  absorbed_x_.setZero();
  absorbed_y_.setZero();
}

void OnlineDynamicFilter::absorbIncrement(Eigen::Vector3d& increment_x,
                                          Eigen::Vector3d& increment_y) {
  // The position only: the WPG's velocity and acceleration are left alone, so that the CoM
  // sent (WPG + sentCorrection) keeps the velocity and acceleration it had. Absorbed whole, the
  // velocity and acceleration would be counted twice (by the WPG from now on, and by the
  // correction, which moves on with them), a kink of the CoM sent at every NMPC iteration.
  increment_x = Eigen::Vector3d(state_x_(0) - absorbed_x_(0), 0.0, 0.0);
  increment_y = Eigen::Vector3d(state_y_(0) - absorbed_y_(0), 0.0, 0.0);
  absorbed_x_(0) = state_x_(0);
  absorbed_y_(0) = state_y_(0);
}

void OnlineDynamicFilter::absorbCorrection(Eigen::Vector3d& absorbed_x,
                                           Eigen::Vector3d& absorbed_y) {
  absorbed_x = state_x_;
  absorbed_y = state_y_;
  reset();
}

void OnlineDynamicFilter::step(const Eigen::Ref<const Eigen::MatrixXd>& error_window) {
  if (error_window.cols() != 2 || error_window.rows() < 1 || !error_window.allFinite())
    throw std::invalid_argument("online dynamic filter: expected a k x 2 finite error window, "
                                "k >= 1");
  // The servo of PreviewController::track at one instant k (Kajita 2003, eq. 9-11):
  //   u = -Gi sum_{i<=k} (p_i - e_i) - Gx x_k - sum_{j=1}^{NL} Gd_j e_{k+j},
  // e_{k+j} = window row j, the last row held past the window's end.
  const Eigen::VectorXd& gains = controller_.previewGains();
  const Eigen::Index length = gains.size();
  const Eigen::Index last = error_window.rows() - 1;
  const Eigen::Index inside = std::min<Eigen::Index>(length, last);
  const auto advance = [&](Eigen::Vector3d& x, double& error_sum, int axis) {
    const double p = controller_.C() * x;
    error_sum += p - error_window(0, axis);
    double preview = gains.head(inside).dot(error_window.col(axis).segment(1, inside));
    if (inside < length) preview += gains.tail(length - inside).sum() * error_window(last, axis);
    const double u =
        -controller_.integralGain() * error_sum - controller_.stateGain().dot(x) - preview;
    x = controller_.A() * x + controller_.B() * u;
  };
  advance(state_x_, error_sum_x_, 0);
  advance(state_y_, error_sum_y_, 1);
}

}  // namespace wpg
