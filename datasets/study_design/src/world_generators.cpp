// Generated worlds of comparison studies (world_generators.hpp).
#include "world_generators.hpp"

#include <cmath>
#include <cstdint>
#include <map>

#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::datasets::detail {
namespace {

// The parameters of one generator, read with their defaults.
class Parameters {
 public:
  Parameters(const YAML::Node& node, std::string key, const std::vector<std::string>& known,
             const std::string& expected, const Source& source)
      : entries_(readMap(node, key, known, expected, source, true)),
        key_(std::move(key)),
        source_(source) {}

  std::string key(const std::string& name) const { return childKey(key_, name); }
  bool given(const std::string& name) const { return present(entries_, name); }

  double positive(const std::string& name, double fallback) const {
    if (!given(name)) return fallback;
    const double value =
        readPositive(entry(entries_, name), key(name), "a positive number", source_);
    checkLength(name, value);
    return value;
  }
  double atLeast(const std::string& name, double minimum, double fallback) const {
    if (!given(name)) return fallback;
    const double value = readNumberAtLeast(entry(entries_, name), key(name), minimum,
                                           "a number >= " + formatNumber(minimum), source_);
    checkLength(name, value);
    return value;
  }
  double number(const std::string& name, double fallback) const {
    if (!given(name)) return fallback;
    return readLength(entry(entries_, name), key(name), "a number", source_);
  }
  int integer(const std::string& name, int minimum, int fallback) const {
    if (!given(name)) return fallback;
    return readInteger(entry(entries_, name), key(name), minimum,
                       "an integer >= " + std::to_string(minimum), source_);
  }
  // Pairs [low, high] with low < high (`strict`) or low <= high, or `fallback`.
  template <int Size>
  Eigen::Matrix<double, Size, 1> ranges(const std::string& name,
                                        const Eigen::Matrix<double, Size, 1>& fallback,
                                        const std::string& expected, bool strict) const {
    if (!given(name)) return fallback;
    const auto value = readLengthVector<Size>(entry(entries_, name), key(name), expected, source_);
    for (int i = 0; i + 1 < Size; i += 2) {
      if (strict ? !(value[i] < value[i + 1]) : !(value[i] <= value[i + 1])) {
        source_.failWith(key(name), "expected " + expected + (strict ? " with each low < high"
                                                                      : " with low <= high"));
      }
    }
    return value;
  }
  [[noreturn]] void fail(const std::string& message) const { source_.failWith(key_, message); }

 private:
  // Every real parameter of a generator is a length or a position [m] (input_limits.hpp).
  void checkLength(const std::string& name, double value) const {
    checkMagnitude(value, kMaxLength, "m", entry(entries_, name), key(name), "a length", source_);
  }

