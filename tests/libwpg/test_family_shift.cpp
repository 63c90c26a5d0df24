// Each built-in constraint family's shiftedRow: the row its active row r becomes when the
// horizon moves on by one sample, and by one step when a step was completed (the warm start's
// active set, NmpcSolver::shiftActiveSet). Over a walk, at the next sample and on the shifted
// plan (the warm start), the row r' = shiftedRow(r) must measure the same constraint at the
// same instant as r did at the solution of the sample before, hence the same value of g:
//   cop               the CoP of the same instant against the same foot (eq. 9-13);
//   step_feasibility  the same step against the step before it (eq. 14-15);
//   yaw_bound         the same pair of steps (eq. 16-17);
//   obstacle          the same step against the same obstacle (eq. 18-19);
//   corridor          the CoP of the same instant, the same step, against the same wall.
// The landing bounds (Sec. III-C3) keep their axis and sign during a swing (the same Jacobian
// row) and leave when the swing ends. A family that does not shift its rows (r' = r) fails
// here: its row r at the next sample measures a later instant or another step.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "../common/obstacle_fields.hpp"
#include "nmpc_test_problems.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/pattern_generator.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::WalkingParameters;

// g and its Jacobian of a problem at a plan.
struct Rows {
  NmpcProblem problem;
  VectorXd U, g;
  MatrixXd J;
};

Rows evaluate(const NmpcModel& model, const NmpcProblem& problem, const VectorXd& U) {
  Rows rows{problem, U, VectorXd(model.inequalityCount()),
            MatrixXd(model.inequalityCount(), model.layout().variableCount())};
  wpg::evaluateConstraints(model, problem, U, rows.g, &rows.J);
  return rows;
}

// One sample of the walk to the next: the solution of sample k and the warm start of k + 1.
// (The problems' obstacle pointers are cleared once the walk is over: the generator owned
// what they pointed to.)
struct Transition {
  Rows solved;        // sample k: its problem at its solution
  Rows warm;          // sample k + 1: its problem at the shifted plan (before its solve)
  bool step_completed = false;
  Rows warm_on_previous_slots;  // `warm` with the obstacle slots (and normals) of sample k
};

struct Walk {
  NmpcModel model;  // the generator's
  std::vector<Transition> transitions;
};

// A walk forward then turning, past obstacles on both sides, with the landing bounds on:
// every family has active rows. Keeps the transitions between two walking samples (not
// starting, not standing: the generator drops the warm start when the phase changes).
Walk walkTransitions(WalkingParameters w) {
  w.max_landing_speed = 0.4;
  w.max_landing_yaw_rate = 1.5;
  wpg::GeneratorSettings settings;
  settings.max_obstacles_in_qp = 3;
  // wpg's corridor (builtin_extensions.hpp) with walls beyond the obstacles: its rows are
  // evaluated at every sample but never active, so the walk is the one without it.
  settings.constraints = {{"corridor", {{"left", 5.0}, {"right", -5.0}}}};
  wpg::PatternGenerator generator(w, settings);
  generator.setObstacles(wpg_test::obstacleCorridor(12, 0.9));
  const NmpcModel& model = generator.model();
  const int S = w.stepSamples();
  const int periods = static_cast<int>(std::lround(w.sampling_period / w.control_period));
  std::vector<Transition> transitions;
  bool previous_walking = false;
  Rows previous;
  bool previous_completes = false;
  for (int k = 0; k < 70; ++k) {
    const Vector3d command = k < 40 ? Vector3d(0.25, 0.0, 0.0) : Vector3d(0.2, 0.0, 0.25);
    const VectorXd warm_start = generator.solver().plan();
    generator.update(k * w.sampling_period, command);
    const bool walking = !generator.standing() && !generator.starting();
    if (walking && previous_walking) {
      NmpcProblem previous_slots = generator.problem();
      previous_slots.obstacle_slot = previous.problem.obstacle_slot;
      previous_slots.obstacle_normal = previous.problem.obstacle_normal;
      previous_slots.obstacle_offset = previous.problem.obstacle_offset;
      // The next landing's own half-plane (obstacle_landing_linearization: step) is chosen
      // afresh at every sample, facing the landing: what step 0 had at sample k if it is still
      // step 0, else what step 1 had (its border), so that the rows compared are the same
      // half-planes on the shifted steps.
      previous_slots.obstacle_landing_normal = previous_completes
                                                   ? previous.problem.obstacle_normal
                                                   : previous.problem.obstacle_landing_normal;
      previous_slots.obstacle_landing_offset = previous_completes
                                                   ? previous.problem.obstacle_offset
                                                   : previous.problem.obstacle_landing_offset;
      transitions.push_back({previous, evaluate(model, generator.problem(), warm_start),
                             previous_completes, evaluate(model, previous_slots, warm_start)});
    }
    previous = evaluate(model, generator.problem(), generator.solver().plan());
    previous_walking = walking;
    previous_completes = walking && generator.phaseSample() == S - 1;
    // The plan executed exactly (no push): the shifted plan predicts what the plan did.
    Vector3d com_x = generator.comX(), com_y = generator.comY();
    for (int i = 0; i < periods; ++i) {
      wpg::integrateJerk(com_x, generator.plan().jerk_x, w.control_period);
      wpg::integrateJerk(com_y, generator.plan().jerk_y, w.control_period);
    }
    generator.advance(com_x, com_y);
  }
  for (Transition& t : transitions) {
    for (Rows* rows : {&t.solved, &t.warm, &t.warm_on_previous_slots})
      rows->problem.obstacles = nullptr;
  }
  return {model, transitions};
}

