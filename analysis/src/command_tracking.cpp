// Steady-state command tracking (command_tracking.hpp; definition: datasets/METRICS.md).
#include "wpg/analysis/command_tracking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace wpg::analysis {

SteadyTracking steadyTracking(const WalkingParameters& w, const WalkRequest& request,
                              const WalkTrajectory& tr) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  SteadyTracking result{kNaN, kNaN, kNaN, kNaN};
  const std::size_t n = tr.size();
  if (request.reference.empty() || n == 0) return result;
  const VelocityCommand& command = request.reference.back();

  // The steady steps: the landings at or after the settling time.
  std::vector<double> landings;
  for (std::size_t k = 2; k < tr.footsteps.size(); ++k)
    if (tr.footsteps[k].landing_time >= command.t + kSteadySettlingTime - 1e-9)
      landings.push_back(tr.footsteps[k].landing_time);

  // The heading: the free-flyer yaw unwrapped, then its centred mean over one gait cycle W
  // (samples i - h .. i + h - 1): the feet turn once per step, the mean over two steps is
  // smooth, and the sway's part of the velocity, periodic over W, then averages out. W is two
  // of the steady steps as they were walked (their mean duration: with the adaptive step
  // timing a command may be walked with shorter steps than the parameters'), two steps of the
  // parameters without them.
  const double cycle =
      landings.size() >= 3
          ? 2.0 * (landings.back() - landings.front()) / static_cast<double>(landings.size() - 1)
          : 2.0 * w.stepDuration();
  const std::size_t h = static_cast<std::size_t>(std::lround(cycle / (2.0 * w.control_period)));
  if (h == 0 || n < 2 * h + 1) return result;
  std::vector<double> yaw(n), sums(n + 1, 0.0);
  yaw[0] = tr.free_flyer_yaw[0];
  for (std::size_t i = 1; i < n; ++i) {
    const double step = std::remainder(tr.free_flyer_yaw[i] - tr.free_flyer_yaw[i - 1], 2.0 * M_PI);
    yaw[i] = yaw[i - 1] + step;
  }
  for (std::size_t i = 0; i < n; ++i) sums[i + 1] = sums[i] + yaw[i];
  const auto heading = [&](std::size_t i) {
    return (sums[i + h] - sums[i - h]) / static_cast<double>(2 * h);
  };

  // Whole gait cycles: from the first landing at or after the settling time to the last
  // landing an even number of steps later whose heading window ends within the walk.
  const auto sampleAt = [&](double t) {
    return static_cast<std::size_t>(
        std::lower_bound(tr.time.begin(), tr.time.end(), t - 1e-9) - tr.time.begin());
  };
  std::size_t steps = 0;
  for (std::size_t k = 2; k < landings.size(); k += 2) {
    const std::size_t b = sampleAt(landings[k]);
    if (b + h <= n) steps = k;
  }
  if (steps == 0) return result;
  const std::size_t a = sampleAt(landings[0]), b = sampleAt(landings[steps]);
  if (a < h || b <= a) return result;

  double vx = 0.0, vy = 0.0;
  for (std::size_t i = a; i < b; ++i) {
    const double c = std::cos(heading(i)), s = std::sin(heading(i));
    vx += c * tr.com_vel[i].x() + s * tr.com_vel[i].y();
    vy += -s * tr.com_vel[i].x() + c * tr.com_vel[i].y();
  }
  const double count = static_cast<double>(b - a);
  result.vx = vx / count;
  result.vy = vy / count;
  result.omega = (heading(b) - heading(a)) / (tr.time[b] - tr.time[a]);
  const auto score = [](double measured, double commanded, double floor) {
    return std::abs(measured - commanded) /
           std::max(kSteadyRelativeTolerance * std::abs(commanded), floor);
  };
  const Eigen::Vector3d& v = command.velocity;
  result.score = std::max({score(result.vx, v.x(), kSteadyVelocityFloor),
                           score(result.vy, v.y(), kSteadyVelocityFloor),
                           score(result.omega, v.z(), kSteadyYawRateFloor)});
  return result;
}

}  // namespace wpg::analysis
