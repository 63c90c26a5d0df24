// Obstacles in scenario files and run datasets: the `obstacles:` list and the generator's
// obstacle keys load, round-trip through the resolved YAML and reject bad input with one line
// naming the file and the key; the dataset stores the obstacles as a table under
// /runs/<name>/obstacles/ and the footstep clearances under /runs/<name>/checks/, read back
// with the plain HDF5 C++ API.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <H5Cpp.h>

#include "hdf5_read.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <unistd.h>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/obstacles.hpp"

namespace fs = std::filesystem;
using wpg::ObstacleType;
using wpg::datasets::InputError;
using wpg::datasets::loadScenario;
using wpg::datasets::Scenario;

namespace {

using wpg_test::kRobotsDir;
using wpg_test::kScenariosDir;

const char* const kHeader =
    "name: obstacle_test\n"
    "robot: hrp2\n"
    "duration: 5.0\n"
    "reference:\n"
    "  - {t: 1.0, v: [0.2, 0.0, 0.0]}\n";

// The example of SCENARIOS.md.
const char* const kExampleObstacles =
    "obstacles:\n"
    "  - {type: circle, center: [1.5, 0.0], radius: 0.3, margin: 0.2}\n"
    "  - {type: box, center: [3.0, 1.0], size: [0.4, 0.6], yaw: 0.3, margin: 0.1}\n"
    "  - {type: polygon, vertices: [[4.0, -0.5], [4.6, -0.4], [4.3, 0.2]], margin: 0.1}\n";

class ObstacleFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  ObstacleFiles() : ScratchDirectoryTest("wpg_test_obstacles") {}

