#pragma once
// Strict, typed reading of YAML input (scenario files, robot files, --set values). Every
// reader takes the key it reads (a dotted path such as `reference[1].v`) and a Source, so that
// a bad value stops with one InputError line naming the file, the key, what was expected and
// what came, never with a value silently ignored or defaulted.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/input_limits.hpp"

namespace wpg::datasets::detail {

// --- text ------------------------------------------------------------------------------------

std::string oneLine(std::string text);  // control characters escaped (\n, \x1b): messages are one line
std::string joinNames(const std::vector<std::string>& names);  // "a, b, c"
std::string childKey(const std::string& parent, const std::string& name);  // parent.name
std::string indexKey(const std::string& parent, std::size_t index);        // parent[index]

// A quoted scalar ("10", '0.2') is a string for us even when its text is a number.
bool isQuoted(const YAML::Node& node);

// What a node is, for "got ..." in messages.
// A whole document that should have been a map, described without quoting it ("a single text
// of 1234 characters"): the file may be anything (a `base:` naming /etc/passwd).
std::string describeDocument(const YAML::Node& node);
std::string describe(const YAML::Node& node);

// Shortest text that reads back to the same double, always recognisable as a float by YAML
// readers (PyYAML needs a dot: "10.0", "1.0e-05").
std::string formatNumber(double value);

// `message` with each "--set '" of a Source's note called `what` instead ("sweep '..."): a
// study's values reach the loader as --set overrides.
std::string renameOverrides(std::string message, const std::string& what);

// --- where an error comes from: the file, and the --set overrides that changed its tree ----

struct AppliedOverride {
  std::string key;   // canonical dotted path, e.g. reference[1].v
  std::string text;  // as given, key=value
};

class Source {
 public:
  explicit Source(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  void addOverride(AppliedOverride applied) { overrides_.push_back(std::move(applied)); }

  // "<file>: key '<key>': expected <expected>, got <what came>"
  [[noreturn]] void fail(const std::string& key, const std::string& expected,
                         const YAML::Node& got) const;
  [[noreturn]] void failWith(const std::string& key, const std::string& message) const;
  [[noreturn]] void failFile(const std::string& message) const;
  // "<file>: <message>" of a check over several keys (libwpg's validate()), whose message
  // quotes the keys it is about ("'duration': ...", "walking parameter 'weight_cop': ..."): with
  // the note of the --set that set one of them, each quoted name tried as `prefix` + name, then
  // as it is ("a/b" names two keys).
  [[noreturn]] void failChecked(const std::string& message, const std::string& prefix = "") const;
  // A warning line in the errors' form: "<file>: key '<key>': <message>" (and the --set).
  std::string warning(const std::string& key, const std::string& message) const;

 private:
  // Points at the --set that produced a bad value, since the file itself may be fine.
  std::string overrideNote(const std::string& key) const;

  std::string file_;
  std::vector<AppliedOverride> overrides_;
};

// --- typed readers; `node` may be undefined (missing key): the message then says so --------

double readNumber(const YAML::Node& node, const std::string& key, const std::string& expected,
                  const Source& source);
double readNumberAtLeast(const YAML::Node& node, const std::string& key, double minimum,
                         const std::string& expected, const Source& source);
double readPositive(const YAML::Node& node, const std::string& key, const std::string& expected,
                    const Source& source);
int readInteger(const YAML::Node& node, const std::string& key, int minimum,
                const std::string& expected, const Source& source);
// YAML 1.2's core booleans; quoted text is a string, and yes/no/on/off (YAML 1.1) are not
// accepted: they read as strings in other YAML readers.
bool readBoolean(const YAML::Node& node, const std::string& key, const std::string& expected,
                 const Source& source);
// A length or a position [m]: a finite number of magnitude at most kMaxLength
// (input_limits.hpp), so that squares and sums of coordinates stay finite.
double readLength(const YAML::Node& node, const std::string& key, const std::string& expected,
                  const Source& source);
// Fails on `key` unless |value| <= limit; `unit` says in what (e.g. "m"). `got` is the node read.
void checkMagnitude(double value, double limit, const char* unit, const YAML::Node& got,
                    const std::string& key, const std::string& expected, const Source& source);
// Names become folder names (robot) and HDF5 group names (scenario): kept plain, and at most
// kMaxNameLength characters.
std::string readName(const YAML::Node& node, const std::string& key, const std::string& expected,
                     const Source& source, std::size_t max_length = kMaxNameLength);

// Fails on `key` unless |value| <= kMaxLength (an entry of a vector of lengths).
void checkLengthEntry(double value, const YAML::Node& got, const std::string& key,
                      const Source& source);

template <int Size>
Eigen::Matrix<double, Size, 1> readVector(const YAML::Node& node, const std::string& key,
                                          const std::string& expected, const Source& source) {
  if (!node.IsDefined() || !node.IsSequence() || node.size() != static_cast<std::size_t>(Size)) {
    source.fail(key, expected, node);
  }
  Eigen::Matrix<double, Size, 1> vector;
  for (int i = 0; i < Size; ++i) {
    vector[i] = readNumber(node[static_cast<std::size_t>(i)], indexKey(key, i), "a number", source);
  }
  return vector;
}

// A vector of lengths or positions [m], each checked as readLength.
template <int Size>
Eigen::Matrix<double, Size, 1> readLengthVector(const YAML::Node& node, const std::string& key,
                                                const std::string& expected,
                                                const Source& source) {
  const Eigen::Matrix<double, Size, 1> vector = readVector<Size>(node, key, expected, source);
  for (int i = 0; i < Size; ++i) {
    const std::size_t index = static_cast<std::size_t>(i);
    checkLengthEntry(vector[i], node[index], indexKey(key, index), source);
  }
  return vector;
}

// The entries of a map, checked: keys are plain scalars, not repeated, all known. A map is
// required; `null_is_empty` accepts `key:` with no value as an empty map (optional sections).
using Entries = std::map<std::string, YAML::Node>;

Entries readMap(const YAML::Node& node, const std::string& key,
                const std::vector<std::string>& known_keys, const std::string& expected,
                const Source& source, bool null_is_empty = false);

// The entry `name` of `entries`, or an undefined node (missing key).
YAML::Node entry(const Entries& entries, const std::string& name);
// `name` is given with a value (not missing, not null).
bool present(const Entries& entries, const std::string& name);

// --- whole documents, syntax errors reported by line ---------------------------------------

// `text` parsed as one YAML document; `origin` names it in messages.
YAML::Node parseYamlText(const std::string& text, const std::string& origin);

// The number of YAML documents in `text`, counting no further than `limit` (throws
// YAML::Exception on a syntax error). Use it, not YAML::LoadAll: on some malformed texts (a
// lone ',') yaml-cpp 0.7 returns empty documents forever, and LoadAll grows its list until
// memory runs out (found by tests/fuzz/fuzz_scenario_loader).
int countYamlDocuments(const std::string& text, int limit);
// The text of the file at `path`; `what` says what it is in messages ("scenario file").
// Throws InputError naming the file (missing, a folder, unreadable).
std::string readTextFile(const std::string& path, const std::string& what);
// The file at `path` parsed as one YAML document.
YAML::Node readYamlFile(const std::string& path, const std::string& what);

}  // namespace wpg::datasets::detail
