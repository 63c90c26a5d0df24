#pragma once
// The paper's constraint families, which NmpcModel's constructor registers in this order, and
// how each numbers its own rows. Row r of a family is row familyFirstRow(k) + r of the model's
// stacked g(U), k its index (NmpcModel::findFamily): no family knows where another's rows are.
//
//   family              eq.              rows
//   cop                 (9)-(13)         4 per sample of the horizon (CopRows)
//   step_feasibility    (14)-(15)        one per polygon edge and previewed step
//   yaw_bound           (16)-(17)        2 per previewed step
//   obstacle            (18)-(19)        one per previewed step and obstacle slot
//   landing_bound       Sec. III-C3      4 (x, y of step 0, upper, lower) when on
//   landing_yaw_bound   Sec. III-C3      2 (yaw of step 0, upper, lower) when on
//   swing_reach         wpg              16 (step 0 along 8 directions, upper, lower); the
//                                        family is registered only when on
#include <memory>

#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {

// CoP in the support polygon of each sample j = 0..N-1, edges +x, -x, +y, -y (eq. 11).
struct CopRows {
  static constexpr int kEdges = 4;
  static int count(const NmpcModel& model) { return kEdges * model.layout().horizon; }
  static int row(int sample, int edge) { return kEdges * sample + edge; }
};

// Previewed step i inside the feasibility polygon attached to the step before it (eq. 15).
struct StepFeasibilityRows {
  int edges = 0;  // of the feasibility polygons (NmpcModel::feasibilityPolygon; mirror images)
  static StepFeasibilityRows of(const NmpcModel& model) {
    return {model.feasibilityPolygon(FootSide::kLeft).edgeCount()};
  }
  int count(const NmpcModel& model) const { return edges * model.layout().steps; }
  int row(int step, int edge) const { return edges * step + edge; }
};

// Yaw of previewed step i against the step before it, upper then lower bound (eq. 16-17).
struct YawBoundRows {
  static int count(const NmpcModel& model) { return 2 * model.layout().steps; }
  static int row(int step, bool upper) { return 2 * step + (upper ? 0 : 1); }
};

// Previewed step i out of the obstacle in slot k (eq. 18-19).
struct ObstacleRows {
  int slots = 0;  // obstacles in the QP at once (NmpcModel::obstacleSlots)
  static ObstacleRows of(const NmpcModel& model) { return {model.obstacleSlots()}; }
  int count(const NmpcModel& model) const { return slots * model.layout().steps; }
  int row(int step, int slot) const { return slots * step + slot; }
};

// Landing of the swing foot (previewed step 0), Sec. III-C3 last paragraph: x then y, upper
// then lower bound each; rows only when max_landing_speed > 0 (a bound that is off costs
// nothing).
struct LandingBoundRows {
  static constexpr int kRows = 4;
  static int count(const NmpcModel& model) {
    return model.parameters().max_landing_speed > 0.0 ? kRows : 0;
  }
  static int row(int axis, bool upper) { return 2 * axis + (upper ? 0 : 1); }  // 0 = x, 1 = y
};

// Its yaw, upper then lower bound; rows only when max_landing_yaw_rate > 0.
struct LandingYawBoundRows {
  static constexpr int kRows = 2;
  static int count(const NmpcModel& model) {
    return model.parameters().max_landing_yaw_rate > 0.0 ? kRows : 0;
  }
  static int row(bool upper) { return upper ? 0 : 1; }
};

// The landing (x, y of step 0) within the swing foot's reach (wpg/swing_foot_reach.hpp):
// direction k = 0..7, upper then lower bound each; registered (NmpcModel's constructor) only
// when max_swing_speed or max_swing_acceleration > 0.
struct SwingReachRows {
  static constexpr int kRows = 16;
  static int count(const NmpcModel& model) {
    const WalkingParameters& w = model.parameters();
    return w.max_swing_speed > 0.0 || w.max_swing_acceleration > 0.0 ? kRows : 0;
  }
  static int row(int direction, bool upper) { return 2 * direction + (upper ? 0 : 1); }
};

std::unique_ptr<ConstraintFamily> makeCopConstraint();              // eq. (9)-(13)
std::unique_ptr<ConstraintFamily> makeStepFeasibilityConstraint();  // eq. (14)-(15)
std::unique_ptr<ConstraintFamily> makeYawBoundConstraint();         // eq. (16)-(17)
std::unique_ptr<ConstraintFamily> makeObstacleConstraint();         // eq. (18)-(19)
std::unique_ptr<ConstraintFamily> makeLandingBoundConstraint();     // Sec. III-C3: x, y
std::unique_ptr<ConstraintFamily> makeLandingYawBoundConstraint();  // Sec. III-C3: yaw
std::unique_ptr<ConstraintFamily> makeSwingReachConstraint();       // wpg: foot speed, accel.

}  // namespace wpg
