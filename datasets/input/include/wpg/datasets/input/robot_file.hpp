#pragma once
// A robot's walking file (robots/<robot>/walking.yaml; docs/robots.md) read on its own, as
// `wpg robot check` reads a robot folder: every walking parameter, `mass` and `multibody:`.
#include <string>

#include "wpg/datasets/input/robot_multibody.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::datasets {

struct RobotFile {
  WalkingParameters walking;
  double mass = 0.0;         // [kg], `mass:`
  RobotMultibody multibody;  // `multibody:` (present false without it)
};

// Reads and checks the file (keys, types, WalkingParameters::validate(): a convex feasibility
// polygon, a CoP area inside the sole, ...). Throws InputError, one line naming the file and
// the key.
RobotFile loadRobotFile(const std::string& path);

}  // namespace wpg::datasets
