// Uses the installed wpg: HRP-2's default walking parameters and a walk request must validate,
// a bad value must be rejected with std::invalid_argument, the online API must generate a walk
// (CoM and feet every control period) that goes forward, generateWalk must agree with it,
// wpg::analysis must count its steps, and wpg::engine must run it as a scenario to the same
// walk, with its metrics.
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include <wpg/analysis/run_summary.hpp>
#include <wpg/datasets/input/scenario.hpp>
#include <wpg/engine/scenario_run.hpp>
#include <wpg/online_walking_generator.hpp>
#include <wpg/walk_generator.hpp>
#include <wpg/walk_request.hpp>
#include <wpg/walking_parameters.hpp>

namespace {

int fail(const char* what) {
  std::cerr << what << "\n";
  return 1;
}

}  // namespace

int main() {
  wpg::WalkingParameters parameters;
  parameters.validate();
  wpg::WalkRequest request;
  request.validate();
  wpg::WalkingParameters bad = parameters;
  bad.com_height = -1.0;
  try {
    bad.validate();
    return fail("validate() accepted a negative CoM height");
  } catch (const std::invalid_argument& e) {
    std::cout << "wpg::wpg ok (rejected: " << e.what() << ")\n";
  }

  // The online API, as a controller embeds it: 4 s at 0.2 m/s, one step() per 5 ms.
  wpg::OnlineWalkingGenerator generator(parameters, wpg::GeneratorSettings());
  generator.reset(Eigen::Vector3d::Zero());
  generator.setCommand(Eigen::Vector3d(0.2, 0.0, 0.0));
  std::vector<wpg::ControlSample> samples;
  int landings = 0;
  while (generator.time() < 4.0 - 1e-9) {
    samples.push_back(generator.step());
    if (generator.lastIteration().status != wpg::IterationStatus::kSolved)
      return fail("an NMPC iteration was not solved");
    if (generator.landed()) ++landings;
  }
  // Read it back: finite CoM and feet, the robot moved forward, the feet took steps.
  for (const wpg::ControlSample& s : samples) {
    if (!s.com_position.allFinite() || !s.left_foot.allFinite() || !s.right_foot.allFinite())
      return fail("non-finite CoM or foot in the online walk");
  }
  const wpg::ControlSample& last = samples.back();
  const double forward = last.com_position.x() - samples.front().com_position.x();
  const double feet = 0.5 * (last.left_foot.x() + last.right_foot.x());
  if (samples.size() != 800 || !(forward > 0.4) || !(feet > 0.3) || landings < 3 ||
      std::abs(last.com_position.y()) > 0.1)
    return fail("the online walk did not go forward");
  std::cout << "online API ok (" << samples.size() << " control periods, CoM " << forward
            << " m forward, " << landings << " steps)\n";

  // generateWalk is a loop over the same API.
  request.duration = 4.0;
  request.reference = {{0.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  const wpg::WalkResult walk = wpg::generateWalk(parameters, request);
  if (!walk.success || walk.trajectory.size() != samples.size() + 1 ||
      walk.trajectory.com[samples.size() - 1] != last.com_position)
    return fail("generateWalk differs from the online API");

  // wpg::analysis: the summary of that walk counts the steps that the online API landed.
  const wpg::analysis::RunSummary summary = wpg::analysis::summarizeRun(walk.trajectory);
  if (summary.steps != static_cast<std::size_t>(landings) ||
      summary.nmpc_iterations != walk.trajectory.mpc.size() || !(summary.displacement > 0.4))
    return fail("wpg::analysis summary disagrees with the walk");
  std::cout << "wpg::analysis ok (" << summary.steps << " steps, " << summary.displacement
            << " m)\n";

  // wpg::engine: the same walk as a scenario (no replay: no robot files needed).
  wpg::datasets::Scenario scenario;
  scenario.name = "downstream";
  scenario.robot = "hrp2";
  scenario.walking = parameters;
  scenario.request = request;
  const wpg::engine::RunResult run = wpg::engine::runScenario(scenario, {});
  if (run.outcome != wpg::engine::RunOutcome::kSucceeded || run.exitStatus() != 0 ||
      run.walk.result.trajectory.com != walk.trajectory.com ||
      run.metrics.steps != static_cast<double>(landings))
    return fail("wpg::engine's run differs from generateWalk");
  std::cout << "wpg::engine ok (" << wpg::engine::runOutcomeName(run.outcome) << ", "
            << run.metrics.steps << " steps)\n";

  // wpg::datasets: a missing scenario file is an InputError.
  try {
    wpg::datasets::loadScenario("/nonexistent/scenario.yaml", {}, "/nonexistent");
    return fail("loadScenario() accepted a missing file");
  } catch (const wpg::datasets::InputError& e) {
    std::cout << "wpg::datasets ok (rejected: " << e.what() << ")\n";
  }
  return 0;
}
