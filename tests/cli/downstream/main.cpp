// Uses the installed wpg: HRP-2's default walking parameters and a walk request must validate,
// and a bad value must be rejected with std::invalid_argument.
#include <iostream>
#include <stdexcept>

#include <wpg/datasets/scenario.hpp>
#include <wpg/walk_request.hpp>
#include <wpg/walking_parameters.hpp>

int main() {
  wpg::WalkingParameters parameters;
  parameters.validate();
  wpg::WalkRequest request;
  request.validate();
  parameters.com_height = -1.0;
  try {
    parameters.validate();
    std::cerr << "validate() accepted a negative CoM height\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cout << "wpg::wpg ok (rejected: " << e.what() << ")\n";
  }
  // wpg::datasets: a missing scenario file is an InputError.
  try {
    wpg::datasets::loadScenario("/nonexistent/scenario.yaml", {}, "/nonexistent");
    std::cerr << "loadScenario() accepted a missing file\n";
    return 1;
  } catch (const wpg::datasets::InputError& e) {
    std::cout << "wpg::datasets ok (rejected: " << e.what() << ")\n";
  }
  return 0;
}
