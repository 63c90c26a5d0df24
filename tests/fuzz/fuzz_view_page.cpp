// libFuzzer target: the page data of `wpg view FILE.h5` (wpg/viewer/run_scene.hpp) and the
// route plans of `--ompl-log` (readRoutePlans). The input is a description of a valid HDF5
// file's content (hdf5_image.hpp), its global heaps then damaged (heap_damage.hpp), read the
// way the commands read it:
//   wpg view:      viewer::loadRun of the file's only run (the walk, the replay's arrays, the
//                  goal, the route plans, the stored scenario), then the page's JSON and the
//                  dashboard's top view;
//   --ompl-log:    readRoutePlans of each run.
// Seeds: the dataset reader's (scripts/fuzz.sh).
//
// Properties checked, beyond "no crash, no sanitizer report, no hang, no huge allocation": bad
// input is an InputError (the CLI's exit 2); an accepted run's plans hold at most
// kMaxStoredPlans plans and kMaxStoredRouteWaypoints waypoints; the page's JSON never holds
// "</" (it sits inside a <script> element: a stored text must not close it).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hdf5_image.hpp"
#include "private_folder.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/storage/run_scene_reader.hpp"
#include "wpg/viewer/run_scene.hpp"
#include "../common/source_dir.hpp"

namespace {

std::string g_path;


[[noreturn]] void propertyViolated(const std::string& what) {
  std::fprintf(stderr, "fuzz_view_page: %s\n", what.c_str());
  std::abort();
}

void checkPlans(const std::vector<wpg::datasets::StoredRoutePlan>& plans) {
  if (plans.size() > wpg::datasets::kMaxStoredPlans) propertyViolated("more plans than the limit");
  std::size_t waypoints = 0;
  for (const auto& plan : plans) waypoints += plan.route.size();
  if (waypoints > wpg::datasets::kMaxStoredRouteWaypoints) propertyViolated("more waypoints than the limit");
}

void readLikeView(const std::string& robots) {
  wpg::viewer::LoadedRun run;
  try {
    run = wpg::viewer::loadRun(g_path, "", robots);
  } catch (const wpg::datasets::InputError&) {
    return;
  }
  checkPlans(run.scene.plans);
  const std::string json = wpg::viewer::runSceneJson(run, "../dashboard.html", "study");
  if (json.find("</") != std::string::npos) propertyViolated("the page's JSON holds '</'");
  wpg::viewer::Json top;
  wpg::viewer::writeTopView(top, run);
  if (top.text().find("</") != std::string::npos) propertyViolated("a top view holds '</'");
}

void readLikeOmplLog() {
  std::vector<std::string> names;
  try {
    names = wpg::datasets::listRuns(g_path);
  } catch (const wpg::datasets::InputError&) {
    return;
  }
  for (const std::string& name : names) {
    try {
      checkPlans(wpg::datasets::readRoutePlans(g_path, name));
    } catch (const wpg::datasets::InputError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_path = wpg_fuzz::scratchFile("wpg-fuzz-page-");  // tmpfs when there is one
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string robots = std::string(wpg_test::sourceDir()) + "/robots";
  const wpg_fuzz::FileImage image = wpg_fuzz::decode(data, size, std::uint64_t{1} << 40);
  if (!wpg_fuzz::writeHdf5(image, g_path)) propertyViolated("cannot create " + g_path);
  wpg_fuzz::applyImageDamage(image, g_path);
  readLikeView(robots);
  readLikeOmplLog();
  return 0;
}
