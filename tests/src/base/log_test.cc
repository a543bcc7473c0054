#include "base/log.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <string>
#include <vector>

namespace msp {
namespace {

struct Piece {
  int level;
  LogSeverity severity;
  std::string text;
};

// Collects what the log writes while it lives; stdout again afterwards.
class CollectingSink {
 public:
  CollectingSink() {
    SetLogSink([this](int level, LogSeverity severity, const std::string& text) {
      pieces.push_back({level, severity, text});
    });
  }
  ~CollectingSink() { SetLogSink(nullptr); }
  std::vector<Piece> pieces;
};

class LogSinkTest : public ::testing::Test {
 protected:
  void SetUp() override { SetLogLevel(kLogDetail); }
  void TearDown() override { SetLogLevel(kLogDetail); }
};

TEST_F(LogSinkTest, TheSinkGetsEachPieceWithItsLevel) {
  CollectingSink sink;
  Logf(kLogDetail, "  %s: %d%%", "a.png", 12);
  Logf(kLogDetail, "\n");
  LogText(kLogProgress, "Round 1/1\n");
  LogText(kLogAlways, "");  // nothing to say: no call
  ASSERT_EQ(sink.pieces.size(), 3u);
  EXPECT_EQ(sink.pieces[0].level, kLogDetail);
  EXPECT_EQ(sink.pieces[0].severity, LogSeverity::kInfo);
  EXPECT_EQ(sink.pieces[0].text, "  a.png: 12%");
  EXPECT_EQ(sink.pieces[1].text, "\n");
  EXPECT_EQ(sink.pieces[2].level, kLogProgress);
  EXPECT_EQ(sink.pieces[2].text, "Round 1/1\n");
}

TEST_F(LogSinkTest, WarningsHaveTheirSeverityAndShowAtEveryLevel) {
  SetLogLevel(0);
  CollectingSink sink;
  LogText(kLogProgress, "hidden\n");
  LogWarning("image file x.png does not exist; ignoring it");
  ASSERT_EQ(sink.pieces.size(), 1u);
  EXPECT_EQ(sink.pieces[0].severity, LogSeverity::kWarning);
  EXPECT_EQ(sink.pieces[0].text, "WARNING: image file x.png does not exist; ignoring it\n");
}

TEST_F(LogSinkTest, LogStreamWritesOnePieceWithManipulators) {
  CollectingSink sink;
  LogStream() << "Elapsed time: " << std::fixed << std::setprecision(3) << 0.5 << " [minutes]\n";
  { LogStream(kLogDetail) << "detail " << 3 << "\n"; }
  ASSERT_EQ(sink.pieces.size(), 2u);
  EXPECT_EQ(sink.pieces[0].text, "Elapsed time: 0.500 [minutes]\n");
  EXPECT_EQ(sink.pieces[0].level, kLogAlways);
  EXPECT_EQ(sink.pieces[1].level, kLogDetail);
}

TEST_F(LogSinkTest, WithoutASinkTheLogGoesToStdout) {
  { CollectingSink sink; }
  testing::internal::CaptureStdout();
  LogText(kLogAlways, "to stdout\n");
  LogWarning("w");
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "to stdout\nWARNING: w\n");
}

}  // namespace
}  // namespace msp
