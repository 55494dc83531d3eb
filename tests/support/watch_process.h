// `rtcli watch` as the tests run it: a child process serving on a free port, its output in a
// file, and what the page asks of it (status, the picture) through cpp-httplib's client.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "io/image/png_file.h"
#include "tests/support/test_paths.h"

extern char** environ;

namespace rt::test {

class WatchProcess {
 public:
  WatchProcess(const std::string& scene, const std::string& folder) : out_(folder + "/watch-out.txt") {
    std::vector<std::string> args = {RTCLI_BINARY, "watch", scene, "--port", "0", "--threads", "2"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    REQUIRE(posix_spawn(&pid_, RTCLI_BINARY, &actions, nullptr, argv.data(), environ) == 0);
    posix_spawn_file_actions_destroy(&actions);
    // The address is the first line it prints.
    const auto start = std::chrono::steady_clock::now();
    while (port_ == 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(30)) {
      const std::string out = rt::test::read_file(out_);
      const size_t at = out.find("http://127.0.0.1:");
      if (at != std::string::npos) port_ = std::atoi(out.c_str() + at + 17);
      else std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    REQUIRE(port_ > 0);
  }
  ~WatchProcess() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  // Ctrl-C; the exit code, -1 if it did not exit within `seconds`.
  int interrupt(double seconds) {
    ::kill(pid_, SIGINT);
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    while (std::chrono::steady_clock::now() - start < std::chrono::duration<double>(seconds)) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
  }
  int port() const { return port_; }
  std::string output() const { return rt::test::read_file(out_); }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/"; }

  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_connection_timeout(5);
    c.set_read_timeout(10);
    return c;
  }
  nlohmann::json status() const {
    auto c = client();
    const auto r = c.Get("/status");
    REQUIRE(r);
    REQUIRE(r->status == 200);
    return nlohmann::json::parse(r->body);
  }
  // The status once `done` says so, within 60 s.
  template <class Done>
  nlohmann::json wait_for(Done done, const char* what) const {
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json s = status();
    while (!done(s) && std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      s = status();
    }
    INFO("waiting for " << what << "; status: " << s.dump());
    REQUIRE(done(s));
    return s;
  }
  // The picture's centre pixel (the sphere), as the page gets it.
  std::array<int, 3> centre(const std::string& folder) const {
    auto c = client();
    const auto r = c.Get("/image.png?layer=color");
    REQUIRE(r);
    REQUIRE(r->status == 200);
    const std::string path = folder + "/centre.png";
    std::ofstream(path, std::ios::binary) << r->body;
    std::string error;
    const auto png = rt::read_png(path, error);
    REQUIRE(png);
    const size_t i = (static_cast<size_t>(png->height / 2 - png->height / 10) * png->width + png->width / 2) * 3;
    return {png->rgb[i], png->rgb[i + 1], png->rgb[i + 2]};
  }

 private:
  std::string out_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace rt::test
