// The OMPL route planner (route_planner.hpp). With ompl_planner_registry.cpp, the only
// translation units of planning/ that include OMPL.
#include "wpg/planning/route_planner.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/util/Console.h>

#include "ompl_planner_registry.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::planning {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

// The longest motion checked in one piece [m]: at most 2 cm on the ground.
constexpr double kMotionResolution = 0.02;
constexpr double kPi = 3.14159265358979323846;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// SE(2) sampling from a generator of our own seed (OMPL's StateSampler keeps a protected
// `rng_`; the default one is seeded from a process-wide sequence).
class SeededSE2Sampler : public ob::StateSampler {
 public:
  SeededSE2Sampler(const ob::StateSpace* space, std::uint32_t seed) : ob::StateSampler(space) {
    rng_.setLocalSeed(seed);
    const ob::RealVectorBounds& bounds = space->as<ob::SE2StateSpace>()->getBounds();
    low_ = {bounds.low[0], bounds.low[1]};
    high_ = {bounds.high[0], bounds.high[1]};
  }
  void sampleUniform(ob::State* state) override {
    auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    se2->setXY(rng_.uniformReal(low_[0], high_[0]), rng_.uniformReal(low_[1], high_[1]));
    se2->setYaw(rng_.uniformReal(-kPi, kPi));
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    const auto* centre = near->as<ob::SE2StateSpace::StateType>();
    auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    se2->setXY(centre->getX() + rng_.uniformReal(-distance, distance),
               centre->getY() + rng_.uniformReal(-distance, distance));
    se2->setYaw(centre->getYaw() + rng_.uniformReal(-distance, distance));
    space_->enforceBounds(state);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double std_dev) override {
    const auto* centre = mean->as<ob::SE2StateSpace::StateType>();
    auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    se2->setXY(rng_.gaussian(centre->getX(), std_dev), rng_.gaussian(centre->getY(), std_dev));
    se2->setYaw(rng_.gaussian(centre->getYaw(), std_dev));
    space_->enforceBounds(state);
  }

 private:
  std::array<double, 2> low_{}, high_{};
};

// Validity: the footprint disc clear of every known obstacle grown by its margin.
class FootprintValidityChecker : public ob::StateValidityChecker {
 public:
  FootprintValidityChecker(const ob::SpaceInformationPtr& si, const World& world, double radius)
      : ob::StateValidityChecker(si), world_(world), radius_(radius) {
    specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
  }
  bool isValid(const ob::State* state) const override {
    const auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    return si_->satisfiesBounds(state) && world_.isStateValid(se2->getX(), se2->getY(), radius_);
  }
  double clearance(const ob::State* state) const override {
    const auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    return world_.clearance(Eigen::Vector2d(se2->getX(), se2->getY())) - radius_;
  }

 private:
  const World& world_;
  double radius_;
};

// Motions: the footprint disc swept along the straight x-y segment, checked whole
// (World::freeFraction). OMPL's default checks states every kMotionResolution along it, which
// lets a route cut a grown corner between two of them (by 15 um, seen with bitstar). A motion
// that sampling finds valid and that is valid whole gives the same answer, so plans that never
// grazed a corner are unchanged.
class SweptFootprintValidator : public ob::MotionValidator {
 public:
  SweptFootprintValidator(const ob::SpaceInformationPtr& si, const World& world, double radius)
      : ob::MotionValidator(si), world_(world), radius_(radius) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool valid = si_->isValid(s2) && freeFraction(s1, s2) >= 1.0;
    ++(valid ? valid_ : invalid_);
    return valid;
  }

  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    const double fraction = freeFraction(s1, s2);
    const bool valid = fraction >= 1.0 && si_->isValid(s2);
    if (!valid) {
      // OMPL's contract: the last valid state and its fraction along the motion.
      last_valid.second = std::min(fraction, 1.0 - 1e-9);
      if (last_valid.first) si_->getStateSpace()->interpolate(s1, s2, last_valid.second,
                                                              last_valid.first);
    }
    ++(valid ? valid_ : invalid_);
    return valid;
  }

 private:
  double freeFraction(const ob::State* s1, const ob::State* s2) const {
    const auto* a = s1->as<ob::SE2StateSpace::StateType>();
    const auto* b = s2->as<ob::SE2StateSpace::StateType>();
    return world_.freeFraction(Eigen::Vector2d(a->getX(), a->getY()),
                               Eigen::Vector2d(b->getX(), b->getY()), radius_);
  }

  const World& world_;
  double radius_;
};

// OMPL's simplifier with its generator (shortcuts, perturbations) seeded.
class SeededPathSimplifier : public og::PathSimplifier {
 public:
  SeededPathSimplifier(const ob::SpaceInformationPtr& si, const ob::GoalPtr& goal,
                       const ob::OptimizationObjectivePtr& objective, std::uint32_t seed)
      : og::PathSimplifier(si, goal, objective) {
    rng_.setLocalSeed(seed);
  }
};

