#pragma once
// The dashboard page of a study (`wpg view BATCH.h5`, `wpg view DIR` of `wpg compare`): the
// summary table's metrics per world x variant or against a swept key, success rates, a top view
// of every run, and one run page per run beside it (PAGE_runs/<run>.html, sharing one script
// file), opened by a click.
#include <string>

#include "wpg/viewer/viewer_page.hpp"

namespace wpg::viewer {

struct DashboardPages {
  std::string page;        // the dashboard
  std::string runs_folder; // the run pages
  std::size_t runs = 0;    // run pages written
};

// Reads the batch (or comparison) file `batch_file` (its robots' URDFs from
// `robots_directory`) and writes `page` and its run pages. Throws InputError on a file the
// readers refuse (nothing is left half-written: each page is written atomically, the
// dashboard last).
DashboardPages writeDashboard(const ViewerAssets& assets, const std::string& batch_file,
                              const std::string& page, const std::string& robots_directory);

}  // namespace wpg::viewer
