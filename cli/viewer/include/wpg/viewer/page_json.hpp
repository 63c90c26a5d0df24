#pragma once
// The JSON a page of `wpg view` reads, built by appending: compact, with the large per-sample
// arrays as base64 of little-endian float32 (a third of their decimal text).
#include <cstdint>
#include <string>
#include <vector>

namespace wpg::viewer {

// JSON text. Strings are escaped so that the text may sit inside a <script> element ('<', '>'
// and '&' as \u escapes); numbers print with 9 significant digits (float32 precision and
// more), non-finite numbers as null.
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

}  // namespace wpg::viewer