// Distinct, reproducible seeds for the generators of one plan (splitmix-like mixing).
std::uint32_t mixSeed(std::uint32_t seed, std::uint32_t stream) {
  std::uint64_t z = (static_cast<std::uint64_t>(seed) << 32) + stream + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return static_cast<std::uint32_t>(z ^ (z >> 31));
}

// The yaw in [-pi, pi): OMPL's SO2 bounds exclude +pi (a goal straight behind, atan2(0, -x) =
// pi, was an invalid state and the plan timed out).
double so2Yaw(double yaw) {
  double wrapped = std::remainder(yaw, 2.0 * kPi);
  if (wrapped >= kPi) wrapped -= 2.0 * kPi;
  return wrapped;
}

double polylineLength(const std::vector<Eigen::Vector3d>& waypoints) {
  double length = 0.0;
  for (std::size_t i = 1; i < waypoints.size(); ++i)
    length += (waypoints[i].head<2>() - waypoints[i - 1].head<2>()).norm();
  return length;
}

std::string plannerList() {
  std::string names;
  for (const auto& entry : detail::omplPlanners())
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

}  // namespace

const char* planStatusName(PlanStatus status) {
  switch (status) {
    case PlanStatus::kExactSolution:
      return "exact_solution";
    case PlanStatus::kApproximateSolution:
      return "approximate_solution";
    case PlanStatus::kNoSolution:
      return "no_solution";
    case PlanStatus::kTimeout:
      return "timeout";
    case PlanStatus::kInvalidStart:
      return "invalid_start";
    case PlanStatus::kInvalidGoal:
      return "invalid_goal";
  }
  return "unknown";
}

std::string planStatusCodes() {
  std::string codes;
  for (int code = 0; code <= static_cast<int>(PlanStatus::kInvalidGoal); ++code) {
    codes += (codes.empty() ? "" : ", ") + std::to_string(code) + "=" +
             planStatusName(static_cast<PlanStatus>(code));
  }
  return codes;
}

const std::vector<std::string>& plannerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& entry : detail::omplPlanners()) list.emplace_back(entry.name);
    return list;
  }();
  return names;
}

bool isKnownPlanner(const std::string& name) { return detail::findOmplPlanner(name) != nullptr; }

bool isReproduciblePlanner(const std::string& name) {
  const detail::OmplPlannerEntry* entry = detail::findOmplPlanner(name);
  return entry && entry->reproducible;
}

PlanningBounds planningBounds(const std::vector<wpg::Obstacle>& obstacles,
                              const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                              const wpg::RoutePlannerSettings& settings) {
  PlanningBounds bounds;
  if (settings.has_bounds) {
    bounds.min = Eigen::Vector2d(settings.bounds[0], settings.bounds[2]);
    bounds.max = Eigen::Vector2d(settings.bounds[1], settings.bounds[3]);
    return bounds;
  }
  bounds.min = start.cwiseMin(goal);
  bounds.max = start.cwiseMax(goal);
  for (const wpg::Obstacle& obstacle : obstacles) {
    Eigen::Vector2d centre;
    double radius = 0.0;
    wpg::boundingCircle(obstacle, &centre, &radius);
    const Eigen::Vector2d reach = Eigen::Vector2d::Constant(radius + obstacle.margin);
    bounds.min = bounds.min.cwiseMin(centre - reach);
    bounds.max = bounds.max.cwiseMax(centre + reach);
  }
  bounds.min.array() -= 2.0;
  bounds.max.array() += 2.0;
  return bounds;
}

RoutePlanner::RoutePlanner(World world, const wpg::RoutePlannerSettings& settings,
                           double robot_radius, PlanningBounds bounds)
    : world_(std::move(world)), settings_(settings), robot_radius_(robot_radius), bounds_(bounds) {
  if (!isKnownPlanner(settings.algorithm)) {
    throw std::invalid_argument("'planner.algorithm': expected one of " + plannerList() +
                                ", got '" + settings.algorithm + "'" +
                                wpg::didYouMean(settings.algorithm, plannerNames()));
  }
  if (!(robot_radius > 0.0) || !std::isfinite(robot_radius)) {
    throw std::invalid_argument("'planner.robot_radius': expected a positive radius in m");
  }
  if (!(settings.time_limit > 0.0) || !std::isfinite(settings.time_limit)) {
    throw std::invalid_argument("'planner.time_limit': expected a positive time in s");
  }
  if (!(bounds.max.array() > bounds.min.array()).all()) {
    throw std::invalid_argument("'planner.bounds': expected min < max");
  }
  // OMPL logs to stderr by default ("Info: RRTConnect: ..."); the CLI keeps stderr for errors.
  // A process-wide setting: once, whatever the threads that make planners.
  static std::once_flag silenced;
  std::call_once(silenced, [] { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); });
}

bool RoutePlanner::isValid(const Eigen::Vector2d& point) const {
  return bounds_.contains(point) && world_.isStateValid(point.x(), point.y(), robot_radius_);
}