  std::string write(const std::string& text, const std::string& name = "scenario.yaml") {
    const std::string path = (directory_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  Scenario load(const std::string& obstacles_text, const std::vector<std::string>& overrides = {}) {
    return loadScenario(write(std::string(kHeader) + obstacles_text), overrides, kRobotsDir);
  }

  // The InputError's message for this scenario text (fails the test when it loads).
  std::string errorOf(const std::string& obstacles_text,
                      const std::vector<std::string>& overrides = {}) {
    const std::string path = write(std::string(kHeader) + obstacles_text);
    try {
      loadScenario(path, overrides, kRobotsDir);
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
      EXPECT_EQ(message.rfind(path, 0), 0u) << "does not start with the file: " << message;
      return message;
    }
    ADD_FAILURE() << "loaded without an error:\n" << obstacles_text;
    return "";
  }
};

TEST_F(ObstacleFiles, ExampleOfTheIssueLoads) {
  const Scenario s = load(kExampleObstacles);
  ASSERT_EQ(s.request.obstacles.size(), 3u);
  const wpg::Obstacle& circle = s.request.obstacles[0];
  EXPECT_EQ(circle.type, ObstacleType::kCircle);
  EXPECT_EQ(circle.center, Eigen::Vector2d(1.5, 0.0));
  EXPECT_EQ(circle.radius, 0.3);
  EXPECT_EQ(circle.margin, 0.2);
  const wpg::Obstacle& box = s.request.obstacles[1];
  EXPECT_EQ(box.type, ObstacleType::kBox);
  EXPECT_EQ(box.center, Eigen::Vector2d(3.0, 1.0));
  EXPECT_EQ(box.size, Eigen::Vector2d(0.4, 0.6));
  EXPECT_EQ(box.yaw, 0.3);
  EXPECT_EQ(box.margin, 0.1);
  const wpg::Obstacle& polygon = s.request.obstacles[2];
  EXPECT_EQ(polygon.type, ObstacleType::kPolygon);
  ASSERT_EQ(polygon.vertices.size(), 3u);
  EXPECT_EQ(polygon.vertices[1], Eigen::Vector2d(4.6, -0.4));
  EXPECT_EQ(polygon.margin, 0.1);
  // Generator defaults (GeneratorSettings).
  EXPECT_EQ(s.request.generator.max_obstacles_in_qp, 4);
  EXPECT_EQ(s.request.generator.obstacle_reach, 1.5);
  EXPECT_EQ(s.request.generator.max_detour, 2.5);
}

TEST_F(ObstacleFiles, OptionalKeysHaveDefaultsAndGeneratorKeysAreRead) {
  const Scenario s = load(
      "generator: {max_obstacles_in_qp: 0, obstacle_reach: 2.5, max_detour: 4.0}\n"
      "obstacles:\n"
      "  - {type: circle, center: [1.5, 0.0], radius: 0.3}\n"
      "  - {type: box, center: [3.0, 1.0], size: [0.4, 0.6]}\n"
      "  - {type: polygon, vertices: [[4.3, 0.2], [4.6, -0.4], [4.0, -0.5]]}\n");  // clockwise
  ASSERT_EQ(s.request.obstacles.size(), 3u);
  for (const wpg::Obstacle& o : s.request.obstacles) EXPECT_EQ(o.margin, 0.0);
  EXPECT_EQ(s.request.obstacles[1].yaw, 0.0);
  EXPECT_EQ(s.request.generator.max_obstacles_in_qp, 0);
  EXPECT_EQ(s.request.generator.obstacle_reach, 2.5);
  EXPECT_EQ(s.request.generator.max_detour, 4.0);
  EXPECT_EQ(load("obstacles: []\n").request.obstacles.size(), 0u);
  EXPECT_EQ(load("obstacles:\n").request.obstacles.size(), 0u);
  EXPECT_EQ(load("").request.obstacles.size(), 0u);
  EXPECT_EQ(load("generator: {max_obstacles_in_qp: 32}\n").request.generator.max_obstacles_in_qp,
            32);
}

TEST_F(ObstacleFiles, ResolvedYamlRoundTripsTheObstacles) {
  const Scenario first =
      load(std::string("generator: {max_obstacles_in_qp: 3, obstacle_reach: 2.0}\n") +
           kExampleObstacles);
  for (const char* key : {"obstacles:", "type: circle", "type: box", "type: polygon",
                          "vertices: [[4.0, -0.5], [4.6, -0.4], [4.3, 0.2]]", "yaw: 0.3",
                          "max_obstacles_in_qp: 3", "obstacle_reach: 2.0"}) {
    EXPECT_NE(resolvedScenarioText(first).find(key), std::string::npos)
        << "'" << key << "' missing in:\n"
        << resolvedScenarioText(first);
  }
  const Scenario second =
      loadScenario(write(resolvedScenarioText(first), "resolved.yaml"), {}, kRobotsDir);
  EXPECT_EQ(resolvedScenarioText(second), resolvedScenarioText(first));
  ASSERT_EQ(second.request.obstacles.size(), first.request.obstacles.size());
  for (std::size_t i = 0; i < first.request.obstacles.size(); ++i) {
    const wpg::Obstacle& a = first.request.obstacles[i];
    const wpg::Obstacle& b = second.request.obstacles[i];
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.center, b.center);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.yaw, b.yaw);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.margin, b.margin);
  }
  EXPECT_EQ(second.request.generator.max_obstacles_in_qp, 3);
  EXPECT_EQ(second.request.generator.obstacle_reach, 2.0);
  // Without obstacles the key is still explicit.
  EXPECT_NE(resolvedScenarioText(load("")).find("obstacles: []"), std::string::npos);
}

TEST_F(ObstacleFiles, OverridesReachTheObstacles) {
  const Scenario s =
      load(kExampleObstacles,
           {"obstacles[0].radius=0.4", "obstacles[3]={type: circle, center: [6, 0], radius: 0.1}"});
  ASSERT_EQ(s.request.obstacles.size(), 4u);
  EXPECT_EQ(s.request.obstacles[0].radius, 0.4);
  EXPECT_EQ(s.request.obstacles[3].center, Eigen::Vector2d(6.0, 0.0));
  const std::string message = errorOf(kExampleObstacles, {"obstacles[0].radius=-1"});
  EXPECT_NE(message.find("key 'obstacles[0].radius'"), std::string::npos) << message;
  EXPECT_NE(message.find("--set 'obstacles[0].radius=-1'"), std::string::npos) << message;
}

struct BadCase {
  const char* text;
  const char* key;       // the key the message must name
  const char* expected;  // and a piece of what was expected
};

