#pragma once
// `--shard K/N` of `wpg batch` and `wpg compare`: slice K of N of a study's runs (runs i with
// i mod N = K, datasets::inShardSlice), written into a shard file and joined by `wpg merge`.
#include <string>

#include "wpg/engine/study_executor.hpp"

namespace wpg::cli {

// "K/N" -> slice K of N with 0 <= K < N; UsageError otherwise.
engine::ShardSlice parseShardOption(const std::string& text);

}  // namespace wpg::cli
