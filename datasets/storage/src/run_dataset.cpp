// Writing one run to its own HDF5 file (run_dataset.hpp): its group built (run_group_image.cpp,
// the multibody fields on another thread), then committed into a temporary file under the
// HDF5 lock, which is renamed over the target.
#include "wpg/datasets/storage/run_dataset.hpp"

#include <filesystem>
#include <future>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include "external_link_guard.hpp"
#include "hdf5_writing.hpp"
#include "provenance_attributes.hpp"
#include "run_group_writing.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/version.hpp"

namespace wpg::datasets {

std::mutex& hdf5Mutex() {
  static std::mutex mutex;
  [[maybe_unused]] static const bool links_checked = (detail::installExternalLinkGuard(), true);
  return mutex;
}

namespace fs = std::filesystem;
using namespace detail;  // NOLINT: the image of the file

PreparedRun prepareWalkDatasets(const Scenario& scenario, const wpg::WalkResult& result) {
  checkRunInputs(scenario, result, nullptr, nullptr);
  const WalkTrajectory& walk = result.trajectory;
  return PreparedRun{buildWalkPart(scenario, result), walk.size(), walk.mpc.size(),
                     walk.footsteps.size(), scenario.request.obstacles.size()};
}

void writeRunDataset(const std::string& path, const Scenario& scenario,
                     const wpg::WalkResult& result, const FootstepClearances* clearances,
                     const MultibodyRecord* multibody, const GoalOutcome* goal,
                     const PreparedRun* prepared) {
  checkRunInputs(scenario, result, clearances, multibody);
  if (goal && !scenario.goal.enabled) {
    throw std::invalid_argument("writeRunDataset: a goal outcome for a scenario without a goal");
  }
  const WalkTrajectory& walk = result.trajectory;
  if (prepared && (prepared->samples != walk.size() || prepared->iterations != walk.mpc.size() ||
                   prepared->footsteps != walk.footsteps.size() ||
                   prepared->obstacles != scenario.request.obstacles.size())) {
    throw std::logic_error("writeRunDataset: the prepared walk is not the one written");
  }
  if (path.empty() || !fs::path(path).has_filename()) {
    throw std::invalid_argument("writeRunDataset: '" + path + "' is not a file path");
  }
  // The multibody fields (a replayed run: most of the file's bytes) are built on another
  // thread while this one builds the rest; the same image either way.
  std::future<std::shared_ptr<const GroupImage>> multibody_part;
  if (multibody) {
    try {
      multibody_part = std::async(std::launch::async,
                                  [&] { return buildMultibodyPart(scenario, *multibody); });
    } catch (const std::system_error&) {  // no thread to spare: built below
    }
  }
  GroupImage root;
  writeIntAttribute(root, "schema_version", kRunDatasetSchemaVersion);
  writeStringAttribute(root, "wpg_version", WPG_VERSION_STRING);
  writeProvenanceAttributes(root);
  writeStringAttribute(root, "scenario", resolvedScenarioText(scenario));
  writeStringAttribute(root, "created_by", "wpg");  // wpg run, wpg replay or a program of yours
  RunGroupParts parts;
  if (prepared) parts.walk = prepared->image;
  // The checks and the rest are built here meanwhile; the multibody part is waited for last.
  const DatasetChecks checks = computeDatasetChecks(scenario, result.trajectory, clearances);
  parts.checks = &checks;
  if (multibody_part.valid()) parts.multibody = multibody_part.get();
  buildRunGroup(root.createGroup("runs"), scenario.name, scenario, result, clearances, multibody,
                goal, parts);
  // Written beside the target under an unpredictable name, then renamed over it (atomic on one
  // file system); removed on failure and on SIGINT / SIGTERM (output_file.hpp).
  TemporaryOutput temporary(path);
  {
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    try {
      commitFile(temporary.path(), root);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(path + ": cannot write the HDF5 file (" + error.what() + ")");
    }
  }
  temporary.commit();
}

}  // namespace wpg::datasets
