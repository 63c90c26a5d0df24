// Reading a run dataset back into a WalkResult (layout: datasets/SCHEMA.md). Strict like the
// scenario reader: a missing dataset, a wrong shape, a size beyond the readers' limits (checked
// before anything is allocated, read_limits.hpp), a number that is not finite, a time that does
// not increase or an unknown code is an InputError naming the file, the dataset and the row,
// never a silently shorter or corrupt walk.
#include "wpg/datasets/storage/run_dataset_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include <H5Cpp.h>

#include "external_link_guard.hpp"

#include "hdf5_bounded_reading.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets {
namespace {


class Reader {
 public:
  Reader(std::string path, const H5::Group& run, std::string run_path)
      : path_(std::move(path)), run_(run), run_path_(std::move(run_path)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(path_ + ": " + message);
  }

  // The dataset `name` (below the run group) with `columns` columns (0: 1-D), of type class
  // `type_class`, at most `max_rows` rows; returns its rows. Only the dataspace is read.
  H5::DataSet open(const std::string& name, hsize_t columns, H5T_class_t type_class,
                   hsize_t* rows, hsize_t max_rows = kMaxStoredSamples) const {
    const std::string where = "dataset " + run_path_ + "/" + name;
    if (!run_.nameExists(name)) fail(where + " is missing");
    if (run_.childObjType(name) != H5O_TYPE_DATASET) fail(run_path_ + "/" + name + " is not a dataset");
    H5::DataSet dataset = run_.openDataSet(name);
    const std::string expected =
        columns == 0 ? std::string("(n,)") : "(n, " + std::to_string(columns) + ")";
    // The rank first, then the dimensions into a fixed array: nothing sized by the file.
    const H5::DataSpace space = dataset.getSpace();
    const int rank = columns == 0 ? 1 : 2;
    hsize_t dims[2] = {0, 0};
    if (space.getSimpleExtentType() != H5S_SIMPLE || space.getSimpleExtentNdims() != rank) {
      fail(where + " has the wrong shape: expected " + expected);
    }
    space.getSimpleExtentDims(dims);
    if (columns != 0 && dims[1] != columns) fail(where + " has the wrong shape: expected " + expected);
    if (dims[0] > max_rows) {
      fail(where + " declares " + std::to_string(dims[0]) + " rows: expected at most " +
           std::to_string(max_rows) +
           (max_rows == kMaxStoredSamples ? " (3600 s at 5 ms, datasets/SCHEMA.md, Reading)"
                                          : " (datasets/SCHEMA.md, Reading)"));
    }
    if (dataset.getTypeClass() != type_class) {
      fail(where + " has the wrong type: expected " +
           (type_class == H5T_FLOAT ? "floating-point numbers" : "integers"));
    }
    *rows = dims[0];
    return dataset;
  }

