#pragma once
// A scenario: which robot walks, for how long, following which velocity command, with which
// pushes and solver settings. Read from a YAML file (every key: datasets/SCENARIOS.md), merged
// with the robot's walking parameters (robots/<robot>/walking.yaml) and with command-line
// overrides (`wpg run --set key=value`).
#include <string>
#include <vector>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/robot_multibody.hpp"
#include "wpg/dynamic_filter.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/walk_goal.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::datasets {

struct Scenario {
  std::string name;         // `name:`, also the HDF5 group /runs/<name>
  std::string robot;        // `robot:`, a folder of the robots directory
  std::string source_path;  // the scenario file, as given to loadScenario
  // The robot's multibody model (walking.yaml's `multibody:`): not part of the resolved text, a
  // stored run finds it again in its robot's folder.
  RobotMultibody multibody;
  // The robot's walking.yaml, then the scenario's `walking:` map, then the overrides.
  wpg::WalkingParameters walking;
  // duration, reference, pushes, generator; robot_mass from the robot's `mass` unless the
  // scenario sets `robot_mass`.
  wpg::WalkRequest request;
  // `goal:` and `planner:`: a walk to a goal, its velocity command from the route
  // planner and the path follower (planning/goal_walk.hpp) instead of `reference:`
  // (goal.enabled false without a `goal:`); known_to_planner from the obstacles' flags.
  wpg::GoalRequest goal;
  // The multibody side (paper Sec. IV): `replay:` replays the walk on the robot's multibody
  // model (IK + inverse dynamics, the multibody ZMP), `filter:` also runs the dynamic filter
  // (preview control on the ZMP error) with `filter_settings:`. filter implies replay.
  bool replay = false;
  bool filter = false;
  wpg::PreviewControlSettings filter_settings;  // Qe = 1, R = 1e-6, 1.6 s by default
  // filter_settings.mode (online: the paper's Fig. 3 loop | offline, the default | both) and
  // filter_settings.reinitialize_wpg (default false), wpg/dynamic_filter.hpp.
  wpg::DynamicFilterLoopSettings filter_loop;
  // The robot's own walking.com_height (its walking.yaml), whatever the scenario sets: the
  // plausible CoM heights of the warnings are relative to it.
  double robot_com_height = 0.0;
  // What the loader warns about without refusing it (datasets/SCENARIOS.md, "Warnings"): a
  // commanded velocity the generator clamps, a value outside the robot's plausible range. One
  // line each, "FILE: key 'KEY': ...", like an InputError's; nothing of the walk depends on them.
  // Recorded with the run (the `warnings` attribute, datasets/SCHEMA.md).
  std::vector<std::string> warnings;
};

// Reads `path`, applies `overrides` and merges the robot found in `robots_dir`.
//
// An override is "key=value": the key is a dotted path into the scenario tree with list
// indices, the value is parsed as YAML, e.g. "duration=20", "generator.sqp_iterations=3",
// "walking.max_step_yaw_change=0.17", "reference[1].v=[0.3,0,0]". Missing maps on the way are
// created; an index may be one past the end of a list to append an entry.
//
// Throws InputError (one line: file, key, expected vs. got) on any problem: unreadable file,
// YAML syntax error (with its line), missing or unknown key, wrong type, non-finite number,
// wrong vector length, non-ascending times, unknown robot, malformed override, and values
// rejected by WalkingParameters::validate() or WalkRequest::validate().
Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides,
                      const std::string& robots_dir);

// The same from the scenario's text (e.g. the `scenario` attribute of a run dataset);
// `origin` stands for the file name in messages and in Scenario::source_path, e.g.
// "out/walk_forward.h5:/scenario".
Scenario loadScenarioText(const std::string& text, const std::string& origin,
                          const std::vector<std::string>& overrides,
                          const std::string& robots_dir);

// The whole scenario after merging the robot parameters and the overrides, as YAML text: every
// key explicit (all walking parameters, all generator settings), numbers in their shortest
// exact form. Loading it as a scenario file gives the same Scenario again. It is what every
// dataset stores (the `scenario` attribute), made when the dataset is written: a study makes
// its runs' scenarios by the million, and only the runs it writes need the text.
std::string resolvedScenarioText(const Scenario& scenario);

}  // namespace wpg::datasets