TEST_F(ObstacleFiles, BadObstaclesAreInputErrorsNamingTheKey) {
  const BadCase cases[] = {
      {"obstacles: {type: circle}\n", "key 'obstacles'", "a list of obstacles"},
      {"obstacles:\n  - [1.5, 0.0]\n", "key 'obstacles[0]'", "a map"},
      {"obstacles:\n  - {type: ellipse, center: [1, 0], radius: 0.3}\n", "key 'obstacles[0].type'",
       "circle, box or polygon"},
      {"obstacles:\n  - {center: [1, 0], radius: 0.3}\n", "key 'obstacles[0].type'", "missing"},
      {"obstacles:\n  - {type: circle, center: [1, 0], radius: -0.3}\n",
       "key 'obstacles[0].radius'", "positive radius"},
      {"obstacles:\n  - {type: circle, center: [1, 0], radius: 0.0}\n", "key 'obstacles[0].radius'",
       "positive radius"},
      {"obstacles:\n  - {type: circle, radius: 0.3}\n", "key 'obstacles[0].center'", "missing"},
      {"obstacles:\n  - {type: circle, center: [1, 0, 0], radius: 0.3}\n",
       "key 'obstacles[0].center'", "2 numbers"},
      {"obstacles:\n  - {type: circle, center: [1, .nan], radius: 0.3}\n",
       "key 'obstacles[0].center[1]'", "not a finite number"},
      {"obstacles:\n  - {type: circle, center: [1, 0], radius: 0.3, margin: -0.1}\n",
       "key 'obstacles[0].margin'", ">= 0"},
      {"obstacles:\n  - {type: circle, center: [1, 0], radius: 0.3, size: [1, 1]}\n",
       "key 'obstacles[0].size'", "unknown key"},
      {"obstacles:\n  - {type: box, center: [1, 0], radius: 0.3}\n", "key 'obstacles[0].radius'",
       "unknown key"},
      {"obstacles:\n  - {type: box, size: [0.4, 0.6]}\n", "key 'obstacles[0].center'", "missing"},
      {"obstacles:\n  - {type: box, center: [1, 0], size: [0.4, -0.6]}\n",
       "key 'obstacles[0].size'", "positive"},
      {"obstacles:\n  - {type: box, center: [1, 0], size: [0.4, 0.6], yaw: \"0.3\"}\n",
       "key 'obstacles[0].yaw'", "an angle in rad"},
      {"obstacles:\n  - {type: polygon, vertices: [[0, 0], [1, 0]]}\n",
       "key 'obstacles[0].vertices'", "at least 3"},
      {"obstacles:\n  - {type: polygon, vertices: [[0, 0], [1, 0], [2]]}\n",
       "key 'obstacles[0].vertices[2]'", "2 numbers"},
      {"obstacles:\n  - {type: circle, center: [1, 0], radius: 0.3}\n"
       "  - {type: polygon, vertices: [[1.0, -0.5], [1.6, -0.5], [0.9, 0.2], [1.0, 0.5]]}\n",
       "key 'obstacles[1].vertices'", "a convex polygon, got one not strictly convex"},
      {"obstacles:\n  - {type: polygon, vertices: [[1, 0], [1.5, 0], [2, 0]]}\n",
       "key 'obstacles[0].vertices'", "degenerate"},
      {"obstacles:\n  - {type: polygon, vertices: [[0, 0], [1, 0], [0, 1]], center: [0, 0]}\n",
       "key 'obstacles[0].center'", "unknown key"},
      {"generator: {max_obstacles_in_qp: 33}\n", "key 'generator.max_obstacles_in_qp'", "[0, 32]"},
      {"generator: {max_obstacles_in_qp: -1}\n", "key 'generator.max_obstacles_in_qp'", "[0, 32]"},
      {"generator: {max_obstacles_in_qp: 2.5}\n", "key 'generator.max_obstacles_in_qp'", "[0, 32]"},
      {"generator: {obstacle_reach: 0}\n", "key 'generator.obstacle_reach'", "positive distance"},
      {"generator: {max_detour: -1}\n", "key 'generator.max_detour'", "positive distance"},
      {"generator: {max_detour: .nan}\n", "key 'generator.max_detour'", "positive distance"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = errorOf(c.text);
    EXPECT_NE(message.find(c.key), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(ShippedObstacleScenarios, LoadAndRoundTrip) {
  const struct {
    const char* name;
    std::size_t obstacles;
  } shipped[] = {{"paper_experiment_a", 1},
                 {"paper_experiment_b", 1},
                 {"obstacle_boxes", 3},
                 {"obstacle_polygon", 2},
                 {"obstacle_cluttered", 7},
                 {"obstacle_slalom", 3},
                 {"obstacle_box_on_path", 1},
                 {"obstacle_box_then_circle", 2},
                 {"obstacle_gap", 2},
                 {"obstacle_enclosure", 3},
                 {"obstacle_turning", 1},
                 {"obstacle_lateral", 1},
                 {"obstacle_wall", 1}};
  const std::string path = (fs::temp_directory_path() /
                            ("wpg_test_obstacles_resolved_" + std::to_string(::getpid()) + ".yaml"))
                               .string();
  for (const auto& entry : shipped) {
    SCOPED_TRACE(entry.name);
    const Scenario s = loadScenario(kScenariosDir + "/" + entry.name + ".yaml", {}, kRobotsDir);
    EXPECT_EQ(s.name, entry.name);
    EXPECT_EQ(s.request.obstacles.size(), entry.obstacles);
    std::ofstream(path) << resolvedScenarioText(s);
    EXPECT_EQ(resolvedScenarioText(loadScenario(path, {}, kRobotsDir)), resolvedScenarioText(s));
  }
  fs::remove(path);
  const Scenario a = loadScenario(kScenariosDir + "/paper_experiment_a.yaml", {}, kRobotsDir);
  EXPECT_EQ(a.request.reference.back().velocity, Eigen::Vector3d(0.2, 0.0, 0.0));
  const Scenario b = loadScenario(kScenariosDir + "/paper_experiment_b.yaml", {}, kRobotsDir);
  EXPECT_EQ(b.request.reference.back().velocity, Eigen::Vector3d(0.2, 0.0, 0.2));
  EXPECT_EQ(b.walking.max_step_yaw_change, 0.17);
  // Every kind appears among the cluttered field's obstacles.
  const Scenario c = loadScenario(kScenariosDir + "/obstacle_cluttered.yaml", {}, kRobotsDir);
  int kinds[3] = {0, 0, 0};
  for (const wpg::Obstacle& o : c.request.obstacles) ++kinds[static_cast<int>(o.type)];
  EXPECT_GT(kinds[0], 0);
  EXPECT_GT(kinds[1], 0);
  EXPECT_GT(kinds[2], 0);
}

// --- the dataset ------------------------------------------------------------------------------

using namespace wpg_test;  // HDF5 readers (hdf5_read.hpp)

const std::vector<Eigen::Vector3d> kHandMadeSteps = {
    Eigen::Vector3d(0.0, 0.095, 0.0), Eigen::Vector3d(0.0, -0.095, 0.0),
    Eigen::Vector3d(1.0, 0.1, 0.0), Eigen::Vector3d(2.8, 0.9, 0.2)};

// A short hand-made walk: footsteps at known places (x, y, yaw), samples of matching length.
wpg::WalkResult handMadeWalk(const std::vector<Eigen::Vector3d>& steps = kHandMadeSteps) {
  wpg::WalkResult result;
  wpg::WalkTrajectory& t = result.trajectory;
  for (int i = 0; i < 10; ++i) {
    t.time.push_back(0.005 * i);
    t.com.emplace_back(0.0, 0.0, 0.814);
    t.com_vel.emplace_back(0.0, 0.0, 0.0);
    t.com_acc.emplace_back(0.0, 0.0, 0.0);
    t.cop.emplace_back(0.0, 0.0);
    t.left_foot.emplace_back(0.0, 0.095, 0.0, 0.0);
    t.right_foot.emplace_back(0.0, -0.095, 0.0, 0.0);
    t.free_flyer_yaw.push_back(0.0);
    t.support.push_back(wpg::SupportState::kDouble);
  }
  for (const Eigen::Vector3d& pose : steps) {
    wpg::Footstep step;
    step.pose = pose;
    t.footsteps.push_back(step);
  }
  return result;
}

TEST_F(ObstacleFiles, DatasetHoldsTheObstacleTableAndTheFootstepChecks) {
  const Scenario scenario = load(kExampleObstacles);
  const wpg::WalkResult result = handMadeWalk();
  wpg::datasets::FootstepClearances clearances;
  clearances.clearance = {0.5, 0.6, -0.05, 0.01};
  clearances.clearance_obstacle = {0, 0, 0, 1};
  clearances.foot_distance = {0.7, 0.8, 0.15, 0.11};
  const std::string path = (directory_ / "run.h5").string();
  wpg::datasets::writeRunDataset(path, scenario, result, &clearances);

  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group obstacles = file.openGroup("/runs/obstacle_test/obstacles");
  EXPECT_EQ(intAttribute(obstacles, "count"), 3);
  const std::vector<std::uint8_t> types =
      readAll<std::uint8_t>(obstacles, "type", H5::PredType::NATIVE_UINT8);
  EXPECT_EQ(types, (std::vector<std::uint8_t>{0, 1, 2}));
  EXPECT_EQ(stringAttribute(obstacles.openDataSet("type"), "codes"), "0=circle, 1=box, 2=polygon");
  std::vector<hsize_t> dims;
  EXPECT_EQ(readDoubles(obstacles, "center", &dims),
            (std::vector<double>{1.5, 0.0, 3.0, 1.0, 0.0, 0.0}));
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 2}));
  EXPECT_EQ(readDoubles(obstacles, "radius"), (std::vector<double>{0.3, 0.0, 0.0}));
  EXPECT_EQ(readDoubles(obstacles, "size"), (std::vector<double>{0.0, 0.0, 0.4, 0.6, 0.0, 0.0}));
  EXPECT_EQ(readDoubles(obstacles, "yaw"), (std::vector<double>{0.0, 0.3, 0.0}));
  EXPECT_EQ(readDoubles(obstacles, "margin"), (std::vector<double>{0.2, 0.1, 0.1}));
  // Outlines: none for the circle, the box's 4 corners, the triangle's 3 vertices.
  EXPECT_EQ(readInts(obstacles, "vertex_start"), (std::vector<int>{0, 0, 4}));
  EXPECT_EQ(readInts(obstacles, "vertex_count"), (std::vector<int>{0, 4, 3}));
  const std::vector<double> vertices = readDoubles(obstacles, "vertices", &dims);
  ASSERT_EQ(dims, (std::vector<hsize_t>{7, 2}));
  const std::vector<Eigen::Vector2d> box = scenario.request.obstacles[1].worldVertices();
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(vertices[2 * k], box[k].x());
    EXPECT_EQ(vertices[2 * k + 1], box[k].y());
  }
  EXPECT_EQ(vertices[2 * 4], 4.0);  // the triangle, counter-clockwise as given
  EXPECT_EQ(vertices[2 * 5 + 1], -0.4);
  for (const char* name : {"center", "radius", "size", "yaw", "margin", "vertices"}) {
    SCOPED_TRACE(name);
    EXPECT_FALSE(stringAttribute(obstacles.openDataSet(name), "units").empty());
    EXPECT_FALSE(stringAttribute(obstacles.openDataSet(name), "description").empty());
  }
  EXPECT_EQ(stringAttribute(obstacles.openDataSet("vertices"), "frame"), "world");

  const H5::Group checks = file.openGroup("/runs/obstacle_test/checks");
  EXPECT_EQ(readDoubles(checks, "step_clearance"), clearances.clearance);
  EXPECT_EQ(readInts(checks, "step_clearance_obstacle"), clearances.clearance_obstacle);
  EXPECT_EQ(readDoubles(checks, "step_foot_distance"), clearances.foot_distance);
  EXPECT_EQ(doubleAttribute(checks, "min_step_clearance"), -0.05);
  EXPECT_EQ(doubleAttribute(checks, "min_step_foot_distance"), 0.11);
  // Centres computed by the writer against the NMPC's constraint, d >= margin + the sole radius:
  // the initial feet and (1, 0.1) are nearest to the circle, (2.8, 0.9) to the box (0.2 m from
  // its centre along its short axis... inside it).
  const double foot = scenario.walking.obstacle_foot_radius;
  ASSERT_GT(foot, 0.0);  // HRP-2's sole half diagonal
  const wpg::AnalyticObstacleDistance exact(scenario.request.obstacles);
  const std::vector<double> centre = readDoubles(checks, "step_centre_clearance");
  const std::vector<int> centre_obstacle = readInts(checks, "step_centre_clearance_obstacle");
  ASSERT_EQ(centre.size(), 4u);
  EXPECT_NEAR(centre[0], std::hypot(1.5, 0.095) - 0.3 - 0.2 - foot, 1e-12);
  EXPECT_NEAR(centre[2], std::hypot(0.5, 0.1) - 0.3 - 0.2 - foot, 1e-12);
  EXPECT_EQ(centre_obstacle[2], 0);
  EXPECT_NEAR(centre[3], exact.signedDistance(1, {2.8, 0.9}, nullptr) - 0.1 - foot, 1e-12);
  EXPECT_LT(centre[3], 0.0);
  EXPECT_EQ(centre_obstacle[3], 1);
  EXPECT_EQ(doubleAttribute(checks, "min_step_centre_clearance"), centre[3]);
  EXPECT_EQ(stringAttribute(checks.openDataSet("step_clearance"), "units"), "m");
}

