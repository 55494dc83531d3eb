#include "io/scene/texture_parser.h"

#include "io/base/input_file.h"

namespace rt {
namespace {

// [u, v] or one number for both, each a finite float; a scale must not be zero.
std::optional<Vec2> read_pair(const JsonReader& r, const Json& v, const std::string& ptr, bool nonzero) {
  const auto one = [&](const Json& x, const std::string& at) -> std::optional<float> {
    const auto n = read_number(r, x, at, kAnyNumber);
    if (!n) return std::nullopt;
    if (nonzero && *n == 0.0) {
      r.expected(at, "a scale that is not zero", x);
      return std::nullopt;
    }
    return static_cast<float>(*n);
  };
  if (v.is_number()) {
    const auto n = one(v, ptr);
    return n ? std::optional<Vec2>(Vec2(*n)) : std::nullopt;
  }
  if (!v.is_array() || v.size() != 2) {
    r.expected(ptr, "an array of 2 numbers [u, v], or one number for both", v);
    return std::nullopt;
  }
  const auto a = one(v[0], ptr + "/0"), b = one(v[1], ptr + "/1");
  return a && b ? std::optional<Vec2>(Vec2(*a, *b)) : std::nullopt;
}

void parse_mapping(const JsonReader& r, ObjectReader& o, TextureMapping& m) {
  if (const Json* p = o.get("projection")) {
    if (const auto k = read_choice(r, *p, o.child("projection"), {"uv", "planar", "spherical", "cylindrical"}))
      m.projection = static_cast<Projection>(*k);
  }
  if (const auto set = o.number("texcoord", NumberRule{0, 1, false, false, true}))
    m.uv_set = static_cast<uint32_t>(*set);
  if (const Json* s = o.get("scale")) {
    if (const auto v = read_pair(r, *s, o.child("scale"), true)) m.scale = *v;
  }
  if (const Json* s = o.get("offset")) {
    if (const auto v = read_pair(r, *s, o.child("offset"), false)) m.offset = *v;
  }
  if (const auto deg = o.number("rotation")) m.rotation_degrees = static_cast<float>(*deg);
  if (const Json* w = o.get("wrap")) {
    // One mode for both axes, or [u, v].
    const std::vector<std::string> modes{"repeat", "clamp", "mirror"};
    const std::string ptr = o.child("wrap");
    if (w->is_array() && w->size() == 2) {
      const auto u = read_choice(r, (*w)[0], ptr + "/0", modes), v = read_choice(r, (*w)[1], ptr + "/1", modes);
      if (u && v) m.wrap = WrapModes(static_cast<TextureWrap>(*u), static_cast<TextureWrap>(*v));
    } else if (w->is_array()) {
      r.expected(ptr, "one wrap mode (\"repeat\", \"clamp\" or \"mirror\") or an array of 2, [u, v]", *w);
    } else if (const auto k = read_choice(r, *w, ptr, modes)) {
      m.wrap = static_cast<TextureWrap>(*k);
    }
  }
  if (const Json* a = o.get("axis")) {
    if (const auto k = read_choice(r, *a, o.child("axis"), {"x", "y", "z"}))
      m.axis = static_cast<ProjectionAxis>(*k + 1);
  }
  if (const Json* f = o.get("filter")) {
    if (const auto k = read_choice(r, *f, o.child("filter"), kTextureFilters)) m.filter = *k;
  }
}

std::optional<TextureFileReference> file_reference(const JsonReader& r, const Json& v, const std::string& ptr,
                                                   const std::string& folder, TextureEncoding encoding) {
  const auto file = read_string(r, v, ptr);
  if (!file) return std::nullopt;
  if (file->empty()) {
    r.expected(ptr, "the path of a PNG, JPEG or WebP image", v);
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
  const Json* file = o.get("file", true, "the path of a PNG, JPEG or WebP image");
  parse_mapping(r, o, mapping);
  if (extra) extra(o);
  o.finish();
  if (!file) return std::nullopt;
  return file_reference(r, *file, o.child("file"), scene_folder, encoding);
}

}  // namespace rt
