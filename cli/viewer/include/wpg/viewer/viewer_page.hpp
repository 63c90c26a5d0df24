#pragma once
// The pages of `wpg view` (docs/viewer.md): the bundled viewer and the HTML template found in
// the build or install tree, the provenance every page shows, and the page written atomically.
#include <string>

#include "wpg/viewer/page_json.hpp"

namespace wpg::viewer {

struct ViewerAssets {
  std::string folder;    // where wpg_viewer.js and page.html were found
  std::string script;    // the bundle, to be inlined
  std::string page;      // the template (analysis/viewer/page.html)
};
// $WPG_VIEWER_DIR alone when set; else the bundle of the build tree this library was built in,
// then `data_directory`/analysis/viewer (the installed data folder). Throws
// datasets::InputError naming the places looked in and the way to build the bundle (a build
// without Node.js has none).
ViewerAssets loadViewerAssets(const std::string& data_directory);

// The provenance object of every page: {"version", "commit", "machine", "date", "source"}.
void writeProvenance(Json& json, const std::string& source);

// The page: the template with the data (a JSON <script>) and the viewer, inline or, when
// `script_src` is not empty, as <script src="script_src"> (the run pages of a study share one
// script file beside them). Written atomically to `path` (its folder created).
void writePage(const ViewerAssets& assets, const std::string& path, const std::string& data_json,
               const std::string& script_src = "");

// Writes `text` to `path` atomically (the shared script of a study's run pages).
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace wpg::viewer