struct ShiftCheck {
  int compared = 0;      // rows compared (active at both samples)
  int completed = 0;     // of them across a completed step
  int left = 0;          // rows that left (shiftedRow -1)
  double worst = 0.0;    // largest |g_next(r') - g(r)| [family's unit]
  std::string where;
};

// Family `name`'s rows across every transition: g at the next sample's warm start, row
// shiftedRow(r), against g at the solution, row r. Rows inactive at either sample (g = -1
// exactly: a fixed step, an empty slot) say nothing and are skipped.
ShiftCheck checkValues(const NmpcModel& model, const std::vector<Transition>& transitions,
                       const char* name) {
  const int family = model.findFamily(name);
  EXPECT_GE(family, 0) << name;
  ShiftCheck check;
  if (family < 0) return check;
  const int first = model.familyFirstRow(family);
  for (std::size_t t = 0; t < transitions.size(); ++t) {
    const Transition& tr = transitions[t];
    for (int r = 0; r < model.familyRowCount(family); ++r) {
      const int shifted = model.family(family).shiftedRow(model, r, tr.step_completed);
      EXPECT_LT(shifted, model.familyRowCount(family)) << name << " row " << r;
      if (shifted < 0) {
        ++check.left;
        continue;
      }
      const double before = tr.solved.g(first + r), after = tr.warm.g(first + shifted);
      if (before == -1.0 || after == -1.0) continue;
      ++check.compared;
      if (tr.step_completed) ++check.completed;
      const double difference = std::abs(after - before);
      if (difference > check.worst) {
        check.worst = difference;
        check.where = "transition " + std::to_string(t) + ", row " + std::to_string(r) + " -> " +
                      std::to_string(shifted) + (tr.step_completed ? " (step completed)" : "");
      }
    }
  }
  return check;
}

class FamilyShift : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    WalkingParameters w;
    w.max_step_yaw_change = 0.17;
    walk_ = new Walk(walkTransitions(w));
  }
  static void TearDownTestSuite() {
    delete walk_;
    walk_ = nullptr;
  }
  static const NmpcModel& model() { return walk_->model; }
  static const std::vector<Transition>& transitions() { return walk_->transitions; }

  // The shifted rows of `name` measure what they measured, to rounding (measured: 2e-15 at
  // most; the LIPM prediction of the same instant from the integrated CoM state), across
  // samples within a step and across completed steps; a row one sample or one step off
  // differs by the CoP's or the steps' motion (centimetres).
  static void expectSameValues(const char* name, int min_compared, int min_completed) {
    const ShiftCheck check = checkValues(model(), transitions(), name);
    EXPECT_LE(check.worst, 1e-12) << name << ": " << check.where;
    EXPECT_GE(check.compared, min_compared) << name;
    EXPECT_GE(check.completed, min_completed) << name;
  }

 private:
  static Walk* walk_;
};

