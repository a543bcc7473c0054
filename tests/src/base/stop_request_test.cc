#include "base/stop_request.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>

#include "base/log.h"
#include "base/parallel_for.h"

namespace msp {
namespace {

class StopRequestTest : public ::testing::Test {
 protected:
  void TearDown() override { ClearStopRequest(); }
};

TEST_F(StopRequestTest, ParallelForStopsEarlyAndThrowsOnTheCallingThread) {
  const ScopedStopHandler handler;  // this thread unwinds
  for (int threads : {1, 3}) {
    std::atomic<int> calls{0};
    RequestStop(SIGTERM);
    try {
      ParallelFor(0, 1000, threads, [&](int) { ++calls; });
      FAIL() << "no StopRequested with " << threads << " thread(s)";
    } catch (const StopRequested& stop) {
      EXPECT_EQ(stop.signal_number(), SIGTERM);
      EXPECT_STREQ(stop.what(), "stopped by SIGTERM");
    }
    EXPECT_EQ(calls, 0);
    ClearStopRequest();
  }
}

// The request comes from a worker, as a signal may arrive on any thread; the
// thread that installed the handler unwinds.
TEST_F(StopRequestTest, AStopDuringTheLoopEndsItAfterTheItemsUnderWay) {
  const ScopedStopHandler handler;
  std::atomic<int> calls{0};
  EXPECT_THROW(ParallelFor(0, 1000, 2,
                           [&](int i) {
                             ++calls;
                             if (i == 10) RequestStop(SIGINT);
                           }),
               StopRequested);
  EXPECT_LT(calls, 1000);
}

TEST_F(StopRequestTest, RunsEveryItemWithoutARequest) {
  std::atomic<int> calls{0};
  ParallelFor(0, 100, 2, [&](int) { ++calls; });
  EXPECT_EQ(calls, 100);
  EXPECT_EQ(PendingStopSignal(), 0);
}

TEST_F(StopRequestTest, TheHandlerTurnsASignalIntoARequest) {
  InstallStopHandlers();
  ASSERT_EQ(::raise(SIGINT), 0);  // would end the test process without the handler
  EXPECT_EQ(PendingStopSignal(), SIGINT);
  EXPECT_THROW(ThrowIfStopRequested(), StopRequested);
  EXPECT_EQ(SignalName(SIGTERM), "SIGTERM");
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
}

std::atomic<int> host_handler_calls{0};
extern "C" void HostHandler(int) { ++host_handler_calls; }

TEST_F(StopRequestTest, AScopedHandlerLendsSigintAndGivesItBack) {
  signal(SIGINT, HostHandler);
  RequestStop(SIGTERM);  // left by an earlier run
  {
    ScopedStopHandler handler;
    EXPECT_EQ(PendingStopSignal(), 0);
    ASSERT_EQ(::raise(SIGINT), 0);
    EXPECT_EQ(PendingStopSignal(), SIGINT);
    ASSERT_EQ(::raise(SIGINT), 0);  // a second one is the same request, not a kill
    EXPECT_THROW(ThrowIfStopRequested(), StopRequested);
    EXPECT_EQ(host_handler_calls, 0);
  }
  ClearStopRequest();
  ASSERT_EQ(::raise(SIGINT), 0);
  EXPECT_EQ(host_handler_calls, 1);
  EXPECT_EQ(PendingStopSignal(), 0);
  signal(SIGINT, SIG_DFL);
}

TEST(StopRequestedTest, CarriesAMessageOfItsOwn) {
  const StopRequested stop(SIGINT, "Stopped by SIGINT before any map was computed");
  EXPECT_EQ(stop.signal_number(), SIGINT);
  EXPECT_STREQ(stop.what(), "Stopped by SIGINT before any map was computed");
}

TEST(LogTest, ALineShowsUpToTheLogLevel) {
  SetLogLevel(1);
  EXPECT_TRUE(LogEnabled(kLogProgress));
  EXPECT_FALSE(LogEnabled(kLogDetail));
  SetLogLevel(0);
  EXPECT_FALSE(LogEnabled(kLogProgress));
  testing::internal::CaptureStdout();
  Logf(kLogProgress, "hidden %d\n", 1);
  SetLogLevel(2);
  Logf(kLogDetail, "shown %d\n", 2);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "shown 2\n");
}

}  // namespace
}  // namespace msp
