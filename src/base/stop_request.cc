#include "base/stop_request.h"

#include <signal.h>

#include <atomic>
#include <thread>

namespace msp {
namespace {

// Lock-free, hence async-signal-safe to store to.
std::atomic<int> pending_signal{0};
std::thread::id main_thread;

extern "C" void OnStopSignal(int signal_number) { pending_signal.store(signal_number); }

}  // namespace

StopRequested::StopRequested(int signal_number)
    : std::runtime_error("stopped by " + SignalName(signal_number)),
      signal_number_(signal_number) {}

StopRequested::StopRequested(int signal_number, const std::string& message)
    : std::runtime_error(message), signal_number_(signal_number) {}

void InstallStopHandlers() {
  main_thread = std::this_thread::get_id();
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: a second Ctrl-C takes the default action and ends the run now.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGXFSZ, SIG_IGN);
}

ScopedStopHandler::ScopedStopHandler() {
  main_thread = std::this_thread::get_id();
  pending_signal.store(0);
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previous_);
}

ScopedStopHandler::~ScopedStopHandler() { sigaction(SIGINT, &previous_, nullptr); }

int PendingStopSignal() { return pending_signal.load(); }

void ThrowIfStopRequested() {
  const int signal_number = pending_signal.load(std::memory_order_relaxed);
  if (signal_number != 0 && std::this_thread::get_id() == main_thread) {
    throw StopRequested(signal_number);
  }
}

void RequestStop(int signal_number) { pending_signal.store(signal_number); }

void ClearStopRequest() { pending_signal.store(0); }

std::string SignalName(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

}  // namespace msp
