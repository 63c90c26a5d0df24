// The runs of a comparison study file read back (wpg/datasets/storage/comparison_runs.hpp).
#include "wpg/datasets/storage/comparison_runs.hpp"

#include <mutex>

#include <H5Cpp.h>

#include "external_link_guard.hpp"
#include "hdf5_bounded_reading.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets {
namespace {

constexpr const char* kSummary = "batch/summary";

// A 1-D dataset of at most `max_rows` rows, bounded before anything is allocated.
hsize_t rowsOf(const H5::DataSet& dataset, std::size_t element_size, std::uint64_t max_rows,
               const std::string& path, const std::string& where) {
  const std::vector<hsize_t> dims =
      detail::boundedExtent(dataset.getSpace(), element_size, max_rows, path, "dataset " + where);
  if (dims.size() != 1) throw InputError(path + ": dataset " + where + ": expected one column");
  return dims[0];
}

std::vector<double> numbers(const H5::Group& group, const std::string& name, hsize_t expected,
                            const std::string& path, const std::string& where) {
  if (!group.nameExists(name) || group.childObjType(name) != H5O_TYPE_DATASET) {
    throw InputError(path + ": dataset " + where + "/" + name +
                     " is missing: expected the study file of `wpg compare`");
  }
  const H5::DataSet dataset = group.openDataSet(name);
  const hsize_t rows = rowsOf(dataset, sizeof(double), kMaxStoredSamples, path, where + "/" + name);
  if (expected != static_cast<hsize_t>(-1) && rows != expected) {
    throw InputError(path + ": dataset " + where + "/" + name + ": expected " +
                     std::to_string(expected) + " rows, got " + std::to_string(rows));
  }
  const H5T_class_t type = dataset.getTypeClass();
  if (type != H5T_FLOAT && type != H5T_INTEGER) {
    throw InputError(path + ": dataset " + where + "/" + name + ": expected numbers");
  }
  std::vector<double> values(rows);
  if (rows > 0) dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
  return values;
}

std::vector<std::string> strings(const H5::Group& group, const std::string& name, hsize_t expected,
                                 const std::string& path) {
  const std::string where = std::string(kSummary) + "/" + name;
  if (!group.nameExists(name) || group.childObjType(name) != H5O_TYPE_DATASET) {
    throw InputError(path + ": dataset /" + where +
                     " is missing: expected the study file of `wpg compare`");
  }
  const H5::DataSet dataset = group.openDataSet(name);
  const hsize_t rows = rowsOf(dataset, sizeof(char*), kMaxReadElements, path, "/" + where);
  if (rows != expected || dataset.getTypeClass() != H5T_STRING) {
    throw InputError(path + ": dataset /" + where + ": expected " + std::to_string(expected) +
                     " strings");
  }
  return detail::readVariableStrings(dataset, path, "dataset /" + where);
}

}  // namespace

std::vector<StoredComparisonRun> readComparisonRuns(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());  // also guards the runs' external links
  H5::Exception::dontPrint();
  std::vector<StoredComparisonRun> runs;
  try {
    const H5::H5File file = detail::openFileForReading(path);
    if (!file.nameExists("batch") || !file.nameExists(kSummary) || !file.nameExists("runs")) {
      throw InputError(path + ": no /batch/summary or /runs: expected the study file of `wpg compare`");
    }
    const H5::Group table = file.openGroup(kSummary);
    const std::string where = std::string("/") + kSummary;
    const std::vector<double> done = numbers(table, "done", static_cast<hsize_t>(-1), path, where);
    const hsize_t count = done.size();
    const std::vector<std::string> names = strings(table, "name", count, path);
    const std::vector<std::string> worlds = strings(table, "sweep.world", count, path);
    const std::vector<std::string> variants = strings(table, "sweep.variant", count, path);
    const auto column = [&](const char* name) { return numbers(table, name, count, path, where); };
    const std::vector<double> seeds = column("sweep.seed"), reached = column("goal_reached"),
                              time_to_goal = column("time_to_goal"), walked = column("path_length"),
                              steps = column("steps"), route = column("route_length"),
                              clearance = column("step_centre_clearance_min"),
                              replans = column("replans"), blocked = column("blocked");
    const H5::Group groups = file.openGroup("runs");
    for (hsize_t i = 0; i < count; ++i) {
      StoredComparisonRun run;
      run.name = names[i];
      run.world = worlds[i];
      run.variant = variants[i];
      run.seed = seeds[i];
      run.done = done[i] == 1.0 && groups.nameExists(run.name);
      if (run.done) {
        run.goal_reached = reached[i] == 1.0;
        run.blocked = blocked[i] == 1.0;
        run.time_to_goal = time_to_goal[i];
        run.path_length = walked[i];
        run.steps = steps[i];
        run.route_length = route[i];
        run.clearance_min = clearance[i];
        run.replans = static_cast<int>(replans[i]);
        const std::string group_path = "/runs/" + run.name;
        const H5::Group group = groups.openGroup(run.name);  // through the link guard
        if (!group.nameExists("plans") || !group.nameExists("mpc")) {
          throw InputError(path + ": " + group_path + ": expected a walk to a goal (plans/, mpc/)");
        }
        const H5::Group plans = group.openGroup("plans");
        if (detail::readStringAttribute(plans, "algorithm", path, group_path + "/plans:") != "none") {
          run.planning_times =
              numbers(plans, "planning_time", static_cast<hsize_t>(-1), path, group_path + "/plans");
        }
        run.nmpc_solve_times = numbers(group.openGroup("mpc"), "solve_time",
                                       static_cast<hsize_t>(-1), path, group_path + "/mpc");
      }
      runs.push_back(std::move(run));
    }
  } catch (const H5::Exception& error) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
    throw InputError(path + ": cannot read the comparison's runs (" + error.getDetailMsg() + ")");
  }
  return runs;
}

}  // namespace wpg::datasets
