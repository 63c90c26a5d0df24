#pragma once
// The nonlinear MPC of Naveau et al. 2017 (Sec. III), as functions over a constant model, a
// per-sample problem and a solver bound to the model that owns its plan, warm start and
// scratch (no allocation per sample). One header per piece:
//
//   wpg/nmpc/layout.hpp             U = [jerk_x (N), F_x (nf), jerk_y (N), F_y (nf), F_theta (nf)]
//                                   (eq. 6)
//   wpg/nmpc/problem.hpp            what changes every sample: phase, CoM state, references
//   wpg/nmpc/model.hpp              constants: prediction (eq. 1-3), Hessians, families and the
//                                   rows it assigns them
//   wpg/nmpc/cost.hpp               cost (5)-(8)
//   wpg/nmpc/constraint_family.hpp  the interface of the nonlinear rows g(U) <= 0, linearized at
//                                   the previous iterate as in (21b); each family numbers its
//                                   own rows
//   wpg/nmpc/builtin_families.hpp   the paper's families and their rows:
//       CoP in the rotated support polygon       (9)-(13)   4 rows per sample
//       step inside the previous step's polygon  (14)-(15)  5 rows per step
//       yaw change between consecutive steps     (16)-(17)  2 rows per step
//       obstacle avoidance                       (18)-(19)  1 row per step and obstacle slot
//       swing foot's landing bound      Sec. III-C3 last paragraph: x, y (4 rows) and yaw (2 rows)
//                                       as two families, each off by default
//   wpg/nmpc/cost_term.hpp          the interface of added cost terms 1/2 |r(U)|^2 (Gauss-Newton)
//   wpg/nmpc/extension_registry.hpp families and cost terms registered by name with parameters
//   wpg/nmpc/builtin_extensions.hpp wpg's registered ones: corridor (family), look_at (cost)
//   wpg/nmpc/numdiff.hpp            finite-difference check of any family's or term's Jacobian
//   wpg/nmpc/solver.hpp             Gauss-Newton SQP, staged relaxation, LMPC baseline
#include "wpg/nmpc/builtin_extensions.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/cost.hpp"
#include "wpg/nmpc/cost_term.hpp"
#include "wpg/nmpc/extension_registry.hpp"
#include "wpg/nmpc/layout.hpp"
#include "wpg/nmpc/model.hpp"
#include "wpg/nmpc/numdiff.hpp"
#include "wpg/nmpc/problem.hpp"
#include "wpg/nmpc/solver.hpp"
