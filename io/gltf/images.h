// The images of a glTF file's materials, each decoded once per encoding into
// ImportedModel::textures: from a data URI, a buffer view or a file in the model's folder
// (percent-encoded URIs, "%20" a space). Images with the same source (several images on one
// buffer view or file) share one texture. Each image's size is read from its header and
// counted against the scene's texel budget before it is decoded. An image that cannot be used is
// a warning and leaves the slot empty: the model still renders. Two things stop the import
// instead (failure()): an image that does not fit in the budget, and a URI that leaves the
// model's folder (unless LoadLimits::outside_files).
//
// Decoding is the slow part of loading a textured model (a 2048^2 PBR model's five images took
// longer than its render), so slots are first handed out against images claimed in order, and
// finish() decodes them all at once on every thread, then numbers the textures as one thread
// would have and points the materials' slots at them.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/gltf/imported_model.h"
#include "io/image/texture_file.h"

namespace tinygltf {
class Model;
class Value;
}  // namespace tinygltf

namespace rt {

// "%20" -> " ": glTF URIs are percent-encoded.
std::string percent_decoded(const std::string& uri);

// A glTF textureInfo, as the material refers to a texture.
struct GltfTextureRef {
  int index = -1;
  int texcoord = 0;
  const tinygltf::Value* transform = nullptr;  // its KHR_texture_transform object, if any
  std::string pointer;                         // where the textureInfo is ("/materials/0/normalTexture")
};

class ImageDecoder {
 public:
  // Problems go to `report`: unusable images are warnings (the material renders without them), a
  // file outside the model's folder is an error, and the texel budget stops the import.
  ImageDecoder(const tinygltf::Model& model, const std::string& base_dir, const LoadLimits& limits, LimitUsage& usage,
               ImportedModel& out, Reporter& report);

  // The slot for a material's texture: its image decoded as `encoding` (colour is sRGB, normal
  // and metallic-roughness maps are data, alpha masks read the alpha channel), its UV set, its
  // sampler's wrap and filter modes and its KHR_texture_transform.
  TextureSlot slot(const GltfTextureRef& ref, TextureEncoding encoding, const std::string& where);
  // A data slot for an image file beside the glTF file (rtcli's extras, at pointer `at`), decoded once.
  TextureSlot file_slot(const std::string& uri, const std::string& where, const std::string& at);

  // Whether the images the file's textures use, each source once and sized from its header, fit
  // in what is left of the scene's texel budget; if not, it is reported. Before decoding any.
  bool fit_in_budget();

  // Decodes every image the slots handed out so far refer to, on `threads` threads (0: all),
  // reports those that cannot be decoded (their slots become empty), and renumbers the slots of
  // `materials` to the textures' places in ImportedModel::textures.
  void finish(std::vector<Material>& materials, unsigned threads);

  // Whether the import must stop (a file outside the folder, the texel budget): reported.
  bool failed() const { return failed_; }

 private:
  // Where an image's bytes are: the key images share a texture by (one per encoding), the name
  // messages give it, and its bytes in memory or the path of its file.
  struct Source {
    std::string key;  // "view N", "image N" (a data URI's bytes), "file PATH"; empty: no data
    std::string name;
    std::span<const unsigned char> bytes;  // a buffer view's or a data URI's
    std::string path;                      // or a file's, resolved against the model's folder
    std::string uri;                       // the file's URI, as the model writes it
    std::string pointer;                   // the image's ("/images/2"), or the extras' naming the file
  };
  Source source_of(size_t image_index) const;
  Source file_source(const std::string& uri, const std::string& pointer) const;

  // An image claimed for decoding: its bytes (a file's kept here), its header, what it is for.
  struct Claimed {
    std::vector<unsigned char> file;
    std::span<const unsigned char> bytes;
    ImageHeader header;
    Source source;
    TextureEncoding encoding;
    std::string where;
  };

  // The texture `source` decodes to as `encoding` (claimed the first time, shared after): until
  // finish(), an index into claimed_.
  uint32_t decode(const Source& source, TextureEncoding encoding, const std::string& where);
  // A file's bytes, if it is in the model's folder (an error otherwise) and readable (a warning
  // otherwise).
  std::optional<std::vector<unsigned char>> read_file(const Source& source, const std::string& where);
  uint32_t claim(std::vector<unsigned char> file, std::span<const unsigned char> bytes, const Source& source,
                 TextureEncoding encoding, const std::string& where);
  // A buffer view's bytes (empty if it has none).
  std::span<const unsigned char> view_bytes(int view) const;
  void read_sampler(int sampler, TextureMapping& mapping);
  void read_transform(const tinygltf::Value& transform, TextureMapping& mapping, const std::string& where,
                      const std::string& at);

  const tinygltf::Model& model_;
  const std::string& base_dir_;
  const LoadLimits& limits_;
  LimitUsage& usage_;
  ImportedModel& out_;
  Reporter& report_;
  // Per source key and encoding: its texture, or kNoTexture if unusable.
  std::map<std::pair<std::string, TextureEncoding>, uint32_t> decoded_;
  std::vector<Claimed> claimed_;
  bool failed_ = false;
};

}  // namespace rt
