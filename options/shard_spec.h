// --MspStereo.shard "K/N": which reference images one of N processes that
// share a workspace computes. Problem k belongs to shard k mod N, so every
// shard gets every N-th problem of patch-match.cfg's order and the shards'
// work stays alike when neighbouring problems are alike in size.
#pragma once

#include <string>
#include <vector>

namespace msp {

struct ShardSpec {
  int index = 0;  // K, in [0, count)
  int count = 1;  // N >= 1
};

// Parses "K/N" (decimal, 0 <= K < N). Throws OptionError naming
// --MspStereo.shard, the value and the expected form.
ShardSpec ParseShardSpec(const std::string& text);

// "K/N"
std::string ToString(const ShardSpec& shard);

// The shard of problem `problem` (its index in the problem list).
int ShardOfProblem(int problem, const ShardSpec& shard);

// The problems of `shard` among `num_problems`, ascending.
std::vector<int> ProblemsOfShard(int num_problems, const ShardSpec& shard);

}  // namespace msp
