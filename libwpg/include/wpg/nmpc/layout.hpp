#pragma once
// Index layout of the NMPC's decision vector U (paper eq. 6). The inequality rows g(U) <= 0
// are not indexed here: each constraint family indexes its own rows (constraint_family.hpp,
// builtin_families.hpp) from the first row the model assigns it (NmpcModel::familyFirstRow).
#include <Eigen/Core>

namespace wpg {

struct NmpcLayout {
  int horizon = 0;  // N
  int steps = 0;    // nf

  // U = [jerk_x (N), F_x (nf), jerk_y (N), F_y (nf), F_theta (nf)]
  int jerkX() const { return 0; }
  int stepX() const { return horizon; }
  int jerkY() const { return horizon + steps; }
  int stepY() const { return 2 * horizon + steps; }
  int stepYaw() const { return 2 * horizon + 2 * steps; }
  int variableCount() const { return 2 * horizon + 3 * steps; }
  // Equality rows E U = e fixing steps (buildStepEqualities): x, y, yaw of each step at most.
  int maxEqualityCount() const { return 3 * steps; }
};

}  // namespace wpg
