// Reading a run's joint angles, multibody ZMP, goal and routes for `wpg view`
// (run_scene_reader.hpp). Every size a dataset declares is bounded before anything is
// allocated (hdf5_bounded_reading.hpp), every number checked finite (NaN where the schema says
// "not measured" only), so that a damaged file is one line and exit 2, never a NaN on screen.
#include "wpg/datasets/storage/run_scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <H5Cpp.h>

#include "hdf5_bounded_reading.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets {
namespace {

constexpr hsize_t kMaxConfigurationSize = 1024;  // columns of q: HRP-2 has 37

class SceneReader {
 public:
  SceneReader(std::string path, std::string where) : path_(std::move(path)), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& message) const { throw InputError(path_ + ": " + message); }

  // A float dataset of `rows` rows (0: any number up to `max_rows`) and `columns` columns (0:
  // 1-D; -1: any, returned in *columns_found); finite values.
  std::vector<double> doubles(const H5::Group& group, const std::string& name, hsize_t rows,
                              long columns, hsize_t* columns_found = nullptr,
                              hsize_t* rows_found = nullptr,
                              std::uint64_t max_rows = kMaxStoredSamples) const {
    const std::string what = "dataset " + where_ + name;
    if (group.childObjType(name) != H5O_TYPE_DATASET) fail(where_ + name + " is not a dataset");
    const H5::DataSet dataset = group.openDataSet(name);
    if (dataset.getTypeClass() != H5T_FLOAT) fail(what + " has the wrong type: expected floating-point numbers");
    const std::vector<hsize_t> dims =
        detail::boundedExtent(dataset.getSpace(), sizeof(double), kMaxReadElements, path_, what);
    const std::size_t rank = columns == 0 ? 1 : 2;
    if (dims.size() != rank) fail(what + " has the wrong shape: expected " + std::to_string(rank) + " dimensions");
    if (rows != 0 && dims[0] != rows) {
      fail(what + " has " + std::to_string(dims[0]) + " rows, expected " + std::to_string(rows) +
           " (as its time)");
    }
    if (dims[0] > max_rows) {
      fail(what + " declares " + std::to_string(dims[0]) + " rows: expected at most " +
           std::to_string(max_rows));
    }
    const hsize_t width = rank == 1 ? 1 : dims[1];
    if (columns > 0 && width != static_cast<hsize_t>(columns)) {
      fail(what + " has " + std::to_string(width) + " columns, expected " + std::to_string(columns));
    }
    if (columns < 0 && (width < 1 || width > kMaxConfigurationSize)) {
      fail(what + " has " + std::to_string(width) + " columns, expected 1 to " +
           std::to_string(kMaxConfigurationSize));
    }
    if (columns_found) *columns_found = width;
    if (rows_found) *rows_found = dims[0];
    std::vector<double> values(static_cast<std::size_t>(dims[0] * width));
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) {
        fail(what + " row " + std::to_string(i / width) + " column " + std::to_string(i % width) +
             ": expected a finite number, got " + std::to_string(values[i]));
      }
    }
    return values;
  }

  std::vector<int> integers(const H5::Group& group, const std::string& name, hsize_t rows) const {
    const std::string what = "dataset " + where_ + name;
    if (group.childObjType(name) != H5O_TYPE_DATASET) fail(where_ + name + " is not a dataset");
    const H5::DataSet dataset = group.openDataSet(name);
    if (dataset.getTypeClass() != H5T_INTEGER) fail(what + " has the wrong type: expected integers");
    const std::vector<hsize_t> dims =
        detail::boundedExtent(dataset.getSpace(), sizeof(int), kMaxStoredSamples, path_, what);
    if (dims.size() != 1 || dims[0] != rows) {
      fail(what + " has the wrong shape: expected (" + std::to_string(rows) + ",)");
    }
    std::vector<int> values(static_cast<std::size_t>(rows));
    if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_INT);
    return values;
  }

  // A number attribute; NaN allowed (the schema's "not reached", "no yaw"), infinities not.
  double number(const H5::H5Object& object, const std::string& name, const std::string& where) const {
    const double value = detail::readNumberAttribute(object, name, path_, where);
    if (std::isinf(value)) fail("attribute " + where + name + ": expected a finite number or NaN");
    return value;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string where_;
};

