#pragma once
// What `wpg batch` and `wpg compare` call the fields of the engine's study request: the engine's
// messages about a bad value name the option the user typed.
#include "wpg/engine/study_request.hpp"

namespace wpg::cli {

inline engine::RequestFieldNames studyOptionNames() {
  engine::RequestFieldNames names;
  names.jobs = "-j";
  names.output = "-o";
  names.shard = "--shard";
  names.ompl_log = "--ompl-log";
  return names;
}

}  // namespace wpg::cli
