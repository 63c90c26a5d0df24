// Nearest known name to a mistyped one (nearest_name.hpp).
#include "wpg/nearest_name.hpp"

#include <algorithm>

namespace wpg {

std::string asciiLower(std::string text) {
  for (char& c : text) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return text;
}

std::size_t nameDistance(const std::string& a_text, const std::string& b_text) {
  const std::string a = asciiLower(a_text), b = asciiLower(b_text);
  // d[i][j]: distance between the first i letters of a and the first j of b (optimal string
  // alignment: a swap of neighbours counts one edit).
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

std::string nearestName(const std::string& given, const std::vector<std::string>& known) {
  std::string nearest;
  std::size_t best = 0;
  bool tie = false;
  for (const std::string& name : known) {
    const std::size_t distance = nameDistance(given, name);
    const std::size_t allowed = std::max<std::size_t>(1, std::max(given.size(), name.size()) / 3);
    if (distance > allowed) continue;
    if (nearest.empty() || distance < best) {
      nearest = name;
      best = distance;
      tie = false;
    } else if (distance == best && name != nearest) {
      tie = true;
    }
  }
  if (!nearest.empty() || tie) return tie ? std::string() : nearest;
  // A shortened name ("max_step_yaw" for "max_step_yaw_change"): the one known name it begins.
  const std::string lower = asciiLower(given);
  if (lower.size() < 3) return "";
  for (const std::string& name : known) {
    if (asciiLower(name).compare(0, lower.size(), lower) != 0) continue;
    if (!nearest.empty()) return "";  // the beginning of several
    nearest = name;
  }
  return nearest;
}

std::string didYouMean(const std::string& given, const std::vector<std::string>& known) {
  const std::string nearest = nearestName(given, known);
  return nearest.empty() ? std::string() : "; did you mean '" + nearest + "'?";
}

}  // namespace wpg
