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

#ifndef WPG_VERSION_STRING
#error "WPG_VERSION_STRING must be defined (libwpg's CMake target gives it)"
#endif

namespace wpg::datasets {
namespace {

using detail::DatasetInfo;

void writeStringColumn(H5::Group& group, const std::string& name,
                       const std::vector<std::string>& values, const char* description) {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  const hsize_t count = values.size();
  H5::DataSet dataset = group.createDataSet(name, type, H5::DataSpace(1, &count));
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  if (count > 0) dataset.write(pointers.data(), type);
  detail::writeStringAttribute(dataset, "units", "1");
  detail::writeStringAttribute(dataset, "description", description);
}

template <typename Get>
std::vector<double> columnOf(const std::vector<PushSweepRow>& rows, Get get) {
  std::vector<double> values;
  for (const PushSweepRow& row : rows) values.push_back(get(row));
  return values;
}

void writeFile(const std::string& path, const PushSweepFile& sweep) {
  // Closing the file closes every object still open and flushes them (a strong close): a write
  // that fails there (a full disk) is an error of file.close(), not a message of ~H5File that
  // the commit would never hear of (the partial file was renamed into place).
  H5::FileAccPropList access;
  access.setFcloseDegree(H5F_CLOSE_STRONG);
  auto owned = std::make_unique<H5::H5File>(detail::createHdf5File(path, access));
  H5::H5File& file = *owned;
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
  H5::Group group = file.createGroup("push_sweep");
  const std::vector<PushSweepRow>& rows = sweep.rows;
  {
    std::vector<double> lift_off = sweep.step_lift_off;
    H5::Group root = file.openGroup("/");
    detail::writeDoubles(root, "step_lift_off", lift_off, 0,
                         {"s", nullptr, "lift-off of each situation's swept step (order: attribute situations)", nullptr});
  }
  std::vector<std::string> situations, directions, scenarios;
  for (const PushSweepRow& row : rows) {
    situations.push_back(row.situation);
    directions.push_back(row.direction);
    scenarios.push_back(row.scenario);
  }
  writeStringColumn(group, "situation", situations, "forward (walking at 0.2 m/s) or on_spot");
  writeStringColumn(group, "direction", directions,
                    "sagittal+/- (world x), coronal+/- (world y)");
  writeStringColumn(group, "scenario", scenarios, "scenario that replays the push (--set pushes[0]=...)");
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
  try {
    file.close();  // inside the caller's try: a failed flush is an error
  } catch (const H5::Exception&) {
    // HDF5 1.10 crashes when a file whose close failed is closed again (as ~H5File would):
    // the handle is let go; the caller removes the temporary file, the CLI exits without
    // HDF5's termination (exit 3, cli/main.cpp).
    static_cast<void>(owned.release());
    throw;
  }
}

}  // namespace

void writePushSweepFile(const std::string& path, const PushSweepFile& sweep) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
  }
  TemporaryOutput temporary(path);  // exclusive, removed on error and on SIGINT / SIGTERM
  {
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    H5::Exception::dontPrint();
    try {
      writeFile(temporary.path(), sweep);
    } catch (const H5::Exception& error) {
      throw std::runtime_error(path + ": cannot write the HDF5 file (" + error.getDetailMsg() + ")");
    }
  }
  temporary.commit();
}

}  // namespace wpg::datasets