RoutePlan RoutePlanner::plan(const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                             std::uint32_t seed) const {
  RoutePlan result;
  if (!isValid(start.head<2>())) {
    result.status = PlanStatus::kInvalidStart;
    return result;
  }
  if (!isValid(goal.head<2>())) {
    result.status = PlanStatus::kInvalidGoal;
    return result;
  }
  const detail::OmplPlannerEntry& entry = *detail::findOmplPlanner(settings_.algorithm);

  auto space = std::make_shared<ob::SE2StateSpace>();
  ob::RealVectorBounds space_bounds(2);
  space_bounds.setLow(0, bounds_.min.x());
  space_bounds.setHigh(0, bounds_.max.x());
  space_bounds.setLow(1, bounds_.min.y());
  space_bounds.setHigh(1, bounds_.max.y());
  space->setBounds(space_bounds);
  // Every sampler the planner allocates gets the next seed of this plan's sequence (the order
  // of allocation is the planner's own, hence reproducible).
  auto sampler_count = std::make_shared<std::uint32_t>(0);
  space->setStateSamplerAllocator([seed, sampler_count](const ob::StateSpace* s) {
    return std::make_shared<SeededSE2Sampler>(s, mixSeed(seed, 1000 + (*sampler_count)++));
  });
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(
      std::make_shared<FootprintValidityChecker>(si, world_, robot_radius_));
  // Motions are checked whole (SweptFootprintValidator); the resolution is left for the
  // planners that interpolate states along a motion themselves: at most 2 cm on the ground.
  si->setStateValidityCheckingResolution(kMotionResolution / space->getMaximumExtent());
  si->setMotionValidator(std::make_shared<SweptFootprintValidator>(si, world_, robot_radius_));
  si->setup();

  ob::ScopedState<ob::SE2StateSpace> start_state(space), goal_state(space);
  start_state->setXY(start.x(), start.y());
  start_state->setYaw(so2Yaw(start.z()));
  goal_state->setXY(goal.x(), goal.y());
  goal_state->setYaw(so2Yaw(goal.z()));
  auto problem = std::make_shared<ob::ProblemDefinition>(si);
  problem->setStartAndGoalStates(start_state, goal_state);
  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
  problem->setOptimizationObjective(objective);

  ob::PlannerPtr planner = entry.make(si, mixSeed(seed, 1));
  planner->setProblemDefinition(problem);
  planner->setup();

  // Termination: the time limit always; the optimizing planners also after max_iterations
  // checks made on this thread (a planner's helper threads check it too: not counted).
  const Clock::time_point begin = Clock::now();
  const std::thread::id planning_thread = std::this_thread::get_id();
  const double time_limit = settings_.time_limit;
  const int max_iterations = settings_.max_iterations;
  auto iterations = std::make_shared<int>(0);
  const bool optimizing = entry.optimizing;
  const ob::PlannerTerminationCondition termination([=]() {
    if (seconds(begin) >= time_limit) return true;
    if (std::this_thread::get_id() != planning_thread) return false;
    ++*iterations;
    return optimizing && *iterations > max_iterations;
  });
  ob::PlannerStatus status = planner->solve(termination);
  PlanStatistics& stats = result.statistics;
  stats.time = seconds(begin);
  stats.iterations = *iterations;
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  stats.graph_states = static_cast<int>(data.numVertices());
  stats.graph_motions = static_cast<int>(data.numEdges());

  const bool has_path = problem->hasSolution();
  if (status == ob::PlannerStatus::EXACT_SOLUTION && has_path &&
      !problem->hasApproximateSolution()) {
    result.status = PlanStatus::kExactSolution;
  } else if (has_path && (status == ob::PlannerStatus::APPROXIMATE_SOLUTION ||
                          problem->hasApproximateSolution())) {
    result.status = PlanStatus::kApproximateSolution;
  } else {
    result.status = stats.time >= time_limit ? PlanStatus::kTimeout : PlanStatus::kNoSolution;
  }
  if (!result.solved()) return result;

  stats.solved = true;
  stats.approximate_solution = result.status == PlanStatus::kApproximateSolution;
  stats.solution_difference = stats.approximate_solution ? problem->getSolutionDifference() : 0.0;
  og::PathGeometric path(*problem->getSolutionPath()->as<og::PathGeometric>());
  stats.solution_length = path.length();
  const Clock::time_point simplify_begin = Clock::now();
  SeededPathSimplifier simplifier(si, problem->getGoal(), objective, mixSeed(seed, 2));
  simplifier.simplifyMax(path);
  stats.simplification_time = seconds(simplify_begin);
  stats.simplified_solution_length = path.length();

  stats.solution_clearance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < path.getStateCount(); ++i) {
    const auto* se2 = path.getState(i)->as<ob::SE2StateSpace::StateType>();
    result.waypoints.emplace_back(se2->getX(), se2->getY(), se2->getYaw());
    stats.solution_clearance =
        std::min(stats.solution_clearance,
                 world_.clearance(result.waypoints.back().head<2>()) - robot_radius_);
  }
  result.length = polylineLength(result.waypoints);
  return result;
}

}  // namespace wpg::planning
