// A run read for the page of `wpg view` and written as its JSON (run_scene.hpp). The page
// decodes the arrays named here (analysis/viewer/src/scene_page.js): keep the two in step.
#include "wpg/viewer/run_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "wpg/viewer/viewer_page.hpp"
#include "wpg/obstacles.hpp"

namespace fs = std::filesystem;

namespace wpg::viewer {
namespace {

const char* obstacleType(ObstacleType type) {
  switch (type) {
    case ObstacleType::kCircle: return "circle";
    case ObstacleType::kBox: return "box";
    case ObstacleType::kPolygon: return "polygon";
  }
  return "polygon";
}

std::string formatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

// Every `step`-th sample and the last one.
std::vector<std::size_t> keptSamples(std::size_t n, std::size_t step) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < n; i += step) kept.push_back(i);
  if (!kept.empty() && kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

template <typename Row>
std::vector<float> columnsOf(const std::vector<Row>& rows, const std::vector<std::size_t>& kept,
                             int columns) {
  std::vector<float> values;
  values.reserve(kept.size() * static_cast<std::size_t>(columns));
  for (const std::size_t i : kept) {
    for (int c = 0; c < columns; ++c) values.push_back(static_cast<float>(rows[i][c]));
  }
  return values;
}

std::vector<float> rowsOf(const std::vector<double>& flat, std::size_t width,
                          const std::vector<std::size_t>& kept) {
  std::vector<float> values;
  if (flat.empty()) return values;
  values.reserve(kept.size() * width);
  for (const std::size_t i : kept) {
    for (std::size_t c = 0; c < width; ++c) values.push_back(static_cast<float>(flat[i * width + c]));
  }
  return values;
}

std::string subtitleOf(const LoadedRun& run) {
  const WalkTrajectory& t = run.stored.result.trajectory;
  std::string text = run.stored.robot + " · " + formatSeconds(t.time.back()) + " · " +
                     std::to_string(t.footsteps.size() >= 2 ? t.footsteps.size() - 2 : 0) +
                     " steps";
  if (!run.scene.q.empty()) {
    text += run.stored.zmp_error && run.stored.zmp_error->filtered ? " · replayed, filtered"
                                                                    : " · replayed";
  }
  if (run.scene.goal) {
    text += run.scene.goal->reached ? " · goal reached at " + formatSeconds(run.scene.goal->time_to_goal)
                                    : " · goal not reached";
  }
  const WalkResult& walk = run.stored.result;
  if (walk.blocked) {
    // Where and since when (the dataset's blocked_since, blocked_x, blocked_y); the message
    // only when something else failed the walk first.
    char where[96];
    std::snprintf(where, sizeof where, " at (%.2f, %.2f) m", walk.blocked_position.x(),
                  walk.blocked_position.y());
    text += " · blocked since t = " + formatSeconds(walk.blocked_since) + where;
    if (walk.message.find("the robot is blocked: ") == std::string::npos) {
      text += " · failed: " + walk.message;
    }
    return text;
  }
  text += walk.success ? " · success" : " · failed: " + walk.message;
  return text;
}

// The plan of each NMPC iteration (mpc/plan/), for the page's preview at the time shown (the
// ghost steps and the predicted CoM): per iteration its time, its previewed samples, the CoM
// predicted at each (x, y) and the previewed steps (landing time, x, y, yaw, side). Null when
// the run has no plan (`generator.record_plan: false`, or a file written before it). The
// iterations are decimated evenly when they would take more than half the page's floats.
void writePlanPreview(Json& json, const WalkTrajectory& t) {
  const PlanLog& plans = t.plans;
  if (plans.empty() || plans.size() != t.mpc.size() || plans.max_samples <= 0) {
    json.null();
    return;
  }
  const std::size_t k = plans.size();
  const auto n = static_cast<std::size_t>(plans.max_samples);
  const auto nf = static_cast<std::size_t>(plans.steps);
  const std::size_t per_iteration = 2 * n + 4 * nf + 1;
  const std::size_t budget = kMaxPageFloats / 2;
  const std::size_t step = std::max<std::size_t>(1, (k * per_iteration + budget - 1) / budget);
  std::vector<float> time, com, steps;
  std::vector<std::uint8_t> count, side;
  for (const std::size_t i : keptSamples(k, step)) {
    time.push_back(static_cast<float>(t.mpc[i].time));
    count.push_back(static_cast<std::uint8_t>(std::min(plans.samples[i], 255)));
    for (std::size_t j = 0; j < 2 * n; ++j) com.push_back(static_cast<float>(plans.com_position[i * 2 * n + j]));
    for (std::size_t s = 0; s < nf; ++s) {
      for (std::size_t c = 0; c < 4; ++c) steps.push_back(static_cast<float>(plans.step[(i * nf + s) * 4 + c]));
      side.push_back(plans.step_side[i * nf + s]);
    }
  }
  json.beginObject();
  json.key("samples").integer(static_cast<long long>(n));
  json.key("steps").integer(static_cast<long long>(nf));
  json.key("decimation").integer(static_cast<long long>(step));
  json.key("time").floats(time);
  json.key("count").bytes(count);
  json.key("com").floats(com);
  json.key("step").floats(steps);
  json.key("side").bytes(side);
  json.endObject();
}

}  // namespace

LoadedRun loadRun(const std::string& path, const std::string& run_name,
                  const std::string& robots_directory) {
  LoadedRun run;
  run.file = path;
  run.stored = datasets::readRunDataset(path, run_name);
  run.scene = datasets::readRunScene(path, run.stored.name, run.stored.result.trajectory.time.size());
  run.scenario = datasets::loadScenarioText(run.stored.scenario_yaml,
                                            path + ":/runs/" + run.stored.name + "/scenario", {},
                                            robots_directory);
  // The URDF the robot folder's walking file names (multibody.urdf); none without it.
  std::ifstream in;
  if (run.scenario.multibody.present)
    in.open(fs::path(robots_directory) / run.stored.robot / run.scenario.multibody.urdf);
  if (in) {
    std::ostringstream text;
    text << in.rdbuf();
    run.urdf = text.str();
  }
  return run;
}

void writeObstacles(Json& json, const datasets::Scenario& scenario) {
  json.beginArray();
  const std::vector<Obstacle>& obstacles = scenario.request.obstacles;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Obstacle& o = obstacles[i];
    json.beginObject();
    json.key("type").string(obstacleType(o.type));
    json.key("center").numbers({o.center.x(), o.center.y()});
    json.key("radius").number(o.radius);
    json.key("margin").number(o.margin);
    json.key("known").boolean(scenario.goal.knownToPlanner(i));
    json.key("outline").beginArray();
    for (const Eigen::Vector2d& v : o.worldVertices()) json.numbers({v.x(), v.y()});
    json.endArray();
    json.endObject();
  }
  json.endArray();
}

