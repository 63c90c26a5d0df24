// The scenario's sections and the robot file (scenario_sections.hpp).
#include "scenario_sections.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "parameter_fields.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/datasets/input/robot_file.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::datasets::detail {
namespace {

namespace fs = std::filesystem;

// The entries of the list `node` (key `key`), each read by
// `read_entry(item, "key[i]", the entries read so far)`. A missing or null list is empty when
// `optional`; anything but a list fails with `expected`.
template <typename T, typename ReadEntry>
std::vector<T> readList(const YAML::Node& node, const std::string& key, bool optional,
                        const std::string& expected, const Source& source,
                        ReadEntry read_entry) {
  std::vector<T> items;
  if (optional && (!node.IsDefined() || node.IsNull())) return items;
  if (!node.IsDefined() || !node.IsSequence()) source.fail(key, expected, node);
  for (std::size_t i = 0; i < node.size(); ++i) {
    items.push_back(read_entry(node[i], indexKey(key, i), items));
  }
  return items;
}

// Shape checks owned by libwpg (convexity, degenerate polygons). Their message reads
// "'<key>': expected <field>: <what>"; ours names the field's key instead.
void validateObstacle(const Obstacle& obstacle, const std::string& key, const Source& source) {
  try {
    obstacle.validate(key);
  } catch (const std::invalid_argument& error) {
    std::string message = error.what();
    std::string field_key = key;
    const std::string prefix = "'" + key + "': ";
    if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
    const std::string expected = "expected ";
    const std::size_t colon = message.find(": ");
    if (message.compare(0, expected.size(), expected) == 0 && colon != std::string::npos) {
      const std::string field = message.substr(expected.size(), colon - expected.size());
      if (!field.empty() &&
          field.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos) {
        field_key = childKey(key, field);
        message = expected + message.substr(colon + 2);
      }
    }
    source.failWith(field_key, message);
  }
}

// One entry of `obstacles:`; the keys depend on the type, read first.
Obstacle readObstacle(const YAML::Node& item, const std::string& key, const Source& source,
                      bool* known_to_planner) {
  const std::string map_expected = "a map {type: circle, box or polygon, ...} (SCENARIOS.md)";
  if (!item.IsMap()) source.fail(key, map_expected, item);
  // (A missing key of a const map is an invalid node: replace it by an undefined one.)
  const YAML::Node found_type = item["type"];
  const YAML::Node type_node =
      found_type.IsDefined() ? found_type : YAML::Node(YAML::NodeType::Undefined);
  Obstacle obstacle;
  std::vector<std::string> keys;
  const std::string type = type_node.IsScalar() ? type_node.Scalar() : "";
  if (type == "circle") {
    obstacle.type = ObstacleType::kCircle;
    keys = {"type", "center", "radius", "margin", "known_to_planner"};
  } else if (type == "box") {
    obstacle.type = ObstacleType::kBox;
    keys = {"type", "center", "size", "yaw", "margin", "known_to_planner"};
  } else if (type == "polygon") {
    obstacle.type = ObstacleType::kPolygon;
    keys = {"type", "vertices", "margin", "known_to_planner"};
  } else {
    source.fail(key + ".type", "circle, box or polygon", type_node);
  }
  const Entries entries = readMap(item, key, keys, map_expected, source);
  if (obstacle.type == ObstacleType::kCircle || obstacle.type == ObstacleType::kBox) {
    obstacle.center = readLengthVector<2>(entry(entries, "center"), key + ".center",
                                    "[x, y] in m, world frame (2 numbers)", source);
  }
  if (obstacle.type == ObstacleType::kCircle) {
    obstacle.radius =
        readPositive(entry(entries, "radius"), key + ".radius", "a positive radius in m", source);
    checkMagnitude(obstacle.radius, kMaxLength, "m", entry(entries, "radius"), key + ".radius",
                   "a positive radius in m", source);
  }
  if (obstacle.type == ObstacleType::kBox) {
    const std::string size_expected = "[length along its x, width] in m (2 positive numbers)";
    obstacle.size =
        readLengthVector<2>(entry(entries, "size"), key + ".size", size_expected, source);
    if (!(obstacle.size.minCoeff() > 0.0))
      source.fail(key + ".size", size_expected, entry(entries, "size"));
    if (present(entries, "yaw")) {
      obstacle.yaw = readNumber(entry(entries, "yaw"), key + ".yaw", "an angle in rad", source);
    }
  }
  if (obstacle.type == ObstacleType::kPolygon) {
    const std::string vertices_expected =
        "a list of at least 3 [x, y] vertices in m, world frame, of a convex polygon";
    const YAML::Node vertices = entry(entries, "vertices");
    if (!vertices.IsDefined() || !vertices.IsSequence() || vertices.size() < 3) {
      source.fail(key + ".vertices", vertices_expected, vertices);
    }
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      obstacle.vertices.push_back(readLengthVector<2>(vertices[v], indexKey(key + ".vertices", v),
                                                "[x, y] in m (2 numbers)", source));
    }
  }
  if (present(entries, "margin")) {
    obstacle.margin = readNumberAtLeast(entry(entries, "margin"), key + ".margin", 0.0,
                                        "a distance >= 0 in m", source);
    checkMagnitude(obstacle.margin, kMaxLength, "m", entry(entries, "margin"), key + ".margin",
                   "a distance >= 0 in m", source);
  }
  // Walks to a goal: an obstacle the route planner learns of only once sensed; the NMPC
  // avoids it either way.
  *known_to_planner = true;
  if (present(entries, "known_to_planner")) {
    *known_to_planner = readBoolean(entry(entries, "known_to_planner"), key + ".known_to_planner",
                                    "true or false", source);
  }
  validateObstacle(obstacle, key, source);
  return obstacle;
}

}  // namespace