StoredGoalOutcome readGoal(const SceneReader& reader, const H5::Group& run, const std::string& where) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const auto optional = [&](const char* name, double fallback) {
    return run.attrExists(name) ? reader.number(run, name, where) : fallback;
  };
  StoredGoalOutcome goal;
  goal.x = reader.number(run, "goal_x", where);
  goal.y = reader.number(run, "goal_y", where);
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y)) {
    reader.fail("attribute " + where + "goal_x/goal_y: expected finite numbers");
  }
  goal.yaw = optional("goal_yaw", kNaN);
  goal.tolerance = optional("goal_tolerance", 0.0);
  goal.yaw_tolerance = optional("goal_yaw_tolerance", kNaN);
  if (!(goal.tolerance >= 0.0)) reader.fail("attribute " + where + "goal_tolerance: expected a number >= 0");
  goal.reached = optional("goal_reached", 0.0) == 1.0;
  goal.time_to_goal = optional("time_to_goal", kNaN);
  if (run.attrExists("goal_outcome")) {
    goal.outcome = detail::readStringAttribute(run, "goal_outcome", reader.path(), where);
  }
  return goal;
}

// The name of `code` in a `codes` attribute ("0=start, 1=strayed, ..."), or the code itself.
std::string codeName(const std::string& codes, int code) {
  const std::string key = std::to_string(code) + "=";
  std::size_t at = 0;
  while (at < codes.size()) {
    const std::size_t end = std::min(codes.find(", ", at), codes.size());
    if (codes.compare(at, key.size(), key) == 0) return codes.substr(at + key.size(), end - at - key.size());
    at = end + 2;
  }
  return std::to_string(code);
}

std::string codesOf(const std::string& path, const H5::Group& group, const std::string& name,
                    const std::string& where) {
  const H5::DataSet dataset = group.openDataSet(name);
  if (!dataset.attrExists("codes")) return "";
  return detail::readStringAttribute(dataset, "codes", path, where + name + ":");
}

std::vector<StoredRoutePlan> readPlans(const std::string& path, const H5::Group& plans,
                                       const std::string& where) {
  const SceneReader reader(path, where);
  hsize_t p = 0;
  const std::vector<double> times = reader.doubles(plans, "time", 0, 0, nullptr, &p, kMaxStoredPlans);
  const std::vector<int> triggers = reader.integers(plans, "trigger", p);
  const std::vector<int> statuses = reader.integers(plans, "status", p);
  const std::vector<int> starts = reader.integers(plans, "route_start", p);
  const std::vector<int> counts = reader.integers(plans, "route_count", p);
  std::vector<double> planning_times(static_cast<std::size_t>(p), 0.0);
  if (plans.nameExists("planning_time")) planning_times = reader.doubles(plans, "planning_time", p, 0);
  // The OMPL statistics: optional (NaN / -1 when absent).
  const auto optional_doubles = [&](const char* name) {
    return plans.nameExists(name) ? reader.doubles(plans, name, p, 0)
                                  : std::vector<double>(static_cast<std::size_t>(p), StoredRoutePlan::kUnknown);
  };
  const auto optional_counts = [&](const char* name) {
    return plans.nameExists(name) ? reader.integers(plans, name, p)
                                  : std::vector<int>(static_cast<std::size_t>(p), -1);
  };
  const std::vector<double> route_length = optional_doubles("route_length");
  const std::vector<double> solution_length = optional_doubles("solution_length");
  const std::vector<double> simplified_length = optional_doubles("simplified_solution_length");
  const std::vector<double> clearance = optional_doubles("solution_clearance");
  const std::vector<double> simplification_time = optional_doubles("simplification_time");
  const std::vector<int> graph_states = optional_counts("graph_states");
  const std::vector<int> graph_motions = optional_counts("graph_motions");
  hsize_t r = 0;
  const std::vector<double> routes =
      reader.doubles(plans, "routes", 0, 3, nullptr, &r, kMaxStoredRouteWaypoints);
  const std::string trigger_codes = codesOf(path, plans, "trigger", where);
  const std::string status_codes = codesOf(path, plans, "status", where);
  std::vector<StoredRoutePlan> result(static_cast<std::size_t>(p));
  hsize_t next_row = 0;  // each route its own rows, in order, as the writer concatenates them
  for (std::size_t i = 0; i < result.size(); ++i) {
    if (starts[i] < 0 || counts[i] < 0 || static_cast<hsize_t>(starts[i]) != next_row ||
        next_row + static_cast<hsize_t>(counts[i]) > r) {
      reader.fail("dataset " + where + "route_start row " + std::to_string(i) + ": expected " +
                  std::to_string(next_row) + " (the routes' rows in order, each route its own; " +
                  std::to_string(r) + " rows of routes), got start " + std::to_string(starts[i]) +
                  " count " + std::to_string(counts[i]));
    }
    next_row += static_cast<hsize_t>(counts[i]);
    StoredRoutePlan& plan = result[i];
    plan.time = times[i];
    plan.trigger = triggers[i];
    plan.status = statuses[i];
    plan.trigger_name = codeName(trigger_codes, triggers[i]);
    plan.status_name = codeName(status_codes, statuses[i]);
    plan.planning_time = planning_times[i];
    plan.route_length = route_length[i];
    plan.solution_length = solution_length[i];
    plan.simplified_solution_length = simplified_length[i];
    plan.solution_clearance = clearance[i];
    plan.simplification_time = simplification_time[i];
    plan.graph_states = graph_states[i];
    plan.graph_motions = graph_motions[i];
    for (int k = 0; k < counts[i]; ++k) {
      const std::size_t row = static_cast<std::size_t>(starts[i] + k);
      plan.route.emplace_back(routes[3 * row], routes[3 * row + 1], routes[3 * row + 2]);
    }
  }
  return result;
}

