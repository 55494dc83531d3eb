#include "cli/bench/timing.h"

#include <sys/wait.h>
#include <unistd.h>

namespace rt {

double time_in_fresh_process(const std::function<void()>& run) {
  return run_in_fresh_process([&] {
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
}

double run_in_fresh_process(const std::function<double()>& run) {
  int fds[2];
  if (pipe(fds) != 0) return -1.0;
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    return -1.0;
  }
  if (child == 0) {
    close(fds[0]);
    const double seconds = run();
    const bool sent = write(fds[1], &seconds, sizeof seconds) == static_cast<ssize_t>(sizeof seconds);
    _exit(sent ? 0 : 1);  // no destructors, no atexit handlers: the parent owns those
  }
  close(fds[1]);
  double seconds = -1.0;
  if (read(fds[0], &seconds, sizeof seconds) != static_cast<ssize_t>(sizeof seconds)) seconds = -1.0;
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1.0;
}

}  // namespace rt
