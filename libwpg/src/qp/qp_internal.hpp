#pragma once
#include <cstring>
// Pieces shared by the QP solver's sources (not installed).
// The kernels that dominate the dual method (the Givens chains over J, the products C x) are
// element-wise across rows: every row's result is the same sequence of IEEE multiplications and
// additions whatever the vector width. Compiled twice, for AVX2 and for the baseline x86-64
// (SSE2), and chosen when the program loads, they run twice as wide where the processor can,
// with the same bits. Only multiplications and additions are used, and libwpg is compiled with
// -ffp-contract=off (libwpg/CMakeLists.txt: GCC would otherwise contract them into FMAs in any
// clone whose target has FMA), so no clone rounds differently. GCC only (Clang's sanitizer
// build takes the baseline).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define WPG_QP_KERNEL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define WPG_QP_KERNEL_CLONES
#endif

namespace wpg::qp {

// The Givens rotations of one working-set update form a chain over neighbouring columns of J;
// they are applied a block of this many rows at a time (working_set_factorization.cpp).
constexpr int kRowBlock = 8;

// J is stored with its row count rounded up to a whole number of row blocks (the extra rows
// are zero and stay zero under rotations), so that the rotations have no scalar remainder.
inline int paddedRows(int rows) { return (rows + kRowBlock - 1) / kRowBlock * kRowBlock; }

// Four doubles of a column, for the kernels above: GCC's and Clang's vector extension, which
// each clone compiles at its own width (one AVX2 register, or two SSE2 ones). Loads and stores
// by memcpy (J's and C's columns are only 16-byte aligned), through references: a 32-byte
// vector passed by value would have another ABI in the baseline and the AVX2 clones.
using Lanes = double __attribute__((vector_size(4 * sizeof(double))));
constexpr int kLaneCount = 4;
inline void loadLanes(Lanes& v, const double* p) { std::memcpy(&v, p, sizeof v); }
inline void storeLanes(double* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }

}  // namespace wpg::qp