const std::vector<std::string>& topLevelKeys() {
  static const std::vector<std::string> keys = {
      "name",   "robot",     "duration", "robot_mass", "generator",      "reference",
      "pushes", "obstacles", "walking",  "replay",     "filter",         "filter_settings",
      "goal",   "planner",   "constraints", "costs"};
  return keys;
}

GeneratorSettings readGenerator(const YAML::Node& node, const Source& source) {
  GeneratorSettings settings;
  if (!node.IsDefined()) return settings;
  std::vector<std::string> keys = {"algorithm"};
  for (const std::string& name : settingNames(generatorSettingFields())) keys.push_back(name);
  keys.push_back("stop_when_blocked");
  keys.push_back("record_plan");
  const Entries entries = readMap(node, "generator", keys, "a map of generator settings", source,
                                  /*null_is_empty=*/true);
  if (present(entries, "algorithm")) {
    const YAML::Node algorithm = entry(entries, "algorithm");
    if (!algorithm.IsScalar() ||
        !parseGeneratorAlgorithm(asciiLower(algorithm.Scalar()), &settings.algorithm)) {
      source.failWith("generator.algorithm",
                      "expected nmpc or lmpc, got " + describe(algorithm) +
                          (algorithm.IsScalar() ? didYouMean(algorithm.Scalar(), {"nmpc", "lmpc"})
                                                : std::string()));
    }
  }
  readSettingFields(entries, "generator", generatorSettingFields(), source, &settings);
  if (present(entries, "stop_when_blocked")) {
    settings.stop_when_blocked =
        readBoolean(entry(entries, "stop_when_blocked"), "generator.stop_when_blocked",
                    "true or false", source);
  }
  if (present(entries, "record_plan")) {
    settings.record_plan = readBoolean(entry(entries, "record_plan"), "generator.record_plan",
                                       "true or false", source);
  }
  return settings;
}

