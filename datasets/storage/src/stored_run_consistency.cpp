// A stored walk against its stored scenario (wpg/datasets/storage/stored_run_consistency.hpp): the
// generator's timing and shape (libwpg/src/walk_generator.cpp, OnlineWalkingGenerator::time()),
// checked so that a walk and a scenario that do not belong together are refused before any
// replay or metric uses them.
#include "wpg/datasets/storage/stored_run_consistency.hpp"

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>

#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets {
namespace {

std::string number(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

class ConsistencyCheck {
 public:
  ConsistencyCheck(const std::string& path, const StoredRun& stored, const Scenario& scenario)
      : path_(path), run_path_("/runs/" + stored.name), stored_(stored), scenario_(scenario) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(path_ + ": " + message + " (the stored scenario does not match the walk)");
  }

  void robot() const {
    if (stored_.robot != scenario_.robot) {
      fail("attribute " + run_path_ + ":robot is '" + stored_.robot +
           "', expected the scenario's robot '" + scenario_.robot + "'");
    }
  }

  // Sample i at i x control_period (the generator forms it as k T + s dt: a few ulps apart).
  void sampleTimes() const {
    const std::vector<double>& time = stored_.result.trajectory.time;
    const double dt = scenario_.walking.control_period;
    for (std::size_t i = 0; i < time.size(); ++i) {
      const double expected = static_cast<double>(i) * dt;
      if (!(std::abs(time[i] - expected) <= kTimeTolerance * dt)) {
        fail("dataset " + run_path_ + "/time row " + std::to_string(i) + ": expected " +
             number(expected) + " s (row x walking.control_period " + number(dt) + " s), got " +
             number(time[i]) + " s");
      }
    }
    const std::size_t most = maxSamples();
    if (time.size() > most) {
      fail("dataset " + run_path_ + "/time has " + std::to_string(time.size()) +
           " rows: expected at most " + std::to_string(most) + " (duration " +
           number(scenario_.request.duration) + " s at walking.control_period " + number(dt) +
           " s)");
    }
  }

  // The LIPM keeps the CoM at com_height (eq. 3).
  void comHeight() const {
    const auto& com = stored_.result.trajectory.com;
    const double h = scenario_.walking.com_height;
    for (std::size_t i = 0; i < com.size(); ++i) {
      if (!(std::abs(com[i].z() - h) <= 1e-9 * std::max(1.0, h))) {
        fail("dataset " + run_path_ + "/com row " + std::to_string(i) +
             " column 2: expected walking.com_height " + number(h) + " m, got " +
             number(com[i].z()) + " m");
      }
    }
  }

  void iterationTimes() const {
    const WalkTrajectory& t = stored_.result.trajectory;
    const double T = scenario_.walking.sampling_period;
    const double last = t.time.empty() ? 0.0 : t.time.back();
    for (std::size_t j = 0; j < t.mpc.size(); ++j) {
      const double expected = static_cast<double>(j) * T;
      if (!(std::abs(t.mpc[j].time - expected) <= kTimeTolerance * T)) {
        fail("dataset " + run_path_ + "/mpc/time row " + std::to_string(j) + ": expected " +
             number(expected) + " s (row x walking.sampling_period " + number(T) + " s), got " +
             number(t.mpc[j].time) + " s");
      }
      if (t.mpc[j].time > last + kTimeTolerance * T) {
        fail("dataset " + run_path_ + "/mpc/time row " + std::to_string(j) + ": expected at most " +
             "the walk's last sample time " + number(last) + " s, got " + number(t.mpc[j].time) +
             " s");
      }
    }
    // One iteration at every NMPC instant before the last sample.
    const double instants = std::ceil(last / T - kTimeTolerance);
    if (static_cast<double>(t.mpc.size()) < instants) {
      fail("dataset " + run_path_ + "/mpc/time has " + std::to_string(t.mpc.size()) +
           " rows: expected " + number(instants) + " (one per walking.sampling_period " +
           number(T) + " s up to " + number(last) + " s)");
    }
  }

  void footsteps() const {
    const WalkTrajectory& t = stored_.result.trajectory;
    const std::string where = "dataset " + run_path_ + "/footsteps";
    if (t.footsteps.size() < 2 || t.footsteps[0].side != FootSide::kLeft ||
        t.footsteps[1].side != FootSide::kRight || t.footsteps[0].landing_time != 0.0 ||
        t.footsteps[1].landing_time != 0.0) {
      fail(where + ": expected the initial left and right feet first, at landing time 0");
    }
    if (t.footsteps.size() > 2 + t.mpc.size()) {
      fail(where + " has " + std::to_string(t.footsteps.size()) + " rows: expected at most " +
           std::to_string(2 + t.mpc.size()) + " (the two initial feet and one per NMPC iteration)");
    }
    const double last = t.time.empty() ? 0.0 : t.time.back();
    const double dt = scenario_.walking.control_period;
    for (std::size_t j = 2; j < t.footsteps.size(); ++j) {
      const double landing = t.footsteps[j].landing_time;
      if (!(landing >= t.footsteps[j - 1].landing_time && landing <= last + dt)) {
        fail(where + " row " + std::to_string(j) + " column 0: expected a landing time from " +
             number(t.footsteps[j - 1].landing_time) + " s (the previous row) to " +
             number(last) + " s (the walk's end), got " + number(landing) + " s");
      }
      const double lift_off = t.footsteps[j].lift_off_time;  // NaN: not stored (older files)
      if (!std::isnan(lift_off) && !(lift_off >= 0.0 && lift_off < landing)) {
        fail("dataset " + run_path_ + "/footstep_lift_off row " + std::to_string(j) +
             ": expected a lift-off time from 0 s to the landing time " + number(landing) +
             " s, got " + number(lift_off) + " s");
      }
    }
  }

 private:
  // Relative to the period: far above the rounding of k T + s dt, far below one period.
  static constexpr double kTimeTolerance = 1e-6;

  std::size_t maxSamples() const {
    const double T = scenario_.walking.sampling_period;
    const double iterations = std::round(scenario_.request.duration / T);
    const double sub_samples = std::round(T / scenario_.walking.control_period);
    // Both bounded by the scenario loader (duration <= kMaxWalkDuration, periods >= 1e-6 s).
    return static_cast<std::size_t>(iterations * sub_samples) + 1;
  }

  const std::string& path_;
  std::string run_path_;
  const StoredRun& stored_;
  const Scenario& scenario_;
};

}  // namespace

void checkStoredRunMatchesScenario(const std::string& path, const StoredRun& stored,
                                   const Scenario& scenario) {
  const ConsistencyCheck check(path, stored, scenario);
  check.robot();
  check.sampleTimes();
  check.comHeight();
  check.iterationTimes();
  check.footsteps();
}

}  // namespace wpg::datasets
