#pragma once
// Random NMPC problems and plans for the tests of the cost and of the constraint families.
#include <random>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "wpg/nmpc.hpp"

namespace wpg_test {

using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::FootSide;
using wpg::NmpcLayout;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::WalkingParameters;

struct Rng {
  explicit Rng(unsigned seed) : engine(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine);
  }
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(engine); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  // Yaws over the whole circle and beyond (+-3.5 rad), with extra weight on large ones.
  double yaw() { return chance(0.3) ? (chance(0.5) ? 1.0 : -1.0) * uniform(2.8, 3.5) : uniform(-3.5, 3.5); }
  std::mt19937 engine;
};

// Which previewed steps are fixed (landed or final): none, the first, at random, or all
// (standing).
enum class FixedMode { kNone, kFirst, kRandom, kAll };

inline NmpcProblem randomProblem(const NmpcModel& model, int pattern, FootSide first_side, FixedMode mode,
                          Rng& rng) {
  const NmpcLayout& L = model.layout();
  const WalkingParameters& w = model.parameters();
  NmpcProblem problem = model.makeProblem();
  auto& phase = problem.phase;
  phase.pattern = pattern;
  const bool standing = pattern == model.standingPattern();
  model.rowStepsOf(pattern, phase.row_step);
  phase.first_step_side = first_side;
  phase.support_pose = Vector3d(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.yaw());
  phase.support_half_length = w.copHalfLength();
  phase.support_half_width =
      standing ? 0.5 * w.initial_foot_separation + w.copHalfWidth() : w.copHalfWidth();
  for (int i = 0; i < L.steps; ++i) {
    bool fixed = false;
    if (mode == FixedMode::kFirst) fixed = i == 0;
    if (mode == FixedMode::kRandom) fixed = rng.chance(0.5);
    if (mode == FixedMode::kAll) fixed = true;
    phase.step_fixed(i) = fixed ? 1 : 0;
    phase.fixed_step_pose.col(i) =
        Vector3d(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.yaw());
  }
  problem.com_x = Vector3d(phase.support_pose.x() + rng.uniform(-0.5, 0.5), rng.uniform(-1, 1),
                           rng.uniform(-4, 4));
  problem.com_y = Vector3d(phase.support_pose.y() + rng.uniform(-0.5, 0.5), rng.uniform(-1, 1),
                           rng.uniform(-4, 4));
  for (int j = 0; j < L.horizon; ++j) {
    problem.velocity_x(j) = rng.uniform(-0.4, 0.4);
    problem.velocity_y(j) = rng.uniform(-0.3, 0.3);
  }
  for (int i = 0; i < L.steps; ++i) problem.yaw_reference(i) = rng.yaw();
  return problem;
}

inline VectorXd randomU(const NmpcModel& model, const NmpcProblem& problem, Rng& rng) {
  const NmpcLayout& L = model.layout();
  VectorXd U(L.variableCount());
  for (int j = 0; j < L.horizon; ++j) {
    U(L.jerkX() + j) = 3.0 * rng.normal();
    U(L.jerkY() + j) = 3.0 * rng.normal();
  }
  for (int i = 0; i < L.steps; ++i) {
    U(L.stepX() + i) = problem.phase.support_pose.x() + rng.uniform(-0.8, 0.8);
    U(L.stepY() + i) = problem.phase.support_pose.y() + rng.uniform(-0.8, 0.8);
    U(L.stepYaw() + i) = rng.yaw();
  }
  return U;
}

// Rows of the built-in families in the model's stacked g(U): the family's own row (its
// builtin_families.hpp indexing) from the first row the model assigned it.
inline int familyRow(const NmpcModel& model, const char* family, int row) {
  const int index = model.findFamily(family);
  if (index < 0) throw std::invalid_argument(std::string("no family named ") + family);
  return model.familyFirstRow(index) + row;
}
inline int copRow(const NmpcModel& model, int sample, int edge) {
  return familyRow(model, "cop", wpg::CopRows::row(sample, edge));
}
inline int feasibilityRow(const NmpcModel& model, int step, int edge) {
  return familyRow(model, "step_feasibility", wpg::StepFeasibilityRows::of(model).row(step, edge));
}
inline int feasibilityEdges(const NmpcModel& model) {
  return wpg::StepFeasibilityRows::of(model).edges;
}
inline int yawRow(const NmpcModel& model, int step, bool upper) {
  return familyRow(model, "yaw_bound", wpg::YawBoundRows::row(step, upper));
}
inline int obstacleRow(const NmpcModel& model, int step, int slot) {
  return familyRow(model, "obstacle", wpg::ObstacleRows::of(model).row(step, slot));
}

}  // namespace wpg_test
