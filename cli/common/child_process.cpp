#include "cli/common/child_process.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace rt {
namespace {

// Starts args[0] with `actions` (may be null); the child's pid, or 0 with `error` set.
pid_t spawn(const std::vector<std::string>& args, const posix_spawn_file_actions_t* actions, std::string& error) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], actions, nullptr, argv.data(), environ);
  if (spawned != 0) {
    error = args[0] + ": " + std::strerror(spawned);
    return 0;
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

bool run_program(const std::vector<std::string>& args, std::string& out) {
  int fds[2];
  if (::pipe(fds) != 0) return false;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  std::string error;
  const pid_t pid = spawn(args, &actions, error);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (pid == 0) {
    ::close(fds[0]);
    out = error + "\n";
    return false;
  }
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.append(buffer, static_cast<size_t>(n));
  }
  ::close(fds[0]);
  return wait_for(pid) == 0;
}

int run_program_attached(const std::vector<std::string>& args, std::string& error) {
  const pid_t pid = spawn(args, nullptr, error);
  return pid == 0 ? -1 : wait_for(pid);
}

}  // namespace rt
