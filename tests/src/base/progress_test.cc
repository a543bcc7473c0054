#include "base/progress.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace msp {
namespace {

TEST(EstimateSecondsLeftTest, ScalesTheMeasuredRateToTheWorkLeft) {
  // 25 of 100 units in 10 s: 0.4 s per unit, 75 left.
  EXPECT_DOUBLE_EQ(EstimateSecondsLeft(25, 100, 10), 30);
  EXPECT_DOUBLE_EQ(EstimateSecondsLeft(100, 100, 10), 0);
  EXPECT_DOUBLE_EQ(EstimateSecondsLeft(120, 100, 10), 0);  // never negative
}

TEST(EstimateSecondsLeftTest, UnknownBeforeAnythingIsDone) {
  EXPECT_LT(EstimateSecondsLeft(0, 100, 10), 0);
  EXPECT_EQ(FormatDuration(EstimateSecondsLeft(0, 100, 10)), "?");
}

TEST(ProgressMeterTest, WeightsImagePassesBySizeNotByCount) {
  // A coarse round of 4 images at 80x60 then a fine round at 160x120: after
  // the coarse round half of the image-passes are done but a fifth of the work.
  const double coarse = 80 * 60, fine = 160 * 120;
  ProgressMeter meter(8, 4 * coarse + 4 * fine);
  for (int i = 0; i < 4; ++i) meter.Add(coarse);
  EXPECT_EQ(meter.done_items(), 4);
  EXPECT_DOUBLE_EQ(meter.done_weight() / meter.total_weight(), 0.2);
  // 4 coarse passes took 8 s: the fine ones, 4 times the pixels, take 32 s.
  EXPECT_DOUBLE_EQ(EstimateSecondsLeft(meter.done_weight(), meter.total_weight(), 8), 32);
  EXPECT_EQ(meter.Line(8), "progress 4/8 image-passes (20.0% of the work), elapsed 8s, ETA 32s");
}

TEST(ProgressMeterTest, EndsAtAllDoneWithNothingLeft) {
  ProgressMeter meter(2, 3);
  meter.Add(1);
  meter.Add(2);
  EXPECT_EQ(meter.Line(65),
            "progress 2/2 image-passes (100.0% of the work), elapsed 1m05s, ETA 0s");
}

TEST(FormatDurationTest, SecondsMinutesHours) {
  EXPECT_EQ(FormatDuration(0), "0s");
  EXPECT_EQ(FormatDuration(44.6), "45s");
  EXPECT_EQ(FormatDuration(59.4), "59s");
  EXPECT_EQ(FormatDuration(187), "3m07s");
  EXPECT_EQ(FormatDuration(3599), "59m59s");
  EXPECT_EQ(FormatDuration(3600 * 2 + 60 * 5 + 10), "2h05m");
  EXPECT_EQ(FormatDuration(-1), "?");
}

TEST(ProgressListenerTest, HearsTheTotalsOfEachReport) {
  std::vector<ProgressUpdate> updates;
  SetProgressListener([&](const ProgressUpdate& update) { updates.push_back(update); });
  ProgressMeter meter(4, 4);
  ReportProgress(meter, 0);  // nothing done: no rate, no estimate
  meter.Add(1);
  ReportProgress(meter, 3);
  SetProgressListener(nullptr);
  meter.Add(1);
  ReportProgress(meter, 6);  // no listener: nobody hears it
  ASSERT_EQ(updates.size(), 2u);
  EXPECT_EQ(updates[0].done, 0);
  EXPECT_LT(updates[0].seconds_left, 0);
  EXPECT_EQ(updates[1].done, 1);
  EXPECT_EQ(updates[1].total, 4);
  EXPECT_DOUBLE_EQ(updates[1].elapsed_seconds, 3);
  EXPECT_DOUBLE_EQ(updates[1].seconds_left, 9);
}

TEST(ProgressListenerTest, AListenerMayEndTheRunByThrowing) {
  SetProgressListener([](const ProgressUpdate&) { throw std::runtime_error("stop here"); });
  ProgressMeter meter(1, 1);
  EXPECT_THROW(ReportProgress(meter, 1), std::runtime_error);
  SetProgressListener(nullptr);
}

}  // namespace
}  // namespace msp
