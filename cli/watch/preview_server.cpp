#include "cli/watch/preview_server.h"

#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "cli/common/report.h"
#include "cli/watch/orbit.h"
#include "cli/watch/preview_images.h"
#include "io/image/png_encoder.h"

namespace rt {

const std::string& preview_page_html();  // cli/watch/preview_page.cpp.in

namespace {

constexpr size_t kMaxBody = 4096;  // the page sends no bodies at all

void fail_request(HttpResponse& res, int status, const std::string& why) {
  res.status = status;
  res.set_content(why + "\n", "text/plain; charset=utf-8");
}

void not_found(const HttpRequest& req, HttpResponse& res) {
  fail_request(res, 404, "not found: " + req.path + " (the page is at /)");
}

// A number parameter in [lo, hi]; the whole text must be the number.
std::optional<double> number_param(const HttpRequest& req, const char* key, double fallback, double lo, double hi) {
  if (!req.has_param(key)) return fallback;
  const std::string text = req.param(key);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
  return v;
}

// The layer and display transform a picture request asks for; nothing (400 sent) if they are bad.
struct PictureRequest {
  PreviewLayer layer = PreviewLayer::kColor;
  DisplayTransform display;
};

std::optional<PictureRequest> picture_request(const HttpRequest& req, const PreviewImage& image, HttpResponse& res) {
  PictureRequest p;
  p.display = image.display;
  if (req.has_param("layer")) {
    const auto layer = kPreviewLayers.parse(req.param("layer"));
    if (!layer) {
      std::string names;
      for (const std::string& n : kPreviewLayers.names()) names += (names.empty() ? "" : ", ") + n;
      fail_request(res, 400, "layer: expected one of " + names);
      return std::nullopt;
    }
    p.layer = *layer;
  }
  const auto exposure = number_param(req, "exposure", image.display.exposure, -kMaxExposure, kMaxExposure);
  if (!exposure) {
    fail_request(res, 400, "exposure: expected a number of stops in [-20, 20]");
    return std::nullopt;
  }
  p.display.exposure = static_cast<float>(*exposure);
  if (req.has_param("tone")) {
    const auto tone = kToneMaps.parse(req.param("tone"));
    if (!tone) {
      fail_request(res, 400, "tone: expected clamp or filmic");
      return std::nullopt;
    }
    p.display.curve = *tone;
  }
  return p;
}

nlohmann::json status_json(const PreviewStatus& s) {
  nlohmann::json j;
  j["scene"] = s.scene;
  j["scene_version"] = s.scene_version;
  j["image_version"] = s.image_version;
  j["load_failed"] = s.load_failed;
  j["reload"] = s.reload;
  j["first_image_seconds"] = s.first_image_seconds;
  j["animated"] = s.animated;
  j["first_frame"] = s.first_frame;
  j["last_frame"] = s.last_frame;
  j["rendering"] = s.rendering;
  j["rays_per_second"] = s.rays_per_second;
  j["problems"] = nlohmann::json::array();
  for (const Diagnostic& d : s.problems)
    j["problems"].push_back(
        {{"severity", d.severity == Severity::kError ? "error" : "warning"}, {"text", diagnostic_text(d)}});
  if (s.image) {
    const PreviewImage& im = *s.image;
    j["image"] = {{"width", im.width},
                  {"height", im.height},
                  {"film_width", im.film.width()},
                  {"film_height", im.film.height()},
                  {"frame", im.frame},
                  {"samples", im.samples},
                  {"target_samples", im.target_samples},
                  {"stage", im.stage},
                  {"last", im.last},
                  {"seconds", im.seconds},
                  {"rays", im.rays},
                  {"scene_version", im.scene_version},
                  {"exposure", im.display.exposure},
                  {"tone_map", std::string(kToneMaps.name(im.display.curve))},
                  {"yaw", im.yaw},
                  {"pitch", im.pitch}};
  } else {
    j["image"] = nullptr;
  }
  return j;
}

}  // namespace

PreviewServer::PreviewServer(PreviewBoard& board, std::function<bool(int)> show_frame,
                             std::function<void(float, float)> show_orbit, std::string download_name)
    : board_(board),
      show_frame_(std::move(show_frame)),
      show_orbit_(std::move(show_orbit)),
      download_name_(std::move(download_name)) {}

PreviewServer::~PreviewServer() { stop(); }

bool PreviewServer::bind(const std::string& host, int port, std::string& error) {
  host_ = host;
  std::string why;
  module_ = LoadableModule::open("rtcli-http", why);
  MakeHttpServer* make = module_ ? module_->function<MakeHttpServer>(kMakeHttpServerSymbol, why) : nullptr;
  if (!make) {
    error = "the preview page's HTTP server is not available: " + why;
    return false;
  }
  server_.reset(make(routes(), HttpLimits{kMaxBody}));
  port_ = server_->bind(host, port);
  if (port_ > 0) return true;
  error = "could not listen on " + host + ":" + std::to_string(port) +
          (port == 0 ? "" : " (is another program using the port? --port 0 picks a free one)");
  return false;
}

void PreviewServer::start() {
  thread_ = std::thread([this] { server_->listen(); });
}

void PreviewServer::stop() {
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

HttpRoutes PreviewServer::routes() {
  HttpRoutes r;
  // Only the names this server answers to: a page served from another name (DNS rebinding)
  // must not read the render.
  r.admit = [this](const HttpRequest& req, HttpResponse& res) {
    const std::string& host = req.host;
    const std::string port = ":" + std::to_string(port_);
    const bool ok = host == host_ + port || host == "localhost" + port || host == "127.0.0.1" + port ||
                    host == "[::1]" + port ||
                    (host_ == "0.0.0.0" && host.size() > port.size() &&
                     host.compare(host.size() - port.size(), port.size(), port) == 0);
    if (!ok) fail_request(res, 403, "this server answers to " + host_ + port + " and localhost" + port + " only");
    return ok;
  };
  r.error = [](const HttpRequest& req, HttpResponse& res) {
    if (res.status == 404) not_found(req, res);
    else if (res.status == 500) fail_request(res, 500, "the request could not be answered");
    else fail_request(res, res.status, "bad request");
  };
  r.get = [this](const HttpRequest& req, HttpResponse& res) { get(req, res); };
  r.post = [this](const HttpRequest& req, HttpResponse& res) { post(req, res); };
  return r;
}

void PreviewServer::get(const HttpRequest& req, HttpResponse& res) {
  if (req.path == "/") {
    res.set_header("Cache-Control", "no-store");
    res.set_content(preview_page_html(), "text/html; charset=utf-8");
  } else if (req.path == "/status") {
    res.set_header("Cache-Control", "no-store");
    res.set_content(status_json(board_.status()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                    "application/json");
  } else if (req.path == "/image.png" || req.path == "/save.png") {
    const bool save = req.path == "/save.png";
    const std::shared_ptr<const PreviewImage> image = board_.image();
    if (!image) return fail_request(res, 503, "no image yet: the first render has not finished");
    const std::optional<PictureRequest> p = picture_request(req, *image, res);
    if (!p) return;
    const std::vector<uint8_t> png = encode_png(preview_layer(*image, p->layer, p->display));
    res.set_header("Cache-Control", "no-store");
    if (save)
      res.set_header("Content-Disposition", "attachment; filename=\"" + download_name_ + "-" +
                                                std::string(kPreviewLayers.name(p->layer)) + "-" +
                                                std::to_string(image->samples) + "spp.png\"");
    res.set_content(std::string(png.begin(), png.end()), "image/png");
  } else if (req.path == "/save.exr") {
    const std::shared_ptr<const PreviewImage> image = board_.image();
    if (!image) return fail_request(res, 503, "no image yet: the first render has not finished");
    std::vector<uint8_t> exr;
    std::string error;
    if (!preview_exr(*image, exr, error)) return fail_request(res, 500, error);
    res.set_header("Content-Disposition",
                   "attachment; filename=\"" + download_name_ + "-" + std::to_string(image->samples) + "spp.exr\"");
    res.set_content(std::string(exr.begin(), exr.end()), "image/x-exr");
  } else {
    not_found(req, res);
  }
}

void PreviewServer::post(const HttpRequest& req, HttpResponse& res) {
  if (req.path == "/frame") {
    const auto n = number_param(req, "n", NAN, -1e9, 1e9);
    if (!n || !std::isfinite(*n) || *n != std::floor(*n)) return fail_request(res, 400, "n: expected a frame number");
    if (!show_frame_(static_cast<int>(*n)))
      return fail_request(res, 400, "n: expected a frame of the scene's animation");
    res.status = 204;
  } else if (req.path == "/view") {
    const auto yaw = number_param(req, "yaw", 0.0, -360.0, 360.0);
    const auto pitch = number_param(req, "pitch", 0.0, -kMaxOrbitPitch, kMaxOrbitPitch);
    if (!yaw || !pitch)
      return fail_request(res, 400, "yaw: expected degrees in [-360, 360]; pitch: degrees in [-89, 89]");
    show_orbit_(static_cast<float>(*yaw), static_cast<float>(*pitch));
    res.status = 204;
  } else {
    not_found(req, res);
  }
}

}  // namespace rt