PreviewControlSettings readFilterSettings(const YAML::Node& node, const Source& source,
                                          DynamicFilterLoopSettings* loop) {
  PreviewControlSettings settings;
  if (!node.IsDefined()) return settings;
  std::vector<std::string> keys = settingNames(filterSettingFields());
  keys.push_back("mode");
  keys.push_back("reinitialize_wpg");
  keys.push_back("online_input_weight");
  const Entries entries = readMap(node, "filter_settings", keys,
                                  "a map {error_weight, input_weight, preview_time, mode, "
                                  "reinitialize_wpg, online_input_weight}",
                                  source, /*null_is_empty=*/true);
  readSettingFields(entries, "filter_settings", filterSettingFields(), source, &settings);
  if (present(entries, "mode")) {
    const YAML::Node mode = entry(entries, "mode");
    if (!mode.IsScalar() || !parseDynamicFilterMode(asciiLower(mode.Scalar()), &loop->mode)) {
      source.failWith(
          "filter_settings.mode",
          "expected online, offline, both or closed_loop, got " + describe(mode) +
              (mode.IsScalar()
                   ? didYouMean(mode.Scalar(), {"online", "offline", "both", "closed_loop"})
                   : std::string()));
    }
  }
  if (present(entries, "reinitialize_wpg")) {
    loop->reinitialize_wpg = readBoolean(entry(entries, "reinitialize_wpg"),
                                         "filter_settings.reinitialize_wpg", "true or false",
                                         source);
    // closed_loop is its own re-initialisation (wpg/dynamic_filter.hpp): one or the other.
    if (loop->reinitialize_wpg && loop->mode == DynamicFilterMode::kClosedLoop) {
      source.fail("filter_settings.reinitialize_wpg",
                  "false with mode closed_loop (closed_loop re-initialises the WPG its own way)",
                  entry(entries, "reinitialize_wpg"));
    }
  }
  if (present(entries, "online_input_weight")) {
    loop->online_input_weight =
        readPositive(entry(entries, "online_input_weight"), "filter_settings.online_input_weight",
                     "a positive weight (R of the online loop)", source);
  }
  return settings;
}

std::vector<VelocityCommand> readReference(const YAML::Node& node, const Source& source) {
  const auto read_command = [&source](const YAML::Node& item, const std::string& key,
                                      const std::vector<VelocityCommand>& before) {
    const Entries entries =
        readMap(item, key, {"t", "v"}, "a map {t: seconds, v: [vx, vy, omega]}", source);
    VelocityCommand command;
    command.t = readNumberAtLeast(entry(entries, "t"), key + ".t", 0.0,
                                  "a time >= 0 in seconds", source);
    if (!before.empty() && !(command.t > before.back().t)) {
      source.fail(key + ".t",
                  "a time after " + indexKey("reference", before.size() - 1) + ".t = " +
                      formatNumber(before.back().t) + " s (times strictly ascending)",
                  entry(entries, "t"));
    }
    command.velocity = readVector<3>(entry(entries, "v"), key + ".v",
                                     "[vx m/s, vy m/s, omega rad/s] (3 numbers)", source);
    return command;
  };
  return readList<VelocityCommand>(
      node, "reference", /*optional=*/false,
      "a list of {t: seconds, v: [vx, vy, omega]} entries (may be empty: stand still)", source,
      read_command);
}

std::vector<Push> readPushes(const YAML::Node& node, const Source& source) {
  const auto read_push = [&source](const YAML::Node& item, const std::string& key,
                                   const std::vector<Push>&) {
    const Entries entries = readMap(item, key, {"t", "force", "duration"},
                                    "a map {t: s, force: [fx, fy] N, duration: s}", source);
    Push push;
    push.t = readNumberAtLeast(entry(entries, "t"), key + ".t", 0.0, "a time >= 0 in seconds",
                               source);
    push.force = readVector<2>(entry(entries, "force"), key + ".force",
                               "[fx, fy] in N, world frame (2 numbers)", source);
    for (std::size_t i = 0; i < 2; ++i) {
      checkMagnitude(push.force[static_cast<int>(i)], kMaxPushForce, "N",
                     entry(entries, "force")[i], indexKey(key + ".force", i), "a force", source);
    }
    if (present(entries, "duration")) {
      push.duration = readPositive(entry(entries, "duration"), key + ".duration",
                                   "a positive duration in seconds", source);
    }
    return push;
  };
  return readList<Push>(node, "pushes", /*optional=*/true,
                        "a list of {t: s, force: [fx, fy] N, duration: s} entries", source,
                        read_push);
}

