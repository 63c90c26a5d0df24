// The push search's bisection (wpg/engine/push_recovery_search.hpp) on recovery predicates with
// known answers, each call standing for one walk: the largest recovered force is found within
// the tolerance below the true bound, the bracket's invariant holds (the result recovered, a
// force `tolerance` above it did not), the upper bound is reported as such, and a stronger push
// that recovers again (recovery not monotone in the force) moves the search above it.
#include <cmath>
#include <functional>
#include <stdexcept>

#include <gtest/gtest.h>

#include "wpg/engine/push_recovery_search.hpp"

using wpg::engine::PushSearchResult;
using wpg::engine::PushSearchSettings;
using wpg::engine::searchLargestRecoveredForce;

namespace {

// The search with a predicate that counts its calls.
struct CountedSearch {
  PushSearchResult result;
  int calls = 0;
};
CountedSearch search(const std::function<bool(double)>& recovered,
                     const PushSearchSettings& settings) {
  CountedSearch counted;
  counted.result = searchLargestRecoveredForce(
      [&](double force) {
        ++counted.calls;
        return recovered(force);
      },
      settings);
  return counted;
}

}  // namespace

TEST(PushSearch, MonotoneRecoveryIsBracketedWithinTheTolerance) {
  PushSearchSettings settings;  // [0, 600] N, 2.5 N, stronger x 1.15
  for (const double bound : {3.0, 47.3, 123.4, 299.99, 490.0, 597.0}) {
    SCOPED_TRACE(bound);
    const auto recovered = [bound](double force) { return force <= bound; };
    const CountedSearch counted = search(recovered, settings);
    const PushSearchResult& r = counted.result;
    EXPECT_TRUE(recovered(r.force));
    EXPECT_LE(r.force, bound);
    EXPECT_GT(r.force, bound - settings.tolerance);
    EXPECT_FALSE(r.at_upper_bound);
    EXPECT_TRUE(r.stronger_fails);
    EXPECT_EQ(r.walks, counted.calls);
    // Above 20 N the first bracket's force x 1.15 is beyond the bound: max_force, log2(600 /
    // 2.5) < 8 halvings and the one stronger check. Below, the stronger checks climb to it.
    if (bound > 20.0) EXPECT_LE(r.walks, 1 + 8 + 1);
  }
}

TEST(PushSearch, ATighterToleranceBracketsTighter) {
  PushSearchSettings settings;
  settings.tolerance = 0.01;
  const double bound = 123.456;
  const PushSearchResult r = search([&](double f) { return f <= bound; }, settings).result;
  EXPECT_LE(r.force, bound);
  EXPECT_GT(r.force, bound - 0.01);
}

TEST(PushSearch, RecoveringTheUpperBoundStopsAtOnce) {
  PushSearchSettings settings;
  settings.max_force = 250.0;
  const CountedSearch counted = search([](double) { return true; }, settings);
  EXPECT_EQ(counted.result.force, 250.0);
  EXPECT_TRUE(counted.result.at_upper_bound);
  EXPECT_EQ(counted.calls, 1);
}

TEST(PushSearch, NothingRecoveredGivesZero) {
  const PushSearchSettings settings;
  const CountedSearch counted = search([](double force) { return force <= 0.0; }, settings);
  EXPECT_EQ(counted.result.force, 0.0);
  EXPECT_TRUE(counted.result.stronger_fails);
  EXPECT_FALSE(counted.result.at_upper_bound);
}

TEST(PushSearch, AStrongerPushThatRecoversMovesTheSearchAboveIt) {
  // Recovered up to 70 N, not in (70, 78), again in [78, 140]: the bisection from [0, 600]
  // first brackets 70 N (its midpoint 75 N fails); 1.15 x that lands in [78, 140] and
  // recovers, so the search starts again above it and ends below 140 N.
  const auto recovered = [](double force) {
    return force <= 70.0 || (force >= 78.0 && force <= 140.0);
  };
  const PushSearchSettings settings;
  const CountedSearch counted = search(recovered, settings);
  const PushSearchResult& r = counted.result;
  EXPECT_TRUE(recovered(r.force));
  EXPECT_LE(r.force, 140.0);
  EXPECT_GT(r.force, 140.0 - settings.tolerance);
  EXPECT_TRUE(r.stronger_fails);
  EXPECT_FALSE(recovered(settings.stronger_factor * r.force));
  EXPECT_EQ(r.walks, counted.calls);
}

TEST(PushSearch, AStrongerPushBeyondTheBoundIsReportedAtTheBound) {
  // Recovered up to 180 N and from 205 N on, so not at the bound 200 N: the bisection brackets
  // 180 N, and 1.15 x that (about 207 N) recovers beyond the bound, which ends the search.
  PushSearchSettings settings;
  settings.max_force = 200.0;
  const auto recovered = [](double force) { return force <= 180.0 || force >= 205.0; };
  const PushSearchResult r = search(recovered, settings).result;
  EXPECT_TRUE(r.at_upper_bound);
  EXPECT_FALSE(r.stronger_fails);
  EXPECT_GE(r.force, settings.max_force);
  EXPECT_TRUE(recovered(r.force));
}

TEST(PushSearch, AToleranceBelowWhatDoublesResolveStopsWhenTheBracketStopsShrinking) {
  // 1e-300 N: no two doubles near 123 N are that close, the bracket stops shrinking at one ulp
  // (~1.4e-14 N) after about 55 halvings; the bisection must stop there, not loop forever.
  PushSearchSettings settings;
  settings.tolerance = 1e-300;
  const double bound = 123.456;
  int calls = 0;
  const PushSearchResult r = searchLargestRecoveredForce(
      [&](double f) {
        if (++calls > 10000) throw std::runtime_error("the bisection does not end");
        return f <= bound;
      },
      settings);
  EXPECT_LE(r.force, bound);
  EXPECT_GE(r.force, std::nextafter(bound, 0.0));  // the bracket is one ulp wide
  EXPECT_LT(calls, 2 * 64);
}
