#include "io/gltf/file.h"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

#include "io/base/base64.h"
#include "io/base/input_file.h"
#include "io/gltf/accessor.h"
#include "io/gltf/compressed_geometry.h"
#include "io/gltf/supported_extensions.h"
#include "io/json/document.h"
#include "io/json/reader.h"

namespace rt {
namespace {

// What the file-system callbacks share: the model's folder, the budget left for external
// buffers, and the files read.
struct FileAccess {
  std::string base_dir;
  bool outside_files = false;  // LoadLimits::outside_files
  uint64_t budget = 0;
  std::vector<std::string> files;
};

// tinygltf looks for a buffer in the model's folder, then in the current one. Every path in the
// model's folder "exists", so that read_file() says what is wrong with it (missing, a FIFO, a
// link loop, outside the folder) instead of tinygltf's "file not found"; the current folder is
// never searched.
bool file_exists(const std::string& path, void* user) {
  const std::string& base = static_cast<FileAccess*>(user)->base_dir;
  return path.size() > base.size() && path.compare(0, base.size(), base) == 0;
}

std::string expand_path(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto* access = static_cast<FileAccess*>(user);
  std::string error;
  if (!access->outside_files && !is_inside_folder(path, access->base_dir)) {
    if (err)
      *err = outside_folder_message(path.substr(std::min(path.size(), access->base_dir.size() + 1)), access->base_dir);
    return false;
  }
  auto bytes = read_input_bytes(path, access->budget, error);
  if (!bytes) {
    if (err) *err = error;
    return false;
  }
  access->budget -= bytes->size();
  access->files.push_back(path);
  *out = std::move(*bytes);
  return true;
}

bool write_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "rtcli never writes glTF files";
  return false;
}

// Images are not decoded here: one from a data URI keeps its encoded bytes in image->image, and
// the importer decodes only those a material it maps actually uses. One in a buffer view is read
// later from the view, once check_buffer_views has seen it inside its buffer: tinygltf hands
// this callback the view's bytes without that check.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// tinygltf's messages end lines with "\n" and may repeat a prefix; one line per message, joined.
std::string clean(const std::string& text) {
  std::string out, line;
  for (const char c : text + "\n") {
    if (c != '\n') {
      line.push_back(c);
      continue;
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (!line.empty()) out += (out.empty() ? "" : "; ") + clean_parser_message(line);
    line.clear();
  }
  return out;
}

uint32_t read_u32(const unsigned char* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);  // GLB is little-endian, as is every machine rtcli builds on
  return v;
}

void append_u32(std::vector<unsigned char>& out, uint32_t v) {
  unsigned char b[4];
  std::memcpy(b, &v, 4);
  out.insert(out.end(), b, b + 4);
}

// A .glb with another JSON chunk and the original's chunks after its JSON (the BIN chunk).
std::vector<unsigned char> glb_with_json(const std::string& json, const std::vector<unsigned char>& glb) {
  std::string padded = json;
  while (padded.size() % 4) padded.push_back(' ');
  const size_t rest = 20 + read_u32(glb.data() + 12);
  // The header's first 8 bytes, then the rest in one allocation. (Built from the range rather
  // than inserted into an empty vector, which GCC 12's -Wstringop-overflow misreads as a write
  // past its end.)
  std::vector<unsigned char> out(glb.begin(), glb.begin() + 8);
  out.reserve(20 + padded.size() + (glb.size() > rest ? glb.size() - rest : 0));
  append_u32(out, 0);  // total length, below
  append_u32(out, static_cast<uint32_t>(padded.size()));
  append_u32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), padded.begin(), padded.end());
  out.insert(out.end(), glb.begin() + static_cast<std::ptrdiff_t>(rest), glb.end());
  const auto total = static_cast<uint32_t>(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

bool load_model(tinygltf::TinyGLTF& loader, tinygltf::Model& model, std::string& err, std::string& warn, bool binary,
                const std::vector<unsigned char>& bytes, std::string_view json, const std::string& base_dir) {
  try {
    return binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                static_cast<unsigned int>(bytes.size()), base_dir)
                  : loader.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                               base_dir);
  } catch (const std::bad_alloc&) {
    throw;  // the caller reports memory exhaustion
  } catch (const std::exception& e) {
    err = e.what();
    return false;
  }
}

