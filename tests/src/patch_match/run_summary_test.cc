#include "patch_match/run_summary.h"

#include <gtest/gtest.h>

namespace msp {
namespace {

TEST(RunSummaryTest, PassSharesAndValidPixels) {
  const std::string text = FormatRunSummary(
      {{"round 1/1, photometric pass 1", 30.04}, {"round 1/1, geometric pass 2", 90}},
      {{"a.png", 10, 10, 25}, {"b.png", 10, 10, -1}});
  EXPECT_NE(text.find("round 1/1, photometric pass 1       30.0s   25.0%"), std::string::npos)
      << text;
  EXPECT_NE(text.find("round 1/1, geometric pass 2         1m30s   75.0%"), std::string::npos)
      << text;
  EXPECT_NE(text.find("all passes                          2m00s  100.0%"), std::string::npos)
      << text;
  EXPECT_NE(text.find("a.png      10x10            25   25.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("b.png      10x10  kept (final maps from an earlier run)"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace msp
