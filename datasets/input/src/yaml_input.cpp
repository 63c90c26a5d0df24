// Typed YAML readers (yaml_input.hpp): strict on purpose. A typo in a key, a string where a
// number belongs or a NaN must stop the run with a message naming the file and the key, never
// be ignored silently (a batch of a thousand runs with a misspelled parameter is worse than no
// batch).
#include "wpg/datasets/input/yaml_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::datasets::detail {
namespace {

namespace fs = std::filesystem;

std::string shortened(const std::string& text, std::size_t max_length = 80) {
  if (text.size() <= max_length) return text;
  return text.substr(0, max_length - 3) + "...";
}

// `outer` is `inner` or one of its parents (dotted path / list index).
bool encloses(const std::string& outer, const std::string& inner) {
  if (inner.compare(0, outer.size(), outer) != 0) return false;
  return inner.size() == outer.size() || inner[outer.size()] == '.' ||
         inner[outer.size()] == '[';
}

// YAML's non-finite spellings (.inf, -.Inf, .NaN, ...) and the bare C ones.
bool isNonFiniteSpelling(const std::string& text) {
  static const std::set<std::string> spellings = {
      ".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF", "-.inf", "-.Inf", "-.INF",
      ".nan", ".NaN", ".NAN", "inf",   "-inf",  "+inf",  "nan",   "NaN",   "Infinity",
      "-Infinity"};
  return spellings.count(text) > 0;
}

}  // namespace

// ------------------------------------------------------------------------------------------
// Text
// ------------------------------------------------------------------------------------------

std::string oneLine(std::string text) { return escapeControlCharacters(text); }

std::string joinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string childKey(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "." + name;
}

std::string indexKey(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string renameOverrides(std::string message, const std::string& what) {
  for (std::size_t at = message.find("--set '"); at != std::string::npos;
       at = message.find("--set '", at + what.size())) {
    message.replace(at, 5, what);
  }
  return message;
}

bool isQuoted(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "!"; }

std::string describe(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing (the key is missing)";
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "null (no value)";
    case YAML::NodeType::Scalar:
      if (isQuoted(node)) return "the string \"" + shortened(oneLine(node.Scalar()), 60) + "\"";
      return shortened(oneLine(node.Scalar()), 60);
    case YAML::NodeType::Sequence:
    case YAML::NodeType::Map: {
      YAML::Emitter flow;
      flow.SetMapFormat(YAML::Flow);
      flow.SetSeqFormat(YAML::Flow);
      flow << node;
      const std::string what = node.IsSequence()
                                   ? "a list of " + std::to_string(node.size()) + " entries "
                                   : std::string("a map ");
      return what + shortened(oneLine(flow.c_str()), 60);
    }
    case YAML::NodeType::Undefined:
      break;
  }
  return "nothing";
}

std::string formatNumber(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  std::string text(buffer.data(), result.ptr);
  if (text.find_first_of(".ein") == std::string::npos) return text + ".0";
  const std::size_t e = text.find('e');
  if (e != std::string::npos && text.find('.') == std::string::npos) text.insert(e, ".0");
  return text;
}

// ------------------------------------------------------------------------------------------
// Source
// ------------------------------------------------------------------------------------------

void Source::fail(const std::string& key, const std::string& expected,
                  const YAML::Node& got) const {
  failWith(key, "expected " + expected + ", got " + describe(got));
}

void Source::failWith(const std::string& key, const std::string& message) const {
  throw InputError(oneLine(file_ + ": key '" + key + "': " + message + overrideNote(key)));
}

void Source::failFile(const std::string& message) const {
  throw InputError(oneLine(file_ + ": " + message));
}

void Source::failChecked(const std::string& message, const std::string& prefix) const {
  // Every text between two neighbouring quotes that is shaped as a key (an apostrophe in the
  // prose makes its neighbours prose, with spaces: never a key).
  const auto key_shaped = [](const std::string& text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
             return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
                    c == '[' || c == ']' || c == '/';
           });
  };
  std::string note;
  for (std::size_t open = message.find('\''); open != std::string::npos && note.empty();) {
    const std::size_t close = message.find('\'', open + 1);
    if (close == std::string::npos) break;
    const std::string names = message.substr(open + 1, close - open - 1);
    for (std::size_t start = 0; key_shaped(names) && start < names.size() && note.empty();) {
      const std::size_t slash = std::min(names.find('/', start), names.size());
      const std::string name = names.substr(start, slash - start);
      if (!name.empty()) {
        note = overrideNote(prefix + name);
        if (note.empty()) note = overrideNote(name);
      }
      start = slash + 1;
    }
    open = close;
  }
  throw InputError(oneLine(file_ + ": " + message + note));
}

