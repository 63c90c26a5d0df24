#pragma once
// The dashboard page of a study (`wpg view BATCH.h5`, `wpg view DIR` of `wpg compare`): the
// summary table's metrics per world x variant or against a swept key, success rates, a top view
// of every run, and one run page per run beside it (PAGE_runs/<run>.html, sharing one script
// file), opened by a click.
#include <string>
#include <vector>

#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/viewer/viewer_page.hpp"

namespace wpg::viewer {

struct DashboardPages {
  std::string page;        // the dashboard
  std::string runs_folder; // the run pages
  std::size_t runs = 0;    // run pages written
};

// What a dashboard will write, known from the study's summary table alone (no run read): the
// dashboard, its runs folder, one page per finished run and the shared script. The front end
// checks every file of `outputs` (datasets::checkOutputPaths) and the folder
// (datasets::checkOutputFolder) before any run is read.
struct DashboardPlan {
  std::string batch_file, page;
  std::string runs_folder;               // PAGE_runs beside the page
  datasets::BatchSummaryTable table;
  std::vector<std::size_t> finished;     // rows of the runs that have a page
  std::vector<std::string> run_pages;    // their pages, in `finished` order
  std::vector<datasets::PlannedOutput> outputs;  // the dashboard, the run pages, the script
};
// Reads /batch/summary of `batch_file` (a batch or comparison file). Throws InputError.
DashboardPlan planDashboard(const std::string& batch_file, const std::string& page);

// Reads every finished run of the plan (its robots' URDFs from `robots_directory`) and writes
// the dashboard and its run pages. Throws InputError on a run the readers refuse (nothing is
// left half-written: each page is written atomically, the dashboard last).
DashboardPages writeDashboard(const ViewerAssets& assets, const DashboardPlan& plan,
                              const std::string& robots_directory);

}  // namespace wpg::viewer
