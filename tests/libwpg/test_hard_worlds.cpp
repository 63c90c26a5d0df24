// Hard obstacle worlds: no crash, no NaN; either a clear input error or a run that ends with
// its status recorded. libwpg's exact 2-D distance is the
// world model here (planning/'s FCL world is checked against it in tests/planning).
#include <gtest/gtest.h>

#include <string>

#include "wpg/walk_generator.hpp"

namespace {

wpg::Obstacle circle(double x, double y, double radius, double margin) {
  wpg::Obstacle o;
  o.center = Eigen::Vector2d(x, y);
  o.radius = radius;
  o.margin = margin;
  return o;
}

wpg::Obstacle box(double x, double y, double length, double width, double yaw, double margin) {
  wpg::Obstacle o;
  o.type = wpg::ObstacleType::kBox;
  o.center = Eigen::Vector2d(x, y);
  o.size = Eigen::Vector2d(length, width);
  o.yaw = yaw;
  o.margin = margin;
  return o;
}

wpg::WalkRequest forward(double duration) {
  wpg::WalkRequest request;
  request.duration = duration;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.0, 0.1)}};
  return request;
}

void expectFinite(const wpg::WalkTrajectory& tr) {
  for (std::size_t i = 0; i < tr.size(); ++i) {
    ASSERT_TRUE(tr.com[i].allFinite() && tr.cop[i].allFinite() && tr.left_foot[i].allFinite() &&
                tr.right_foot[i].allFinite())
        << "t = " << tr.time[i];
  }
  for (const auto& log : tr.mpc) ASSERT_TRUE(std::isfinite(log.cost)) << "t = " << log.time;
}

// No landed step centre inside an obstacle grown by its margin and the sole radius, unless
// the run says so.
void expectStepsClearOrReported(const wpg::WalkingParameters& w, const wpg::WalkRequest& request,
                                const wpg::WalkResult& result) {
  const wpg::AnalyticObstacleDistance distance(request.obstacles);
  double worst = 1e9;
  for (const auto& step : result.trajectory.footsteps) {
    if (step.landing_time <= 0.0) continue;
    for (int o = 0; o < distance.obstacleCount(); ++o)
      worst = std::min(worst, distance.signedDistance(o, step.pose.head<2>(), nullptr) -
                                  request.obstacles[o].margin - w.obstacle_foot_radius);
  }
  if (worst < -1e-6) {
    EXPECT_FALSE(result.success) << "a step is " << -worst << " m inside a margin, unreported";
    EXPECT_NE(result.message.find("margin"), std::string::npos) << result.message;
  }
}

TEST(HardWorlds, ObstacleOnTheStartingFeetIsAnInputError) {
  wpg::WalkRequest request = forward(5.0);
  request.obstacles = {circle(0.0, 0.1, 0.1, 0.05)};
  try {
    wpg::generateWalk(wpg::WalkingParameters(), request);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("obstacles[0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("initial feet"), std::string::npos) << e.what();
  }
}

TEST(HardWorlds, EnclosedRobotNeverCrashesAndReportsWhatHappened) {
  const wpg::WalkingParameters w;
  wpg::WalkRequest request = forward(12.0);
  // A ring of boxes around the start, 0.8 m away: no way out.
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4.0;
    request.obstacles.push_back(box(0.8 * std::cos(a), 0.8 * std::sin(a), 0.2, 0.7, a, 0.05));
  }
  request.generator.max_obstacles_in_qp = 8;
  const wpg::WalkResult result = wpg::generateWalk(w, request);
  expectFinite(result.trajectory);
  expectStepsClearOrReported(w, request, result);
  EXPECT_EQ(result.trajectory.size(), 2401u);
  // Either it stays inside the ring (and, stuck there, ends blocked), or the QP became
  // infeasible, its obstacle rows were relaxed first (balance before obstacles) and the run says
  // a step entered a margin.
  if (result.success || result.blocked) {
    EXPECT_LT(result.trajectory.com.back().head<2>().norm(), 0.8);
  } else {
    bool relaxed = false;
    for (const auto& log : result.trajectory.mpc)
      relaxed = relaxed || log.status == wpg::IterationStatus::kRelaxedObstacle;
    EXPECT_TRUE(relaxed);
  }
}

TEST(HardWorlds, OverlappingObstaclesAreAvoidedTogether) {
  const wpg::WalkingParameters w;
  wpg::WalkRequest request = forward(15.0);
  request.obstacles = {circle(1.5, -0.7, 0.3, 0.1), box(1.7, -0.6, 0.6, 0.4, 0.5, 0.1),
                       circle(1.9, -0.8, 0.25, 0.1)};
  const wpg::WalkResult result = wpg::generateWalk(w, request);
  expectFinite(result.trajectory);
  expectStepsClearOrReported(w, request, result);
}

TEST(HardWorlds, DegenerateOrNonConvexPolygonsAreInputErrors) {
  wpg::WalkRequest request = forward(5.0);
  wpg::Obstacle flat;
  flat.type = wpg::ObstacleType::kPolygon;
  flat.vertices = {{1.0, 1.0}, {2.0, 1.0}, {3.0, 1.0}};
  request.obstacles = {flat};
  EXPECT_THROW(wpg::generateWalk(wpg::WalkingParameters(), request), std::invalid_argument);
  wpg::Obstacle dart;
  dart.type = wpg::ObstacleType::kPolygon;
  dart.vertices = {{1.0, 1.0}, {2.0, 1.5}, {1.0, 2.0}, {1.3, 1.5}};
  request.obstacles = {dart};
  EXPECT_THROW(wpg::generateWalk(wpg::WalkingParameters(), request), std::invalid_argument);
}

}  // namespace
