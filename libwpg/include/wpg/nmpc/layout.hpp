#pragma once
// Index layout of the NMPC's decision vector U (paper eq. 6) and of its inequality rows.
#include <Eigen/Core>

namespace wpg {

struct NmpcLayout {
  int horizon = 0;         // N
  int steps = 0;           // nf
  int feasibility_edges = 0;
  int obstacle_slots = 0;  // obstacles that may enter the QP at once
  // All inequality rows: the built-in families below, then the rows of families registered
  // after them (NmpcModel::addConstraintFamily).
  int inequality_rows = 0;

  // U = [jerk_x (N), F_x (nf), jerk_y (N), F_y (nf), F_theta (nf)]
  int jerkX() const { return 0; }
  int stepX() const { return horizon; }
  int jerkY() const { return horizon + steps; }
  int stepY() const { return 2 * horizon + steps; }
  int stepYaw() const { return 2 * horizon + 2 * steps; }
  int variableCount() const { return 2 * horizon + 3 * steps; }

  // Rows of the built-in families, in registration order (NmpcModel's constructor).
  static constexpr int kCopEdges = 4;
  int copRow(int sample, int edge) const { return kCopEdges * sample + edge; }
  int feasibilityRow(int step, int edge) const {
    return kCopEdges * horizon + feasibility_edges * step + edge;
  }
  int yawRow(int step, bool upper) const {
    return kCopEdges * horizon + feasibility_edges * steps + 2 * step + (upper ? 0 : 1);
  }
  int obstacleRow(int step, int slot) const {
    return kCopEdges * horizon + feasibility_edges * steps + 2 * steps + obstacle_slots * step + slot;
  }
  int firstObstacleRow() const { return obstacleRow(0, 0); }
  // landing_bound: x, y of previewed step 0, upper then lower (4 rows, metres), then
  // landing_yaw_bound: its yaw (2 rows, radians); each family's rows exist only when its rate
  // is on (> 0), so that a bound that is off costs nothing
  static constexpr int kLandingPositionRows = 4;
  static constexpr int kLandingYawRows = 2;
  int landing_position_rows = 0;
  int landing_yaw_rows = 0;
  // axis 0 = x, 1 = y (landing_bound), 2 = yaw (landing_yaw_bound)
  int landingRow(int axis, bool upper) const {
    const int first = obstacleRow(steps, 0) + (axis == 2 ? landing_position_rows : 2 * axis);
    return first + (upper ? 0 : 1);
  }
  int builtinRowCount() const {
    return obstacleRow(steps, 0) + landing_position_rows + landing_yaw_rows;
  }
  int inequalityCount() const { return inequality_rows; }
  int maxEqualityCount() const { return 3 * steps; }
};

}  // namespace wpg
