#include "options/shard_spec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "options/option_check.h"
#include "options/option_parser.h"

namespace msp {
namespace {

TEST(ShardSpec, ParsesKOfN) {
  const ShardSpec shard = ParseShardSpec("2/5");
  EXPECT_EQ(shard.index, 2);
  EXPECT_EQ(shard.count, 5);
  EXPECT_EQ(ToString(shard), "2/5");
  EXPECT_EQ(ParseShardSpec("0/1").count, 1);
}

TEST(ShardSpec, RefusesMalformedAndOutOfRangeValuesNamingTheOption) {
  const std::vector<std::pair<std::string, std::string>> cases = {{"3/3", "numbered 0 to 2"},
                                                                  {"0/0", "at least 1"},
                                                                  {"1", "K/N"},
                                                                  {"-1/2", "K/N"},
                                                                  {"a/2", "K/N"},
                                                                  {"1/ 2", "K/N"},
                                                                  {"", "K/N"},
                                                                  {"1/2/3", "K/N"},
                                                                  {"99999999999/2", "K/N"}};
  for (const auto& [text, why] : cases) {
    try {
      ParseShardSpec(text);
      ADD_FAILURE() << "accepted `" << text << "`";
    } catch (const OptionError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("--MspStereo.shard"), std::string::npos) << message;
      EXPECT_NE(message.find("`" + text + "`"), std::string::npos) << message;
      EXPECT_NE(message.find(why), std::string::npos) << message;
    }
  }
}

TEST(ShardSpec, EveryProblemBelongsToExactlyOneShard) {
  for (int count : {1, 2, 3, 7}) {
    std::vector<int> owners(10, 0);
    for (int index = 0; index < count; ++index) {
      for (int k : ProblemsOfShard(10, ShardSpec{index, count})) {
        ++owners[k];
        EXPECT_EQ(ShardOfProblem(k, ShardSpec{index, count}), index);
      }
    }
    for (int n : owners) EXPECT_EQ(n, 1) << count << " shards";
  }
  EXPECT_EQ(ProblemsOfShard(7, ShardSpec{1, 3}), (std::vector<int>{1, 4}));
  EXPECT_TRUE(ProblemsOfShard(2, ShardSpec{4, 5}).empty());
}

TEST(ShardSpec, OptionCheckRefusesAShardWithAListAndANonPositiveTimeout) {
  MspStereoOptions options;
  options.shard = "1/2";
  EXPECT_NO_THROW(CheckMspStereoOptions(options));
  options.image_list = "list.txt";
  EXPECT_THROW(CheckMspStereoOptions(options), OptionError);
  options = MspStereoOptions();
  options.shard = "2/2";
  EXPECT_THROW(CheckMspStereoOptions(options), OptionError);
  options = MspStereoOptions();
  options.shard_timeout = 0;
  EXPECT_THROW(CheckMspStereoOptions(options), OptionError);
}

}  // namespace
}  // namespace msp
