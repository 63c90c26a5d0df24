#pragma once
// Prediction matrices of the linear inverted pendulum with piecewise-constant jerk
// (paper eq. 1-3): for one horizontal axis, with state c_hat = [c, c', c''] at sample k and
// the jerks of samples k..k+N-1,
//   C_{k+1}  = position_state * c_hat + position_jerk * jerks        (rows j = 1..N)
//   C'_{k+1} = velocity_state * c_hat + velocity_jerk * jerks
//   C''_{k+1}= acceleration_state * c_hat + acceleration_jerk * jerks
//   Z_{k+1}  = cop_state * c_hat + cop_jerk * jerks,   z = c - h/g c''      (eq. 3)
#include <Eigen/Core>

namespace wpg {

struct LipmPrediction {
  LipmPrediction() = default;
  LipmPrediction(int horizon_length, double sampling_period, double com_height, double gravity);

  int horizon_length = 0;
  double sampling_period = 0.0;
  double height_over_gravity = 0.0;
  Eigen::Matrix<double, Eigen::Dynamic, 3> position_state, velocity_state, acceleration_state,
      cop_state;
  Eigen::MatrixXd position_jerk, velocity_jerk, acceleration_jerk, cop_jerk;  // lower triangular
};

// State transition of one axis over a duration dt with constant jerk (eq. 2 with T = dt),
// plus an external acceleration that moves the CoM but not the controlled acceleration (a
// push, paper Sec. V-B: the CoP z = c - h/g c'' keeps the controlled c'' only).
inline void integrateJerk(Eigen::Vector3d& state, double jerk, double dt,
                          double external_acceleration = 0.0) {
  const double dt2 = dt * dt, dt3 = dt2 * dt;
  state(0) += state(1) * dt + (state(2) + external_acceleration) * dt2 / 2.0 + jerk * dt3 / 6.0;
  state(1) += (state(2) + external_acceleration) * dt + jerk * dt2 / 2.0;
  state(2) += jerk * dt;
}

}  // namespace wpg
