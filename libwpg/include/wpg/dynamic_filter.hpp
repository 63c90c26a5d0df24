#pragma once
// The dynamic filter of the paper (Sec. IV, Fig. 3 and 6; Kajita et al. 2003): the LIPM
// ignores the inertia of the limbs, so the multibody ZMP of the replayed motion differs from
// the reference CoP. A second preview controller, driven by that ZMP error, yields a CoM
// correction whose cart-table ZMP equals the error; added to the WPG's CoM it cancels the
// error to first order ("one iteration of the dynamic filter is sufficient").
#include <Eigen/Core>

#include "wpg/preview_control.hpp"

namespace wpg {

// zmp_error: n x 2, (reference CoP - multibody ZMP) at the control period, world x and y.
// correction: n x 2, the CoM correction to add to the WPG's CoM (starts at rest at zero).
void dynamicFilterCorrection(const PreviewController& controller,
                             const Eigen::Ref<const Eigen::MatrixXd>& zmp_error,
                             Eigen::Ref<Eigen::MatrixXd> correction);

}  // namespace wpg
