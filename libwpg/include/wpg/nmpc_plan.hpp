#pragma once
// What one NMPC iteration predicts (the preview of the paper's Fig. 2): the previewed
// footsteps, the CoM state and jerk at every previewed sample, the CoP there (eq. 1-3 applied
// to the plan U of eq. 6 from the iteration's CoM state) and the rows of each constraint
// family the QP left active. NmpcPlan is one iteration's, sized once (PatternGenerator::
// previewPlan fills it without allocating); PlanLog is a walk's, one row per NMPC iteration,
// the layout of the dataset's mpc/plan/ (datasets/SCHEMA.md).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace wpg {

struct NmpcPlan {
  double time = 0.0;             // [s] the iteration's sampling instant t_k
  double sampling_period = 0.0;  // [s] T
  // Previewed samples of the cadence in force (N; the adaptive step timing's shorter steps
  // have fewer); rows beyond it are 0. 0: no NMPC ran (a fall).
  int samples = 0;
  // Row j is sample k + j + 1, at t_k + (j + 1) T: the CoM predicted by eq. (1)-(2) [m, m/s,
  // m/s^2], the CoP z = c - h/g c'' (eq. 3) [m]; x, y columns, world frame.
  Eigen::Matrix<double, Eigen::Dynamic, 2> com_position, com_velocity, com_acceleration, cop;
  // Row j: the jerk [m/s^3] held over [t_k + j T, t_k + (j + 1) T] (row 0 is executed).
  Eigen::Matrix<double, Eigen::Dynamic, 2> jerk;
  // The previewed steps (nf; step 0 is the landing of the current swing): x, y [m], yaw [rad],
  // the instant it becomes the support [s] (0 when it does not within the horizon: standing)
  // and its side (1 left, 2 right: FootSide).
  Eigen::Matrix<double, Eigen::Dynamic, 3> step_pose;
  Eigen::VectorXd step_landing_time;
  Eigen::VectorXi step_side;
  // Active inequality rows of the iteration's last QP per constraint family, in the model's
  // family order (WalkTrajectory::constraint_families).
  Eigen::VectorXi active_rows;

  // Sizes every field (allocates) and clears it.
  void resize(int max_samples, int steps, int families);
  int capacity() const { return static_cast<int>(com_position.rows()); }
  // No NMPC ran: every value and count 0.
  void clear(double time);
};

// One NmpcPlan per NMPC iteration, flattened (row-major): iteration i, sample j at row
// i * max_samples + j of the per-sample fields, step s at row i * steps + s.
struct PlanLog {
  int max_samples = 0, steps = 0, families = 0;
  double sampling_period = 0.0;
  std::vector<int> samples;                       // per iteration
  std::vector<double> com_position, com_velocity, com_acceleration, jerk, cop;  // x, y
  std::vector<double> step;                       // landing time, x, y, yaw
  std::vector<std::uint8_t> step_side;            // 1 left, 2 right
  std::vector<int> active_rows;                   // per iteration x family

  std::size_t size() const { return samples.size(); }
  bool empty() const { return samples.empty(); }
  // Sets the widths and reserves `iterations` rows (allocates; append then does not).
  void reserve(int max_samples_, int steps_, int families_, double sampling_period_,
               std::size_t iterations);
  // Appends `plan` (its first max_samples rows; 0 beyond its samples).
  void append(const NmpcPlan& plan);
};

}  // namespace wpg