std::vector<Obstacle> readObstacles(const YAML::Node& node, const Source& source,
                                    std::vector<bool>* known_to_planner) {
  if (known_to_planner) known_to_planner->clear();
  return readList<Obstacle>(
      node, "obstacles", /*optional=*/true,
      "a list of obstacles such as {type: circle, center: [x, y], radius: r, margin: m}", source,
      [&source, known_to_planner](const YAML::Node& item, const std::string& key,
                                  const std::vector<Obstacle>&) {
        bool known = true;
        Obstacle obstacle = readObstacle(item, key, source, &known);
        if (known_to_planner) known_to_planner->push_back(known);
        return obstacle;
      });
}

RobotMultibody readMultibody(const YAML::Node& node, const Source& source) {
  const Entries entries =
      readMap(node, "multibody",
              {"urdf", "left_sole_frame", "right_sole_frame", "standing_posture"},
              "a map {urdf: FILE.urdf, left_sole_frame: LINK, right_sole_frame: LINK, "
              "standing_posture: STATE}",
              source);
  const std::string name = "a name of letters, digits, '_', '-', '.'";
  RobotMultibody out;
  out.present = true;
  out.urdf = readName(entry(entries, "urdf"), "multibody.urdf",
                      "the URDF file of the robot folder (a file name: " + name + ")", source);
  out.left_sole_frame = readName(entry(entries, "left_sole_frame"), "multibody.left_sole_frame",
                                 "the URDF link on the left sole (" + name + ")", source);
  out.right_sole_frame = readName(entry(entries, "right_sole_frame"),
                                  "multibody.right_sole_frame",
                                  "the URDF link on the right sole (" + name + ")", source);
  out.standing_posture = present(entries, "standing_posture")
                             ? readName(entry(entries, "standing_posture"),
                                        "multibody.standing_posture",
                                        "an SRDF <group_state> name (" + name + ")", source)
                             : std::string("half_sitting");
  if (out.left_sole_frame == out.right_sole_frame) {
    source.fail("multibody.right_sole_frame", "a link other than left_sole_frame",
                entry(entries, "right_sole_frame"));
  }
  return out;
}

std::vector<std::string> knownRobots(const std::string& robots_dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(robots_dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code file_ec;
    if (fs::is_regular_file(it->path() / "walking.yaml", file_ec)) {
      names.push_back(it->path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

Robot loadRobot(const std::string& robot_file) {
  // A study loads its robot's file once per run, hundreds of times: each loading thread keeps
  // the file it parsed last (parsing is what costs), keyed by its path and its text, so a file
  // that changed is parsed again. Per thread: yaml-cpp's nodes are not shared across threads.
  thread_local std::string cached_file, cached_text;
  thread_local Robot cached;
  const std::string text = readTextFile(robot_file, "robot walking parameters");
  if (robot_file == cached_file && text == cached_text) return cached;
  const Source source(robot_file);
  const YAML::Node root = parseYamlText(text, robot_file);
  std::vector<std::string> keys = walkingFieldNames();
  keys.push_back("mass");
  keys.push_back("multibody");
  const Entries entries =
      readMap(root, "", keys, "a map of walking parameters (docs/robots.md)", source);
  Robot robot;
  readWalkingFields(entries, "", /*require_all=*/true, source, &robot.walking);
  robot.nodes = entries;
  robot.nodes.erase("mass");
  robot.nodes.erase("multibody");
  robot.mass = readPositive(entry(entries, "mass"), "mass", "a positive mass in kg", source);
  if (present(entries, "multibody")) robot.multibody = readMultibody(entry(entries, "multibody"), source);
  cached_file = robot_file;
  cached_text = text;
  cached = robot;
  return robot;
}

}  // namespace wpg::datasets::detail

namespace wpg::datasets {

RobotFile loadRobotFile(const std::string& path) {
  const detail::Robot robot = detail::loadRobot(path);
  try {
    robot.walking.validate();
  } catch (const std::invalid_argument& error) {
    detail::Source(path).failChecked(error.what());
  }
  return {robot.walking, robot.mass, robot.multibody};
}

}  // namespace wpg::datasets