// The NMPC keeps a step centre margin + obstacle_foot_radius from an obstacle (nmpc.cpp's
// obstacle rows): a step between the two distances violates the constraint and must read < 0
// (schema 1 stored sd - margin, which read such a step as "holds").
TEST_F(ObstacleFiles, StepCentreClearanceIsTheMarginOfTheNmpcConstraint) {
  // One circle at (1.5, 0), radius 0.3, margin 0.2: its margin ends 0.5 m from the centre.
  const Scenario scenario =
      load("obstacles:\n  - {type: circle, center: [1.5, 0.0], radius: 0.3, margin: 0.2}\n");
  const double foot = scenario.walking.obstacle_foot_radius;
  ASSERT_GT(foot, 0.05);
  const double inside = 0.5 + 0.5 * foot;   // past the margin, inside margin + foot radius
  const double outside = 0.5 + foot + 0.03;  // clear of both
  const std::vector<Eigen::Vector3d> steps = {
      Eigen::Vector3d(0.0, 0.095, 0.0), Eigen::Vector3d(0.0, -0.095, 0.0),
      Eigen::Vector3d(1.5 - inside, 0.0, 0.0), Eigen::Vector3d(1.5, outside, 0.0)};
  const std::string path = (directory_ / "run.h5").string();
  wpg::datasets::writeRunDataset(path, scenario, handMadeWalk(steps));

  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group checks = file.openGroup("/runs/obstacle_test/checks");
  const std::vector<double> centre = readDoubles(checks, "step_centre_clearance");
  ASSERT_EQ(centre.size(), 4u);
  EXPECT_NEAR(centre[2], -0.5 * foot, 1e-12);  // sd - margin = +0.5 foot: "holds" in schema 1
  EXPECT_LT(centre[2], 0.0);
  EXPECT_NEAR(centre[3], 0.03, 1e-12);
  EXPECT_EQ(doubleAttribute(checks, "min_step_centre_clearance"), centre[2]);
  EXPECT_EQ(intAttribute(file, "schema_version"), 2);  // the field's meaning changed in 2
}

