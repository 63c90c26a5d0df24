#pragma once
// The ZMP error of a walk before and after the dynamic filter (paper Sec. IV, Fig. 6): the
// distance between the reference CoP of the WPG and the ZMP of the multibody model, as the
// summaries and the Sec. V-C table report it.
#include "wpg/multibody_validation.hpp"

namespace wpg::analysis {

struct ZmpErrorComparison {
  bool filtered = false;       // the dynamic filter ran: `after` holds the filtered motion's error
  ZmpErrorStatistics before;   // [m] the WPG's motion replayed as it is
  ZmpErrorStatistics after;    // [m] the filtered motion replayed (the replay copies `before`
                               // when the filter did not run)
};

// The ZMP error of a replay; the filter counts as run when the replay holds a filtered CoM.
ZmpErrorComparison compareZmpError(const MultibodyValidation& validation);

}  // namespace wpg::analysis
