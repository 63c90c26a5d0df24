// The multibody fields of a run dataset (run_group_writing.hpp): the replay of the walk on the
// multibody model, the dynamic filter and the control chain's timing (datasets/SCHEMA.md).
#include <string>
#include <vector>

#include "hdf5_writing.hpp"
#include "run_group_writing.hpp"

namespace wpg::datasets::detail {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

void writeMultibody(GroupImage& run, const Scenario& scenario, const MultibodyRecord& multibody) {
  const MultibodyValidation& mb = multibody.validation;
  const std::uint64_t nq = mb.configuration_names.size();
  std::vector<std::string> units;
  for (std::uint64_t j = 0; j < nq; ++j) units.push_back(j < 3 ? "m" : j < 7 ? "1" : "rad");
  const bool filtered = mb.com_filtered.size() > 0;
  const std::string q_units = joined(units);
  const std::string q_columns = joined(mb.configuration_names);
  DatasetImage& q = writeDataset(
      run, "q", rowMajor(mb.q).data(), static_cast<std::uint64_t>(mb.q.rows()), nq,
      ElementType::kFloat64,
      {q_units.c_str(), "world",
       filtered ? "configuration of the robot following the filtered CoM (com_filtered), from the "
                  "walking IK: base position, base orientation quaternion (w, x, y, z), joint "
                  "values in the URDF's order"
                : "configuration of the robot following the generated CoM, from the walking IK: "
                  "base position, base orientation quaternion (w, x, y, z), joint values in the "
                  "URDF's order",
       q_columns.c_str()});
  writeStringListAttribute(q, "names", mb.configuration_names);
  writeDoubles(run, "zmp_multibody", rowMajor(mb.zmp_multibody), 2,
               {"m", "world",
                "ZMP of the multibody model (inverse dynamics of the IK motion of the generated "
                "CoM and feet), before the dynamic filter",
                "x, y"});
  if (filtered) {
    writeDoubles(run, "com_filtered", rowMajor(mb.com_filtered), 3,
                 {"m", "world",
                  "centre of mass corrected by the dynamic filter: com + the preview controller's "
                  "correction of the ZMP error (paper Sec. IV)",
                  "x, y, z"});
    writeDoubles(run, "zmp_multibody_filtered", rowMajor(mb.zmp_multibody_filtered), 2,
                 {"m", "world", "ZMP of the multibody model following com_filtered", "x, y"});
  }

  GroupImage& group = run.createGroup("multibody");
  writeStringAttribute(group, "description",
                       "multibody replay of the walk (walking IK, inverse dynamics) and dynamic "
                       "filter; ZMP errors are |cop - zmp| in m, RMS and max over the samples "
                       "(after = before without the filter)");
  writeIntAttribute(group, "filtered", filtered ? 1 : 0);
  writeDoubleAttribute(group, "zmp_error_rms_before", mb.before.rms);
  writeDoubleAttribute(group, "zmp_error_max_before", mb.before.max);
  writeDoubleAttribute(group, "zmp_error_rms_after", mb.after.rms);
  writeDoubleAttribute(group, "zmp_error_max_after", mb.after.max);
  writeIntAttribute(group, "ik_failures", mb.ik_failures);
  writeDoubleAttribute(group, "max_ik_com_error", mb.max_ik_com_error);
  writeDoubleAttribute(group, "max_ik_foot_error", mb.max_ik_foot_error);
  writeIntAttribute(group, "samples_with_limit_violations", mb.samples_with_limit_violations);
  writeDoubleAttribute(group, "max_limit_violation", mb.max_limit_violation);
  writeStringListAttribute(group, "violated_joints", mb.violated_joints);
  writeDoubleAttribute(group, "filter_error_weight", scenario.filter_settings.error_weight);
  writeDoubleAttribute(group, "filter_input_weight", scenario.filter_settings.input_weight);
  writeDoubleAttribute(group, "filter_preview_time", scenario.filter_settings.preview_time);
  const double online_r = scenario.filter_loop.online_input_weight;  // R of the online loop
  writeDoubleAttribute(group, "filter_online_input_weight", online_r);
  writeStringAttribute(group, "filter_mode", mb.filter_mode);  // closed_loop, online, offline, ""
  writeIntAttribute(group, "wpg_reinitialized", mb.wpg_reinitialized ? 1 : 0);
  if (mb.has_offline_comparison) {
    // filter_settings.mode both: the offline pass over the open-loop walk, for comparison.
    writeDoubleAttribute(group, "offline_zmp_error_rms_before", mb.offline_before.rms);
    writeDoubleAttribute(group, "offline_zmp_error_max_before", mb.offline_before.max);
    writeDoubleAttribute(group, "offline_zmp_error_rms_after", mb.offline_after.rms);
    writeDoubleAttribute(group, "offline_zmp_error_max_after", mb.offline_after.max);
  }

  // Timing profile of the control chain per NMPC iteration (paper Sec. V-C).
  GroupImage& timing = run.createGroup("timing");
  writeStringAttribute(timing, "description",
                       "wall time of the control chain per NMPC iteration (paper Sec. V-C): NMPC, "
                       "walking IK, multibody ZMP, dynamic filter; the whole-walk stages (ZMP, "
                       "filter) spread evenly over the iterations");
  const Eigen::VectorXd& chain = mb.chain_time;
  writeDoubles(timing, "chain_time", std::vector<double>(chain.data(), chain.data() + chain.size()),
               0, {"s", nullptr, "wall time of the whole chain in each NMPC iteration", nullptr});
  writeDoubles(timing, "chain_stage_time", rowMajor(mb.chain_stage_time), 4,
               {"s", nullptr, "wall time of each stage of the chain in each NMPC iteration",
                "nmpc, ik, multibody_zmp, filter"});
  writeDoubleAttribute(timing, "chain_time_average", multibody.chain_time.average);
  writeDoubleAttribute(timing, "chain_time_std", multibody.chain_time.std_dev);
  writeDoubleAttribute(timing, "chain_time_min", multibody.chain_time.min);
  writeDoubleAttribute(timing, "chain_time_max", multibody.chain_time.max);

  // Per control period (the paper's unit: one 5 ms tick, Sec. V-C).
  if (mb.tick_stage_time.rows() > 0) {
    writeDoubles(timing, "tick_stage_time", rowMajor(mb.tick_stage_time), 4,
                 {"s", nullptr,
                  mb.tick_stages_measured
                      ? "wall time of each stage in each control period (online loop: every "
                        "stage measured in its own tick); wpg = the generator's step (the NMPC "
                        "when it runs, the interpolation, the preview of the plan)"
                      : "wall time of each stage in each control period (offline pass: the NMPC "
                        "and the IK measured per tick, the multibody ZMP and the filter over the "
                        "whole walk spread evenly)",
                  "wpg, ik, multibody_zmp, filter"});
    writeInts(timing, "tick_nmpc", std::vector<int>(mb.tick_nmpc.begin(), mb.tick_nmpc.end()),
              {"1", nullptr, "1 when the NMPC ran in that control period", nullptr});
    writeIntAttribute(timing, "tick_stages_measured", mb.tick_stages_measured ? 1 : 0);
  }
}


}  // namespace wpg::datasets::detail
