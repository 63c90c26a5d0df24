#include "wpg/dynamic_filter.hpp"

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

}  // namespace wpg
