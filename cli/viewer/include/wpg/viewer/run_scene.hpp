#pragma once
// A run as the page of `wpg view` shows it: read from a run, batch or index file (the walk,
// the replay's joint angles, the goal, the routes, and the stored scenario's obstacles,
// pushes and sole size), then written as the page's JSON (the scene) or as a small top view
// for the dashboard of a study.
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/storage/run_scene_reader.hpp"
#include "wpg/viewer/page_json.hpp"

namespace wpg::viewer {

struct LoadedRun {
  std::string file;  // the file it was read from
  datasets::StoredRun stored;
  datasets::StoredRunScene scene;
  datasets::Scenario scenario;  // the stored scenario, loaded again (obstacles, pushes, feet)
  std::string urdf;             // the robot folder's multibody.urdf, empty when there is none
};

// Reads /runs/<run_name> of `path` (empty name: the file's only run), and the robot's URDF
// from `robots_directory`. Throws InputError (one line naming the file) on anything the
// readers refuse.
LoadedRun loadRun(const std::string& path, const std::string& run_name,
                  const std::string& robots_directory);

// Samples per page at most, over every per-sample array (a 3600 s replayed walk would be
// 190 MB): beyond it the samples are decimated evenly (the page says so).
constexpr std::size_t kMaxPageFloats = 1500000;

// The run page's JSON object (kind "run"). `back`, when not empty, is a link shown in the
// header (the dashboard the run page belongs to).
std::string runSceneJson(const LoadedRun& run, const std::string& back = "",
                         const std::string& back_label = "");

// The run's top view for a dashboard: {"path": CoM x, y (float32 base64, at most ~300 points),
// "obstacles", "goal", "reached", "success", "blocked"} appended to `json` as an object.
void writeTopView(Json& json, const LoadedRun& run);

// Obstacles as the page draws them: type, centre, radius, margin, known to the planner, and
// the world outline of boxes and polygons.
void writeObstacles(Json& json, const datasets::Scenario& scenario);

}  // namespace wpg::viewer
