#include "cli/render/resume_plan.h"

#include <algorithm>
#include <map>

#include "cli/common/report.h"
#include "cli/render/sample_state.h"
#include "core/render/integrator.h"
#include "io/image/exr_file.h"

namespace rt {
namespace {

// "key=value;" pairs of a settings text (cli/render/settings_text.h), the samples a pixel left
// out of "path" (what a resumed render changes).
std::map<std::string, std::string> settings_but_samples(const std::string& text) {
  std::map<std::string, std::string> out;
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = text.find(';', at);
    const std::string item = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    const size_t eq = item.find('=');
    if (eq != std::string::npos) {
      std::string value = item.substr(eq + 1);
      if (item.compare(0, eq, "path") == 0) value = value.substr(std::min(value.size(), value.find(',')));
      out[item.substr(0, eq)] = value;
    }
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

std::string attribute(const ExrImage& image, const char* key) {
  const auto it = image.attributes.find(key);
  return it == image.attributes.end() ? "" : it->second;
}

}  // namespace

std::optional<SampleState> resume_state(const std::string& path, const RenderIdentity& identity, int frame,
                                        const PixelWindow& window, const RenderSettings& settings, bool layers) {
  const std::string what = "--resume " + path + ": ";
  if (!integrator_samples_pixels(settings.integrator))
    return fail(what + "adds samples to the path tracer's render; " + settings.integrator +
                " takes each pixel's rays at once (use --integrator path)"),
           std::nullopt;
  std::string error;
  const std::optional<ExrImage> image = read_exr(path, kMaxPixels, error);
  if (!image) return fail(what + error), std::nullopt;
  if (attribute(*image, exr_key::kSceneHash).empty())
    return fail(what + "not an EXR that rtcli render wrote (it says nothing of its scene)"), std::nullopt;
  // What differs, by name.
  std::vector<std::string> differs;
  if (attribute(*image, exr_key::kSceneHash) != identity.scene_hash)
    differs.push_back("the scene (its files have changed since: their hash is " +
                      attribute(*image, exr_key::kSceneHash) + ", now " + identity.scene_hash + ")");
  const auto before = settings_but_samples(attribute(*image, exr_key::kSettings));
  const auto now = settings_but_samples(identity.settings);
  for (const auto& [key, value] : now) {
    const auto it = before.find(key);
    const std::string was = it == before.end() ? "none" : it->second;
    if (was != value) differs.push_back("setting " + key + " (" + was + ", now " + value + ")");
  }
  if (attribute(*image, exr_key::kFrame) != std::to_string(frame))
    differs.push_back("the frame (" + attribute(*image, exr_key::kFrame) + ", now " + std::to_string(frame) + ")");
  const PixelWindow& w = image->window;
  if (w.x0 != window.x0 || w.y0 != window.y0 || w.x1 != window.x1 || w.y1 != window.y1 ||
      image->width != settings.width || image->height != settings.height)
    differs.push_back("the pixels rendered (" + attribute(*image, exr_key::kCrop) + " of " +
                      std::to_string(image->width) + "x" + std::to_string(image->height) + ", now " +
                      std::to_string(window.x0) + "," + std::to_string(window.y0) + "," + std::to_string(window.x1) +
                      "," + std::to_string(window.y1) + " of " + std::to_string(settings.width) + "x" +
                      std::to_string(settings.height) + ")");
  if (!differs.empty()) {
    std::string list;
    for (size_t i = 0; i < differs.size(); ++i) list += (i ? "; " : "") + differs[i];
    return fail(what + "another render's: " + list + ". Only the samples a pixel (--spp) may change"), std::nullopt;
  }
  std::optional<SampleState> state = read_sample_state(*image, layers, kMaxSamplesPerPixel, error);
  if (!state) return fail(what + error), std::nullopt;
  int most = 0;
  for (const SampleSums& p : *state) most = std::max(most, p.n);
  if (most > settings.path.samples_per_pixel)
    return fail(what + "it has " + std::to_string(most) + " samples a pixel already; --spp is the total (more than " +
                std::to_string(most) + ")"),
           std::nullopt;
  return state;
}

}  // namespace rt
