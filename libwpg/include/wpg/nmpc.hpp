#pragma once
// The nonlinear MPC of Naveau et al. 2017 (Sec. III), as functions over a constant model, a
// per-sample problem and a solver that owns its plan and warm start (the constant model apart
// from a workspace made once from it, so that a solve allocates nothing). One header per piece:
//
//   wpg/nmpc/layout.hpp             U = [jerk_x (N), F_x (nf), jerk_y (N), F_y (nf), F_theta (nf)]
//                                   (eq. 6) and the rows of the constraint families
//   wpg/nmpc/problem.hpp            what changes every sample: phase, CoM state, references
//   wpg/nmpc/model.hpp              constants: prediction (eq. 1-3), Hessians, families
//   wpg/nmpc/cost.hpp               cost (5)-(8)
//   wpg/nmpc/constraint_family.hpp  the interface of the nonlinear rows g(U) <= 0, linearized at
//                                   the previous iterate as in (21b):
//       CoP in the rotated support polygon       (9)-(13)   4 rows per sample
//       step inside the previous step's polygon  (14)-(15)  5 rows per step
//       yaw change between consecutive steps     (16)-(17)  2 rows per step
//       obstacle avoidance                       (18)-(19)  1 row per step and obstacle slot
//       swing foot's landing bound      Sec. III-C3 last paragraph: x, y (4 rows) and yaw (2 rows)
//                                       as two families, each off by default
//   wpg/nmpc/numdiff.hpp            finite-difference check of any family's Jacobian
//   wpg/nmpc/solver.hpp             Gauss-Newton SQP, staged relaxation, LMPC baseline
#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/cost.hpp"
#include "wpg/nmpc/layout.hpp"
#include "wpg/nmpc/model.hpp"
#include "wpg/nmpc/numdiff.hpp"
#include "wpg/nmpc/problem.hpp"
#include "wpg/nmpc/solver.hpp"
