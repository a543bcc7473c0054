#include "options/shard_spec.h"

#include <cctype>
#include <climits>
#include <cstdlib>

#include "options/option_name.h"
#include "options/option_parser.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

// A non-negative decimal number without sign or spaces; false when `text`
// is not one or does not fit an int.
bool ParseCount(const std::string& text, int* value) {
  if (text.empty() || text.size() > 9) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  *value = std::atoi(text.c_str());
  return true;
}

}  // namespace

ShardSpec ParseShardSpec(const std::string& text) {
  const std::string option = MSP_OPTION_FLAG_OF(MspStereoOptions, shard);
  const size_t slash = text.find('/');
  ShardSpec shard;
  if (slash == std::string::npos || !ParseCount(text.substr(0, slash), &shard.index) ||
      !ParseCount(text.substr(slash + 1), &shard.count)) {
    throw OptionError("invalid value `" + text + "` for " + option +
                      ": must be K/N with whole numbers 0 <= K < N, e.g. 0/4");
  }
  if (shard.count < 1) {
    throw OptionError("invalid value `" + text + "` for " + option +
                      ": the number of shards N must be at least 1");
  }
  if (shard.index >= shard.count) {
    throw OptionError("invalid value `" + text + "` for " + option + ": the shards of " +
                      std::to_string(shard.count) + " processes are numbered 0 to " +
                      std::to_string(shard.count - 1));
  }
  return shard;
}

std::string ToString(const ShardSpec& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

int ShardOfProblem(int problem, const ShardSpec& shard) { return problem % shard.count; }

std::vector<int> ProblemsOfShard(int num_problems, const ShardSpec& shard) {
  std::vector<int> problems;
  for (int k = shard.index; k < num_problems; k += shard.count) problems.push_back(k);
  return problems;
}

}  // namespace msp
