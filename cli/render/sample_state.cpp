#include "cli/render/sample_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace rt {
namespace {

// A double as four 16-bit parts, each exact in a float: no bit pattern (a NaN's) ever passes
// through a float register.
void split(double v, float* out) {
  uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (int k = 0; k < 4; ++k) out[k] = static_cast<float>((bits >> (48 - 16 * k)) & 0xffffu);
}

std::optional<double> join(const float* in) {
  uint64_t bits = 0;
  for (int k = 0; k < 4; ++k) {
    if (!(in[k] >= 0.0f && in[k] <= 65535.0f) || in[k] != std::floor(in[k])) return std::nullopt;
    bits = (bits << 16) | static_cast<uint64_t>(in[k]);
  }
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

ExrLayer layer(const char* name, std::vector<std::string> channels, size_t pixels) {
  ExrLayer l{name, std::move(channels), {}, true};
  l.values.reserve(pixels * l.channels.size());
  return l;
}

void push3(ExrLayer& l, Vec3 v) {
  for (int c = 0; c < 3; ++c) l.values.push_back(v[c]);
}

// A layer read back, its channels in the order written (OpenEXR lists them alphabetically).
struct Channels {
  const ExrLayer* layer = nullptr;
  std::vector<size_t> order;  // index in the layer of each channel asked for
  explicit operator bool() const { return layer != nullptr; }
  float at(size_t pixel, size_t k) const { return layer->values[pixel * layer->channels.size() + order[k]]; }
  Vec3 vec3(size_t pixel) const { return Vec3(at(pixel, 0), at(pixel, 1), at(pixel, 2)); }
};

Channels find(const ExrImage& image, const char* name, const std::vector<std::string>& channels) {
  Channels out;
  const ExrLayer* l = image.layer(name);
  if (!l || l->channels.size() != channels.size()) return out;
  for (const std::string& c : channels) {
    const auto it = std::find(l->channels.begin(), l->channels.end(), c);
    if (it == l->channels.end()) return out;
    out.order.push_back(static_cast<size_t>(it - l->channels.begin()));
  }
  out.layer = l;
  return out;
}

std::string format_count(float n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(n));
  return buf;
}

bool finite_non_negative(Vec3 v) { return std::isfinite(v.x + v.y + v.z) && v.x >= 0 && v.y >= 0 && v.z >= 0; }

}  // namespace

std::vector<ExrLayer> sample_state_layers(const SampleState& state, bool layers) {
  const size_t n = state.size();
  ExrLayer sum = layer("state.sum", {"R", "G", "B"}, n), count = layer("state.count", {"N"}, n),
           lum = layer("state.luminance", {"A", "B", "C", "D"}, n),
           squares = layer("state.squares", {"A", "B", "C", "D"}, n);
  ExrLayer albedo = layer("state.albedo", {"R", "G", "B"}, layers ? n : 0),
           normal = layer("state.normal", {"X", "Y", "Z"}, layers ? n : 0),
           emission = layer("state.emission", {"R", "G", "B"}, layers ? n : 0),
           distance = layer("state.distance", {"Z"}, layers ? n : 0);
  for (const SampleSums& p : state) {
    push3(sum, p.sum);
    count.values.push_back(static_cast<float>(p.stopped ? -p.n : p.n));
    float parts[4];
    split(p.luminance, parts);
    lum.values.insert(lum.values.end(), parts, parts + 4);
    split(p.luminance_squares, parts);
    squares.values.insert(squares.values.end(), parts, parts + 4);
    if (layers) {
      push3(albedo, p.layers.albedo);
      push3(normal, p.layers.normal);
      push3(emission, p.layers.emission);
      distance.values.push_back(p.layers.distance);
    }
  }
  std::vector<ExrLayer> out{std::move(sum), std::move(count), std::move(lum), std::move(squares)};
  if (layers)
    for (ExrLayer* l : {&albedo, &normal, &emission, &distance}) out.push_back(std::move(*l));
  return out;
}

bool has_sample_state(const ExrImage& image) { return image.layer("state.count") != nullptr; }

std::optional<SampleState> read_sample_state(const ExrImage& image, bool layers, int most_samples, std::string& error) {
  const std::vector<std::string> rgb = {"R", "G", "B"}, xyz = {"X", "Y", "Z"}, parts = {"A", "B", "C", "D"};
  const Channels sum = find(image, "state.sum", rgb), count = find(image, "state.count", {"N"}),
                 lum = find(image, "state.luminance", parts), squares = find(image, "state.squares", parts);
  if (!sum || !count || !lum || !squares) {
    error = "holds no sample sums to continue from (rtcli writes them in every EXR of the path tracer)";
    return std::nullopt;
  }
  const Channels albedo = find(image, "state.albedo", rgb), normal = find(image, "state.normal", xyz),
                 emission = find(image, "state.emission", rgb), distance = find(image, "state.distance", {"Z"});
  const bool has_layers = albedo && normal && emission && distance;
  if (layers && !has_layers) {
    error =
        "was rendered without the first hit's layers, which this render gathers (--aov or --denoise): render "
        "the first part with them too";
    return std::nullopt;
  }
  for (const Channels* c : {&sum, &count, &lum, &squares, &albedo, &normal, &emission, &distance})
    if (*c && !c->layer->exact) {
      error = "holds its sample sums as half floats (\"" + c->layer->name +
              "\"): they must be 32-bit floats, as rtcli writes them";
      return std::nullopt;
    }
  SampleState state(static_cast<size_t>(image.window.pixels()));
  for (size_t i = 0; i < state.size(); ++i) {
    SampleSums& p = state[i];
    const float n = count.at(i, 0);
    const float whole = std::fabs(n);
    if (!(whole >= 1.0f && whole <= static_cast<float>(most_samples)) || whole != std::floor(whole)) {
      error = "pixel " + std::to_string(i) + " of its window: expected a count of 1 to " +
              std::to_string(most_samples) + " samples, found " + format_count(n);
      return std::nullopt;
    }
    p.n = static_cast<int>(whole);
    p.stopped = n < 0.0f;
    p.sum = sum.vec3(i);
    float l_parts[4], s_parts[4];
    for (size_t k = 0; k < 4; ++k) {
      l_parts[k] = lum.at(i, k);
      s_parts[k] = squares.at(i, k);
    }
    const auto l = join(l_parts);
    const auto s = join(s_parts);
    if (!finite_non_negative(p.sum) || !l || !s || !std::isfinite(*l) || !std::isfinite(*s) || *l < 0.0 || *s < 0.0) {
      error = "pixel " + std::to_string(i) + " of its window: expected finite, non-negative sums";
      return std::nullopt;
    }
    p.luminance = *l;
    p.luminance_squares = *s;
    if (layers) {
      p.layers.albedo = albedo.vec3(i);
      p.layers.normal = normal.vec3(i);
      p.layers.emission = emission.vec3(i);
      p.layers.distance = distance.at(i, 0);
      const Vec3 all = p.layers.albedo + p.layers.normal + p.layers.emission;
      if (!std::isfinite(all.x + all.y + all.z + p.layers.distance)) {
        error = "pixel " + std::to_string(i) + " of its window: expected finite layer sums";
        return std::nullopt;
      }
    }
  }
  return state;
}

}  // namespace rt
