#pragma once
// The limits every reader of HDF5 files (run, batch and comparison files, `wpg diff`'s generic
// walk) holds a file to BEFORE it allocates anything for it: a file we did not write may
// declare any size (a 226 KB chunked dataset can declare 2e8 rows of fill values), any rank
// and any link graph. Documented in datasets/SCHEMA.md, "Reading".
#include <cstdint>

#include "wpg/walk_generator.hpp"

namespace wpg::datasets {

// Rows of a run's per-sample datasets (`time`, `com`, ...; and of `footsteps` and `mpc/`): the
// most the writer can write (kMaxControlPeriods control periods, 3600 s at 5 ms, and the
// closing sample).
constexpr std::uint64_t kMaxStoredSamples = static_cast<std::uint64_t>(kMaxControlPeriods) + 1;

// Route plans of one run (`plans/` rows) and waypoints of all its routes (`plans/routes` rows),
// each route its own rows (route_start the rows before it): a page of `wpg view` holds every
// waypoint, and a crafted 0.7 MB file whose 720001 plans each named all its rows made a 70 MB
// page. The writer makes one plan at the start, at most one a second when strayed, one per
// obstacle found in the way and three retries (walk_goal.hpp): a 3600 s walk stays far below.
constexpr std::uint64_t kMaxStoredPlans = 10000;
constexpr std::uint64_t kMaxStoredRouteWaypoints = 100000;

// A run's plan (`mpc/plan/`): previewed samples and steps of an iteration, at most what the
// walking parameters allow (horizon_length <= 200, previewed_steps <= 10).
constexpr std::uint64_t kMaxStoredPlanSamples = 200;
constexpr std::uint64_t kMaxStoredPlanSteps = 10;

// Elements of any one dataset or attribute a reader loads (2^26: 512 MiB as float64). The
// largest dataset wpg writes, `q` of a 3600 s walk of HRP-2, has about 2.7e7.
constexpr std::uint64_t kMaxReadElements = std::uint64_t{1} << 26;

// Bytes of any one dataset or attribute a reader loads (an element may be wider than a number).
constexpr std::uint64_t kMaxReadBytes = std::uint64_t{1} << 29;

// Nesting of groups a generic walk of a file (`wpg diff`) follows; wpg writes 4 levels.
constexpr int kMaxGroupDepth = 16;

}  // namespace wpg::datasets