std::string Source::warning(const std::string& key, const std::string& message) const {
  return oneLine(file_ + ": key '" + key + "': " + message + overrideNote(key));
}

std::string Source::overrideNote(const std::string& key) const {
  for (const AppliedOverride& applied : overrides_) {
    // The bad key is the override's key, lies below it, or holds it (a list that an
    // override lengthened).
    if (encloses(applied.key, key) || encloses(key, applied.key)) {
      return " (set by --set '" + applied.text + "')";
    }
  }
  return "";
}

// ------------------------------------------------------------------------------------------
// Typed readers
// ------------------------------------------------------------------------------------------

double readNumber(const YAML::Node& node, const std::string& key, const std::string& expected,
                  const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  std::string text = node.Scalar();
  if (isNonFiniteSpelling(text)) {
    source.failWith(key, "expected " + expected + ", got " + text + " (not a finite number)");
  }
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(begin, end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end) {
    source.fail(key, expected, node);
  }
  if (!std::isfinite(value)) {
    source.failWith(key, "expected " + expected + ", got " + text + " (not a finite number)");
  }
  return value;
}

double readNumberAtLeast(const YAML::Node& node, const std::string& key, double minimum,
                         const std::string& expected, const Source& source) {
  const double value = readNumber(node, key, expected, source);
  if (value < minimum) source.fail(key, expected, node);
  return value;
}

double readPositive(const YAML::Node& node, const std::string& key, const std::string& expected,
                    const Source& source) {
  const double value = readNumber(node, key, expected, source);
  if (!(value > 0.0)) source.fail(key, expected, node);
  return value;
}

int readInteger(const YAML::Node& node, const std::string& key, int minimum,
                const std::string& expected, const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  std::string text = node.Scalar();
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  int value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end || value < minimum) {
    source.fail(key, expected, node);
  }
  return value;
}

bool readBoolean(const YAML::Node& node, const std::string& key, const std::string& expected,
                 const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  const std::string& text = node.Scalar();
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  source.fail(key, expected, node);
}

void checkMagnitude(double value, double limit, const char* unit, const YAML::Node& got,
                    const std::string& key, const std::string& expected, const Source& source) {
  if (std::abs(value) <= limit) return;
  source.failWith(key, "expected " + expected + " of magnitude at most " + formatNumber(limit) +
                           " " + unit + " (SCENARIOS.md, \"Limits\"), got " + describe(got));
}

double readLength(const YAML::Node& node, const std::string& key, const std::string& expected,
                  const Source& source) {
  const double value = readNumber(node, key, expected, source);
  checkMagnitude(value, kMaxLength, "m", node, key, expected, source);
  return value;
}

void checkLengthEntry(double value, const YAML::Node& got, const std::string& key,
                      const Source& source) {
  checkMagnitude(value, kMaxLength, "m", got, key, "a length or coordinate", source);
}

std::string readName(const YAML::Node& node, const std::string& key, const std::string& expected,
                     const Source& source, std::size_t max_length) {
  if (!node.IsDefined() || !node.IsScalar()) source.fail(key, expected, node);
  const std::string& text = node.Scalar();
  const bool plain = !text.empty() && text.size() <= max_length && text != "." &&
                     text != ".." &&
                     text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789_-.") == std::string::npos;
  if (!plain) source.fail(key, expected, node);
  return text;
}

std::string describeDocument(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "an empty file";
  if (node.IsScalar())
    return "a single text of " + std::to_string(node.Scalar().size()) + " characters (not a map)";
  if (node.IsSequence()) return "a list of " + std::to_string(node.size()) + " entries (not a map)";
  return describe(node);
}

