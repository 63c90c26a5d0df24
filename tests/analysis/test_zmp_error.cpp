// The ZMP error before/after the dynamic filter as the summaries read it from a replay.
#include <gtest/gtest.h>

#include "wpg/analysis/zmp_error.hpp"

using wpg::MultibodyValidation;
using wpg::analysis::compareZmpError;
using wpg::analysis::ZmpErrorComparison;

TEST(ZmpError, FilteredReplayGivesBeforeAndAfter) {
  MultibodyValidation v;
  v.com_filtered = Eigen::MatrixXd::Zero(5, 3);
  v.before = {0.0177, 0.0350};
  v.after = {0.0019, 0.0042};
  const ZmpErrorComparison c = compareZmpError(v);
  EXPECT_TRUE(c.filtered);
  EXPECT_EQ(c.before.rms, 0.0177);
  EXPECT_EQ(c.before.max, 0.0350);
  EXPECT_EQ(c.after.rms, 0.0019);
  EXPECT_EQ(c.after.max, 0.0042);
}

TEST(ZmpError, ReplayWithoutFilterIsNotFiltered) {
  MultibodyValidation v;  // no filtered CoM
  v.before = {0.02, 0.04};
  v.after = v.before;
  const ZmpErrorComparison c = compareZmpError(v);
  EXPECT_FALSE(c.filtered);
  EXPECT_EQ(c.before.rms, 0.02);
  EXPECT_EQ(c.before.max, 0.04);
}