  // Finite numbers only: a NaN or an infinity would be copied into every later output.
  std::vector<double> doubles(const std::string& name, hsize_t columns, hsize_t* rows,
                              hsize_t max_rows = kMaxStoredSamples) const {
    H5::DataSet dataset = open(name, columns, H5T_FLOAT, rows, max_rows);
    const std::size_t width = columns == 0 ? 1 : static_cast<std::size_t>(columns);
    std::vector<double> values(static_cast<std::size_t>(*rows) * width);
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) {
        fail("dataset " + run_path_ + "/" + name + " row " + std::to_string(i / width) +
             (columns == 0 ? std::string() : " column " + std::to_string(i % width)) +
             ": expected a finite number, got " + std::to_string(values[i]));
      }
    }
    return values;
  }

  // A time column: finite (doubles) and strictly increasing.
  std::vector<double> times(const std::string& name, hsize_t* rows) const {
    std::vector<double> values = doubles(name, 0, rows);
    for (std::size_t i = 1; i < values.size(); ++i) {
      if (!(values[i] > values[i - 1])) {
        fail("dataset " + run_path_ + "/" + name + " row " + std::to_string(i) +
             ": expected strictly increasing times, got " + std::to_string(values[i]) +
             " s after " + std::to_string(values[i - 1]) + " s");
      }
    }
    return values;
  }

  // `columns` integers a row (0: 1-D).
  std::vector<int> integers(const std::string& name, hsize_t* rows, hsize_t columns = 0,
                            hsize_t max_rows = kMaxStoredSamples) const {
    H5::DataSet dataset = open(name, columns, H5T_INTEGER, rows, max_rows);
    std::vector<int> values(static_cast<std::size_t>(*rows) * std::max<hsize_t>(columns, 1));
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_INT);
    return values;
  }

  // Counts: integers >= 0, exactly `expected_rows` of them.
  std::vector<int> counts(const std::string& name, hsize_t expected_rows) const {
    hsize_t rows = 0;
    std::vector<int> values = integers(name, &rows);
    expectRows(name, rows, expected_rows);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] < 0) {
        fail("dataset " + run_path_ + "/" + name + " row " + std::to_string(i) +
             ": expected a count >= 0, got " + std::to_string(values[i]));
      }
    }
    return values;
  }

  // Integers in [low, high], one per row, exactly `expected_rows` of them.
  std::vector<int> codes(const std::string& name, hsize_t expected_rows, int low, int high,
                         hsize_t max_rows = kMaxStoredSamples) const {
    hsize_t rows = 0;
    std::vector<int> values = integers(name, &rows, 0, max_rows);
    expectRows(name, rows, expected_rows);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] < low || values[i] > high) {
        fail("dataset " + run_path_ + "/" + name + " row " + std::to_string(i) +
             " holds the code " + std::to_string(values[i]) + ", expected " +
             std::to_string(low) + " to " + std::to_string(high));
      }
    }
    return values;
  }

  void expectRows(const std::string& name, hsize_t rows, hsize_t expected) const {
    if (rows != expected) {
      fail("dataset " + run_path_ + "/" + name + " has " + std::to_string(rows) +
           " rows, expected " + std::to_string(expected) + " (as its time)");
    }
  }

  std::string stringAttribute(const H5::H5Object& object, const std::string& name,
                              const std::string& where) const {
    return detail::readStringAttribute(object, name, path_, where);
  }

  double numberAttribute(const H5::H5Object& object, const std::string& name,
                         const std::string& where) const {
    const double value = detail::readNumberAttribute(object, name, path_, where);
    if (std::isnan(value)) return value;  // NaN: not measured (SCHEMA.md)
    if (!std::isfinite(value)) {
      fail("attribute " + where + name + ": expected a finite number or NaN, got " +
           std::to_string(value));
    }
    return value;
  }

 private:
  std::string path_;
  const H5::Group& run_;
  std::string run_path_;
};

template <int Size>
std::vector<Eigen::Matrix<double, Size, 1>> rowsOf(const std::vector<double>& values) {
  std::vector<Eigen::Matrix<double, Size, 1>> rows(values.size() / Size);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i] = Eigen::Map<const Eigen::Matrix<double, Size, 1>>(values.data() + Size * i);
  }
  return rows;
}

