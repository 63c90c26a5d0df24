// OMPL's geometric planners by name (ompl_planner_registry.hpp). One of the two translation
// units of planning/ that include OMPL (route_planner.cpp is the other): its headers cost
// ~1.4 s per unit on this machine.
#include "ompl_planner_registry.hpp"

#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sst/SST.h>

namespace wpg::planning::detail {
namespace {

namespace og = ompl::geometric;
using ompl::base::PlannerPtr;
using ompl::base::SpaceInformationPtr;

// A planner whose own generator (a protected `rng_`: goal bias, range draws) is seeded.
template <typename Planner>
class SeededPlanner : public Planner {
 public:
  SeededPlanner(const SpaceInformationPtr& si, std::uint32_t seed) : Planner(si) {
    this->rng_.setLocalSeed(seed);
  }
};

template <typename Planner>
PlannerPtr makeSeeded(const SpaceInformationPtr& si, std::uint32_t seed) {
  return std::make_shared<SeededPlanner<Planner>>(si, seed);
}

// Planners without a generator of their own that a subclass can reach: their samplers are
// seeded (the state space's allocator), nothing else.
template <typename Planner>
PlannerPtr make(const SpaceInformationPtr& si, std::uint32_t /*seed*/) {
  return std::make_shared<Planner>(si);
}

}  // namespace

const std::vector<OmplPlannerEntry>& omplPlanners() {
  // reproducible: tested (tests/planning/test_route_planner.cpp) or drawing only from the
  // seeded samplers and a seeded rng_. Not: PRM-family (a second thread checks for solutions
  // while the roadmap grows), informed and BIT* samplers (OMPL allocates their base sampler
  // with allocDefaultStateSampler, bypassing the seeded allocator), and planners whose
  // generator is private.
  static const std::vector<OmplPlannerEntry> planners = {
      {"rrtconnect", false, true, &makeSeeded<og::RRTConnect>},
      {"rrt", false, true, &makeSeeded<og::RRT>},
      {"rrtstar", true, true, &makeSeeded<og::RRTstar>},
      {"informedrrtstar", true, false, &makeSeeded<og::InformedRRTstar>},
      {"sorrtstar", true, false, &makeSeeded<og::SORRTstar>},
      {"rrtsharp", true, false, &make<og::RRTsharp>},
      {"bitstar", true, false, &make<og::BITstar>},
      {"abitstar", true, false, &make<og::ABITstar>},
      {"prm", false, false, &makeSeeded<og::PRM>},
      {"prmstar", true, false, &make<og::PRMstar>},
      {"lazyprmstar", true, false, &make<og::LazyPRMstar>},
      {"fmt", false, false, &make<og::FMT>},
      {"bfmt", false, false, &make<og::BFMT>},
      {"trrt", false, false, &makeSeeded<og::TRRT>},
      {"bitrrt", false, false, &make<og::BiTRRT>},
      {"lbtrrt", true, false, &make<og::LBTRRT>},
      {"kpiece", false, false, &make<og::KPIECE1>},
      {"bkpiece", false, false, &make<og::BKPIECE1>},
      {"lbkpiece", false, false, &make<og::LBKPIECE1>},
      {"est", false, false, &make<og::EST>},
      {"biest", false, false, &make<og::BiEST>},
      {"sbl", false, false, &make<og::SBL>},
      {"sst", true, false, &make<og::SST>},
  };
  return planners;
}

const OmplPlannerEntry* findOmplPlanner(const std::string& name) {
  for (const OmplPlannerEntry& entry : omplPlanners()) {
    if (name == entry.name) return &entry;
  }
  return nullptr;
}

}  // namespace wpg::planning::detail
