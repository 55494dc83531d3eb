#include "io/texture_parser.h"

#include "io/input_file.h"

namespace rt {
namespace {

constexpr std::string_view kPairExpected = "an array of 2 numbers [u, v], or one number for both";

// [u, v] or one number for both, each finite (and not zero where `nonzero`).
std::optional<Vec2> read_pair(const JsonReader& r, const Json& v, const std::string& ptr, bool nonzero) {
  const auto ok = [&](const Json& x) {
    return x.is_number() && std::isfinite(x.get<double>()) && !(nonzero && x.get<double>() == 0.0);
  };
  if (ok(v)) return Vec2(static_cast<float>(v.get<double>()));
  if (v.is_array() && v.size() == 2 && ok(v[0]) && ok(v[1]))
    return Vec2(static_cast<float>(v[0].get<double>()), static_cast<float>(v[1].get<double>()));
  r.expected(ptr, nonzero ? std::string(kPairExpected) + ", not zero" : std::string(kPairExpected), v);
  return std::nullopt;
}

void parse_mapping(const JsonReader& r, ObjectReader& o, TextureMapping& m) {
  if (const Json* p = o.get("projection")) {
    if (const auto k = read_choice(r, *p, o.child("projection"), {"uv", "planar", "spherical", "cylindrical"}))
      m.projection = static_cast<Projection>(*k);
  }
  if (const auto set = o.number("texcoord", NumberRule{0, 1, false, false, true})) m.uv_set = static_cast<uint32_t>(*set);
  if (const Json* s = o.get("scale")) {
    if (const auto v = read_pair(r, *s, o.child("scale"), true)) m.scale = *v;
  }
  if (const Json* s = o.get("offset")) {
    if (const auto v = read_pair(r, *s, o.child("offset"), false)) m.offset = *v;
  }
  if (const auto deg = o.number("rotation")) m.rotation_degrees = static_cast<float>(*deg);
  if (const Json* w = o.get("wrap")) {
    if (const auto k = read_choice(r, *w, o.child("wrap"), {"repeat", "clamp", "mirror"}))
      m.wrap = static_cast<TextureWrap>(*k);
  }
  if (const Json* f = o.get("filter")) {
    if (const auto k = read_choice(r, *f, o.child("filter"), {"nearest", "bilinear", "trilinear"}))
      m.filter = static_cast<TextureFilter>(*k);
  }
}

std::optional<TextureFileReference> file_reference(const JsonReader& r, const Json& v, const std::string& ptr,
                                                   const std::string& folder, TextureEncoding encoding) {
  const auto file = read_string(r, v, ptr);
  if (!file) return std::nullopt;
  if (file->empty()) {
    r.expected(ptr, "the path of a PNG or JPEG image", v);
    return std::nullopt;
  }
  return TextureFileReference{*file, resolve_path(folder, *file), encoding, ptr};
}

}  // namespace

std::optional<TextureFileReference> parse_texture_slot(const JsonReader& r, const Json& value, const std::string& ptr,
                                                       const std::string& scene_folder, TextureEncoding encoding,
                                                       TextureMapping& mapping,
                                                       const std::function<void(ObjectReader&)>& extra) {
  if (value.is_string()) return file_reference(r, value, ptr, scene_folder, encoding);
  if (!value.is_object()) {
    r.expected(ptr, "an image file name, or an object with \"file\" and mapping keys", value);
    return std::nullopt;
  }
  ObjectReader o(r, value, ptr);
  const Json* file = o.get("file", true, "the path of a PNG or JPEG image");
  parse_mapping(r, o, mapping);
  if (extra) extra(o);
  o.finish();
  if (!file) return std::nullopt;
  return file_reference(r, *file, o.child("file"), scene_folder, encoding);
}

}  // namespace rt