TEST_F(ObstacleFiles, WithoutClearancesOnlyTheCentresAreChecked) {
  const std::string path = (directory_ / "run.h5").string();
  wpg::datasets::writeRunDataset(path, load(kExampleObstacles), handMadeWalk());
  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group checks = file.openGroup("/runs/obstacle_test/checks");
  EXPECT_TRUE(checks.nameExists("step_centre_clearance"));
  EXPECT_TRUE(checks.attrExists("min_step_centre_clearance"));
  EXPECT_FALSE(checks.nameExists("step_clearance"));
  EXPECT_FALSE(checks.attrExists("min_step_clearance"));
}

TEST_F(ObstacleFiles, WithoutObstaclesTheTableIsEmptyAndNoStepIsChecked) {
  const std::string path = (directory_ / "run.h5").string();
  wpg::datasets::writeRunDataset(path, load(""), handMadeWalk());
  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group obstacles = file.openGroup("/runs/obstacle_test/obstacles");
  EXPECT_EQ(intAttribute(obstacles, "count"), 0);
  std::vector<hsize_t> dims;
  readDoubles(obstacles, "vertices", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{0, 2}));
  readDoubles(obstacles, "radius", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{0}));
  const H5::Group checks = file.openGroup("/runs/obstacle_test/checks");
  EXPECT_FALSE(checks.nameExists("step_centre_clearance"));
  EXPECT_FALSE(checks.attrExists("min_step_centre_clearance"));
}

TEST_F(ObstacleFiles, ClearancesOfTheWrongLengthAreRejectedBeforeWriting) {
  wpg::datasets::FootstepClearances clearances;
  clearances.clearance = {0.5, 0.6, -0.05};  // 3 entries, 4 footsteps
  clearances.clearance_obstacle = {0, 0, 0, 1};
  clearances.foot_distance = {0.7, 0.8, 0.15, 0.11};
  const std::string path = (directory_ / "run.h5").string();
  EXPECT_THROW(
      wpg::datasets::writeRunDataset(path, load(kExampleObstacles), handMadeWalk(), &clearances),
      std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));
}

}  // namespace
