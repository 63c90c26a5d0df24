// Uses the installed core (wpg::wpg) alone: a 4 s walk with the online API must go forward and
// land steps, and the version header must give the package's version.
#include <cstring>
#include <iostream>

#include <wpg/online_walking_generator.hpp>
#include <wpg/version.hpp>

int main(int argc, char** argv) {
  if (argc != 2 || std::strcmp(argv[1], wpg::kVersion) != 0) {
    std::cerr << "wpg::kVersion is " << wpg::kVersion << ", expected " << (argc > 1 ? argv[1] : "?")
              << "\n";
    return 1;
  }
  const wpg::WalkingParameters hrp2;
  wpg::OnlineWalkingGenerator generator(hrp2, wpg::GeneratorSettings());
  generator.reset(Eigen::Vector3d::Zero());
  generator.setCommand(Eigen::Vector3d(0.2, 0.0, 0.0));
  int landings = 0;
  double x = 0.0;
  for (int tick = 0; tick < 800; ++tick) {  // 4 s of 5 ms periods
    const wpg::ControlSample& sample = generator.step();
    if (generator.landed()) ++landings;
    x = sample.com_position.x();
  }
  if (!(x > 0.3) || landings < 3) {
    std::cerr << "the core's walk: CoM x " << x << " m, " << landings << " landings\n";
    return 1;
  }
  std::cout << "core: CoM at x = " << x << " m after 4 s, " << landings << " landings\n";
  return 0;
}