  Entries entries_;
  std::string key_;
  const Source& source_;
};

YAML::Node flowVector(std::initializer_list<double> values) {
  YAML::Node node(YAML::NodeType::Sequence);
  for (const double value : values) node.push_back(value);
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

YAML::Node box(double x, double y, double length, double width, double margin) {
  YAML::Node node;
  node["type"] = "box";
  node["center"] = flowVector({x, y});
  node["size"] = flowVector({length, width});
  node["margin"] = margin;
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

YAML::Node circle(double x, double y, double radius, double margin) {
  YAML::Node node;
  node["type"] = "circle";
  node["center"] = flowVector({x, y});
  node["radius"] = radius;
  node["margin"] = margin;
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

// Circles drawn uniformly over `area` (centres) and `radius`, each kept only when its margin
// stays `clearance` away from the start (the origin) and the goal, so that every field is a
// valid goal scenario (the planner's footprint disc fits at both ends).
GeneratedWorld randomField(const Parameters& p, int run_seed) {
  const int count = p.integer("count", 1, 10);
  // Each circle takes up to 1000 draws, and every run of the study holds them all.
  if (count > kMaxGeneratedObstacles) {
    p.fail("expected count at most " + std::to_string(kMaxGeneratedObstacles) +
           " (SCENARIOS.md, \"Limits\"), got " + std::to_string(count));
  }
  const int seed = p.integer("seed", 0, 0);
  const Eigen::Vector4d area = p.ranges<4>("area", Eigen::Vector4d(1.0, 5.0, -1.5, 1.5),
                                            "[x_min, x_max, y_min, y_max]", true);
  const Eigen::Vector2d radius = p.ranges<2>("radius", Eigen::Vector2d(0.15, 0.3), "[low, high]",
                                               false);
  if (radius[0] <= 0.0) p.fail("expected radius [low, high] with low > 0");
  const double margin = p.atLeast("margin", 0.0, 0.15);
  const double clearance = p.atLeast("clearance", 0.0, 0.5);
  GeneratedWorld world;
  world.goal = {area[1] + 1.0, 0.5 * (area[2] + area[3])};
  // The field's own seed and the run's seed mixed into one SplitMix64 state.
  std::uint64_t state = static_cast<std::uint64_t>(seed) * 0x9e3779b97f4a7c15ull +
                        static_cast<std::uint64_t>(run_seed);
  world.obstacles = YAML::Node(YAML::NodeType::Sequence);
  constexpr int kAttempts = 1000;
  for (int i = 0; i < count; ++i) {
    bool placed = false;
    for (int attempt = 0; attempt < kAttempts && !placed; ++attempt) {
      const double x = area[0] + (area[1] - area[0]) * nextUniform(&state);
      const double y = area[2] + (area[3] - area[2]) * nextUniform(&state);
      const double r = radius[0] + (radius[1] - radius[0]) * nextUniform(&state);
      const Eigen::Vector2d centre(x, y);
      const double reach = r + margin + clearance;
      if (centre.norm() < reach || (centre - world.goal).norm() < reach) continue;
      // Rounded to the millimetre: the resolved scenario states the world in short numbers.
      world.obstacles.push_back(circle(std::round(x * 1e3) / 1e3, std::round(y * 1e3) / 1e3,
                                       std::round(r * 1e3) / 1e3, margin));
      placed = true;
    }
    if (!placed) {
      p.fail("expected an area where " + std::to_string(count) +
             " obstacles fit clear of the start and the goal, could not place obstacle " +
             std::to_string(i));
    }
  }
  return world;
}

// A U open towards the robot (goal_u_trap.yaml's shape): two arms along x from `opening` to
// `opening + depth`, `width` apart, closed by a back wall; the goal behind it.
GeneratedWorld uTrap(const Parameters& p) {
  const double opening = p.positive("opening", 1.1);
  const double depth = p.positive("depth", 1.6);
  const double width = p.positive("width", 2.0);
  const double thickness = p.positive("thickness", 0.2);
  const double margin = p.atLeast("margin", 0.0, 0.1);
  GeneratedWorld world;
  world.obstacles = YAML::Node(YAML::NodeType::Sequence);
  world.obstacles.push_back(box(opening + depth - 0.5 * thickness, 0.0, thickness,
                                width + thickness, margin));
  world.obstacles.push_back(box(opening + 0.5 * depth, 0.5 * width, depth, thickness, margin));
  world.obstacles.push_back(box(opening + 0.5 * depth, -0.5 * width, depth, thickness, margin));
  world.goal = {opening + depth + 1.5, 0.0};
  return world;
}

// Two walls along x, `width` apart (free width between them) around y = `offset`, from x =
// `start` over `length`; the goal beyond its far end.
GeneratedWorld corridor(const Parameters& p) {
  const double start = p.positive("start", 1.0);
  const double length = p.positive("length", 4.0);
  const double width = p.positive("width", 1.2);
  const double offset = p.number("offset", 0.0);
  const double thickness = p.positive("thickness", 0.2);
  const double margin = p.atLeast("margin", 0.0, 0.1);
  GeneratedWorld world;
  world.obstacles = YAML::Node(YAML::NodeType::Sequence);
  const double wall_y = 0.5 * (width + thickness);
  world.obstacles.push_back(box(start + 0.5 * length, offset + wall_y, length, thickness, margin));
  world.obstacles.push_back(box(start + 0.5 * length, offset - wall_y, length, thickness, margin));
  world.goal = {start + length + 1.0, offset};
  return world;
}

// A wall across the way at x = `distance` with a door `width` wide centred at y = `offset`,
// each side of it `span` long; the goal 2 m behind it.
GeneratedWorld doorway(const Parameters& p) {
  const double distance = p.positive("distance", 2.0);
  const double width = p.positive("width", 1.0);
  const double offset = p.number("offset", 0.0);
  const double span = p.positive("span", 3.0);
  const double thickness = p.positive("thickness", 0.2);
  const double margin = p.atLeast("margin", 0.0, 0.1);
  GeneratedWorld world;
  world.obstacles = YAML::Node(YAML::NodeType::Sequence);
  const double side_y = 0.5 * (width + span);
  world.obstacles.push_back(box(distance, offset + side_y, thickness, span, margin));
  world.obstacles.push_back(box(distance, offset - side_y, thickness, span, margin));
  world.goal = {distance + 2.0, 0.0};
  return world;
}

}  // namespace

const std::vector<std::string>& worldGeneratorNames() {
  static const std::vector<std::string> names = {"random_field", "u_trap", "corridor", "doorway"};
  return names;
}

GeneratedWorld generateWorld(const std::string& generator, const YAML::Node& parameters,
                             const std::string& key, int run_seed, const Source& source) {
  if (generator == "random_field") {
    return randomField(Parameters(parameters, key,
                                  {"count", "seed", "area", "radius", "margin", "clearance"},
                                  "a map with count, seed, area, radius, margin, clearance",
                                  source),
                       run_seed);
  }
  if (generator == "u_trap") {
    return uTrap(Parameters(parameters, key, {"opening", "depth", "width", "thickness", "margin"},
                            "a map with opening, depth, width, thickness, margin", source));
  }
  if (generator == "corridor") {
    return corridor(Parameters(parameters, key,
                               {"start", "length", "width", "offset", "thickness", "margin"},
                               "a map with start, length, width, offset, thickness, margin",
                               source));
  }
  if (generator == "doorway") {
    return doorway(Parameters(parameters, key,
                              {"distance", "width", "offset", "span", "thickness", "margin"},
                              "a map with distance, width, offset, span, thickness, margin",
                              source));
  }
  source.failWith(key, "unknown world generator '" + generator + "'" +
                           didYouMean(generator, worldGeneratorNames()) + "; expected one of " +
                           joinNames(worldGeneratorNames()));
}

}  // namespace wpg::datasets::detail
