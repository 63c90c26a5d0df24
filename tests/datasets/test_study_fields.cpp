// A study's runs made from its compiled fields (compiled_sweep.hpp, scenario_field.hpp) are
// the runs loaded from YAML: for every run of every shipped study and of sweeps of every kind
// of field, the same scenario field by field, the same resolved text byte for byte, the same
// warnings word for word; and a run the fields cannot make (a structural key, a refused value)
// is loaded, with the loader's message.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace fs = std::filesystem;
using wpg::datasets::InputError;
using wpg::datasets::Scenario;
using wpg::datasets::Study;
using wpg::datasets::StudyRun;

namespace {

Study loadStudyFile(const std::string& path) {
  return wpg::datasets::loadStudy(
      path, [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
      wpg_test::kRobotsDir);
}

// The resolved text holds every field the walk reads, each number in its shortest exact form
// (equal texts: equal bits); the rest is compared here.
void expectSameScenario(const Scenario& fast, const Scenario& loaded, const std::string& where) {
  EXPECT_EQ(resolvedScenarioText(fast), resolvedScenarioText(loaded)) << where;
  EXPECT_EQ(fast.name, loaded.name) << where;
  EXPECT_EQ(fast.robot, loaded.robot) << where;
  EXPECT_EQ(fast.source_path, loaded.source_path) << where;
  EXPECT_EQ(fast.warnings, loaded.warnings) << where;
  EXPECT_EQ(fast.robot_com_height, loaded.robot_com_height) << where;
  EXPECT_EQ(fast.multibody.present, loaded.multibody.present) << where;
  EXPECT_EQ(fast.multibody.urdf, loaded.multibody.urdf) << where;
  EXPECT_EQ(fast.multibody.standing_posture, loaded.multibody.standing_posture) << where;
  EXPECT_EQ(fast.replay, loaded.replay) << where;
  EXPECT_EQ(fast.filter, loaded.filter) << where;
  EXPECT_EQ(fast.goal.enabled, loaded.goal.enabled) << where;
  // A few numbers bit for bit, besides their text: the swept ones of the studies below.
  EXPECT_EQ(fast.walking.com_height, loaded.walking.com_height) << where;
  EXPECT_EQ(fast.walking.weight_cop, loaded.walking.weight_cop) << where;
  ASSERT_EQ(fast.request.reference.size(), loaded.request.reference.size()) << where;
  for (std::size_t i = 0; i < fast.request.reference.size(); ++i) {
    EXPECT_EQ(fast.request.reference[i].velocity, loaded.request.reference[i].velocity) << where;
  }
  ASSERT_EQ(fast.request.pushes.size(), loaded.request.pushes.size()) << where;
  for (std::size_t i = 0; i < fast.request.pushes.size(); ++i) {
    EXPECT_EQ(fast.request.pushes[i].force, loaded.request.pushes[i].force) << where;
  }
}

// Every run of `study` made both ways: equal, and made from the fields unless `loaded_runs`.
void expectEveryRunEqual(const Study& study, bool from_fields = true) {
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const StudyRun fast = study.runs[i];
    const StudyRun loaded = study.runs.loaded(i);
    const std::string where = study.name + " run " + std::to_string(i);
    ASSERT_EQ(fast.from_fields, from_fields) << where;
    ASSERT_FALSE(loaded.from_fields) << where;
    expectSameScenario(fast.scenario, loaded.scenario, where);
  }
}

class StudyFields : public wpg_test::ScratchDirectoryTest {
 protected:
  StudyFields() : ScratchDirectoryTest("wpg_test_study_fields") {}

  Study load(const std::string& text) {
    const fs::path path = directory_ / "study.yaml";
    std::ofstream(path) << text;
    return loadStudyFile(path.string());
  }
};

}  // namespace

// Every shipped study with a sweep: every run from the fields, equal to the run loaded.
TEST(ShippedStudyFields, EveryRunEqualsTheLoadedRun) {
  int studies = 0;
  for (const auto& file : fs::directory_iterator(wpg_test::kSourceDir + "/datasets/studies")) {
    std::ifstream in(file.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("\nsweep:") == std::string::npos) continue;  // a comparison (worlds x variants)
    SCOPED_TRACE(file.path().string());
    expectEveryRunEqual(loadStudyFile(file.path().string()));
    ++studies;
  }
  EXPECT_GE(studies, 5);
}

