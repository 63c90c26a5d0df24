// Pages of `wpg view`: assets, JSON, base64, atomic writing (view_page.hpp).
#include "view_page.hpp"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cli_common.hpp"
#include "wpg/datasets/output_file.hpp"
#include "wpg/datasets/provenance.hpp"

#ifndef WPG_VIEWER_BUILD_DIR
#define WPG_VIEWER_BUILD_DIR ""
#endif

namespace fs = std::filesystem;

namespace wpg::cli {
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
  if (at == std::string::npos) throw UsageError(where + ": the template has no " + marker);
  text.replace(at, marker.size(), with);
}

}  // namespace

ViewerAssets loadViewerAssets() {
  // $WPG_VIEWER_DIR alone when set; else the build tree first (a rebuilt bundle is seen at
  // once), then the installed data folder.
  std::vector<fs::path> places;
  if (const char* from_env = std::getenv("WPG_VIEWER_DIR"); from_env && *from_env) {
    places.emplace_back(from_env);
  } else {
    if (std::strlen(WPG_VIEWER_BUILD_DIR) > 0) places.emplace_back(WPG_VIEWER_BUILD_DIR);
    places.push_back(fs::path(dataDirectory()) / "analysis" / "viewer");
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
  throw UsageError(
      "the viewer is not built (no wpg_viewer.js in " + looked +
      "): it is bundled at build time with Node.js and npm; install them (scripts/setup.sh, or "
      "the Debian packages nodejs npm), then reconfigure and build: cmake -S . -B build "
      "-DWPG_BUILD_VIEWER=ON && cmake --build build --target wpg_viewer_bundle");
}

// --- JSON -----------------------------------------------------------------------------------

void Json::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) text_ += ',';
    first_.back() = false;
  }
}

Json& Json::key(const std::string& name) {
  separate();
  quoted(name);
  text_ += ':';
  after_key_ = true;
  return *this;
}

Json& Json::string(const std::string& value) {
  separate();
  quoted(value);
  return *this;
}

void Json::quoted(const std::string& value) {
  text_ += '"';
  for (const unsigned char c : value) {
    switch (c) {
      case '"': text_ += "\\\""; break;
      case '\\': text_ += "\\\\"; break;
      case '\n': text_ += "\\n"; break;
      case '\t': text_ += "\\t"; break;
      case '\r': text_ += "\\r"; break;
      default:
        if (c < 0x20 || c == '<' || c == '>' || c == '&') {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
          text_ += escaped;
        } else {
          text_ += static_cast<char>(c);
        }
    }
  }
  text_ += '"';
}

Json& Json::number(double value) {
  separate();
  if (!std::isfinite(value)) {
    text_ += "null";
    return *this;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  text_ += text;
  return *this;
}

Json& Json::integer(long long value) {
  separate();
  text_ += std::to_string(value);
  return *this;
}

Json& Json::boolean(bool value) {
  separate();
  text_ += value ? "true" : "false";
  return *this;
}

Json& Json::null() {
  separate();
  text_ += "null";
  return *this;
}

Json& Json::beginObject() {
  separate();
  text_ += '{';
  first_.push_back(true);
  return *this;
}

Json& Json::endObject() {
  text_ += '}';
  first_.pop_back();
  return *this;
}

Json& Json::beginArray() {
  separate();
  text_ += '[';
  first_.push_back(true);
  return *this;
}

Json& Json::endArray() {
  text_ += ']';
  first_.pop_back();
  return *this;
}

Json& Json::floats(const std::vector<float>& values) {
  // Little-endian float32, whatever the machine: the page reads it into a Float32Array.
  std::vector<std::uint8_t> bytes(4 * values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &values[i], 4);
    for (int b = 0; b < 4; ++b) bytes[4 * i + b] = static_cast<std::uint8_t>(bits >> (8 * b));
  }
  return this->bytes(bytes);
}

Json& Json::bytes(const std::vector<std::uint8_t>& values) {
  separate();
  text_ += '"';
  text_ += base64(values.data(), values.size());
  text_ += '"';
  return *this;
}

Json& Json::numbers(const std::vector<double>& values) {
  beginArray();
  for (const double value : values) number(value);
  return endArray();
}

Json& Json::strings(const std::vector<std::string>& values) {
  beginArray();
  for (const std::string& value : values) string(value);
  return endArray();
}

std::string base64(const std::uint8_t* data, std::size_t size) {
  static const char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve(4 * ((size + 2) / 3));
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const std::uint32_t word = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    for (int shift = 18; shift >= 0; shift -= 6) text += kAlphabet[(word >> shift) & 63];
  }
  if (i < size) {
    const std::uint32_t word = (data[i] << 16) | (i + 1 < size ? data[i + 1] << 8 : 0);
    text += kAlphabet[(word >> 18) & 63];
    text += kAlphabet[(word >> 12) & 63];
    text += i + 1 < size ? kAlphabet[(word >> 6) & 63] : '=';
    text += '=';
  }
  return text;
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

// --- writing ----------------------------------------------------------------------------------

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

}  // namespace wpg::cli
