// The memo of Hessian factors (shared_hessian_factor.hpp).
//
// Keyed by the Hessian's bits rather than by the walking parameters it is built from: the key
// cannot miss an input the Hessian gains one day, and equal bits give equal factors by
// construction (compute() is a deterministic function of them). compute() reads the lower
// triangle only once the matrix is finite, so a finite Hessian's key is its lower triangle
// (half the memory; a non-finite one is refused by compute() and never stored). One memo per process, not per thread: the runs of a
// study that share a Hessian are spread over the workers, and a factor costs a lock and a
// lookup of a few thousand instructions against some 160 000 to compute.
#include "wpg/qp/shared_hessian_factor.hpp"

#include <cstdint>
#include <cstring>
#include <list>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace wpg::qp {
namespace {

// What the memo may hold: the 1200 factors (of at most 38 x 38, 17 kB with their key) of a
// study of 40 distinct walking parameter sets with four step cadences each fit with room to
// spare; a larger variety of Hessians keeps the most recently used ones.
constexpr std::size_t kBudgetBytes = std::size_t{32} << 20;

// The lower triangle of a finite square Hessian, column by column: the only entries
// compute() reads. Each column's part is contiguous (Eigen's column-major storage, inner
// stride 1 for a Ref to a MatrixXd or a block of one).
class LowerTriangle {
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

// FNV-1a over the entries' 64-bit patterns (a word at a time: bytes would cost 8 times more).
std::size_t hashOf(const LowerTriangle& triangle) {
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

bool sameBits(const LowerTriangle& triangle, const std::vector<double>& key) {
  if (triangle.entries() != key.size()) return false;
  const double* stored = key.data();
  bool same = true;
  triangle.forEachColumn([&](const double* first, std::size_t count) {
    same = same && std::memcmp(first, stored, count * sizeof(double)) == 0;
    stored += count;
  });
  return same;
}

class FactorMemo {
 public:
  std::shared_ptr<const HessianFactor> find(const LowerTriangle& triangle, std::size_t hash) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = lookUp(triangle, hash);
    if (found == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, found);  // the most recently used first
    return found->factor;
  }

  // The factor stored for the triangle: `factor` unless another thread stored one meanwhile
  // (the same bits).
  std::shared_ptr<const HessianFactor> insert(const LowerTriangle& triangle, std::size_t hash,
                                              std::shared_ptr<const HessianFactor> factor) {
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
    while (bytes_ > kBudgetBytes && entries_.size() > 1) evictLeastRecentlyUsed();
    return entries_.front().factor;
  }

 private:
  struct Entry {
    std::size_t hash = 0;
    std::vector<double> key;  // the lower triangle
    std::shared_ptr<const HessianFactor> factor;
    std::size_t bytes = 0;
  };
  using Entries = std::list<Entry>;

  Entries::iterator lookUp(const LowerTriangle& triangle, std::size_t hash) {
    const auto range = index_.equal_range(hash);
    for (auto it = range.first; it != range.second; ++it)
      if (sameBits(triangle, it->second->key)) return it->second;
    return entries_.end();
  }

  void evictLeastRecentlyUsed() {
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

  std::mutex mutex_;
  Entries entries_;  // the most recently used first
  std::unordered_multimap<std::size_t, Entries::iterator> index_;
  std::size_t bytes_ = 0;
};

FactorMemo& memo() {
  static FactorMemo memo;
  return memo;
}

}  // namespace

std::shared_ptr<const HessianFactor> sharedHessianFactor(
    const Eigen::Ref<const Eigen::MatrixXd>& hessian) {
  if (hessian.rows() != hessian.cols() || !hessian.allFinite()) return nullptr;  // as compute()
  const LowerTriangle triangle(hessian);
  const std::size_t hash = hashOf(triangle);
  if (auto factor = memo().find(triangle, hash)) return factor;
  // Computed outside the lock: two threads may both compute a new Hessian's factor, to the
  // same bits; the first stored is kept.
  auto factor = std::make_shared<HessianFactor>();
  if (!factor->compute(hessian)) return nullptr;
  return memo().insert(triangle, hash, std::move(factor));
}

}  // namespace wpg::qp