Entries readMap(const YAML::Node& node, const std::string& key,
                const std::vector<std::string>& known_keys, const std::string& expected,
                const Source& source, bool null_is_empty) {
  Entries entries;
  if (null_is_empty && node.IsDefined() && node.IsNull()) return entries;
  if (!node.IsDefined() || !node.IsMap()) {
    if (key.empty()) source.failFile("expected " + expected + ", got " + describeDocument(node));
    source.fail(key, expected, node);
  }
  for (const auto& pair : node) {
    if (!pair.first.IsScalar()) {
      source.fail(key.empty() ? "<top level>" : key, "keys that are plain names",
                  pair.first);
    }
    const std::string name = pair.first.Scalar();
    const std::string full = childKey(key, name);
    bool known = false;
    for (const std::string& k : known_keys) known = known || k == name;
    if (!known) {
      source.failWith(full, "unknown key (a typo?)" + didYouMean(name, known_keys) +
                                "; known keys" +
                                (key.empty() ? std::string() : " of '" + key + "'") + ": " +
                                joinNames(known_keys));
    }
    if (!entries.emplace(name, pair.second).second) {
      source.failWith(full, "appears twice; give each key once");
    }
  }
  return entries;
}

YAML::Node entry(const Entries& entries, const std::string& name) {
  const auto it = entries.find(name);
  if (it == entries.end()) return YAML::Node(YAML::NodeType::Undefined);
  return it->second;
}

bool present(const Entries& entries, const std::string& name) {
  const auto it = entries.find(name);
  return it != entries.end() && !it->second.IsNull();
}

// ------------------------------------------------------------------------------------------
// Documents
// ------------------------------------------------------------------------------------------

namespace {

// Ignores every event: only the number of documents is wanted.
class DocumentCounter : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

}  // namespace

int countYamlDocuments(const std::string& text, int limit) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentCounter ignore;
  int count = 0;
  while (count < limit && parser.HandleNextDocument(ignore)) ++count;
  return count;
}

YAML::Node parseYamlText(const std::string& text, const std::string& origin) {
  try {
    if (countYamlDocuments(text, 2) > 1) {
      throw InputError(oneLine(origin) +
                       ": expected one YAML document, got several (separated by '---')");
    }
    return YAML::Load(text);  // the only document (null when the text has none)
  } catch (const YAML::DeepRecursion& error) {
    throw InputError(oneLine(origin + ": line " + std::to_string(error.mark.line + 1) +
                             ": expected lists and maps nested less deeply (the YAML reader "
                             "stops past a few hundred levels; SCENARIOS.md, \"Limits\")"));
  } catch (const YAML::Exception& error) {
    std::string where;
    if (!error.mark.is_null()) {
      where = "line " + std::to_string(error.mark.line + 1) + ", column " +
              std::to_string(error.mark.column + 1) + ": ";
    }
    throw InputError(oneLine(origin + ": " + where + "YAML syntax error: " + error.msg));
  }
}

std::string readTextFile(const std::string& path, const std::string& what) {
  const std::string shown = oneLine(path);
  const auto cannot = [&](const std::string& why) {
    return InputError(shown + ": cannot read the " + what + ": " + why);
  };
  // Opened without blocking (a FIFO without a writer would wait forever), then checked on
  // the open descriptor: only a regular file of bounded size is read, and never past the cap
  // (a file that grows while read, or /proc files that report size 0).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw cannot(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw cannot(std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw cannot("it is a directory");
  const std::string too_large = "expected a file of at most " +
                                std::to_string(kMaxInputFileBytes >> 20) +
                                " MiB (SCENARIOS.md, \"Limits\")";
  if (!S_ISREG(info.st_mode)) {
    throw cannot("expected a regular file, got a device, FIFO or socket");
  }
  if (static_cast<unsigned long long>(info.st_size) > kMaxInputFileBytes) {
    throw cannot(too_large + ", got " + std::to_string(info.st_size) + " bytes");
  }
  std::string text;
  std::array<char, 65536> buffer{};
  while (true) {
    const ssize_t count = ::read(fd, buffer.data(), buffer.size());
    if (count < 0) {
      if (errno == EINTR) continue;
      throw cannot(std::strerror(errno));
    }
    if (count == 0) break;
    text.append(buffer.data(), static_cast<std::size_t>(count));
    if (text.size() > kMaxInputFileBytes) throw cannot(too_large);
  }
  return text;
}

YAML::Node readYamlFile(const std::string& path, const std::string& what) {
  return parseYamlText(readTextFile(path, what), path);
}

}  // namespace wpg::datasets::detail
