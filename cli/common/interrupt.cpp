#include "cli/common/interrupt.h"

#include <csignal>

namespace rt {
namespace {

// A signal handler can reach nothing but static storage: these two are the program's only
// globals, written by the handler and read through InterruptWatch.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

// The first signal raises the flag; a second one gets the default action (terminate) at once.
// (Not SA_RESETHAND: ThreadSanitizer, which defers handlers, then applies the default action to
// the first signal too.)
extern "C" void on_signal(int sig) {
  if (g_interrupted.exchange(true)) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal.store(sig);
}

}  // namespace

InterruptWatch::InterruptWatch() {
  g_interrupted = false;
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = &on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

InterruptWatch::~InterruptWatch() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

const std::atomic<bool>& InterruptWatch::flag() const { return g_interrupted; }
int InterruptWatch::signal() const { return g_signal.load(); }

SignalBlock::SignalBlock() {
  sigset_t block;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  sigprocmask(SIG_BLOCK, &block, &saved_);
}

SignalBlock::~SignalBlock() { sigprocmask(SIG_SETMASK, &saved_, nullptr); }

}  // namespace rt
