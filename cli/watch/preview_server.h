// The page of `rtcli watch` and what it asks for, served by cpp-httplib on its own threads (through
// librtcli-http.so, cli/watch/http_module.h, loaded by bind()). It
// serves nothing from disk: the page is built in, and every other answer is made from the board
// (cli/watch/preview_board.h): the status as JSON, the picture as PNG (a layer, an exposure, a
// tone map), the film as EXR. Requests are checked, not trusted: unknown paths and methods get
// 404, bad parameters 400 with the reason, bodies over 4 KiB 413, and a Host header that is not
// the address served 403 (a web page elsewhere cannot read the render by DNS rebinding). A bad
// request never touches the render.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "cli/watch/http_module.h"
#include "cli/watch/preview_board.h"
#include "io/base/loadable_module.h"

namespace rt {

class PreviewServer {
 public:
  // `show_frame` moves the render to another frame of the animation (false: no such frame);
  // `show_orbit` turns the preview's camera (degrees of yaw and pitch).
  PreviewServer(PreviewBoard& board, std::function<bool(int)> show_frame, std::function<void(float, float)> show_orbit,
                std::string download_name);
  ~PreviewServer();  // stops
  PreviewServer(const PreviewServer&) = delete;
  PreviewServer& operator=(const PreviewServer&) = delete;

  // Loads the HTTP module and binds `host`:`port` (port 0: any free one). False, with `error`,
  // when it cannot.
  bool bind(const std::string& host, int port, std::string& error);
  int port() const { return port_; }
  // Serves on its own thread until stop().
  void start();
  void stop();

 private:
  HttpRoutes routes();
  void get(const HttpRequest& req, HttpResponse& res);
  void post(const HttpRequest& req, HttpResponse& res);

  PreviewBoard& board_;
  std::function<bool(int)> show_frame_;
  std::function<void(float, float)> show_orbit_;
  std::string download_name_;                     // the scene's name, for saved files
  std::shared_ptr<const LoadableModule> module_;  // declared before server_: outlives it
  std::unique_ptr<HttpServer> server_;
  std::string host_;
  int port_ = 0;
  std::thread thread_;
};

}  // namespace rt
