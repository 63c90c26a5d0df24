// Descriptive statistics of a sample (sample_statistics.hpp).
#include "wpg/analysis/sample_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wpg::analysis {

SampleStatistics describeSample(const Eigen::Ref<const Eigen::VectorXd>& values) {
  SampleStatistics statistics;
  statistics.count = static_cast<std::size_t>(values.size());
  if (values.size() == 0) return statistics;
  statistics.mean = values.mean();
  if (values.size() > 1) {
    // Bessel's correction: the chain times are a sample of the controller's timing, not the
    // whole population.
    statistics.std_dev = std::sqrt((values.array() - statistics.mean).square().sum() /
                                   static_cast<double>(values.size() - 1));
  }
  statistics.min = values.minCoeff();
  statistics.max = values.maxCoeff();
  return statistics;
}

double median(const Eigen::Ref<const Eigen::VectorXd>& values) {
  if (values.size() == 0) return 0.0;
  std::vector<double> copy(values.data(), values.data() + values.size());
  const std::size_t middle = copy.size() / 2;
  // Partial ordering is enough: the middle element, then the largest of the lower half.
  std::nth_element(copy.begin(), copy.begin() + static_cast<std::ptrdiff_t>(middle), copy.end());
  const double upper = copy[middle];
  if (copy.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(copy.begin(), copy.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower + upper);
}

}  // namespace wpg::analysis