// mpc/plan/ (datasets/SCHEMA.md), when the walk recorded it, into `plans`: k iterations of N
// previewed samples and nf previewed steps. The sizes come from the attributes, bounded
// (read_limits.hpp) before any dataset is opened; every dataset must have exactly its rows.
void readPlans(const std::string& path, const H5::Group& mpc, const std::string& mpc_path,
               hsize_t k, std::size_t families, PlanLog& plans) {
  if (!mpc.nameExists("plan")) return;
  if (mpc.childObjType("plan") != H5O_TYPE_GROUP) {
    throw InputError(path + ": " + mpc_path + "/plan is not a group");
  }
  const H5::Group group = mpc.openGroup("plan");
  const std::string where = mpc_path + "/plan";
  const Reader reader(path, group, where);
  const auto bounded = [&](const char* name, std::uint64_t low, std::uint64_t high) {
    const double value = detail::readNumberAttribute(group, name, path, where + ":");
    if (!(value >= static_cast<double>(low) && value <= static_cast<double>(high)) ||
        value != std::floor(value)) {
      reader.fail("attribute " + where + ":" + name + ": expected an integer in [" +
                  std::to_string(low) + ", " + std::to_string(high) + "], got " +
                  std::to_string(value));
    }
    return static_cast<hsize_t>(value);
  };
  const hsize_t n = bounded("samples", 1, kMaxStoredPlanSamples);
  const hsize_t nf = bounded("steps", 1, kMaxStoredPlanSteps);
  const double period = detail::readNumberAttribute(group, "sampling_period", path, where + ":");
  if (!(period > 0.0 && std::isfinite(period))) {
    reader.fail("attribute " + where + ":sampling_period: expected a positive number of seconds");
  }
  if (k * n * 4 > kMaxReadElements) {
    reader.fail(where + ": " + std::to_string(k) + " iterations of " + std::to_string(n) +
                " samples: expected at most " + std::to_string(kMaxReadElements / 4) +
                " previewed samples in all (datasets/SCHEMA.md, Reading)");
  }
  const auto exactly = [&](const char* name, hsize_t rows, hsize_t expected, const char* per) {
    if (rows != expected) {
      reader.fail("dataset " + where + "/" + name + " has " + std::to_string(rows) +
                  " rows, expected " + std::to_string(expected) + " (" + per + ")");
    }
  };
  plans.max_samples = static_cast<int>(n);
  plans.steps = static_cast<int>(nf);
  plans.sampling_period = period;
  plans.samples = reader.codes("sample_count", k, 0, static_cast<int>(n));
  hsize_t rows = 0;
  const auto per_sample = [&](const char* name) {
    std::vector<double> values = reader.doubles(name, 2, &rows, k * n);
    exactly(name, rows, k * n, "mpc iterations x samples");
    return values;
  };
  plans.com_position = per_sample("com");
  plans.com_velocity = per_sample("com_vel");
  plans.com_acceleration = per_sample("com_acc");
  plans.jerk = per_sample("jerk");
  plans.cop = per_sample("cop");
  plans.step = reader.doubles("steps", 4, &rows, k * nf);
  exactly("steps", rows, k * nf, "mpc iterations x steps");
  for (const int side : reader.codes("step_side", k * nf, 0, 2, k * nf))
    plans.step_side.push_back(static_cast<std::uint8_t>(side));
  plans.families = 0;
  if (group.nameExists("active_rows") && families > 0) {
    std::vector<int> active = reader.integers("active_rows", &rows, families, k);
    exactly("active_rows", rows, k, "mpc iterations");
    for (std::size_t i = 0; i < active.size(); ++i) {
      if (active[i] < 0) {
        reader.fail("dataset " + where + "/active_rows row " + std::to_string(i / families) +
                    ": expected a count >= 0, got " + std::to_string(active[i]));
      }
    }
    plans.families = static_cast<int>(families);
    plans.active_rows = std::move(active);
  }
}

// The groups under /runs, and the external links of the index of a sharded batch
// (batch_index.hpp), taken for the runs they name without following them: following one opens
// its shard; the run read is checked when it is opened. One pass of H5Literate: a group that
// holds external links has HDF5's new-style link storage, where getObjnameByIdx sorts every
// link again at each call (measured: `wpg analyze` of a 200-run index 6x slower than of the
// same runs in one file, listing the runs at each run read).
std::vector<std::string> runGroupNames(const H5::Group& runs) {
  std::vector<std::string> names;
  hsize_t position = 0;
  H5Literate(
      runs.getId(), H5_INDEX_NAME, H5_ITER_INC, &position,
      [](hid_t group, const char* name, const H5L_info_t* link, void* data) -> herr_t {
        H5O_info_t object;
        if (link->type == H5L_TYPE_EXTERNAL ||
            (H5Oget_info_by_name(group, name, &object, H5P_DEFAULT) >= 0 &&
             object.type == H5O_TYPE_GROUP)) {
          static_cast<std::vector<std::string>*>(data)->push_back(name);
        }
        return 0;
      },
      &names);
  return names;
}

// A lean run (a study's `fields:`, datasets/SCHEMA.md "Lean runs") names its fields in the
// attribute `fields`; reading it as a walk needs the per-sample fields, the footsteps and the
// NMPC log. Said in one line, with what it lacks, rather than "dataset com is missing".
void checkWholeWalkStored(const std::string& path, const H5::Group& run,
                          const std::string& run_path) {
  if (!run.attrExists("fields")) return;  // every field
  const std::vector<std::string> held =
      detail::readStringListAttribute(run, "fields", path, run_path + ":");
  std::string lacks, has;
  for (const char* needed : {"com", "cop", "feet", "footsteps", "mpc"}) {
    if (std::find(held.begin(), held.end(), needed) == held.end()) {
      lacks += (lacks.empty() ? "" : ", ") + std::string(needed);
    }
  }
  if (lacks.empty()) return;
  for (const std::string& name : held) has += (has.empty() ? "" : ", ") + name;
  throw InputError(path + ": run " + run_path + " is a lean run (fields " + has + "): it lacks " +
                   lacks + ", which reading its walk needs; read its summary row "
                   "(wpg.io.load_summary) or its fields with h5py (datasets/SCHEMA.md, \"Lean "
                   "runs\")");
}

