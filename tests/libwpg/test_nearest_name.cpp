// The nearest known name to a mistyped one (nearest_name.hpp): distances of known edits, case
// ignored, nothing suggested for a name far from all, or equally near two.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "wpg/nearest_name.hpp"

namespace {

using wpg::didYouMean;
using wpg::nameDistance;
using wpg::nearestName;

TEST(NearestName, DistanceCountsEachEditOnce) {
  EXPECT_EQ(nameDistance("algorithm", "algorithm"), 0u);
  EXPECT_EQ(nameDistance("algoritm", "algorithm"), 1u);     // a deletion
  EXPECT_EQ(nameDistance("algorithmm", "algorithm"), 1u);   // an insertion
  EXPECT_EQ(nameDistance("algorythm", "algorithm"), 1u);    // a substitution
  EXPECT_EQ(nameDistance("algorihtm", "algorithm"), 1u);    // two neighbours swapped
  EXPECT_EQ(nameDistance("RRTConnect", "rrtconnect"), 0u);  // case ignored
  EXPECT_EQ(nameDistance("", "abc"), 3u);
  EXPECT_EQ(nameDistance("kitten", "sitting"), 3u);
  // Symmetric.
  EXPECT_EQ(nameDistance("sitting", "kitten"), 3u);
}

TEST(NearestName, SuggestsTheNearestKnownName) {
  const std::vector<std::string> planner_keys = {"algorithm", "time_limit", "max_iterations",
                                                 "seed", "robot_radius"};
  EXPECT_EQ(nearestName("algoritm", planner_keys), "algorithm");
  EXPECT_EQ(nearestName("Algorithm", planner_keys), "algorithm");
  EXPECT_EQ(nearestName("timelimit", planner_keys), "time_limit");
  EXPECT_EQ(didYouMean("sed", planner_keys), "; did you mean 'seed'?");
  // Cut short: the one name it begins; the beginning of several suggests nothing.
  EXPECT_EQ(nearestName("max_step_yaw", {"max_step_yaw_change", "max_landing_speed"}),
            "max_step_yaw_change");
  EXPECT_EQ(nearestName("max_", {"max_step_yaw_change", "max_landing_speed"}), "");
  // Far from every name: nothing to suggest.
  EXPECT_EQ(nearestName("velocity", planner_keys), "");
  EXPECT_EQ(didYouMean("velocity", planner_keys), "");
  // Equally near two names: no guess.
  EXPECT_EQ(nearestName("ab", {"aa", "bb"}), "");
  EXPECT_EQ(nearestName("x", {}), "");
}

}  // namespace
