#pragma once
// A cache of Hessian factors, each computed once per distinct Hessian, passed to the NMPC
// models that may share it. A study's runs share their walking parameters but for the swept
// keys (speed, weights, height): every run built the same NMPC Hessians again, and their
// factors (an LLT and a triangular inverse per walking pattern and step cadence) were a tenth
// of a batch. A study hands one cache to all its runs (loadStudyScenarios); a generator given
// none makes its own (GeneratorSettings::hessian_factors), so a controller shares nothing
// with anything else in its process.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "wpg/qp/dense_qp_solver.hpp"

namespace wpg::qp {

class HessianFactorCache {
 public:
  // What the cache may hold by default: the 1200 factors (of at most 38 x 38, 17 kB with their
  // key) of a study of 40 distinct walking parameter sets with four step cadences each fit
  // with room to spare; a larger variety of Hessians keeps the most recently used ones.
  static constexpr std::size_t kDefaultBudgetBytes = std::size_t{32} << 20;

  explicit HessianFactorCache(std::size_t budget_bytes = kDefaultBudgetBytes)
      : budget_bytes_(budget_bytes) {}
  HessianFactorCache(const HessianFactorCache&) = delete;
  HessianFactorCache& operator=(const HessianFactorCache&) = delete;

  // The factor HessianFactor::compute(hessian) gives, shared with every earlier call on this
  // cache for a Hessian of the same size and the same bits; null where compute() fails. The
  // factor is a function of those bits alone, so it is the same to the last bit whichever call
  // (or thread) computed it: the number of threads, the order of the runs and what the cache
  // still holds change no result. Thread safe (a lock of this cache). Holds the most recently
  // used factors up to the budget (factors in use stay alive with their users). Allocates.
  std::shared_ptr<const HessianFactor> factor(const Eigen::Ref<const Eigen::MatrixXd>& hessian);

  std::size_t size() const;  // factors held

 private:
  struct Entry {
    std::size_t hash = 0;
    std::vector<double> key;  // the lower triangle
    std::shared_ptr<const HessianFactor> factor;
    std::size_t bytes = 0;
  };
  using Entries = std::list<Entry>;
  class LowerTriangle;

  Entries::iterator lookUp(const LowerTriangle& triangle, std::size_t hash);
  std::shared_ptr<const HessianFactor> insert(const LowerTriangle& triangle, std::size_t hash,
                                              std::shared_ptr<const HessianFactor> factor);
  void evictLeastRecentlyUsed();

  const std::size_t budget_bytes_;
  mutable std::mutex mutex_;
  Entries entries_;  // the most recently used first
  std::unordered_multimap<std::size_t, Entries::iterator> index_;
  std::size_t bytes_ = 0;
};

}  // namespace wpg::qp
