#pragma once
// What each run of a study stores in its batch file: a study's `fields:` list, or `wpg batch
// --fields` (wpg.batch(fields=...)). The names are the groups of the run schema
// (datasets/SCHEMA.md, "Lean runs", where each field's datasets and its size per second of walk
// are listed). A study of 10^5 walks that only needs their footsteps and summary rows stores
// those: about 18 KB a run instead of ~370 KB. Without a `fields:` key every field is stored.
//
// Leaving a field out never changes the others: a lean run's datasets are those of the same
// run stored whole, bit for bit (they are built by the same code; only fewer are built).
#include <string>
#include <vector>

namespace wpg::datasets {

enum class RunField : unsigned {
  kSummary,    // the run's attributes (scenario, outcome, swept values), checks/, its summary row
  kCom,        // time, com, com_vel, com_acc
  kCop,        // time, cop
  kFeet,       // time, left_foot, right_foot, free_flyer_yaw, support
  kFootsteps,  // footsteps, footstep_side, footstep_lift_off
  kMpc,        // mpc/: one row per NMPC iteration (status, cost, slack, ...)
  kPlan,       // mpc/time and mpc/plan/: what each NMPC iteration predicted
  kObstacles,  // obstacles/
  kGoal,       // mpc/command and plans/ of a walk to a goal
  kMultibody,  // q, zmp_multibody, com_filtered, zmp_multibody_filtered, multibody/, timing/
};
constexpr unsigned kRunFieldCount = 10;

// A set of fields; every field by default (a run stored whole).
class RunFields {
 public:
  static RunFields all() { return RunFields((1u << kRunFieldCount) - 1); }
  bool has(RunField field) const { return bits_ & bit(field); }
  bool isAll() const { return bits_ == all().bits_; }
  // Any per-sample field: `time` is stored with it.
  bool hasSamples() const {
    return has(RunField::kCom) || has(RunField::kCop) || has(RunField::kFeet) ||
           has(RunField::kMultibody);
  }
  // The names of the fields held, in the order of runFieldNames().
  std::vector<std::string> names() const;
  // "summary, footsteps" (or "all")
  std::string text() const;
  bool operator==(const RunFields& other) const { return bits_ == other.bits_; }
  bool operator!=(const RunFields& other) const { return bits_ != other.bits_; }

 private:
  explicit RunFields(unsigned bits) : bits_(bits) {}
  static unsigned bit(RunField field) { return 1u << static_cast<unsigned>(field); }
  unsigned bits_;
  friend RunFields parseRunFields(const std::vector<std::string>&, const std::string&);
};

// Every field name, in RunField's order: summary, com, cop, feet, footsteps, mpc, plan,
// obstacles, goal, multibody.
const std::vector<std::string>& runFieldNames();

// The set named by `names` (`all` names every field). Throws InputError, one line starting
// with `where` (e.g. "study.yaml: fields" or "--fields"), for an empty list, a name that is
// not a field (with did-you-mean), a name given twice, and a set without `summary` (the run's
// attributes and its summary row: every batch file's runs have them, `--resume` and `wpg merge`
// read them).
RunFields parseRunFields(const std::vector<std::string>& names, const std::string& where);

// "summary,footsteps" split at its commas (spaces around names ignored), as `--fields` takes it.
std::vector<std::string> splitFieldList(const std::string& text);

}  // namespace wpg::datasets
