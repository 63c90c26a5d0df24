#pragma once
// The data folders and SCENARIO arguments of the subcommands: the engine's
// (wpg/engine/data_paths.hpp), named in the CLI's namespace.
#include "wpg/engine/data_paths.hpp"

namespace wpg::cli {

using engine::dataDirectory;
using engine::kDefaultScenario;
using engine::plotScriptPath;
using engine::resolveScenarioPath;
using engine::robotsDirectory;
using engine::scenariosDirectory;
using engine::shippedScenarioNames;

}  // namespace wpg::cli
