#pragma once
// The constant part of the NMPC (what changes every solve is in NmpcWorkspace): prediction
// matrices (eq. 1-3),
// the Gauss-Newton Hessian of the cost (5)-(8) for every walking pattern with its factor, the
// step feasibility polygons, and the registered constraint families with their row ranges.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/convex_polygon.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/layout.hpp"
#include "wpg/nmpc/problem.hpp"
#include "wpg/qp/dense_qp_solver.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class NmpcModel {
 public:
  // Registers the paper's families: CoP, step feasibility, yaw bound, obstacles (with
  // `obstacle_slots` obstacles at most in the QP at once).
  explicit NmpcModel(const WalkingParameters& parameters, int obstacle_slots = 0);

  // Appends a family after the built-in ones (its rows come last). Call it before building a
  // solver on this model. Throws std::invalid_argument beyond kMaxConstraintFamilies families
  // or for a null family.
  void addConstraintFamily(std::shared_ptr<const ConstraintFamily> family);
  int familyCount() const { return static_cast<int>(families_.size()); }
  const ConstraintFamily& family(int index) const { return *families_[index]; }
  int familyFirstRow(int index) const { return family_first_row_[index]; }
  int familyRowCount(int index) const {
    return family_first_row_[index + 1] - family_first_row_[index];
  }
  // Index of the family owning inequality row `row`, -1 past the last (a search over at most
  // kMaxConstraintFamilies ranges; no allocation).
  int familyOfRow(int row) const;

  const WalkingParameters& parameters() const { return parameters_; }
  const NmpcLayout& layout() const { return layout_; }
  const LipmPrediction& prediction() const { return prediction_; }
  // The velocity J1 tracks: (windowed mean of) C' = tracked_state c_hat + tracked_jerk jerks
  // + the problem's velocity_past (prediction's velocity rows with window 1).
  const Eigen::Matrix<double, Eigen::Dynamic, 3>& trackedVelocityState() const {
    return tracked_velocity_state_;
  }
  const Eigen::MatrixXd& trackedVelocityJerk() const { return tracked_velocity_jerk_; }
  const ConvexPolygon& feasibilityPolygon(FootSide side) const {
    return side == FootSide::kLeft ? feasibility_left_ : feasibility_right_;
  }
  double stepDuration() const { return parameters_.stepDuration(); }

  // Patterns: walking with r = 0 .. S-1 remaining samples (S = samples per step), standing = S.
  int patternCount() const { return static_cast<int>(hessians_.size()); }
  int standingPattern() const { return patternCount() - 1; }
  void rowStepsOf(int pattern, Eigen::Ref<Eigen::VectorXi> row_step) const;
  const Eigen::MatrixXd& hessian(int pattern) const { return hessians_[pattern]; }
  const qp::HessianFactor& hessianFactor(int pattern) const { return factors_[pattern]; }

  // Allocates a problem with the right sizes (not for the hot loop).
  NmpcProblem makeProblem() const;
  // Throws std::invalid_argument saying which field of `problem` has the wrong size (or an
  // obstacle slot pointing outside problem.obstacles, or a pattern out of range) and what was
  // expected. Does not allocate unless it throws. The solver and the evaluators call it.
  void checkProblem(const NmpcProblem& problem) const;
  // Name, unit and relaxation group of each family, in row order (for logs and datasets).
  std::vector<ConstraintFamilyInfo> familyInfo() const;

 private:
  WalkingParameters parameters_;
  NmpcLayout layout_;
  LipmPrediction prediction_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> tracked_velocity_state_;
  Eigen::MatrixXd tracked_velocity_jerk_;
  ConvexPolygon feasibility_left_, feasibility_right_;
  std::vector<Eigen::MatrixXd> hessians_;
  std::vector<qp::HessianFactor> factors_;
  // Families are stateless (const): models share them when copied.
  std::vector<std::shared_ptr<const ConstraintFamily>> families_;
  std::vector<int> family_first_row_;  // familyCount() + 1 entries
};

}  // namespace wpg
