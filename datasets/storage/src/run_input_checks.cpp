// The checks of a run's inputs before anything of it is written (run_group_writing.hpp).
#include <string>

#include "run_group_writing.hpp"

namespace wpg::datasets::detail {
namespace {

// "writeRunDataset: <array> has <count> <unit>, expected <expected> (one per <per>)"
void requireCount(const std::string& array, std::size_t count, std::size_t expected,
                  const char* unit, const char* per) {
  if (count != expected) {
    throw std::invalid_argument("writeRunDataset: " + array + " has " + std::to_string(count) +
                                " " + unit + ", expected " + std::to_string(expected) +
                                " (one per " + per + ")");
  }
}

void checkSizes(const WalkTrajectory& trajectory) {
  const std::size_t n = trajectory.time.size();
  const auto check = [n](const char* name, std::size_t rows) {
    requireCount(std::string("trajectory.") + name, rows, n, "rows", "trajectory.time sample");
  };
  check("com", trajectory.com.size());
  check("com_vel", trajectory.com_vel.size());
  check("com_acc", trajectory.com_acc.size());
  check("cop", trajectory.cop.size());
  check("left_foot", trajectory.left_foot.size());
  check("right_foot", trajectory.right_foot.size());
  check("free_flyer_yaw", trajectory.free_flyer_yaw.size());
  check("support", trajectory.support.size());
  if (trajectory.constraint_families.size() > static_cast<std::size_t>(kMaxConstraintFamilies)) {
    throw std::invalid_argument("trajectory.constraint_families: expected at most " +
                                std::to_string(kMaxConstraintFamilies) + " families, got " +
                                std::to_string(trajectory.constraint_families.size()));
  }
}

void checkClearanceSizes(const FootstepClearances& clearances, const WalkTrajectory& trajectory) {
  const std::size_t m = trajectory.footsteps.size();
  const auto check = [m](const char* name, std::size_t rows) {
    requireCount(std::string("clearances.") + name, rows, m, "entries",
                 "trajectory.footsteps row");
  };
  check("clearance", clearances.clearance.size());
  check("clearance_obstacle", clearances.clearance_obstacle.size());
  check("foot_distance", clearances.foot_distance.size());
}

void checkGroupName(const std::string& name) {
  if (name.empty() || name == "." || name.find('/') != std::string::npos) {
    throw std::invalid_argument("writeRunDataset: scenario name '" + name +
                                "' cannot be an HDF5 group name (expected non-empty, no '/')");
  }
}

void checkMultibodySizes(const MultibodyValidation& multibody, const WalkTrajectory& trajectory) {
  const Eigen::Index n = static_cast<Eigen::Index>(trajectory.size());
  const auto check = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("writeRunDataset: multibody." + what);
  };
  const auto shape = [](const Eigen::MatrixXd& m) {
    return std::to_string(m.rows()) + " x " + std::to_string(m.cols());
  };
  const Eigen::Index nq = static_cast<Eigen::Index>(multibody.configuration_names.size());
  check(multibody.q.rows() == n && multibody.q.cols() == nq && nq > 0,
        "q is " + shape(multibody.q) + ", expected " + std::to_string(n) + " x " +
            std::to_string(nq) + " (one row per sample, one column per configuration name)");
  check(multibody.zmp_multibody.rows() == n && multibody.zmp_multibody.cols() == 2,
        "zmp_multibody is " + shape(multibody.zmp_multibody) + ", expected " +
            std::to_string(n) + " x 2");
  const bool filtered = multibody.com_filtered.size() > 0;
  check(!filtered || (multibody.com_filtered.rows() == n && multibody.com_filtered.cols() == 3),
        "com_filtered is " + shape(multibody.com_filtered) + ", expected " + std::to_string(n) +
            " x 3 or empty");
  check(filtered ? multibody.zmp_multibody_filtered.rows() == n &&
                       multibody.zmp_multibody_filtered.cols() == 2
                 : multibody.zmp_multibody_filtered.size() == 0,
        "zmp_multibody_filtered is " + shape(multibody.zmp_multibody_filtered) + ", expected " +
            (filtered ? std::to_string(n) + " x 2 (com_filtered is given)"
                      : std::string("empty (com_filtered is empty)")));
  check(multibody.tick_stage_time.size() == 0 ||
            (multibody.tick_stage_time.cols() == 4 &&
             multibody.tick_stage_time.rows() ==
                 static_cast<Eigen::Index>(multibody.tick_nmpc.size())),
        "tick_stage_time is " + shape(multibody.tick_stage_time) + ", expected " +
            std::to_string(multibody.tick_nmpc.size()) + " x 4 (one row per tick_nmpc entry)");
  check(multibody.chain_stage_time.rows() == multibody.chain_time.size() &&
            multibody.chain_stage_time.cols() == 4,
        "chain_stage_time is " + shape(multibody.chain_stage_time) + ", expected " +
            std::to_string(multibody.chain_time.size()) + " x 4 (one row per chain_time entry)");
}

// The multibody replay and the dynamic filter (paper Sec. IV, Fig. 6): the motion sent to the
// robot, the multibody ZMP before and after the filter, and how far they are from the

}  // namespace

void checkRunInputs(const Scenario& scenario, const wpg::WalkResult& result,
                    const FootstepClearances* clearances, const MultibodyRecord* multibody) {
  checkSizes(result.trajectory);
  if (clearances) checkClearanceSizes(*clearances, result.trajectory);
  if (multibody) checkMultibodySizes(multibody->validation, result.trajectory);
  checkGroupName(scenario.name);
}

}  // namespace wpg::datasets::detail
