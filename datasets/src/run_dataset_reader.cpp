// Reading a run dataset back into a WalkResult (layout: datasets/SCHEMA.md). Strict like the
// scenario reader: a missing dataset, a wrong shape or an unknown code is an InputError naming
// the file and the dataset, never a silently shorter walk.
#include "wpg/datasets/run_dataset_reader.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include <H5Cpp.h>

#include "wpg/datasets/run_dataset.hpp"

namespace wpg::datasets {
namespace {

namespace fs = std::filesystem;

class Reader {
 public:
  Reader(std::string path, const H5::Group& run, std::string run_path)
      : path_(std::move(path)), run_(run), run_path_(std::move(run_path)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(path_ + ": " + message);
  }

  // The dataset `name` (below the run group) with `columns` columns (0: 1-D), of type class
  // `type_class`; returns its rows.
  H5::DataSet open(const std::string& name, hsize_t columns, H5T_class_t type_class,
                   hsize_t* rows) const {
    const std::string where = run_path_ + "/" + name;
    if (!run_.nameExists(name)) fail("dataset " + where + " is missing");
    if (run_.childObjType(name) != H5O_TYPE_DATASET) fail(where + " is not a dataset");
    H5::DataSet dataset = run_.openDataSet(name);
    const H5::DataSpace space = dataset.getSpace();
    const int rank = space.getSimpleExtentNdims();
    hsize_t dims[2] = {0, 0};
    if (rank == (columns == 0 ? 1 : 2)) space.getSimpleExtentDims(dims);
    if (rank != (columns == 0 ? 1 : 2) || (columns != 0 && dims[1] != columns)) {
      fail("dataset " + where + " has the wrong shape: expected " +
           (columns == 0 ? std::string("(n,)") : "(n, " + std::to_string(columns) + ")"));
    }
    if (dataset.getTypeClass() != type_class) {
      fail("dataset " + where + " has the wrong type: expected " +
           (type_class == H5T_FLOAT ? "floating-point numbers" : "integers"));
    }
    *rows = dims[0];
    return dataset;
  }

  std::vector<double> doubles(const std::string& name, hsize_t columns, hsize_t* rows) const {
    H5::DataSet dataset = open(name, columns, H5T_FLOAT, rows);
    std::vector<double> values(*rows * (columns == 0 ? 1 : columns));
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    return values;
  }

  std::vector<int> integers(const std::string& name, hsize_t* rows) const {
    H5::DataSet dataset = open(name, 0, H5T_INTEGER, rows);
    std::vector<int> values(*rows);
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_INT);
    return values;
  }