// Fields of every kind (walking numbers, integers, polygons and names; generator and filter
// settings; durations, masses, switches; vectors and their entries in lists), in a grid, a zip
// and a random sweep, with values that warn (beyond the clamps, a CoM height out of range, a
// constant of set:): the same runs, the same warnings.
TEST_F(StudyFields, FieldsOfEveryKindInGridZipAndRandom) {
  const Study study = load(R"(name: kinds
base:
  name: kinds
  robot: hrp2
  duration: 4.0
  generator: {algorithm: nmpc, sqp_iterations: 1}
  reference: [{t: 0.0, v: [0.0, 0.0, 0.0]}, {t: 1.0, v: [0.2, 0.0, 0.0]}]
  pushes: [{t: 2.0, force: [10.0, 0.0], duration: 0.1}]
  obstacles: [{type: circle, center: [3.0, 0.0], radius: 0.2, margin: 0.2},
              {type: box, center: [5.0, 1.0], size: [0.4, 0.2], yaw: 0.3, margin: 0.1}]
set: {walking.weight_jerk: 2.0e-5, "reference[0].v": [0.0, 0.0, 0.0]}
sweep:
  grid:
    walking.heading_reference: [command, support_foot]
    walking.velocity_window_samples: [1, 4]
    walking.feasibility_y: [[0.2, 0.3, 0.4, 0.3, 0.2], [0.19, 0.3, 0.41, 0.3, 0.19]]
    generator.obstacle_reach: [1.0, 2.5]
  zip:
    "reference[1].v": [[0.2, 0.0, 0.0], [0.9, 0.5, 0.1], [0.1, 0.0, 0.6]]
    "pushes[0].force[1]": [0.0, 20.0, -30.0]
    "obstacles[1].size": [[0.4, 0.2], [0.6, 0.3], [0.2, 0.2]]
    "obstacles[0].center[1]": [0.0, 0.5, -0.5]
    filter_settings.preview_time: [1.6, 1.2, 2.0]
    duration: [4.0, 5.0, 3.5]
    robot_mass: [58.0, 60.0, 55.0]
    replay: [false, true, false]
    generator.sqp_iterations: [1, 2, 1]
    walking.weight_cop: [300, +1.0e3, 5e2]
  random:
    samples: 4
    seed: 3
    keys:
      walking.com_height: {uniform: [0.55, 0.9]}
      "pushes[0].duration": {uniform: [0.05, 0.2]}
      "obstacles[1].yaw": {uniform: [-7.0, 7.0]}
)");
  ASSERT_EQ(study.runs.size(), 16u * 3u * 4u);
  expectEveryRunEqual(study);
  std::size_t warned = 0;
  for (std::size_t i = 0; i < study.runs.size(); ++i)
    warned += !study.runs[i].scenario.warnings.empty();
  EXPECT_GT(warned, 10u);  // the warnings are compared, not only their absence
}

// A structural key (a list's entry), or two keys one inside the other, are loaded from
// YAML: the same runs.
TEST_F(StudyFields, StructuralKeyIsLoaded) {
  const Study study = load(R"(name: structural
base: walk_forward
sweep:
  grid:
    walking.weight_cop: [300.0, 1000.0]
    "reference[1]": [{t: 1.0, v: [0.1, 0, 0]}, {t: 2.0, v: [0.2, 0, 0]}]
)");
  expectEveryRunEqual(study, /*from_fields=*/false);
  // A whole list compiles, but not with a key inside it (its list may change length).
  const Study nested = load(R"(name: nested
base: {name: nested, robot: hrp2, duration: 3.0, reference: [],
       obstacles: [{type: circle, center: [3.0, 0.0], radius: 0.2, margin: 0.2}]}
sweep:
  grid:
    obstacles: [[{type: circle, center: [3.0, 0.0], radius: 0.2}],
                [{type: circle, center: [2.0, 1.0], radius: 0.3}, {type: box, center: [4.0, 0.0], size: [0.2, 0.2]}]]
    "obstacles[0].radius": [0.1, 0.4]
)");
  expectEveryRunEqual(nested, /*from_fields=*/false);
  const Study whole = load(R"(name: whole
base: {name: whole, robot: hrp2, duration: 3.0, reference: []}
sweep:
  zip:
    obstacles: [[{type: circle, center: [3.0, 0.0], radius: 0.2}],
                [{type: circle, center: [2.0, 1.0], radius: 0.3}, {type: box, center: [4.0, 0.0], size: [0.2, 0.2]}]]
)");
  expectEveryRunEqual(whole);
}

// A run the loader refuses for a combination of values each accepted alone (a CoP margin
// wider than half the foot), left unchecked at load, fails with the loader's message, word
// for word, whether made or loaded; the runs around it are made from the fields.
TEST_F(StudyFields, RefusedRunFailsWithTheLoadersMessage) {
  std::string heights = "[";
  for (int i = 0; i < 300; ++i) heights += (i ? ", " : "") + std::to_string(0.7 + 0.0003 * i);
  const Study study = load(
      "name: refused\nbase: walk_forward\nsweep:\n  grid:\n"
      "    walking.com_height: " +
      heights +
      "]\n"
      "    walking.foot_length: [0.2172, 0.17]\n"
      "    walking.cop_margin_x: [0.05, 0.09]\n");
  const std::size_t refused = 299 * 4 + 2 + 1;  // the last height, 0.17 m, 0.09 m
  ASSERT_EQ(std::count(study.checked_runs.begin(), study.checked_runs.end(), refused), 0);
  std::string made, loaded;
  try {
    (void)study.runs[refused];
  } catch (const InputError& e) {
    made = e.what();
  }
  try {
    (void)study.runs.loaded(refused);
  } catch (const InputError& e) {
    loaded = e.what();
  }
  EXPECT_NE(made.find("cop_margin_x"), std::string::npos) << made;
  EXPECT_EQ(made, loaded);
  EXPECT_TRUE(study.runs[refused - 1].from_fields);
}
