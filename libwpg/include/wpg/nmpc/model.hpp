#pragma once
// The constant part of the NMPC (the model; what changes every sample is NmpcProblem, the
// scratch of a solve NmpcWorkspace): prediction matrices (eq. 1-3), the Gauss-Newton Hessian of
// the cost (5)-(8) for every walking pattern with its factor, the step feasibility polygons,
// and the registered constraint families, each with the range of rows the model assigns it.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/convex_polygon.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/cost_term.hpp"
#include "wpg/nmpc/layout.hpp"
#include "wpg/nmpc/problem.hpp"
#include "wpg/qp/dense_qp_solver.hpp"
#include "wpg/qp/hessian_factor_cache.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class NmpcModel {
 public:
  // Registers the paper's families (builtin_families.hpp): CoP, step feasibility, yaw bound,
  // obstacles (with `obstacle_slots` obstacles at most in the QP at once), landing bounds.
  // The Hessians' factors come from `hessian_factors` when given (shared with the other
  // models that use that cache, qp/hessian_factor_cache.hpp), else are computed here.
  explicit NmpcModel(const WalkingParameters& parameters, int obstacle_slots = 0,
                     qp::HessianFactorCache* hessian_factors = nullptr);

  // Appends a family after the registered ones: its rows start where theirs end. Call it before
  // building a solver on this model. Throws std::invalid_argument beyond
  // kMaxConstraintFamilies families or for a null family.
  void addConstraintFamily(std::shared_ptr<const ConstraintFamily> family);
  int familyCount() const { return static_cast<int>(families_.size()); }
  const ConstraintFamily& family(int index) const { return *families_[index]; }
  // The family's rows are [familyFirstRow, familyFirstRow + familyRowCount) of the stacked g.
  int familyFirstRow(int index) const { return family_first_row_[index]; }
  int familyRowCount(int index) const {
    return family_first_row_[index + 1] - family_first_row_[index];
  }
  // Index of the family named `name` (ConstraintFamily::name), -1 when none is.
  int findFamily(const char* name) const;
  // Index of the family owning inequality row `row`, -1 past the last (a search over at most
  // kMaxConstraintFamilies ranges; no allocation).
  int familyOfRow(int row) const;
  // Appends a cost term (wpg/nmpc/cost_term.hpp) after the registered ones: its residuals
  // start where theirs end. Call it before building a solver on this model. Throws
  // std::invalid_argument for a null term or a negative residual count.
  void addCostTerm(std::shared_ptr<const CostTerm> term);
  int costTermCount() const { return static_cast<int>(cost_terms_.size()); }
  const CostTerm& costTerm(int index) const { return *cost_terms_[index]; }
  int costTermFirstResidual(int index) const { return term_first_residual_[index]; }
  int costTermResidualCount(int index) const {
    return term_first_residual_[index + 1] - term_first_residual_[index];
  }
  // All residuals of the cost terms, stacked in registration order (0 without terms).
  int residualCount() const { return term_first_residual_.back(); }
  // All inequality rows: the families' rows, stacked in registration order.
  int inequalityCount() const { return family_first_row_.back(); }
  // Where the constraint Jacobian (inequalityCount() x variables) may be nonzero: the step
  // columns in every row, the jerk columns of sample k in the rows whose family's
  // jerkSamplesOfRow exceeds k (the CoP rows of samples k..N-1 for the paper's families).
  // The solver's products with the Jacobian skip the rest.
  const qp::ColumnProfile& jacobianProfile() const { return jacobian_profile_; }

  const WalkingParameters& parameters() const { return parameters_; }
  const NmpcLayout& layout() const { return layout_; }
  int obstacleSlots() const { return obstacle_slots_; }  // obstacles in the QP at once
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
  const qp::HessianFactor& hessianFactor(int pattern) const { return *factors_[pattern]; }

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
  int obstacle_slots_ = 0;
  LipmPrediction prediction_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> tracked_velocity_state_;
  Eigen::MatrixXd tracked_velocity_jerk_;
  ConvexPolygon feasibility_left_, feasibility_right_;
  std::vector<Eigen::MatrixXd> hessians_;
  // Shared with the other models of the cache given at construction that have the same
  // Hessian (qp/hessian_factor_cache.hpp): the runs of a study build the same ones again.
  std::vector<std::shared_ptr<const qp::HessianFactor>> factors_;
  // Families are stateless (const): models share them when copied.
  std::vector<std::shared_ptr<const ConstraintFamily>> families_;
  std::vector<int> family_first_row_;  // familyCount() + 1 entries
  std::vector<std::shared_ptr<const CostTerm>> cost_terms_;  // stateless, shared like families
  std::vector<int> term_first_residual_{0};                  // costTermCount() + 1 entries
  qp::ColumnProfile jacobian_profile_;  // of the families registered so far
  // addConstraintFamily without the profile, which the constructor computes once for the
  // paper's families (each update goes over every row of every family).
  void appendFamily(std::shared_ptr<const ConstraintFamily> family);
  void updateJacobianProfile();
};

}  // namespace wpg
