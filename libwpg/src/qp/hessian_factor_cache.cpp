// The cache of Hessian factors (hessian_factor_cache.hpp).
//
// Keyed by the Hessian's bits rather than by the walking parameters it is built from: the key
// cannot miss an input the Hessian gains one day, and equal bits give equal factors by
// construction (compute() is a deterministic function of them). compute() reads the lower
// triangle only once the matrix is finite, so a finite Hessian's key is its lower triangle
// (half the memory; a non-finite one is refused by compute() and never stored). A cache is
// shared by the workers of a study: the runs that share a Hessian are spread over them, and a
// factor costs a lock and a lookup of a few thousand instructions against some 160 000 to
// compute.
#include "wpg/qp/hessian_factor_cache.hpp"

#include <cstdint>
#include <cstring>
#include <utility>

namespace wpg::qp {

// The lower triangle of a finite square Hessian, column by column: the only entries
// compute() reads. Each column's part is contiguous (Eigen's column-major storage, inner
// stride 1 for a Ref to a MatrixXd or a block of one).
class HessianFactorCache::LowerTriangle {
 public:
  explicit LowerTriangle(const Eigen::Ref<const Eigen::MatrixXd>& hessian) : h_(hessian) {}
  std::size_t entries() const {
    const auto n = static_cast<std::size_t>(h_.rows());
    return n * (n + 1) / 2;
  }
  // visit(first, count) for each column's part.
  template <typename Visit>
  void forEachColumn(Visit visit) const {
    for (Eigen::Index j = 0; j < h_.cols(); ++j)
      visit(h_.data() + j * h_.outerStride() + j, static_cast<std::size_t>(h_.rows() - j));
  }

 private:
  const Eigen::Ref<const Eigen::MatrixXd>& h_;
};

namespace {

// FNV-1a over the entries' 64-bit patterns (a word at a time: bytes would cost 8 times more).
template <typename Triangle>
std::size_t hashOf(const Triangle& triangle) {
  std::uint64_t hash = 14695981039346656037ull ^ static_cast<std::uint64_t>(triangle.entries());
  triangle.forEachColumn([&hash](const double* first, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, first + i, sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
  });
  return static_cast<std::size_t>(hash ^ (hash >> 32));
}

template <typename Triangle>
bool sameBits(const Triangle& triangle, const std::vector<double>& key) {
  if (triangle.entries() != key.size()) return false;
  const double* stored = key.data();
  bool same = true;
  triangle.forEachColumn([&](const double* first, std::size_t count) {
    same = same && std::memcmp(first, stored, count * sizeof(double)) == 0;
    stored += count;
  });
  return same;
}

}  // namespace

std::shared_ptr<const HessianFactor> HessianFactorCache::factor(
    const Eigen::Ref<const Eigen::MatrixXd>& hessian) {
  if (hessian.rows() != hessian.cols() || !hessian.allFinite()) return nullptr;  // as compute()
  const LowerTriangle triangle(hessian);
  const std::size_t hash = hashOf(triangle);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = lookUp(triangle, hash);
    if (found != entries_.end()) {
      entries_.splice(entries_.begin(), entries_, found);  // the most recently used first
      return found->factor;
    }
  }
  // Computed outside the lock: two threads may both compute a new Hessian's factor, to the
  // same bits; the first stored is kept.
  auto computed = std::make_shared<HessianFactor>();
  if (!computed->compute(hessian)) return nullptr;
  return insert(triangle, hash, std::move(computed));
}

std::size_t HessianFactorCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

HessianFactorCache::Entries::iterator HessianFactorCache::lookUp(const LowerTriangle& triangle,
                                                                 std::size_t hash) {
  const auto range = index_.equal_range(hash);
  for (auto it = range.first; it != range.second; ++it)
    if (sameBits(triangle, it->second->key)) return it->second;
  return entries_.end();
}

// The factor stored for the triangle: `factor` unless another thread stored one meanwhile
// (the same bits).
std::shared_ptr<const HessianFactor> HessianFactorCache::insert(
    const LowerTriangle& triangle, std::size_t hash, std::shared_ptr<const HessianFactor> factor) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = lookUp(triangle, hash);
  if (found != entries_.end()) return found->factor;
  Entry entry;
  entry.hash = hash;
  entry.key.reserve(triangle.entries());
  triangle.forEachColumn([&entry](const double* first, std::size_t count) {
    entry.key.insert(entry.key.end(), first, first + count);
  });
  entry.factor = std::move(factor);
  entry.bytes = sizeof(double) * (entry.key.size() +
                                  static_cast<std::size_t>(
                                      entry.factor->inverse_factor_transposed.size()));
  bytes_ += entry.bytes;
  entries_.push_front(std::move(entry));
  index_.emplace(hash, entries_.begin());
  while (bytes_ > budget_bytes_ && entries_.size() > 1) evictLeastRecentlyUsed();
  return entries_.front().factor;
}

void HessianFactorCache::evictLeastRecentlyUsed() {
  const auto last = std::prev(entries_.end());
  const auto range = index_.equal_range(last->hash);
  for (auto it = range.first; it != range.second; ++it) {
    if (it->second == last) {
      index_.erase(it);
      break;
    }
  }
  bytes_ -= last->bytes;
  entries_.erase(last);
}

}  // namespace wpg::qp
