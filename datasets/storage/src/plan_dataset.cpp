// mpc/plan/ (plan_dataset.hpp): 2-D datasets, one row per (iteration, previewed sample) or
// (iteration, previewed step), so that h5py reads them with a reshape and no code of ours.
#include "plan_dataset.hpp"

#include <string>

namespace wpg::datasets::detail {

void writePlans(GroupImage& mpc, const WalkTrajectory& trajectory) {
  const PlanLog& plans = trajectory.plans;
  if (plans.empty() || plans.size() != trajectory.mpc.size()) return;
  GroupImage& plan = mpc.createGroup("plan");
  writeStringAttribute(plan, "description",
                       "what each NMPC iteration predicted over its horizon (paper Fig. 2): row "
                       "i * samples + j of the per-sample datasets is previewed sample j + 1 of "
                       "iteration i (row i of mpc/), at mpc/time + (j + 1) * sampling_period; "
                       "row i * steps + s of the step datasets its previewed step s");
  writeIntAttribute(plan, "samples", plans.max_samples);
  writeIntAttribute(plan, "steps", plans.steps);
  writeDoubleAttribute(plan, "sampling_period", plans.sampling_period);
  writeInts(plan, "sample_count", plans.samples,
            {"1", nullptr,
             "previewed samples of each iteration (the horizon of the step timing in force; "
             "0: no NMPC ran); the rows beyond it hold 0",
             nullptr});
  writeDoubles(plan, "com", plans.com_position, 2,
               {"m", "world", "predicted centre of mass position (eq. 1-2)", "x, y"});
  writeDoubles(plan, "com_vel", plans.com_velocity, 2,
               {"m/s", "world", "predicted centre of mass velocity", "x, y"});
  writeDoubles(plan, "com_acc", plans.com_acceleration, 2,
               {"m/s^2", "world", "predicted centre of mass acceleration", "x, y"});
  writeDoubles(plan, "jerk", plans.jerk, 2,
               {"m/s^3", "world",
                "planned CoM jerk held over the period that ends at the sample (row 0 of an "
                "iteration is the one executed)",
                "x, y"});
  writeDoubles(plan, "cop", plans.cop, 2,
               {"m", "world", "predicted centre of pressure z = c - h/g c'' (eq. 3)", "x, y"});
  writeDoubles(plan, "steps", plans.step, 4,
               {"s, m, m, rad", "world",
                "previewed footsteps (step 0: the current swing's landing): the instant it "
                "becomes the support (0: not within the horizon, standing), ankle x, y, yaw",
                "landing_time, x, y, yaw"});
  DatasetImage& side = writeCodes(plan, "step_side", plans.step_side,
                                  {"1", nullptr, "side of each previewed step", nullptr});
  writeStringAttribute(side, "codes", "1=left, 2=right");
  std::string names;
  for (const ConstraintFamilyInfo& family : trajectory.constraint_families)
    names += (names.empty() ? "" : ", ") + family.name;
  if (plans.families > 0 && !names.empty() &&
      static_cast<int>(trajectory.constraint_families.size()) == plans.families) {
    writeDataset(plan, "active_rows", plans.active_rows.data(), plans.size(),
                 static_cast<std::uint64_t>(plans.families), ElementType::kInt32,
                 {"1", nullptr,
                  "inequality rows of each constraint family active at the iteration's last QP "
                  "(one column per family, as mpc/slack)",
                  names.c_str()});
  }
}

}  // namespace wpg::datasets::detail
