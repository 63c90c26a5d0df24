// emitScalar and emitKey (datasets/input/src/plain_scalar.hpp) write what yaml-cpp's own
// Write(std::string) writes, to the byte: keys and values in block and flow maps, items of flow
// lists, for the numbers of formatNumber and for strings that must be quoted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "../../datasets/input/src/plain_scalar.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace {

using wpg::datasets::detail::emitKey;
using wpg::datasets::detail::emitScalar;

// A block map of key: value, then a flow map of the same, then a block list of flow lists of
// the texts, each text written by `write`.
template <typename WriteKey, typename WriteValue>
std::string document(const std::vector<std::string>& texts, WriteKey write_key,
                     WriteValue write_value) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  for (const std::string& text : texts) {
    write_key(out, "k" + std::to_string(&text - texts.data()));
    write_value(out, text);
  }
  write_key(out, "flow");
  out << YAML::Flow << YAML::BeginMap;
  for (const std::string& text : texts) {
    write_key(out, text.empty() ? std::string("empty") : text);
    write_value(out, text);
  }
  out << YAML::EndMap;
  write_key(out, "lists");
  out << YAML::BeginSeq;
  for (std::size_t i = 0; i < texts.size(); i += 3) {
    out << YAML::Flow << YAML::BeginSeq;
    for (std::size_t j = i; j < std::min(i + 3, texts.size()); ++j) write_value(out, texts[j]);
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
  out << YAML::EndMap;
  EXPECT_TRUE(out.good()) << out.GetLastError();
  return out.c_str();
}

TEST(PlainScalar, WritesWhatYamlCppWrites) {
  std::vector<std::string> texts = {
      "com_height", "push_step_single_support_samples", "fixed", "step_in_place", "0.0",
      "-0.0", "1e-05", "-1.5e+300", "nan", "-nan", "inf", "-inf", ".inf", "-", "-a", "+1",
      "_x", "null", "Null", "NULL", "~", "", "a b", "a:b", "a: b", "#a", "a #b", "[1]", "{a}",
      "a,b", "?a", "'a'", "\"a\"", "*a", "&a", "!a", "|a", ">a", "%a", "@a", "`a", "a\tb",
      "a\nb", "trailing ", " leading", "---", "...", "yes", "True", "0x1F", "1:2",
      "\xc3\xa9t\xc3\xa9", std::string(1100, 'a')};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 300; ++i)
    texts.push_back(wpg::datasets::detail::formatNumber(u(rng) * std::pow(10.0, (i % 41) - 20)));
  texts.push_back(wpg::datasets::detail::formatNumber(std::numeric_limits<double>::denorm_min()));
  texts.push_back(wpg::datasets::detail::formatNumber(std::numeric_limits<double>::max()));
  const std::string expected = document(
      texts, [](YAML::Emitter& out, const std::string& key) { out << YAML::Key << key << YAML::Value; },
      [](YAML::Emitter& out, const std::string& value) { out << value; });
  const std::string got = document(
      texts, [](YAML::Emitter& out, const std::string& key) { emitKey(out, key); },
      [](YAML::Emitter& out, const std::string& value) { emitScalar(out, value); });
  EXPECT_EQ(got, expected);
}

}  // namespace