std::string runSceneJson(const LoadedRun& run, const std::string& back,
                         const std::string& back_label) {
  const WalkTrajectory& t = run.stored.result.trajectory;
  const std::size_t n = t.time.size();
  const std::size_t nq = run.scene.q_names.size();
  // Floats per sample: time 1, com 3, cop 2, feet 8, waist yaw 1, q, multibody ZMP 2.
  const std::size_t per_sample = 15 + nq + (run.scene.zmp_multibody.empty() ? 0 : 2);
  const std::size_t step = std::max<std::size_t>(1, (n * per_sample + kMaxPageFloats - 1) / kMaxPageFloats);
  const std::vector<std::size_t> kept = keptSamples(n, step);

  Json json;
  json.beginObject();
  json.key("kind").string("run");
  json.key("title").string(run.stored.name);
  json.key("subtitle").string(subtitleOf(run) +
                              (step > 1 ? " · one sample in " + std::to_string(step) + " shown" : ""));
  writeProvenance(json, fs::path(run.file).filename().string() + ":/runs/" + run.stored.name);
  if (!back.empty()) {
    json.key("back").string(back);
    json.key("back_label").string(back_label);
  }
  json.key("decimation").integer(static_cast<long long>(step));
  json.key("foot").beginObject();
  json.key("length").number(run.scenario.walking.foot_length);
  json.key("width").number(run.scenario.walking.foot_width);
  json.endObject();

  std::vector<float> time;
  std::vector<float> waist;
  std::vector<std::uint8_t> support;
  for (const std::size_t i : kept) {
    time.push_back(static_cast<float>(t.time[i]));
    waist.push_back(static_cast<float>(t.free_flyer_yaw[i]));
    support.push_back(static_cast<std::uint8_t>(t.support[i]));
  }
  json.key("time").floats(time);
  json.key("com").floats(columnsOf(t.com, kept, 3));
  json.key("cop").floats(columnsOf(t.cop, kept, 2));
  json.key("left_foot").floats(columnsOf(t.left_foot, kept, 4));
  json.key("right_foot").floats(columnsOf(t.right_foot, kept, 4));
  json.key("waist_yaw").floats(waist);
  json.key("support").bytes(support);
  if (!run.scene.zmp_multibody.empty()) {
    json.key("zmp_multibody").floats(rowsOf(run.scene.zmp_multibody, 2, kept));
  }
  if (nq > 0 && !run.urdf.empty()) {
    json.key("q").beginObject();
    json.key("names").strings(run.scene.q_names);
    json.key("values").floats(rowsOf(run.scene.q, nq, kept));
    json.endObject();
    json.key("urdf").string(run.urdf);
  } else {
    json.key("q").null();
  }

  json.key("footsteps").beginArray();
  for (const Footstep& step_ : t.footsteps) {
    json.beginArray();
    json.number(step_.landing_time).number(step_.pose.x()).number(step_.pose.y());
    json.number(step_.pose.z()).integer(static_cast<int>(step_.side));
    json.endArray();
  }
  json.endArray();

  std::vector<float> mpc_time, solve_time;
  std::vector<std::uint8_t> status;
  for (const MpcIterationLog& row : t.mpc) {
    mpc_time.push_back(static_cast<float>(row.time));
    solve_time.push_back(static_cast<float>(row.solve_time));
    status.push_back(static_cast<std::uint8_t>(row.status));
  }
  json.key("mpc").beginObject();
  json.key("time").floats(mpc_time);
  json.key("solve_time").floats(solve_time);
  json.key("status").bytes(status);
  json.endObject();
  json.key("preview");
  writePlanPreview(json, t);

  json.key("obstacles");
  writeObstacles(json, run.scenario);
  if (run.scene.goal) {
    const datasets::StoredGoalOutcome& goal = *run.scene.goal;
    json.key("goal").beginObject();
    json.key("x").number(goal.x);
    json.key("y").number(goal.y);
    json.key("yaw").number(goal.yaw);
    json.key("tolerance").number(goal.tolerance);
    json.key("reached").boolean(goal.reached);
    json.key("time_to_goal").number(goal.time_to_goal);
    json.key("outcome").string(goal.outcome);
    json.endObject();
  } else {
    json.key("goal").null();
  }
  json.key("plans").beginArray();
  for (const datasets::StoredRoutePlan& plan : run.scene.plans) {
    json.beginObject();
    json.key("time").number(plan.time);
    json.key("trigger").string(plan.trigger_name);
    json.key("status").string(plan.status_name);
    json.key("route").beginArray();
    for (const Eigen::Vector3d& point : plan.route) json.numbers({point.x(), point.y(), point.z()});
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.key("pushes").beginArray();
  for (const Push& push : run.scenario.request.pushes) {
    json.beginObject();
    json.key("t").number(push.t);
    json.key("duration").number(push.duration);
    json.key("force").numbers({push.force.x(), push.force.y()});
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return json.text();
}

void writeTopView(Json& json, const LoadedRun& run) {
  const WalkTrajectory& t = run.stored.result.trajectory;
  const std::size_t n = t.time.size();
  constexpr std::size_t kPathPoints = 300;
  std::vector<float> path;
  for (const std::size_t i : keptSamples(n, std::max<std::size_t>(1, n / kPathPoints))) {
    path.push_back(static_cast<float>(t.com[i].x()));
    path.push_back(static_cast<float>(t.com[i].y()));
  }
  json.beginObject();
  json.key("path").floats(path);
  json.key("obstacles");
  writeObstacles(json, run.scenario);
  if (run.scene.goal) {
    json.key("goal").numbers({run.scene.goal->x, run.scene.goal->y, run.scene.goal->tolerance});
    json.key("reached").boolean(run.scene.goal->reached);
  } else {
    json.key("goal").null();
    json.key("reached").boolean(run.stored.result.success);
  }
  json.key("success").boolean(run.stored.result.success);
  json.key("blocked").boolean(run.stored.result.blocked);
  json.endObject();
}

}  // namespace wpg::viewer
