#pragma once
// Pieces shared by the QP solver's sources (not installed).
namespace wpg::qp {

// The Givens rotations of one working-set update form a chain over neighbouring columns of J;
// they are applied a block of this many rows at a time (working_set_factorization.cpp).
constexpr int kRowBlock = 8;

// J is stored with its row count rounded up to a whole number of row blocks (the extra rows
// are zero and stay zero under rotations), so that the rotations have no scalar remainder.
inline int paddedRows(int rows) { return (rows + kRowBlock - 1) / kRowBlock * kRowBlock; }

}  // namespace wpg::qp