StoredRun readFile(const std::string& path, const std::string& run_name) {
  H5::H5File file = detail::openFileForReading(path);
  StoredRun stored;
  // A batch file (`wpg batch`) has no root `scenario`: each run group carries its own.
  const bool root_scenario = file.attrExists("scenario");
  if (!root_scenario && !file.attrExists("study")) {
    throw InputError(path + ": root attribute 'scenario' is missing (not a run dataset?)");
  }
  if (root_scenario) stored.scenario_yaml = detail::readStringAttribute(file, "scenario", path, "/:");
  if (!file.nameExists("runs") || file.childObjType("runs") != H5O_TYPE_GROUP) {
    throw InputError(path + ": no group /runs (not a run dataset?)");
  }
  const H5::Group runs = file.openGroup("runs");
  // The runs are listed only when no run is named, or for the message when the named one is
  // missing: a study's reader reads each of its N runs by name, and listing N runs at each
  // read made reading a study quadratic (2000 runs: 117 s for `wpg analyze`).
  const auto first_names = [&](const std::vector<std::string>& names) {
    std::string all;
    for (std::size_t i = 0; i < names.size() && i < 10; ++i) all += (i ? ", " : "") + names[i];
    if (names.size() > 10) all += ", ...";
    return all;
  };
  if (run_name.empty()) {
    const std::vector<std::string> names = runGroupNames(runs);
    if (names.size() != 1) {
      const std::string all = first_names(names);
      throw InputError(path + ": expected one run under /runs, got " +
                       std::to_string(names.size()) + (all.empty() ? "" : " (" + all + ")"));
    }
    stored.name = names.front();
  } else {
    if (!runs.nameExists(run_name) || runs.childObjType(run_name) != H5O_TYPE_GROUP) {
      const std::string all = first_names(runGroupNames(runs));
      throw InputError(path + ": no run /runs/" + run_name + " (runs: " +
                       (all.empty() ? std::string("none") : all) + ")");
    }
    stored.name = run_name;
  }
  const std::string run_path = "/runs/" + stored.name;
  const H5::Group run = runs.openGroup(stored.name);
  const Reader reader(path, run, run_path);
  checkWholeWalkStored(path, run, run_path);

  if (run.attrExists("scenario")) {
    stored.scenario_yaml = reader.stringAttribute(run, "scenario", run_path + ":");
  } else if (!root_scenario) {
    reader.fail("attribute " + run_path + ":scenario is missing (a batch file's run)");
  }
  stored.robot = reader.stringAttribute(run, "robot", run_path + ":");
  if (run.nameExists("multibody") && run.childObjType("multibody") == H5O_TYPE_GROUP) {
    const H5::Group multibody = run.openGroup("multibody");
    const std::string where = run_path + "/multibody:";
    const auto number = [&](const char* name) {
      return multibody.attrExists(name) ? reader.numberAttribute(multibody, name, where)
                                        : std::numeric_limits<double>::quiet_NaN();
    };
    StoredZmpError zmp;
    zmp.filtered = multibody.attrExists("filtered") &&
                   detail::readNumberAttribute(multibody, "filtered", path, where) != 0.0;
    zmp.rms_before = number("zmp_error_rms_before");
    zmp.max_before = number("zmp_error_max_before");
    zmp.rms_after = number("zmp_error_rms_after");
    zmp.max_after = number("zmp_error_max_after");
    stored.zmp_error = zmp;
  }
  if (run.attrExists("message")) stored.result.message = reader.stringAttribute(run, "message", run_path + ":");
  if (run.attrExists("success")) {
    stored.result.success = detail::readNumberAttribute(run, "success", path, run_path + ":") != 0.0;
  }
  // Stuck is an outcome (SCHEMA.md): absent from files written before it was judged (read as
  // not blocked, the whole walk's ratio not known).
  if (run.attrExists("blocked")) {
    stored.result.blocked =
        detail::readNumberAttribute(run, "blocked", path, run_path + ":") != 0.0;
  }
  if (stored.result.blocked) {
    const auto finite = [&](const char* name) {
      if (!run.attrExists(name)) {
        reader.fail("attribute " + run_path + ":" + name + " is missing (blocked is 1)");
      }
      const double value = reader.numberAttribute(run, name, run_path + ":");
      if (!std::isfinite(value)) {
        reader.fail("attribute " + run_path + ":" + name + ": expected a finite number, got nan");
      }
      return value;
    };
    stored.result.blocked_since = finite("blocked_since");
    stored.result.blocked_position = Eigen::Vector2d(finite("blocked_x"), finite("blocked_y"));
  }
  stored.result.progress_ratio = run.attrExists("progress_ratio")
                                     ? reader.numberAttribute(run, "progress_ratio", run_path + ":")
                                     : std::numeric_limits<double>::quiet_NaN();

  WalkTrajectory& t = stored.result.trajectory;
  hsize_t n = 0, rows = 0;
  t.time = reader.times("time", &n);
  if (n < 1) reader.fail("dataset " + run_path + "/time is empty");
  const auto samples = [&](const char* name, hsize_t columns) {
    std::vector<double> values = reader.doubles(name, columns, &rows);
    reader.expectRows(name, rows, n);
    return values;
  };
  t.com = rowsOf<3>(samples("com", 3));
  t.com_vel = rowsOf<3>(samples("com_vel", 3));
  t.com_acc = rowsOf<3>(samples("com_acc", 3));
  t.cop = rowsOf<2>(samples("cop", 2));
  t.left_foot = rowsOf<4>(samples("left_foot", 4));
  t.right_foot = rowsOf<4>(samples("right_foot", 4));
  t.free_flyer_yaw = samples("free_flyer_yaw", 0);
  for (const int code : reader.codes("support", n, 0, 2)) {
    t.support.push_back(static_cast<SupportState>(code));
  }

  hsize_t m = 0;
  const std::vector<double> footsteps = reader.doubles("footsteps", 4, &m);
  const std::vector<int> sides = reader.codes("footstep_side", m, 1, 2);
  // Files written before the step timing was recorded have no lift-off times: NaN.
  std::vector<double> lift_off(m, std::numeric_limits<double>::quiet_NaN());
  if (run.nameExists("footstep_lift_off")) {
    hsize_t rows = 0;
    lift_off = reader.doubles("footstep_lift_off", 0, &rows);
    reader.expectRows("footstep_lift_off", rows, m);
  }
  for (hsize_t j = 0; j < m; ++j) {
    Footstep step;
    step.landing_time = footsteps[4 * j];
    step.lift_off_time = lift_off[j];
    step.pose = Eigen::Vector3d(footsteps[4 * j + 1], footsteps[4 * j + 2], footsteps[4 * j + 3]);
    step.side = static_cast<FootSide>(sides[j]);
    t.footsteps.push_back(step);
  }

  if (!run.nameExists("mpc") || run.childObjType("mpc") != H5O_TYPE_GROUP) {
    reader.fail("group " + run_path + "/mpc is missing");
  }
  const H5::Group mpc = run.openGroup("mpc");
  const Reader log_reader(path, mpc, run_path + "/mpc");
  hsize_t k = 0;
  const std::vector<double> time = log_reader.times("time", &k);
  const auto per_iteration = [&](const char* name) {
    std::vector<double> values = log_reader.doubles(name, 0, &rows);
    log_reader.expectRows(name, rows, k);
    return values;
  };
  const std::vector<double> solve_time = per_iteration("solve_time");
  const std::vector<double> cost = per_iteration("cost");
  // slack: one column per constraint family, named by its `columns` attribute (with `units`
  // and `groups` in the same order)
  const auto split = [](const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find(", ", start), text.size());
      items.push_back(text.substr(start, end - start));
      start = end + 2;
    }
    return items;
  };
  if (!mpc.nameExists("slack") || mpc.childObjType("slack") != H5O_TYPE_DATASET) {
    log_reader.fail("dataset " + run_path + "/mpc/slack is missing");
  }
  const H5::DataSet slack_set = mpc.openDataSet("slack");
  const std::string where = run_path + "/mpc/slack ";
  const std::vector<std::string> columns = split(log_reader.stringAttribute(slack_set, "columns", where));
  const std::vector<std::string> units = split(log_reader.stringAttribute(slack_set, "units", where));
  const std::vector<std::string> groups = split(log_reader.stringAttribute(slack_set, "groups", where));
  if (columns.size() > static_cast<std::size_t>(kMaxConstraintFamilies) ||
      units.size() != columns.size() || groups.size() != columns.size()) {
    log_reader.fail("dataset " + run_path + "/mpc/slack: expected 1 to " +
                    std::to_string(kMaxConstraintFamilies) +
                    " columns with as many units and groups");
  }
  const std::size_t families = columns.size();
  std::vector<double> slack = log_reader.doubles("slack", families, &rows);
  log_reader.expectRows("slack", rows, k);
  if (!(families == 1 && columns[0] == "unknown")) {
    for (std::size_t f = 0; f < families; ++f)
      t.constraint_families.push_back({columns[f], units[f], groups[f]});
  }
  const std::vector<int> relaxed = log_reader.codes("relaxed_families", k, 0, 255);
  const std::vector<int> qp_iterations = log_reader.counts("qp_iterations", k);
  const std::vector<int> sqp_iterations = log_reader.counts("sqp_iterations", k);
  const std::vector<int> status = log_reader.codes("status", k, 0, 255);
  for (hsize_t i = 0; i < k; ++i) {
    if (std::strcmp(iterationStatusName(static_cast<IterationStatus>(status[i])), "unknown") == 0) {
      log_reader.fail("dataset " + run_path + "/mpc/status row " + std::to_string(i) +
                      " holds the unknown code " + std::to_string(status[i]));
    }
    MpcIterationLog row;
    row.time = time[i];
    row.solve_time = solve_time[i];
    row.qp_iterations = qp_iterations[i];
    row.sqp_iterations = sqp_iterations[i];
    row.status = static_cast<IterationStatus>(status[i]);
    row.cost = cost[i];
    for (std::size_t f = 0; f < families; ++f) row.slack[f] = slack[i * families + f];
    if (relaxed[i] >> families != 0) {
      log_reader.fail("dataset " + run_path + "/mpc/relaxed_families row " + std::to_string(i) +
                      ": expected bits of the " + std::to_string(families) +
                      " slack columns only, got " + std::to_string(relaxed[i]));
    }
    row.relaxed_families = static_cast<std::uint32_t>(relaxed[i]);
    row.command.setConstant(std::numeric_limits<double>::quiet_NaN());  // unless stored
    row.commanded_velocity.setConstant(std::numeric_limits<double>::quiet_NaN());  // likewise
    t.mpc.push_back(row);
  }
  if (mpc.nameExists("command")) {  // a walk to a goal: the path follower's commands
    const std::vector<double> command = log_reader.doubles("command", 3, &rows);
    log_reader.expectRows("command", rows, k);
    for (hsize_t i = 0; i < k; ++i) {
      t.mpc[i].command = Eigen::Map<const Eigen::Vector3d>(command.data() + 3 * i);
    }
  }
  if (mpc.nameExists("commanded_velocity")) {  // absent from files written before it was
    const std::vector<double> velocity = log_reader.doubles("commanded_velocity", 2, &rows);
    log_reader.expectRows("commanded_velocity", rows, k);
    for (hsize_t i = 0; i < k; ++i) {
      t.mpc[i].commanded_velocity = Eigen::Map<const Eigen::Vector2d>(velocity.data() + 2 * i);
    }
  }
  readPlans(path, mpc, run_path + "/mpc", k, t.constraint_families.size(), t.plans);
  return stored;
}

}  // namespace

std::vector<std::string> listRuns(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    H5::H5File file = detail::openFileForReading(path);
    if (!file.nameExists("runs") || file.childObjType("runs") != H5O_TYPE_GROUP) {
      throw InputError(path + ": no group /runs (not a run or batch dataset?)");
    }
    std::vector<std::string> names = runGroupNames(file.openGroup("runs"));
    std::sort(names.begin(), names.end());
    return names;
  } catch (const H5::Exception& error) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
    throw InputError(path + ": cannot read the file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

StoredRun readRunDataset(const std::string& path, const std::string& run_name) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    return readFile(path, run_name);
  } catch (const H5::Exception& error) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
    throw InputError(path + ": cannot read the run file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

}  // namespace wpg::datasets
