// The push-sweep file (push_sweep_dataset.hpp): the group /push_sweep, one 1-D dataset per
// column, as /batch/summary of a batch file, so that h5py (or pandas) reads it as a table.
#include "wpg/datasets/storage/push_sweep_dataset.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "hdf5_writing.hpp"
#include "provenance_attributes.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/version.hpp"


namespace wpg::datasets {
namespace {

using detail::DatasetInfo;

template <typename Get>
std::vector<double> columnOf(const std::vector<PushSweepRow>& rows, Get get) {
  std::vector<double> values;
  for (const PushSweepRow& row : rows) values.push_back(get(row));
  return values;
}

// The file's image: its attributes, /step_lift_off and the table /push_sweep.
void buildFile(detail::GroupImage& file, const PushSweepFile& sweep) {
  detail::writeStringAttribute(file, "created_by", "wpg push-sweep");
  detail::writeStringAttribute(file, "wpg_version", WPG_VERSION_STRING);
  detail::writeProvenanceAttributes(file);
  detail::writeIntAttribute(file, "push_sweep_schema_version", 1);
  detail::writeStringListAttribute(file, "situations", sweep.situations);
  detail::writeStringListAttribute(file, "scenarios", sweep.scenarios);
  detail::writeStringListAttribute(file, "overrides", sweep.overrides);
  detail::writeDoubleAttribute(file, "max_force", sweep.max_force);
  detail::writeDoubleAttribute(file, "tolerance", sweep.tolerance);
  detail::writeDoubleAttribute(file, "stronger_factor", sweep.stronger_factor);
  detail::writeDoubleAttribute(file, "max_swing_speed", sweep.max_swing_speed);
  detail::writeDoubleAttribute(file, "max_swing_acceleration", sweep.max_swing_acceleration);
  detail::GroupImage& group = file.createGroup("push_sweep");
  const std::vector<PushSweepRow>& rows = sweep.rows;
  {
    std::vector<double> lift_off = sweep.step_lift_off;
    detail::writeDoubles(file, "step_lift_off", lift_off, 0,
                         {"s", nullptr, "lift-off of each situation's swept step (order: attribute situations)", nullptr});
  }
  std::vector<std::string> situations, directions, scenarios;
  for (const PushSweepRow& row : rows) {
    situations.push_back(row.situation);
    directions.push_back(row.direction);
    scenarios.push_back(row.scenario);
  }
  detail::writeStrings(group, "situation", situations, "forward (walking at 0.2 m/s) or on_spot");
  detail::writeStrings(group, "direction", directions,
                    "sagittal+/- (world x), coronal+/- (world y)");
  detail::writeStrings(group, "scenario", scenarios, "scenario that replays the push (--set pushes[0]=...)");
  detail::writeDoubles(group, "phase", columnOf(rows, [](const PushSweepRow& r) { return r.phase; }),
                       0, {"1", nullptr, "fraction of the step period since the swing foot's lift-off", nullptr});
  detail::writeDoubles(group, "t", columnOf(rows, [](const PushSweepRow& r) { return r.t; }), 0,
                       {"s", nullptr, "push start", nullptr});
  detail::writeDoubles(group, "force", columnOf(rows, [](const PushSweepRow& r) { return r.force; }),
                       0, {"N", nullptr, "largest recovered force, signed along the direction's world axis", nullptr});
  detail::writeDoubles(group, "fx", columnOf(rows, [](const PushSweepRow& r) { return r.fx; }), 0,
                       {"N", "world", "largest recovered force, x", nullptr});
  detail::writeDoubles(group, "fy", columnOf(rows, [](const PushSweepRow& r) { return r.fy; }), 0,
                       {"N", "world", "largest recovered force, y", nullptr});
  detail::writeDoubles(group, "impulse", columnOf(rows, [](const PushSweepRow& r) { return r.impulse; }),
                       0, {"N s", nullptr, "force x duration", nullptr});
  detail::writeDoubles(group, "duration", columnOf(rows, [](const PushSweepRow& r) { return r.duration; }),
                       0, {"s", nullptr, "push duration", nullptr});
  detail::writeDoubles(group, "swing_speed_max",
                       columnOf(rows, [](const PushSweepRow& r) { return r.swing_speed_max; }), 0,
                       {"m/s", nullptr, "swing foot's peak speed in the walk at force", nullptr});
  detail::writeDoubles(
      group, "swing_acceleration_max",
      columnOf(rows, [](const PushSweepRow& r) { return r.swing_acceleration_max; }), 0,
      {"m/s^2", nullptr, "swing foot's peak acceleration in the walk at force", nullptr});
  std::vector<int> bound, walks;
  for (const PushSweepRow& row : rows) {
    bound.push_back(row.at_upper_bound ? 1 : 0);
    walks.push_back(row.walks);
  }
  detail::writeInts(group, "at_upper_bound", bound,
                    {"1", nullptr, "1 when the upper bound max_force itself was recovered", nullptr});
  detail::writeInts(group, "walks", walks, {"1", nullptr, "walks generated by the row's search", nullptr});
  detail::writeStringListAttribute(group, "columns",
                                   {"situation", "direction", "phase", "t", "force", "impulse", "fx",
                                    "fy", "duration", "scenario", "at_upper_bound", "walks",
                                    "swing_speed_max", "swing_acceleration_max"});
}

}  // namespace

void writePushSweepFile(const std::string& path, const PushSweepFile& sweep) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
  }
  detail::GroupImage file;
  buildFile(file, sweep);
  TemporaryOutput temporary(path);  // exclusive, removed on error and on SIGINT / SIGTERM
  {
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    try {
      detail::commitFile(temporary.path(), file);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(path + ": cannot write the HDF5 file (" + error.what() + ")");
    }
  }
  temporary.commit();
}

}  // namespace wpg::datasets
