#pragma once
// The figures: analysis/'s Python scripts, run with Debian's Python (/usr/bin/python3: a pyenv
// python3 first on PATH would not see Debian's h5py and matplotlib).
#include <string>
#include <vector>

namespace wpg::cli {

// Runs /usr/bin/python3 <plot script> run_file -o figure_file [--run run]; returns its exit
// status (kExitBadInput with a message on stderr when Python or its modules are missing).
int drawFigure(const std::string& run_file, const std::string& figure_file,
               const std::string& run = "");
// Runs /usr/bin/python3 script arguments... (the same checks and messages as drawFigure).
int runAnalysisScript(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace wpg::cli
