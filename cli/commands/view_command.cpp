// `wpg view FILE.h5 [--run NAME] [-o PAGE.html]` and `wpg view DIR` (docs/viewer.md): which
// page the input calls for, where it goes, and the checks made before anything is written (the
// input is readable, the output may be replaced, the viewer bundle exists); the pages
// themselves are the viewer library's (wpg/viewer/).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>
#include <vector>

#include "command_options.hpp"
#include "data_paths.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/input_file.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/viewer/run_scene.hpp"
#include "wpg/viewer/study_dashboard.hpp"
#include "wpg/viewer/viewer_page.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// Every file the command writes, through the checks of every other output (docs/robustness.md),
// before the bundle is looked for and before any run is read.
void checkOutputs(const std::vector<datasets::PlannedOutput>& outputs, const std::string& input,
                  const std::string& runs_folder = "") {
  try {
    if (!runs_folder.empty()) datasets::checkOutputFolder(runs_folder);
    datasets::checkOutputPaths(outputs, {input});
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
}

std::string sizeText(const std::string& path) {
  std::error_code ec;
  const auto bytes = fs::file_size(path, ec);
  if (ec) return "";
  char text[32];
  std::snprintf(text, sizeof text, " (%.1f MB)", static_cast<double>(bytes) / 1e6);
  return text;
}

}  // namespace

int viewCommand(const ViewOptions& options) {
  std::error_code ec;
  if (!fs::exists(options.input, ec)) {
    throw UsageError("cannot read '" + options.input + "': no such file or folder");
  }
  fs::path input(options.input);
  const bool folder = fs::is_directory(input, ec);
  if (folder) {
    // The folder of `wpg compare`: its study.h5.
    input /= "study.h5";
    if (!fs::exists(input, ec)) {
      throw UsageError("'" + options.input + "' is a folder without study.h5: expected the output "
                       "folder of `wpg compare`, a run file or a batch file");
    }
  }
  const std::string file = input.string();
  datasets::checkInputFile(file);
  const bool batch = datasets::isBatchFile(file);
  const bool dashboard = batch && options.run.empty();
  std::string page = options.output;
  if (page.empty()) {
    if (folder) page = (fs::path(options.input) / "view.html").string();
    else if (!options.run.empty() && batch) page = fs::path(file).replace_extension("." + options.run + ".html").string();
    else page = fs::path(file).replace_extension(".html").string();
  }
  if (dashboard) {
    const viewer::DashboardPlan plan = viewer::planDashboard(file, page);
    checkOutputs(plan.outputs, file, plan.runs_folder);
    const viewer::ViewerAssets assets = viewer::loadViewerAssets(dataDirectory());
    const viewer::DashboardPages pages = viewer::writeDashboard(assets, plan, robotsDirectory());
    std::cout << "page: " << pages.page << sizeText(pages.page) << ", " << pages.runs
              << " run pages in " << pages.runs_folder << '\n';
    return kExitSuccess;
  }
  checkOutputs({{page, datasets::OutputKind::kHtml}}, file);
  const viewer::ViewerAssets assets = viewer::loadViewerAssets(dataDirectory());
  const viewer::LoadedRun run = viewer::loadRun(file, options.run, robotsDirectory());
  viewer::writePage(assets, page, viewer::runSceneJson(run));
  std::cout << "page: " << page << sizeText(page) << '\n';
  return kExitSuccess;
}

}  // namespace wpg::cli