// KHR_draco_mesh_compression and EXT_meshopt_compression (io/gltf/compressed_geometry.h): the
// document rewritten with its geometry decoded, in `rewritten` (a .glb's bytes or the JSON text);
// false when that failed (reported). Nothing to do leaves `rewritten` empty.
bool decode_compressed(std::string_view json, bool binary, const std::vector<unsigned char>& bytes, FileAccess access,
                       Reporter& report, std::vector<unsigned char>& rewritten) {
  if (json.find("KHR_draco_mesh_compression") == std::string_view::npos &&
      json.find("meshopt_compression") == std::string_view::npos)
    return true;
  Json doc = Json::parse(json, nullptr, /*allow_exceptions=*/false, /*ignore_comments=*/false);
  if (!doc.is_object() || !uses_compressed_geometry(doc)) return true;
  // The buffers, loaded by tinygltf through the same file access (with its own copy of the
  // budget) from a document of nothing else; meshopt's fallback buffers have no data to load.
  Json buffers = doc.contains("buffers") && doc["buffers"].is_array() ? doc["buffers"] : Json::array();
  for (size_t i = 0; i < buffers.size(); ++i)
    if (buffers[i].is_object() && !buffers[i].contains("uri") && !(binary && i == 0))
      buffers[i] = embedded_buffer({0, 0, 0, 0});
  const Json stripped = {{"asset", {{"version", "2.0"}}}, {"buffers", buffers}};
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&file_exists, &expand_path, &read_file, &write_file, &access});
  std::string err, warn;
  const std::string stripped_text = stripped.dump();
  const bool ok =
      binary ? load_model(loader, model, err, warn, true, glb_with_json(stripped_text, bytes), {}, access.base_dir)
             : load_model(loader, model, err, warn, false, {}, stripped_text, access.base_dir);
  if (!ok) {
    report.error("/buffers", err.empty() ? "its buffers could not be read" : clean(err));
    return false;
  }
  std::vector<std::vector<unsigned char>> data;
  for (tinygltf::Buffer& b : model.buffers) data.push_back(std::move(b.data));
  if (!decompress_geometry(doc, data, access.budget, report)) return false;
  const std::string text = doc.dump();
  rewritten = binary ? glb_with_json(text, bytes) : std::vector<unsigned char>(text.begin(), text.end());
  return true;
}

// Images in data URIs of types tinygltf does not know (image/webp: EXT_texture_webp) are left as
// URIs by it: their bytes are taken here, as it takes a PNG's, for the decoder to identify. One
// that is not base64 stays a URI, and is reported as unreadable when a material uses it.
void embedded_images(tinygltf::Model& model) {
  for (tinygltf::Image& image : model.images) {
    if (!image.image.empty() || image.bufferView >= 0 || image.uri.rfind("data:", 0) != 0) continue;
    const size_t comma = image.uri.find(',');
    if (comma == std::string::npos || comma < 12 || image.uri.compare(comma - 7, 7, ";base64") != 0) continue;
    auto bytes = base64_decode(std::string_view(image.uri).substr(comma + 1));
    if (!bytes || bytes->empty()) continue;
    image.image = std::move(*bytes);
    image.uri.clear();
  }
}

}  // namespace

std::string outside_folder_message(const std::string& uri, const std::string& base_dir) {
  return "\"" + uri + "\" is outside the model's folder \"" + base_dir +
         "\": a glTF file's images and buffers are read from its own folder and below, so that a downloaded "
         "model cannot show other files (--allow-outside-files reads it)";
}

namespace {

// Reports each extension the file's extensionsRequired names that rtcli does not implement;
// whether there was one. `json` is the file's JSON (its nesting already checked).
bool report_unsupported_required(std::string_view json, bool binary, Reporter& report) {
  const Json root = Json::parse(json, nullptr, /*allow_exceptions=*/false, /*ignore_comments=*/false);
  if (!root.is_object() || !root.contains("extensionsRequired") || !root["extensionsRequired"].is_array()) return false;
  if (!binary) report.find_places_with(json_places(std::make_shared<const std::string>(json)));
  const auto& supported = supported_gltf_extensions();
  const Json& required = root["extensionsRequired"];
  bool found = false;
  for (size_t i = 0; i < required.size(); ++i) {
    if (!required[i].is_string()) continue;
    const std::string name = required[i].get<std::string>();
    if (std::find(supported.begin(), supported.end(), name) != supported.end()) continue;
    report.error("/extensionsRequired/" + std::to_string(i),
                 "it requires the extension \"" + name + "\", which rtcli does not implement (extensionsRequired)");
    found = true;
  }
  return found;
}

}  // namespace

