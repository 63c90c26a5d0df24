#pragma once
// OMPL's geometric planners by name (private to planning/): one table of names, how each is
// made, whether it runs until its termination condition (the optimizing planners) and whether
// its routes depend on the seed only. The planner's own random number generator is seeded
// where OMPL lets a subclass reach it.
#include <cstdint>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

namespace wpg::planning::detail {

struct OmplPlannerEntry {
  const char* name;
  bool optimizing;    // runs until the termination condition (asymptotically optimal planners)
  bool reproducible;  // every random number it draws comes from seeded generators
  ompl::base::PlannerPtr (*make)(const ompl::base::SpaceInformationPtr&, std::uint32_t seed);
};

const std::vector<OmplPlannerEntry>& omplPlanners();
const OmplPlannerEntry* findOmplPlanner(const std::string& name);  // null when unknown

}  // namespace wpg::planning::detail
