#pragma once
// The search behind `wpg push-sweep` (paper Sec. V-B): for one walking situation, push
// direction and gait phase, the largest force of a 100 ms push that the walk recovers from,
// by bisection on the force. Recovered = the walk completes (no fall), every NMPC iteration
// from the push start on is `solved` (no relaxed constraint of any family, no dropped QP) --
// the same walk under `wpg run <scenario> --set 'pushes[0]={t: .., force: [..], duration: 0.1}'`
// exits 0 (these scenarios have no obstacles, whose relaxed rows would not fail a run) -- and
// the swing foot stays physical: its peak speed and acceleration over the walk (the run's
// checks/swing_foot_speed_max, swing_foot_acceleration_max: central differences of the stored
// ankle trajectories) within PushSearchSettings::max_swing_speed, max_swing_acceleration.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

// A push direction: a unit vector in the world frame (both situations walk along +x).
struct PushDirection {
  const char* name;  // "sagittal+", "sagittal-", "coronal+", "coronal-"
  Eigen::Vector2d unit;
};
const std::vector<PushDirection>& pushDirections();

// Lift-off times [s] of the walk (a double-support sample followed by a single-support one).
std::vector<double> liftOffTimes(const WalkTrajectory& trajectory);

// The walk of `base` with pushes[0] set to {t, force, duration} (appended when it has none).
datasets::Scenario withPush(const datasets::Scenario& base, double t, const Eigen::Vector2d& force,
                            double duration);

struct PushSearchSettings {
  double max_force = 600.0;     // [N] upper end of the bracket
  double tolerance = 2.5;       // [N] bracket width at which the bisection stops
  double duration = 0.1;        // [s] of the push (paper: 100 ms)
  double stronger_factor = 1.15;  // the found force times this must fail (checked, see below)
  // The swing foot's limits of "recovered" (0: not checked): 2 m/s, 50 m/s^2, a physical foot
  // (HRP-2's swing foot walks at 0.8-0.9 m/s; docs/formulation.md, "Swing-foot reach").
  double max_swing_speed = 2.0;          // [m/s]
  double max_swing_acceleration = 50.0;  // [m/s^2]
};

// The swing foot's peaks of one walk (checks/swing_foot_*_max).
struct SwingPeaks {
  double speed = 0.0;         // [m/s]
  double acceleration = 0.0;  // [m/s^2]
};

// Whether the walk of `scenario` recovers from a push starting at `push_start` (see above);
// `peaks`, when given, receives the walk's swing-foot peaks.
bool walkRecovers(const datasets::Scenario& scenario, double push_start,
                  const RunSettings& settings, const PushSearchSettings& limits = {},
                  SwingPeaks* peaks = nullptr);

struct PushSearchResult {
  double force = 0.0;            // [N] largest recovered magnitude (0: none above tolerance)
  bool at_upper_bound = false;   // max_force itself was recovered
  bool stronger_fails = false;   // force x stronger_factor was generated and failed
  int walks = 0;                 // walks generated
  SwingPeaks swing;              // of the walk at `force` (searchLargestRecoveredPush; 0 else)
};

// The search for the largest force that `recovered(force)` accepts (each call is a walk,
// counted in PushSearchResult::walks): bisection on [0, max_force] (max_force first: recovered
// -> at_upper_bound), down to a bracket of `tolerance`. Recovery is not monotone in the force
// everywhere (a stronger push can make the next step land better), so the result is checked:
// when force x stronger_factor recovers too, the bisection starts again above it, until a push
// that much stronger fails (or the bound is reached).
PushSearchResult searchLargestRecoveredForce(const std::function<bool(double force)>& recovered,
                                             const PushSearchSettings& settings);

// That search on the walk of `base` pushed at `t` along `unit` for settings.duration;
// `run_settings`: how each walk runs (the robot models of a scenario that replays).
PushSearchResult searchLargestRecoveredPush(const datasets::Scenario& base, double t,
                                            const Eigen::Vector2d& unit,
                                            const PushSearchSettings& settings,
                                            const RunSettings& run_settings);

}  // namespace wpg::engine
