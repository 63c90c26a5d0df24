// The dashboard of a study and its run pages (study_dashboard.hpp). The page decodes what is
// written here in analysis/viewer/src/dashboard_page.js: keep the two in step.
#include "wpg/viewer/study_dashboard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/viewer/run_scene.hpp"

namespace fs = std::filesystem;

namespace wpg::viewer {
namespace {

// A file name from a run name: the characters a study's names may hold, anything else as '_'.
std::string fileNameOf(const std::string& run) {
  std::string name = run;
  for (char& c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '_' || c == '-';
    if (!plain) c = '_';
  }
  return name + ".html";
}

bool parseNumber(const std::string& text, double* value) {
  if (text == "nan" || text == "inf" || text == "-inf") {
    *value = text == "nan" ? std::nan("") : (text == "inf" ? HUGE_VAL : -HUGE_VAL);
    return true;
  }
  if (text.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end && *end == '\0';
}

// The distinct values of a text column in order of first appearance (the study's order).
std::vector<std::string> distinct(const std::vector<std::string>& cells) {
  std::vector<std::string> values;
  for (const std::string& cell : cells) {
    if (std::find(values.begin(), values.end(), cell) == values.end()) values.push_back(cell);
  }
  return values;
}

}  // namespace

DashboardPages writeDashboard(const ViewerAssets& assets, const std::string& batch_file,
                              const std::string& page, const std::string& robots_directory) {
  const datasets::BatchSummaryTable table = datasets::readBatchSummary(batch_file);
  const auto column = [&](const std::string& name) -> const std::vector<std::string>* {
    const auto it = std::find(table.column_names.begin(), table.column_names.end(), name);
    return it == table.column_names.end() ? nullptr : &table.cells[it - table.column_names.begin()];
  };
  const std::vector<std::string>* names = column("name");
  const std::vector<std::string>* done = column("done");
  if (!names) throw datasets::InputError(batch_file + ": /batch/summary has no column 'name'");
  const std::vector<std::string>* worlds = column("sweep.world");
  const std::vector<std::string>* variants = column("sweep.variant");
  const std::vector<std::string>* seeds = column("sweep.seed");
  const bool comparison = worlds && variants && seeds;

  DashboardPages pages;
  pages.page = page;
  const fs::path page_path(page);
  const std::string folder_name = page_path.stem().string() + "_runs";
  pages.runs_folder = (page_path.parent_path() / folder_name).string();

  Json json;
  json.beginObject();
  json.key("kind").string("dashboard");
  json.key("title").string(table.study);
  json.key("comparison").boolean(comparison);
  writeProvenance(json, fs::path(batch_file).filename().string());
  if (comparison) {
    json.key("worlds").strings(distinct(*worlds));
    json.key("variants").strings(distinct(*variants));
    json.key("seeds").strings(distinct(*seeds));
  }
  json.key("columns").beginArray();
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    std::vector<double> numbers;
    bool numeric = true;
    for (const std::string& cell : table.cells[c]) {
      double value = 0.0;
      if (!parseNumber(cell, &value)) {
        numeric = false;
        break;
      }
      numbers.push_back(value);
    }
    json.beginObject();
    json.key("name").string(table.column_names[c]);
    json.key("unit").string(table.column_units[c]);
    json.key("values");
    if (numeric) json.numbers(numbers); else json.strings(table.cells[c]);
    json.endObject();
  }
  json.endArray();

  // First every run is read (a run the readers refuse stops the command before anything is
  // written) and its top view kept; then the run pages, then the dashboard.
  std::vector<std::size_t> finished;
  json.key("runs").beginArray();
  for (std::size_t row = 0; row < table.rows; ++row) {
    if (done && (*done)[row] != "1") {
      json.null();  // not run yet (an unfinished batch)
      continue;
    }
    const LoadedRun run = loadRun(batch_file, (*names)[row], robots_directory);
    finished.push_back(row);
    json.beginObject();
    json.key("page").string(folder_name + "/" + fileNameOf(run.stored.name));
    json.key("top");
    writeTopView(json, run);
    json.endObject();
  }
  json.endArray();
  json.key("subtitle").string(
      std::to_string(table.rows) + " runs" +
      (comparison ? " · " + std::to_string(distinct(*worlds).size()) + " worlds × " +
                        std::to_string(distinct(*variants).size()) + " variants × " +
                        std::to_string(distinct(*seeds).size()) + " seeds"
                  : ""));
  json.endObject();

  fs::create_directories(pages.runs_folder);
  // One script for every run page (a study of 100 runs would hold 100 copies otherwise).
  writeTextFile((fs::path(pages.runs_folder) / "wpg_viewer.js").string(), assets.script);
  const std::string back = "../" + page_path.filename().string();
  for (const std::size_t row : finished) {
    const LoadedRun run = loadRun(batch_file, (*names)[row], robots_directory);
    writePage(assets, (fs::path(pages.runs_folder) / fileNameOf(run.stored.name)).string(),
              runSceneJson(run, back, table.study + " dashboard"), "wpg_viewer.js");
    ++pages.runs;
  }
  writePage(assets, page, json.text());
  return pages;
}

}  // namespace wpg::viewer