Walk* FamilyShift::walk_ = nullptr;

TEST_F(FamilyShift, WalkHasStepsAndSamplesWithinSteps) {
  int completed = 0;
  for (const Transition& t : transitions()) completed += t.step_completed ? 1 : 0;
  EXPECT_GE(transitions().size(), 50u);
  EXPECT_GE(completed, 5);
  EXPECT_GE(static_cast<int>(transitions().size()) - completed, 40);
}

TEST_F(FamilyShift, CopRowsFollowTheirInstant) {
  // Every sample but the first stays in the horizon: 4 rows leave per transition.
  const ShiftCheck check = checkValues(model(), transitions(), "cop");
  EXPECT_EQ(check.left, static_cast<int>(transitions().size()) * wpg::CopRows::kEdges);
  expectSameValues("cop", 3000, 300);
}

TEST_F(FamilyShift, CorridorRowsFollowTheirInstantAndStep) {
  // The first sample's 2 rows leave at every transition, step 0's 2 at every completed step.
  int completed = 0;
  for (const Transition& t : transitions()) completed += t.step_completed ? 1 : 0;
  const ShiftCheck check = checkValues(model(), transitions(), "corridor");
  EXPECT_EQ(check.left, 2 * static_cast<int>(transitions().size()) + 2 * completed);
  expectSameValues("corridor", 1500, 150);
}

TEST_F(FamilyShift, StepFeasibilityRowsFollowTheirStep) {
  expectSameValues("step_feasibility", 400, 30);
}

TEST_F(FamilyShift, YawBoundRowsFollowTheirStep) { expectSameValues("yaw_bound", 150, 10); }

TEST_F(FamilyShift, ObstacleRowsFollowTheirStep) {
  // The selection of the obstacles is redone at every sample and sorts the slots by distance:
  // at a completed step they usually change places, and a slot keeps its obstacle only as a
  // guess (obstacle_constraint.cpp). What the family shifts is the step: with the slots of the
  // sample before, row (step i, slot k) becomes row (step i - 1, slot k) on the same obstacle.
  std::vector<Transition> same_slots;
  int kept_slots = 0;
  for (const Transition& t : transitions()) {
    if ((t.solved.problem.obstacle_slot.array() < 0).all()) continue;
    if (t.solved.problem.obstacle_slot == t.warm.problem.obstacle_slot) ++kept_slots;
    same_slots.push_back({t.solved, t.warm_on_previous_slots, t.step_completed, {}});
  }
  EXPECT_GE(kept_slots, 40);  // most samples keep their slots as they are
  const ShiftCheck check = checkValues(model(), same_slots, "obstacle");
  EXPECT_LE(check.worst, 1e-12) << check.where;
  EXPECT_GE(check.compared, 250);
  EXPECT_GE(check.completed, 15);
}

// The landing bounds bound step 0's landing against the one planned at the sample before
// (Sec. III-C3): during a swing each row keeps its axis and sign, the same Jacobian row; when
// the step is completed the next swing's landing is another foot's and the rows leave.
TEST_F(FamilyShift, LandingBoundRowsKeepTheirAxisDuringASwing) {
  for (const char* name : {"landing_bound", "landing_yaw_bound"}) {
    const int family = model().findFamily(name);
    ASSERT_GE(family, 0);
    ASSERT_GT(model().familyRowCount(family), 0) << name;
    const int first = model().familyFirstRow(family);
    int compared = 0;
    for (const Transition& t : transitions()) {
      for (int r = 0; r < model().familyRowCount(family); ++r) {
        const int shifted = model().family(family).shiftedRow(model(), r, t.step_completed);
        if (t.step_completed) {
          EXPECT_EQ(shifted, -1) << name << " row " << r;
          continue;
        }
        ASSERT_GE(shifted, 0) << name << " row " << r;
        if (t.solved.g(first + r) == -1.0 || t.warm.g(first + shifted) == -1.0) continue;
        ++compared;
        EXPECT_EQ(t.warm.J.row(first + shifted), t.solved.J.row(first + r)) << name << " row " << r;
        EXPECT_EQ(t.solved.J.row(first + r).cwiseAbs().sum(), 1.0) << name << " row " << r;
      }
    }
      EXPECT_GE(compared, 80) << name;
  }
}

}  // namespace
