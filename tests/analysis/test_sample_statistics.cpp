// describeSample and median on samples whose statistics are computed by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "wpg/analysis/sample_statistics.hpp"

using wpg::analysis::describeSample;
using wpg::analysis::median;
using wpg::analysis::SampleStatistics;

namespace {

Eigen::VectorXd vector(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double value : values) v[i++] = value;
  return v;
}

}  // namespace

TEST(SampleStatistics, KnownSample) {
  // mean 5; squared deviations 9+1+1+1+0+0+4+16 = 32; sample variance 32/7.
  const SampleStatistics s = describeSample(vector({2, 4, 4, 4, 5, 5, 7, 9}));
  EXPECT_EQ(s.count, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_DOUBLE_EQ(s.std_dev, std::sqrt(32.0 / 7.0));
  EXPECT_DOUBLE_EQ(s.min, 2.0);
  EXPECT_DOUBLE_EQ(s.max, 9.0);
}

TEST(SampleStatistics, OrderDoesNotMatterAndNegativeValuesCount) {
  // mean -0.5; deviations 2.5, -2.5, 1.5, -1.5: squares sum 17; sample variance 17/3.
  const SampleStatistics s = describeSample(vector({2, -3, 1, -2}));
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, -0.5);
  EXPECT_DOUBLE_EQ(s.std_dev, std::sqrt(17.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.min, -3.0);
  EXPECT_DOUBLE_EQ(s.max, 2.0);
}

TEST(SampleStatistics, OneValueHasNoSpread) {
  const SampleStatistics s = describeSample(vector({1.5}));
  EXPECT_EQ(s.count, 1u);
  EXPECT_DOUBLE_EQ(s.mean, 1.5);
  EXPECT_DOUBLE_EQ(s.std_dev, 0.0);
  EXPECT_DOUBLE_EQ(s.min, 1.5);
  EXPECT_DOUBLE_EQ(s.max, 1.5);
}

TEST(SampleStatistics, EmptySampleIsAllZero) {
  const SampleStatistics s = describeSample(Eigen::VectorXd());
  EXPECT_EQ(s.count, 0u);
  EXPECT_EQ(s.mean, 0.0);
  EXPECT_EQ(s.std_dev, 0.0);
  EXPECT_EQ(s.min, 0.0);
  EXPECT_EQ(s.max, 0.0);
}

TEST(Median, OddCountIsTheMiddleValue) {
  EXPECT_DOUBLE_EQ(median(vector({3, 1, 2})), 2.0);
  EXPECT_DOUBLE_EQ(median(vector({9, -1, 5, 7, 0})), 5.0);
  EXPECT_DOUBLE_EQ(median(vector({4})), 4.0);
}

TEST(Median, EvenCountIsTheMeanOfTheTwoMiddleValues) {
  EXPECT_DOUBLE_EQ(median(vector({4, 1, 3, 2})), 2.5);
  EXPECT_DOUBLE_EQ(median(vector({10, 0})), 5.0);
  // the two middle values equal: no averaging artefact
  EXPECT_DOUBLE_EQ(median(vector({1, 7, 7, 100, 7, 0})), 7.0);
  // a large outlier moves the mean, not the median
  EXPECT_DOUBLE_EQ(median(vector({1, 2, 3, 1000})), 2.5);
}

TEST(Median, EmptyIsZero) { EXPECT_EQ(median(Eigen::VectorXd()), 0.0); }

TEST(Median, LeavesItsInputUnchangedAndTakesStridedInput) {
  const Eigen::VectorXd values = vector({5, 3, 1, 4, 2});
  const Eigen::VectorXd copy = values;
  EXPECT_DOUBLE_EQ(median(values), 3.0);
  EXPECT_EQ(values, copy);
  // A row of a column-major matrix is not contiguous.
  Eigen::MatrixXd m(2, 4);
  m << 8, 1, 6, 3,  //
      0, 0, 0, 0;
  EXPECT_DOUBLE_EQ(median(m.row(0).transpose()), 4.5);
}