  // Integers in [low, high], one per row, exactly `expected_rows` of them.
  std::vector<int> codes(const std::string& name, hsize_t expected_rows, int low, int high) const {
    hsize_t rows = 0;
    std::vector<int> values = integers(name, &rows);
    expectRows(name, rows, expected_rows);
    for (const int value : values) {
      if (value < low || value > high) {
        fail("dataset " + run_path_ + "/" + name + " holds the code " + std::to_string(value) +
             ", expected " + std::to_string(low) + " to " + std::to_string(high));
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
    if (!object.attrExists(name)) fail("attribute " + where + name + " is missing");
    const H5::Attribute attribute = object.openAttribute(name);
    if (attribute.getTypeClass() != H5T_STRING) fail("attribute " + where + name + " is not a string");
    std::string value;
    attribute.read(attribute.getStrType(), value);
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

StoredRun readFile(const std::string& path, const std::string& run_name) {
  if (!H5::H5File::isHdf5(path)) throw InputError(path + ": not an HDF5 file");
  H5::H5File file(path, H5F_ACC_RDONLY);
  StoredRun stored;
  // A batch file (`wpg batch`) has no root `scenario`: each run group carries its own.
  const bool root_scenario = file.attrExists("scenario");
  if (!root_scenario && !file.attrExists("study")) {
    throw InputError(path + ": root attribute 'scenario' is missing (not a run dataset?)");
  }
  if (root_scenario) {
    const H5::Attribute attribute = file.openAttribute("scenario");
    if (attribute.getTypeClass() != H5T_STRING) {
      throw InputError(path + ": root attribute 'scenario' is not a string");
    }
    attribute.read(attribute.getStrType(), stored.scenario_yaml);
  }
  if (!file.nameExists("runs") || file.childObjType("runs") != H5O_TYPE_GROUP) {
    throw InputError(path + ": no group /runs (not a run dataset?)");
  }
  const H5::Group runs = file.openGroup("runs");
  const std::vector<std::string> names = runGroupNames(runs);
  std::string all;
  for (const std::string& name : names) all += (all.empty() ? "" : ", ") + name;
  if (run_name.empty()) {
    if (names.size() != 1) {
      throw InputError(path + ": expected one run under /runs, got " +
                       std::to_string(names.size()) + (all.empty() ? "" : " (" + all + ")"));
    }
    stored.name = names.front();
  } else {
    if (!runs.nameExists(run_name) || runs.childObjType(run_name) != H5O_TYPE_GROUP) {
      throw InputError(path + ": no run /runs/" + run_name + " (runs: " +
                       (all.empty() ? std::string("none") : all) + ")");
    }
    stored.name = run_name;
  }
  const std::string run_path = "/runs/" + stored.name;
  const H5::Group run = runs.openGroup(stored.name);
  const Reader reader(path, run, run_path);

  if (run.attrExists("scenario")) {
    stored.scenario_yaml = reader.stringAttribute(run, "scenario", run_path + ":");
  } else if (!root_scenario) {
    reader.fail("attribute " + run_path + ":scenario is missing (a batch file's run)");
  }
  stored.robot = reader.stringAttribute(run, "robot", run_path + ":");
  if (run.nameExists("multibody") && run.childObjType("multibody") == H5O_TYPE_GROUP) {
    const H5::Group multibody = run.openGroup("multibody");
    const auto number = [&](const char* name) {
      double value = std::numeric_limits<double>::quiet_NaN();
      if (multibody.attrExists(name)) {
        multibody.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &value);
      }
      return value;
    };
    StoredZmpError zmp;
    int filtered = 0;
    if (multibody.attrExists("filtered")) {
      multibody.openAttribute("filtered").read(H5::PredType::NATIVE_INT, &filtered);
    }
    zmp.filtered = filtered != 0;
    zmp.rms_before = number("zmp_error_rms_before");
    zmp.max_before = number("zmp_error_max_before");
    zmp.rms_after = number("zmp_error_rms_after");
    zmp.max_after = number("zmp_error_max_after");
    stored.zmp_error = zmp;
  }
  if (run.attrExists("message")) stored.result.message = reader.stringAttribute(run, "message", run_path + ":");
  if (run.attrExists("success")) {
    int success = 1;
    run.openAttribute("success").read(H5::PredType::NATIVE_INT, &success);
    stored.result.success = success != 0;
  }

  WalkTrajectory& t = stored.result.trajectory;
  hsize_t n = 0, rows = 0;
  t.time = reader.doubles("time", 0, &n);
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
  for (hsize_t j = 0; j < m; ++j) {
    Footstep step;
    step.landing_time = footsteps[4 * j];
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
  const std::vector<double> time = log_reader.doubles("time", 0, &k);
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
  if (!mpc.nameExists("slack")) log_reader.fail("dataset " + run_path + "/mpc/slack is missing");
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
  const std::vector<int> qp_iterations = log_reader.integers("qp_iterations", &rows);
  log_reader.expectRows("qp_iterations", rows, k);
  const std::vector<int> sqp_iterations = log_reader.integers("sqp_iterations", &rows);
  log_reader.expectRows("sqp_iterations", rows, k);
  const std::vector<int> status = log_reader.codes("status", k, 0, 255);
  for (hsize_t i = 0; i < k; ++i) {
    if (std::strcmp(iterationStatusName(static_cast<IterationStatus>(status[i])), "unknown") == 0) {
      log_reader.fail("dataset " + run_path + "/mpc/status holds the unknown code " +
                      std::to_string(status[i]));
    }
    MpcIterationLog row;
    row.time = time[i];
    row.solve_time = solve_time[i];
    row.qp_iterations = qp_iterations[i];
    row.sqp_iterations = sqp_iterations[i];
    row.status = static_cast<IterationStatus>(status[i]);
    row.cost = cost[i];
    for (std::size_t f = 0; f < families; ++f) row.slack[f] = slack[i * families + f];
    row.relaxed_families = static_cast<std::uint32_t>(relaxed[i]);
    t.mpc.push_back(row);
  }
  return stored;
}

}  // namespace

namespace {

void checkReadable(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": cannot read the run file: no such file");
  if (fs::is_directory(path, ec)) {
    throw InputError(path + ": cannot read the run file: it is a directory");
  }
  if (!std::ifstream(path).good()) {
    throw InputError(path + ": cannot read the run file: permission denied");
  }
}

}  // namespace

std::vector<std::string> listRuns(const std::string& path) {
  checkReadable(path);
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    if (!H5::H5File::isHdf5(path)) throw InputError(path + ": not an HDF5 file");
    H5::H5File file(path, H5F_ACC_RDONLY);
    if (!file.nameExists("runs") || file.childObjType("runs") != H5O_TYPE_GROUP) {
      throw InputError(path + ": no group /runs (not a run or batch dataset?)");
    }
    std::vector<std::string> names = runGroupNames(file.openGroup("runs"));
    std::sort(names.begin(), names.end());
    return names;
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

StoredRun readRunDataset(const std::string& path, const std::string& run_name) {
  checkReadable(path);
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    return readFile(path, run_name);
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the run file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

}  // namespace wpg::datasets
