#pragma once
// J' v for a v that is mostly zeros, over its nonzero entries only, with the same bits as
// Eigen's dense product: the Goldfarb-Idnani method's d = J' n+ (dense_qp_solver.hpp), whose
// normal n+ is a row of C or E (an NMPC CoP row: the jerks up to its sample and its support's
// step; a step's row: 2 to 6 entries; an equality: one).
#include <Eigen/Core>

namespace wpg::qp {

// out = J' v (J: rows = v.size(), at least out.size() columns; the first out.size() are used).
// `pairs` is scratch of at least v.size() / 2 entries (no allocation). Eigen's dense product
// sums, for each column of J, the even entries of v in one SSE lane and the odd ones in the
// other (each in order, from zero), then adds the two lanes, then the last entry when v's size
// is odd, and adds that to zero. This does the same over the pairs (2i, 2i + 1) where v is
// not zero: the pairs it leaves out would add zeros only (J finite), so out has the same bits
// as J.transpose() * v when both are compiled without fused multiply-add (the project's
// x86-64 build).
void transposedTimesSparse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                           const Eigen::Ref<const Eigen::VectorXd>& v,
                           Eigen::Ref<Eigen::VectorXi> pairs, Eigen::Ref<Eigen::VectorXd> out);

}  // namespace wpg::qp
