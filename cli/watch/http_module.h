// What the HTTP module (http_module.cpp, built as librtcli-http.so; io/base/loadable_module.h)
// offers the watch page: a server that binds, hands every request to the routes given, and stops.
// Only this header is shared by the module and the executable, so only the module links
// cpp-httplib (and through it OpenSSL and Brotli, which a render never needs).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rt {

struct HttpRequest {
  std::string method;                                       // "GET", "POST", ...
  std::string path;                                         // without the query
  std::string host;                                         // the Host header ("" when none)
  std::vector<std::pair<std::string, std::string>> params;  // the query's, decoded, in order

  bool has_param(const std::string& key) const {
    for (const auto& [k, v] : params)
      if (k == key) return true;
    return false;
  }
  std::string param(const std::string& key) const {  // the first value; "" when none
    for (const auto& [k, v] : params)
      if (k == key) return v;
    return "";
  }
};

struct HttpResponse {
  int status = 200;
  std::string body;
  std::string content_type = "text/plain";
  std::vector<std::pair<std::string, std::string>> headers;

  void set_header(const std::string& name, const std::string& value) { headers.emplace_back(name, value); }
  void set_content(std::string text, const char* type) {
    body = std::move(text);
    content_type = type;
  }
};

struct HttpRoutes {
  // Asked first for every request: false when it has answered (refused) the request itself.
  std::function<bool(const HttpRequest&, HttpResponse&)> admit;
  std::function<void(const HttpRequest&, HttpResponse&)> get;   // every GET (and HEAD)
  std::function<void(const HttpRequest&, HttpResponse&)> post;  // every POST
  // A request the server refused before the routes (another method: 404; a body over the limit:
  // 413; malformed: 400) or whose route threw (500): the status is set, the body is empty.
  std::function<void(const HttpRequest&, HttpResponse&)> error;
};

struct HttpLimits {
  size_t max_body = 4096;
  int read_timeout_s = 5, write_timeout_s = 5;
  int keep_alive_max_count = 100, keep_alive_timeout_s = 2;
};

class HttpServer {
 public:
  virtual ~HttpServer() = default;
  // Binds host:port (port 0: any free one); the port bound, or -1.
  virtual int bind(const std::string& host, int port) = 0;
  // Answers requests on the calling thread until stop() (from another thread).
  virtual void listen() = 0;
  virtual void stop() = 0;
};

// extern "C" HttpServer* rtcli_make_http_server(HttpRoutes, const HttpLimits&): the caller owns it.
using MakeHttpServer = HttpServer*(HttpRoutes routes, const HttpLimits& limits);
inline constexpr char kMakeHttpServerSymbol[] = "rtcli_make_http_server";

}  // namespace rt
