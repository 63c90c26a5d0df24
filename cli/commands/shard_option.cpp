// `--shard K/N` (shard_option.hpp).
#include "shard_option.hpp"

#include "exit_codes.hpp"

namespace wpg::cli {

engine::ShardSlice parseShardOption(const std::string& text) {
  const auto bad = [&]() {
    return UsageError("--shard: expected K/N, slice K of N with 0 <= K < N (e.g. 0/4), got '" +
                      text + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) throw bad();
  const std::string k = text.substr(0, slash), n = text.substr(slash + 1);
  if (k.find_first_not_of("0123456789") != std::string::npos ||
      n.find_first_not_of("0123456789") != std::string::npos || k.size() > 9 || n.size() > 9) {
    throw bad();
  }
  const int shard = std::stoi(k), count = std::stoi(n);
  if (count < 1 || shard >= count) throw bad();
  return {shard, count};
}

}  // namespace wpg::cli
