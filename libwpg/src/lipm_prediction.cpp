#include "wpg/lipm_prediction.hpp"

#include <Eigen/Dense>

namespace wpg {

LipmPrediction::LipmPrediction(int n, double T, double com_height, double gravity)
    : horizon_length(n), sampling_period(T), height_over_gravity(com_height / gravity) {
  Eigen::Matrix3d A;
  A << 1, T, T * T / 2, 0, 1, T, 0, 0, 1;                 // eq. (2)
  const Eigen::Vector3d B(T * T * T / 6, T * T / 2, T);  // eq. (2)
  const Eigen::RowVector3d cop_output(1.0, 0.0, -height_over_gravity);  // eq. (3)

  position_state.resize(n, 3);
  velocity_state.resize(n, 3);
  acceleration_state.resize(n, 3);
  cop_state.resize(n, 3);
  position_jerk.setZero(n, n);
  velocity_jerk.setZero(n, n);
  acceleration_jerk.setZero(n, n);
  cop_jerk.setZero(n, n);

  // Row j (sample k+j+1) of eq. (1): A^{j+1} c_hat + sum_{i=0}^{j} A^{j-i} B jerk_{k+i}.
  Eigen::Matrix3d A_power = A;  // A^{j+1}
  std::vector<Eigen::Vector3d> AB(n);  // A^i B
  AB[0] = B;
  for (int i = 1; i < n; ++i) AB[i] = A * AB[i - 1];
  for (int j = 0; j < n; ++j) {
    position_state.row(j) = A_power.row(0);
    velocity_state.row(j) = A_power.row(1);
    acceleration_state.row(j) = A_power.row(2);
    cop_state.row(j) = cop_output * A_power;
    for (int i = 0; i <= j; ++i) {
      const Eigen::Vector3d& b = AB[j - i];
      position_jerk(j, i) = b(0);
      velocity_jerk(j, i) = b(1);
      acceleration_jerk(j, i) = b(2);
      cop_jerk(j, i) = cop_output * b;
    }
    A_power = A * A_power;
  }
}

}  // namespace wpg