GltfFile parse_gltf(const std::vector<unsigned char>& bytes, const std::string& base_dir, const LoadLimits& limits,
                    Reporter& report) {
  GltfFile result;
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  // The JSON part: its size and nesting are checked before tinygltf builds a tree of it (which
  // it walks recursively).
  std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (binary) {
    if (bytes.size() < 20) {
      report.error("", "a .glb file of " + std::to_string(bytes.size()) + " bytes is shorter than its 20-byte header");
      return result;
    }
    const uint32_t json_length = read_u32(bytes.data() + 12);
    if (json_length > bytes.size() - 20) {
      report.error("", "the .glb header announces " + std::to_string(json_length) +
                           " bytes of JSON, but the file has only " + std::to_string(bytes.size() - 20) +
                           " after the header: the file is truncated");
      return result;
    }
    json = json.substr(20, json_length);
  }
  if (json.size() > limits.gltf_json_bytes) {
    report.error("", "its JSON is " + format_bytes(json.size()) + ", more than the " +
                         format_bytes(limits.gltf_json_bytes) +
                         " a glTF file's JSON may have (store large buffers in .bin files or a .glb)");
    return result;
  }
  if (!json_nesting_within(json, kMaxJsonNesting)) {
    report.error(
        "", "expected JSON nested at most " + std::to_string(kMaxJsonNesting) + " levels deep, found deeper nesting");
    return result;
  }

  FileAccess access{base_dir,
                    limits.outside_files,
                    limits.gltf_total_bytes - std::min<uint64_t>(limits.gltf_total_bytes, bytes.size()),
                    {}};
  // Compressed geometry is decoded first, into a rewritten document read below in its place.
  if (!binary) report.find_places_with(json_places(std::make_shared<const std::string>(json)));
  std::vector<unsigned char> rewritten;
  if (!decode_compressed(json, binary, bytes, access, report, rewritten)) return result;
  const std::vector<unsigned char>& input = rewritten.empty() ? bytes : rewritten;
  const std::string_view input_json =
      rewritten.empty() || binary ? json
                                  : std::string_view(reinterpret_cast<const char*>(rewritten.data()), rewritten.size());
  auto model = std::make_shared<tinygltf::Model>();
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&file_exists, &expand_path, &read_file, &write_file, &access});
  loader.SetImageLoader(&keep_encoded_image, nullptr);
  std::string err, warn;
  const bool ok = load_model(loader, *model, err, warn, binary, input, input_json, base_dir);
  result.files = std::move(access.files);
  if (!warn.empty()) report.warning("", clean(warn));
  if (!ok) {
    // A file that needs an extension rtcli lacks (Draco's accessors have no bufferView) fails in
    // tinygltf with a message about the symptom: name the extension instead, when that is why.
    if (!report_unsupported_required(json, binary, report))
      report.error("", err.empty() ? "not a readable glTF file" : clean(err));
    return result;
  }
  // A .gltf is JSON text (now known to be well-formed): problems found from here on get its
  // line:column and a caret, as a scene file's do. A .glb's JSON is inside a binary file.
  if (!binary) report.find_places_with(json_places(std::make_shared<const std::string>(json)));
  const auto& supported = supported_gltf_extensions();
  for (size_t i = 0; i < model->extensionsRequired.size(); ++i) {
    const std::string& name = model->extensionsRequired[i];
    if (std::find(supported.begin(), supported.end(), name) == supported.end()) {
      report.error("/extensionsRequired/" + std::to_string(i),
                   "it requires the extension \"" + name + "\", which rtcli does not implement (extensionsRequired)");
      return result;
    }
  }
  // An optional extension we do not implement leaves the file renderable: say what is ignored.
  for (size_t i = 0; i < model->extensionsUsed.size(); ++i) {
    const std::string& name = model->extensionsUsed[i];
    const bool required = std::find(model->extensionsRequired.begin(), model->extensionsRequired.end(), name) !=
                          model->extensionsRequired.end();
    if (!required && std::find(supported.begin(), supported.end(), name) == supported.end())
      report.warning("/extensionsUsed/" + std::to_string(i),
                     "it uses the extension \"" + name + "\", which rtcli ignores (extensionsUsed)");
  }
  if (!check_buffer_views(*model, report)) return result;
  embedded_images(*model);
  result.model = std::move(model);
  return result;
}

}  // namespace rt
