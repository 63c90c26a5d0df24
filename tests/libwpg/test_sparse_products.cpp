// The products that skip zeros (wpg/qp/column_profile.hpp, wpg/qp/sparse_vector_product.hpp)
// give Eigen's dense products to the last bit, and the QP solver solves the same with a
// profile as without: the plans stay bit for bit what they were.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstring>
#include <stdexcept>

#include "wpg/qp/column_profile.hpp"
#include "wpg/qp/sparse_vector_product.hpp"
#include "qp_test_problems.hpp"

namespace {

using namespace qp_test;
using Eigen::VectorXi;
using wpg::qp::ColumnProfile;

bool sameBits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

// A random profile of `rows` x `cols` (some columns empty, some full) and a matrix that is
// zero outside it, with entries of widely different magnitudes (so that any change of the
// order of a row's sum shows in its last bits).
struct Profiled {
  VectorXi first, end;
  MatrixXd C;
};
Profiled randomProfiled(Rng& rng, int rows, int cols) {
  Profiled p{VectorXi(cols), VectorXi(cols), MatrixXd::Zero(rows, cols)};
  for (int k = 0; k < cols; ++k) {
    const int kind = rng.integer(0, 4);
    p.first(k) = kind == 0 ? 0 : rng.integer(0, rows);
    p.end(k) = kind == 0 ? rows : kind == 1 ? p.first(k) : rng.integer(p.first(k), rows);
    for (int r = p.first(k); r < p.end(k); ++r)
      p.C(r, k) = rng.chance(0.1) ? 0.0 : rng.normal() * std::ldexp(1.0, rng.integer(-30, 30));
  }
  return p;
}

TEST(ColumnProfile, MultiplySubtractHasTheBitsOfEigensDenseProduct) {
  Rng rng(11);
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = rng.integer(1, 100), cols = rng.integer(1, 45);
    const Profiled p = randomProfiled(rng, rows, cols);
    const ColumnProfile profile(rows, p.first, p.end);
    ASSERT_TRUE(profile.fits(p.C));
    ASSERT_TRUE(profile.covers(p.C));
    const VectorXd x = rng.normalVector(cols) * 1e3, d = rng.normalVector(rows);
    VectorXd dense(rows);
    dense.noalias() = p.C * x;  // as the QP solver computed C x - d before
    dense -= d;
    VectorXd sparse(rows);
    profile.multiplySubtract(p.C, x, d, sparse);
    ASSERT_TRUE(sameBits(dense, sparse))
        << rows << " x " << cols << ", trial " << trial << ": largest difference "
        << (dense - sparse).cwiseAbs().maxCoeff();
    ++compared;
  }
  EXPECT_EQ(compared, 400);
}

TEST(ColumnProfile, CoversOnlyMatricesWithZerosOutsideIt) {
  Rng rng(12);
  Profiled p = randomProfiled(rng, 30, 10);
  p.first(3) = 5;
  p.end(3) = 20;
  p.C.col(3).setZero();
  p.C(10, 3) = 1.0;
  const ColumnProfile profile(30, p.first, p.end);
  EXPECT_TRUE(profile.covers(p.C));
  p.C(20, 3) = 1e-300;  // one row past the column's range
  EXPECT_FALSE(profile.covers(p.C));
  EXPECT_FALSE(profile.fits(MatrixXd::Zero(31, 10)));
  EXPECT_FALSE(ColumnProfile().fits(p.C));  // no profile: every product dense
}

TEST(ColumnProfile, RejectsRangesOutsideTheRows) {
  EXPECT_THROW(ColumnProfile(4, VectorXi::Constant(2, 0), VectorXi::Constant(2, 5)),
               std::invalid_argument);
  EXPECT_THROW(ColumnProfile(4, VectorXi::Constant(2, -1), VectorXi::Constant(2, 2)),
               std::invalid_argument);
  EXPECT_THROW(ColumnProfile(4, VectorXi::Constant(2, 0), VectorXi::Constant(3, 2)),
               std::invalid_argument);
}

TEST(SparseVectorProduct, HasTheBitsOfEigensDenseProduct) {
  Rng rng(13);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = rng.integer(1, 45);
    // J as the solver holds it: a block of a larger matrix (outer stride), v mostly zeros.
    const MatrixXd storage = rng.normalMatrix(n + 3, n + 2) * 1e2;
    const auto J = storage.topLeftCorner(n, n);
    VectorXd v = VectorXd::Zero(n);
    const double density = rng.uniform(0.0, 1.0);
    for (int i = 0; i < n; ++i)
      if (rng.chance(density)) v(i) = rng.normal() * std::ldexp(1.0, rng.integer(-20, 20));
    VectorXd dense(n);
    dense.noalias() = J.transpose() * v;
    VectorXd sparse(n);
    VectorXi pairs(n / 2 + 1);
    wpg::qp::transposedTimesSparse(J, v, pairs, sparse);
    ASSERT_TRUE(sameBits(dense, sparse)) << "n = " << n << ", trial " << trial;
  }
}

// The solver with a profile of C: the same minimizer, multipliers and active set, bit for bit,
// as without one (the profile only skips zeros).
TEST(ColumnProfile, TheQpSolverSolvesTheSameWithAProfile) {
  Rng rng(14);
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = rng.integer(2, 30), me = rng.integer(0, n / 3), mi = rng.integer(1, 60);
    Qp qp = randomFeasibleQp(rng, n, me, mi, rng.chance(0.3));
    // Zero C outside a random profile (every row keeps a nonzero, so that C stays useful).
    const Profiled p = randomProfiled(rng, static_cast<int>(qp.C.rows()), n);
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < qp.C.rows(); ++r)
        if (r < p.first(k) || r >= p.end(k)) qp.C(r, k) = 0.0;
    HessianFactor factor;
    ASSERT_TRUE(factor.compute(qp.H));
    DenseQpSolver dense(n, me, static_cast<int>(qp.C.rows())), sparse = dense;
    sparse.setInequalityProfile(ColumnProfile(static_cast<int>(qp.C.rows()), p.first, p.end));
    VectorXd x_dense(n), x_sparse(n);
    const QpStatus s_dense = dense.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_dense);
    const QpStatus s_sparse = sparse.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_sparse);
    ASSERT_EQ(s_dense, s_sparse) << "trial " << trial;
    ASSERT_TRUE(sameBits(x_dense, x_sparse)) << "trial " << trial;
    ASSERT_TRUE(sameBits(dense.inequalityMultipliers(), sparse.inequalityMultipliers()));
    ASSERT_EQ(dense.iterations(), sparse.iterations());
    solved += s_dense == QpStatus::kOptimal;
  }
  EXPECT_GT(solved, 50);  // the zeros make some infeasible: compared all the same
}

}  // namespace
