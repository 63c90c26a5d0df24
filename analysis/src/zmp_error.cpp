// The ZMP error before/after the dynamic filter (zmp_error.hpp).
#include "wpg/analysis/zmp_error.hpp"

namespace wpg::analysis {

ZmpErrorComparison compareZmpError(const MultibodyValidation& validation) {
  ZmpErrorComparison comparison;
  // robots' replay fills com_filtered only when the filter ran (multibody_validation.hpp).
  comparison.filtered = validation.com_filtered.size() > 0;
  comparison.before = validation.before;
  comparison.after = validation.after;
  return comparison;
}

}  // namespace wpg::analysis