StoredRunScene readScene(const std::string& path, const std::string& run_name, std::size_t samples) {
  const H5::H5File file = detail::openFileForReading(path);
  const std::string run_path = "/runs/" + run_name;
  if (!file.nameExists("runs") || !file.openGroup("runs").nameExists(run_name)) {
    throw InputError(path + ": no run " + run_path);
  }
  const H5::Group run = file.openGroup("runs").openGroup(run_name);
  const SceneReader reader(path, run_path + "/");
  const auto rows = static_cast<hsize_t>(samples);
  StoredRunScene scene;
  if (run.nameExists("q")) {
    hsize_t nq = 0;
    scene.q = reader.doubles(run, "q", rows, -1, &nq);
    scene.q_names = detail::readStringListAttribute(run.openDataSet("q"), "names", path, run_path + "/q:");
    if (scene.q_names.size() != nq) {
      reader.fail("attribute " + run_path + "/q:names has " + std::to_string(scene.q_names.size()) +
                  " names, expected one per column (" + std::to_string(nq) + ")");
    }
  }
  if (run.nameExists("zmp_multibody")) scene.zmp_multibody = reader.doubles(run, "zmp_multibody", rows, 2);
  if (run.nameExists("zmp_multibody_filtered")) {
    scene.zmp_multibody_filtered = reader.doubles(run, "zmp_multibody_filtered", rows, 2);
  }
  if (run.nameExists("com_filtered")) scene.com_filtered = reader.doubles(run, "com_filtered", rows, 3);
  if (run.attrExists("goal_x")) scene.goal = readGoal(reader, run, run_path + ":");
  if (run.nameExists("plans") && run.childObjType("plans") == H5O_TYPE_GROUP) {
    scene.plans = readPlans(path, run.openGroup("plans"), run_path + "/plans/");
  }
  return scene;
}

std::vector<StoredRoutePlan> readPlansOf(const std::string& path, const std::string& run_name) {
  const H5::H5File file = detail::openFileForReading(path);
  const std::string run_path = "/runs/" + run_name;
  if (!file.nameExists("runs") || !file.openGroup("runs").nameExists(run_name)) {
    throw InputError(path + ": no run " + run_path);
  }
  const H5::Group run = file.openGroup("runs").openGroup(run_name);
  if (!run.nameExists("plans") || run.childObjType("plans") != H5O_TYPE_GROUP) return {};
  return readPlans(path, run.openGroup("plans"), run_path + "/plans/");
}

}  // namespace

std::vector<StoredRoutePlan> readRoutePlans(const std::string& path, const std::string& run_name) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    return readPlansOf(path, run_name);
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the run file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

StoredRunScene readRunScene(const std::string& path, const std::string& run_name,
                            std::size_t samples) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    return readScene(path, run_name, samples);
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the run file (" + error.getFuncName() + ": " +
                     error.getDetailMsg() + ")");
  }
}

}  // namespace wpg::datasets
