// Running another program without a shell: its arguments reach it as they are, whatever they hold
// (job ids and paths from a shared folder, scene paths given to rtcli bench are not trusted).
#pragma once

#include <string>
#include <vector>

namespace rt {

// Runs args[0] (looked up on PATH) with its standard output and error captured into `out`; true
// when it exited 0. On a failure to start, `out` says why.
bool run_program(const std::vector<std::string>& args, std::string& out);

// Runs args[0] (looked up on PATH) on this process's own standard streams; its exit status, or
// -1 when it could not start (`error` then says why) or did not exit normally.
int run_program_attached(const std::vector<std::string>& args, std::string& error);

}  // namespace rt
