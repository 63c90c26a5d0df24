#pragma once
// Descriptive statistics of a sample of measurements (timings, errors): the numbers the
// paper's Sec. V-C table and the run summaries quote.
#include <cstddef>

#include <Eigen/Core>

namespace wpg::analysis {

struct SampleStatistics {
  std::size_t count = 0;
  double mean = 0.0;
  double std_dev = 0.0;  // sample standard deviation (divides by count - 1); 0 when count < 2
  double min = 0.0;      // 0 when count is 0, like max
  double max = 0.0;
};

// count, mean, standard deviation, minimum and maximum of `values` (all 0 when it is empty).
SampleStatistics describeSample(const Eigen::Ref<const Eigen::VectorXd>& values);

// The median of `values`: the middle value of an odd count, the mean of the two middle values
// of an even count; 0 when it is empty.
double median(const Eigen::Ref<const Eigen::VectorXd>& values);

}  // namespace wpg::analysis
