#pragma once
// The pages of `wpg view` (docs/viewer.md): the bundled viewer and the HTML template found in
// the build or install tree, the JSON the page reads (compact: large arrays as base64 of
// little-endian float32), and the page written atomically.
#include <cstdint>
#include <string>
#include <vector>

namespace wpg::cli {

// Thrown when the viewer bundle is missing (a build without Node.js): `wpg view` prints the
// message, which says how to build it, and exits 2.
struct ViewerAssets {
  std::string folder;    // where wpg_viewer.js and page.html were found
  std::string script;    // the bundle, to be inlined
  std::string page;      // the template (analysis/viewer/page.html)
};
// The assets of the build tree the executable comes from, else of the installed data folder.
// Throws UsageError naming both places and the way to build the bundle when neither has them.
ViewerAssets loadViewerAssets();

// JSON text, built by appending. Strings are escaped so that the text may sit inside a
// <script> element ('<', '>' and '&' as \u escapes); numbers print with 9 significant digits
// (float32 precision and more), non-finite numbers as null.
class Json {
 public:
  Json& raw(const std::string& text) { text_ += text; return *this; }
  Json& key(const std::string& name);     // "name": (with the comma before it when needed)
  Json& string(const std::string& value);
  Json& number(double value);
  Json& integer(long long value);
  Json& boolean(bool value);
  Json& null();
  Json& beginObject();
  Json& endObject();
  Json& beginArray();
  Json& endArray();
  // The values as base64 of little-endian float32 (the page decodes them into a Float32Array).
  Json& floats(const std::vector<float>& values);
  Json& bytes(const std::vector<std::uint8_t>& values);  // base64 of the bytes
  Json& numbers(const std::vector<double>& values);       // a JSON array
  Json& strings(const std::vector<std::string>& values);  // a JSON array
  const std::string& text() const { return text_; }

 private:
  void separate();
  void quoted(const std::string& value);
  std::string text_;
  std::vector<bool> first_;  // per open object/array: no member written yet
  bool after_key_ = false;
};

std::string base64(const std::uint8_t* data, std::size_t size);

// The provenance object of every page: {"version", "commit", "machine", "date", "source"}.
void writeProvenance(Json& json, const std::string& source);

// The page: the template with the data (a JSON <script>) and the viewer, inline or, when
// `script_src` is not empty, as <script src="script_src"> (the run pages of a study share one
// script file beside them). Written atomically to `path` (its folder created).
void writePage(const ViewerAssets& assets, const std::string& path, const std::string& data_json,
               const std::string& script_src = "");

// Writes `text` to `path` atomically (the shared script of a study's run pages).
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace wpg::cli
