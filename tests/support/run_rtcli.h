// Running the rtcli binary as a user does, for the CLI tests.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

#include <catch2/catch.hpp>

namespace rt::test {

struct Run {
  int code = -1;       // exit code; -1 if the process did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs rtcli with `args` (shell syntax) from `cwd`; `prefix` goes before the binary (`timeout 10`).
inline Run rtcli(const std::string& args, const std::string& cwd = RTCLI_SOURCE_DIR, const std::string& prefix = "") {
  const std::string command = "cd '" + cwd + "' && " + prefix + " '" + RTCLI_BINARY + "' " + args + " 2>&1";
  Run run;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace rt::test
