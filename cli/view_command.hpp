#pragma once
// `wpg view FILE.h5 [--run NAME] [-o PAGE.html]` and `wpg view DIR`: an HTML page to watch a
// run (its robot, footsteps, obstacles, plots) or to explore a study (docs/viewer.md).
#include <string>

namespace wpg::cli {

struct ViewOptions {
  std::string input;   // a run file, a batch file, or the folder of `wpg compare`
  std::string run;     // --run NAME: one run of a batch file
  std::string output;  // -o PAGE.html; empty: beside the input
};

// Exit 0, or 2 on bad input (nothing written) and when the viewer bundle is missing.
int viewCommand(const ViewOptions& options);

}  // namespace wpg::cli
