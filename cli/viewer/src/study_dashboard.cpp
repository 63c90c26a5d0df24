// The dashboard of a study and its run pages (study_dashboard.hpp). The page decodes what is
// written here in analysis/viewer/src/dashboard_page.js: keep the two in step.
#include "wpg/viewer/study_dashboard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "spool_file.hpp"
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

DashboardPlan planDashboard(const std::string& batch_file, const std::string& page) {
  DashboardPlan plan;
  plan.batch_file = batch_file;
  plan.page = page;
  plan.table = datasets::readBatchSummary(batch_file);
  const auto& table = plan.table;
  const auto name_at = std::find(table.column_names.begin(), table.column_names.end(), "name");
  if (name_at == table.column_names.end())
    throw datasets::InputError(batch_file + ": /batch/summary has no column 'name'");
  const std::vector<std::string>& names = table.cells[name_at - table.column_names.begin()];
  const auto done_at = std::find(table.column_names.begin(), table.column_names.end(), "done");
  const std::vector<std::string>* done =
      done_at == table.column_names.end() ? nullptr : &table.cells[done_at - table.column_names.begin()];
  const fs::path page_path(page);
  const fs::path folder = page_path.parent_path() / (page_path.stem().string() + "_runs");
  plan.runs_folder = folder.string();
  plan.outputs.push_back({page, datasets::OutputKind::kHtml});
  plan.outputs.push_back({(folder / "wpg_viewer.js").string(), datasets::OutputKind::kText});
  for (std::size_t row = 0; row < table.rows; ++row) {
    if (done && (*done)[row] != "1") continue;  // not run yet (an unfinished batch)
    plan.finished.push_back(row);
    plan.run_pages.push_back((folder / fileNameOf(names[row])).string());
    plan.outputs.push_back({plan.run_pages.back(), datasets::OutputKind::kHtml});
  }
  return plan;
}

DashboardPages writeDashboard(const ViewerAssets& assets, const DashboardPlan& plan,
                              const std::string& robots_directory) {
  const std::string& batch_file = plan.batch_file;
  const std::string& page = plan.page;
  const datasets::BatchSummaryTable& table = plan.table;
  const auto column = [&](const std::string& name) -> const std::vector<std::string>* {
    const auto it = std::find(table.column_names.begin(), table.column_names.end(), name);
    return it == table.column_names.end() ? nullptr : &table.cells[it - table.column_names.begin()];
  };
  const std::vector<std::string>& names = *column("name");
  const std::vector<std::string>* worlds = column("sweep.world");
  const std::vector<std::string>* variants = column("sweep.variant");
  const std::vector<std::string>* seeds = column("sweep.seed");
  const bool comparison = worlds && variants && seeds;

  DashboardPages pages;
  pages.page = page;
  const fs::path page_path(page);
  const std::string folder_name = fs::path(plan.runs_folder).filename().string();
  pages.runs_folder = plan.runs_folder;

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

  // Every run is read once: its top view goes into the dashboard and its page's data into a
  // spool (an anonymous temporary file, spool_file.hpp). The pages are written from the spool
  // once every run has been read, so that a run the readers refuse stops the command before
  // anything is written. Reading every run a second time for its page instead took half of
  // `wpg view` of a study.
  const std::string back = "../" + page_path.filename().string();
  SpoolFile spool(page);
  json.key("runs").beginArray();
  std::size_t next = 0;  // in plan.finished
  for (std::size_t row = 0; row < table.rows; ++row) {
    if (next == plan.finished.size() || plan.finished[next] != row) {
      json.null();  // not run yet (an unfinished batch)
      continue;
    }
    const LoadedRun run = loadRun(batch_file, names[row], robots_directory);
    json.beginObject();
    json.key("page").string(folder_name + "/" + fs::path(plan.run_pages[next]).filename().string());
    json.key("top");
    writeTopView(json, run);
    json.endObject();
    spool.append(runSceneJson(run, back, table.study + " dashboard"));
    ++next;
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
  for (std::size_t i = 0; i < plan.finished.size(); ++i) {
    writePage(assets, plan.run_pages[i], spool.read(i), "wpg_viewer.js");
    ++pages.runs;
  }
  writePage(assets, page, json.text());
  return pages;
}

}  // namespace wpg::viewer
