// The JSON of the pages of `wpg view` (page_json.hpp).
#include "wpg/viewer/page_json.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace wpg::viewer {

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

}  // namespace wpg::viewer
