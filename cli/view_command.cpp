// `wpg view` (view_command.hpp): which page the input calls for, where it goes, and the checks
// made before anything is written (the input is readable, the output may be replaced, the
// viewer bundle exists).
#include "view_command.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "cli_common.hpp"
#include "view_dashboard.hpp"
#include "view_page.hpp"
#include "view_run_scene.hpp"
#include "wpg/datasets/batch_dataset.hpp"
#include "wpg/datasets/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

void checkOutput(const std::string& page, const std::string& input) {
  try {
    datasets::checkOutputPath(page, datasets::OutputKind::kHtml, {input});
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
    if (!fs::is_regular_file(input, ec)) {
      throw UsageError("'" + options.input + "' is a folder without study.h5: expected the output "
                       "folder of `wpg compare`, a run file or a batch file");
    }
  }
  const std::string file = input.string();
  const bool batch = datasets::isBatchFile(file);
  const bool dashboard = batch && options.run.empty();
  std::string page = options.output;
  if (page.empty()) {
    if (folder) page = (fs::path(options.input) / "view.html").string();
    else if (!options.run.empty() && batch) page = fs::path(file).replace_extension("." + options.run + ".html").string();
    else page = fs::path(file).replace_extension(".html").string();
  }
  checkOutput(page, file);
  const ViewerAssets assets = loadViewerAssets();

  if (dashboard) {
    const DashboardPages pages = writeDashboard(assets, file, page);
    std::cout << "page: " << pages.page << sizeText(pages.page) << ", " << pages.runs
              << " run pages in " << pages.runs_folder << '\n';
    return kExitSuccess;
  }
  const LoadedRun run = loadRun(file, options.run);
  writePage(assets, page, runSceneJson(run));
  std::cout << "page: " << page << sizeText(page) << '\n';
  return kExitSuccess;
}

}  // namespace wpg::cli
