#include "patch_match/step_ledger.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace msp {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(StepLedgerTest, SharesOfTheRunPerRoundAndStep) {
  StepLedger ledger;
  ledger.AddImagePass(0, "80x60", 80 * 60);
  ledger.Add(0, Step::kSweeps, 1.0, EvaluationCounts{});
  ledger.AddImagePass(1, "160x120", 160 * 120);
  ledger.Add(1, Step::kSweeps, 2.0, EvaluationCounts{});
  ledger.Add(1, Step::kLocalRefine, 1.0, EvaluationCounts{});
  const std::vector<std::string> lines = Lines(ledger.Format());
  // Title, header, then per round 7 steps + 3 phase rows of the sweeps.
  ASSERT_EQ(lines.size(), 2u + 2u * 10u);
  EXPECT_NE(lines[3].find("80x60"), std::string::npos);
  EXPECT_NE(lines[3].find("sweeps"), std::string::npos);
  EXPECT_NE(lines[3].find("25.0%"), std::string::npos);
  EXPECT_NE(lines[4].find("propagation"), std::string::npos);
  EXPECT_NE(lines[13].find("160x120"), std::string::npos);
  EXPECT_NE(lines[13].find("50.0%"), std::string::npos);
  EXPECT_NE(lines[17].find("local refine"), std::string::npos);
  EXPECT_NE(lines[17].find("25.0%"), std::string::npos);
}

TEST(StepLedgerTest, CountsSubtractPerPhase) {
  EvaluationCounts a, b;
  a.windows[1] = 10;
  a.samples[2] = 7;
  b.windows[1] = 4;
  b.samples[2] = 2;
  const EvaluationCounts d = a - b;
  EXPECT_EQ(d.windows[1], 6u);
  EXPECT_EQ(d.samples[2], 5u);
  EXPECT_EQ(d.anchor_windows[0], 0u);
}

// A normal build counts nothing: the counters read zero however much runs.
TEST(StepLedgerTest, NormalBuildReadsZeroCounts) {
  if (EvaluationsCounted()) GTEST_SKIP() << "a counting build";
  const EvaluationCounts c = ReadEvaluationCounts();
  for (int phase = 0; phase < 3; ++phase) EXPECT_EQ(c.windows[phase] + c.samples[phase], 0u);
}

}  // namespace
}  // namespace msp
