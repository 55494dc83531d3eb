// Running the rtcli binary as a user does, for the CLI tests.
#pragma once

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <catch2/catch.hpp>

namespace rt::test {

struct Run {
  int code = -1;       // exit code; -1 if the process did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs a shell command line, its output and exit code.
inline Run run_shell(const std::string& command) {
  Run run;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// Whether `program` is on PATH; if not, says so (the tests that need it skip) and how to get it.
inline bool installed(const std::string& program) {
  if (run_shell("command -v '" + program + "' >/dev/null 2>&1").code == 0) return true;
  WARN(program + " is not installed (tools/install-deps.sh --tests installs it): skipped");
  return false;
}

// Runs rtcli with `args` (shell syntax) from `cwd`; `prefix` goes before the binary (`timeout 10`).
inline Run rtcli(const std::string& args, const std::string& cwd = RTCLI_SOURCE_DIR, const std::string& prefix = "") {
  return run_shell("cd '" + cwd + "' && " + prefix + " '" + RTCLI_BINARY + "' " + args + " 2>&1");
}

// rtcli under a 10-second limit: for refusals, which must be quick; a hang becomes a failure, not a
// stuck test run.
inline Run rtcli_bounded(const std::string& args) { return rtcli(args, RTCLI_SOURCE_DIR, "timeout 10"); }

// A render sent SIGINT (Ctrl-C) once it has loaded: a Ctrl-C while loading ends the process at
// once, with no message. How long loading takes here (a sanitizer build is slower) is measured
// with a one-pixel render of the same scene; the signal comes at three times that, plus `extra`
// seconds. --foreground: otherwise timeout signals the child and then its whole process group,
// and a child that has already handled the first SIGINT takes the second as "Ctrl-C twice: stop
// at once", with no message.
// Seconds a stopped render may take from the signal to its exit: a second to stop, and a margin
// for a loaded 2-core machine. ThreadSanitizer alone takes 1.5 to 2.1 s to free a gigabyte film
// as the process ends (measured, before and after issue 18 alike), so it gets more.
#ifdef RTCLI_UNDER_TSAN
inline constexpr double kStopMargin = 3.5;
#else
inline constexpr double kStopMargin = 2.0;
#endif

struct Interrupted {
  Run run;
  double delay = 0.0;    // seconds from the start to the signal
  double seconds = 0.0;  // from the start to the exit
};

inline Interrupted interrupt_render(const std::string& scene, const std::string& options, const std::string& out,
                                    double extra) {
  const auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  auto start = std::chrono::steady_clock::now();
  REQUIRE(rtcli("render " + scene + " -q --width 1 --height 1 -o '" + out + "'").code == 0);
  Interrupted result;
  result.delay = extra + 3.0 * since(start);
  std::remove(out.c_str());
  start = std::chrono::steady_clock::now();
  result.run = rtcli("render " + scene + " " + options + " -o '" + out + "'", RTCLI_SOURCE_DIR,
                     "timeout --foreground --preserve-status -s INT " + std::to_string(result.delay));
  result.seconds = since(start);
  return result;
}

}  // namespace rt::test
