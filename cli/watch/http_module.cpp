// librtcli-http.so: cpp-httplib behind cli/watch/http_module.h, loaded by the watch page's server.
#include "cli/watch/http_module.h"

#include <httplib.h>

#include "io/base/loadable_module.h"

namespace rt {
namespace {

HttpRequest request_of(const httplib::Request& req) {
  HttpRequest r;
  r.method = req.method;
  r.path = req.path;
  r.host = req.get_header_value("Host");
  r.params.assign(req.params.begin(), req.params.end());
  return r;
}

void answer(const HttpResponse& from, httplib::Response& res) {
  res.status = from.status;
  for (const auto& [name, value] : from.headers) res.set_header(name, value);
  if (!from.body.empty() || from.status != 204) res.set_content(from.body, from.content_type.c_str());
}

// A route of ours as an httplib handler: the request converted in, the answer out.
httplib::Server::Handler handler(std::function<void(const HttpRequest&, HttpResponse&)> route) {
  return [route = std::move(route)](const httplib::Request& req, httplib::Response& res) {
    HttpResponse out;
    route(request_of(req), out);
    answer(out, res);
  };
}

class HttplibServer final : public HttpServer {
 public:
  HttplibServer(HttpRoutes routes, const HttpLimits& limits) : routes_(std::move(routes)) {
    server_.set_payload_max_length(limits.max_body);
    server_.set_read_timeout(limits.read_timeout_s, 0);
    server_.set_write_timeout(limits.write_timeout_s, 0);
    server_.set_keep_alive_max_count(static_cast<size_t>(limits.keep_alive_max_count));
    server_.set_keep_alive_timeout(limits.keep_alive_timeout_s);
    server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
      res.status = 500;  // the error route words it
    });
    server_.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!res.body.empty()) return;  // a route's own answer
      HttpResponse out;
      out.status = res.status;
      routes_.error(request_of(req), out);
      answer(out, res);
    });
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      HttpResponse out;
      if (routes_.admit(request_of(req), out)) return httplib::Server::HandlerResponse::Unhandled;
      answer(out, res);
      return httplib::Server::HandlerResponse::Handled;
    });
    server_.Get(".*", handler(routes_.get));
    server_.Post(".*", handler(routes_.post));
  }

  int bind(const std::string& host, int port) override {
    if (port == 0) {
      const int bound = server_.bind_to_any_port(host);
      return bound > 0 ? bound : -1;
    }
    return server_.bind_to_port(host, port) ? port : -1;
  }
  void listen() override { server_.listen_after_bind(); }
  void stop() override { server_.stop(); }

 private:
  HttpRoutes routes_;
  httplib::Server server_;
};

}  // namespace
}  // namespace rt

extern "C" __attribute__((visibility("default"))) const char* rtcli_module_abi() { return rt::kModuleAbi; }

extern "C" __attribute__((visibility("default"))) rt::HttpServer* rtcli_make_http_server(rt::HttpRoutes routes,
                                                                                         const rt::HttpLimits& limits) {
  return new rt::HttplibServer(std::move(routes), limits);
}
