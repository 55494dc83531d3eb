// Ctrl-C (SIGINT) and SIGTERM while rendering. The handler only raises a flag; the renderer
// checks it before every pixel, so a render stops well within a second and the command exits
// without writing anything (no temporary file exists before the render is complete). A second
// Ctrl-C kills the process at once.
#pragma once

#include <signal.h>

#include <atomic>

namespace rt {

class InterruptWatch {
 public:
  InterruptWatch();   // installs the handlers
  ~InterruptWatch();  // restores the previous ones
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;

  const std::atomic<bool>& flag() const;
  int signal() const;  // the signal that arrived, 0 if none

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

// Blocks SIGINT and SIGTERM for its lifetime (while the image is written and renamed into place),
// so that no signal leaves a temporary file behind.
class SignalBlock {
 public:
  SignalBlock();
  ~SignalBlock();
  SignalBlock(const SignalBlock&) = delete;
  SignalBlock& operator=(const SignalBlock&) = delete;

 private:
  sigset_t saved_;
};

}  // namespace rt
