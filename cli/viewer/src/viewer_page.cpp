// Pages of `wpg view`: assets, provenance, atomic writing (viewer_page.hpp).
#include "wpg/viewer/viewer_page.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/provenance.hpp"

#ifndef WPG_VIEWER_BUILD_DIR
#define WPG_VIEWER_BUILD_DIR ""
#endif

namespace fs = std::filesystem;

namespace wpg::viewer {
namespace {

bool readWhole(const fs::path& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return in.good() || in.eof();
}

void replaceOnce(std::string& text, const std::string& marker, const std::string& with,
                 const std::string& where) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) throw datasets::InputError(where + ": the template has no " + marker);
  text.replace(at, marker.size(), with);
}

}  // namespace

ViewerAssets loadViewerAssets(const std::string& data_directory) {
  // $WPG_VIEWER_DIR alone when set; else the build tree first (a rebuilt bundle is seen at
  // once), then the installed data folder.
  std::vector<fs::path> places;
  if (const char* from_env = std::getenv("WPG_VIEWER_DIR"); from_env && *from_env) {
    places.emplace_back(from_env);
  } else {
    if (std::strlen(WPG_VIEWER_BUILD_DIR) > 0) places.emplace_back(WPG_VIEWER_BUILD_DIR);
    places.push_back(fs::path(data_directory) / "analysis" / "viewer");
  }
  for (const fs::path& folder : places) {
    ViewerAssets assets;
    if (readWhole(folder / "wpg_viewer.js", &assets.script) &&
        readWhole(folder / "page.html", &assets.page) && !assets.script.empty()) {
      assets.folder = folder.string();
      return assets;
    }
  }
  std::string looked;
  for (const fs::path& folder : places) looked += (looked.empty() ? "" : ", ") + folder.string();
  throw datasets::InputError(
      "the viewer is not built (no wpg_viewer.js in " + looked +
      "): it is bundled at build time with Node.js and npm; install them (scripts/setup.sh "
      "--with-viewer, or the Debian packages nodejs npm), then reconfigure and build: cmake -S . -B build "
      "-DWPG_BUILD_VIEWER=ON && cmake --build build --target wpg_viewer_bundle");
}

void writeProvenance(Json& json, const std::string& source) {
  const datasets::Provenance provenance = datasets::currentProvenance();
  json.key("provenance").beginObject();
  json.key("version").string(provenance.version);
  json.key("commit").string(provenance.commit);
  json.key("machine").string(provenance.machine);
  json.key("date").string(provenance.date);
  json.key("source").string(source);
  json.endObject();
}

void writeTextFile(const std::string& path, const std::string& text) {
  datasets::TemporaryOutput temporary(path);
  {
    std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw std::runtime_error(path + ": cannot write it");
  }
  temporary.commit();
}

void writePage(const ViewerAssets& assets, const std::string& path, const std::string& data_json,
               const std::string& script_src) {
  const datasets::Provenance provenance = datasets::currentProvenance();
  std::string page = assets.page;
  const std::string where = (fs::path(assets.folder) / "page.html").string();
  replaceOnce(page, "WPG_GENERATOR",
              "wpg " + provenance.version + " (" + provenance.commit + ") on " +
                  provenance.machine + " at " + provenance.date, where);
  replaceOnce(page, "<!--WPG_DATA-->",
              "<script id=\"wpg-data\" type=\"application/json\">" + data_json + "</script>", where);
  // Inline: the bundle holds no "</script" (build.mjs checks it).
  replaceOnce(page, "<!--WPG_SCRIPT-->",
              script_src.empty() ? "<script>" + assets.script + "</script>"
                                 : "<script src=\"" + script_src + "\"></script>", where);
  writeTextFile(path, page);
}

}  // namespace wpg::viewer
