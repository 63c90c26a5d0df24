#pragma once
// RMS and maximum of the horizontal distance between the WPG's CoP and a multibody ZMP, sample
// by sample (rows where the ZMP is not finite, e.g. an IK failure, are skipped): the error the
// dynamic filter of the paper's Sec. IV reduces. One definition for the offline replay
// (walk_replay.cpp) and the online loop (online_filter_loop.cpp).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "wpg/multibody_validation.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg::robots::detail {

inline ZmpErrorStatistics zmpErrorStatistics(const WalkTrajectory& walk,
                                             const Eigen::MatrixXd& zmp) {
  ZmpErrorStatistics s;
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < zmp.rows(); ++i) {
    const Eigen::Vector2d e = walk.cop[static_cast<std::size_t>(i)] - zmp.row(i).transpose();
    if (!e.allFinite()) continue;
    sum += e.squaredNorm();
    s.max = std::max(s.max, e.norm());
    ++count;
  }
  s.rms = count ? std::sqrt(sum / count) : 0.0;
  return s;
}

}  // namespace wpg::robots::detail
