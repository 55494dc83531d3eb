// What a scene's loads keep between one another while their files stay the same: each glTF
// import (its meshes' BVHs built), each texture and each environment image, with the stamps of
// the files they came from (io/base/file_stamp.h). `rtcli watch` loads the scene again after
// every saved change; with a cache only what changed is read, decoded and built again, so an
// edit to the scene file's materials does not re-read a large model or rebuild its BVHs.
// A load without one (LoadOptions::cache null: render, validate) reads everything. Kept items
// still count against the limits of the load that takes them, as if read. One thread at a time.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/accel/bvh.h"
#include "core/texture/texture.h"
#include "io/base/diagnostics.h"
#include "io/base/file_stamp.h"
#include "io/base/load_options.h"
#include "io/gltf/imported_model.h"
#include "io/image/environment_file.h"

namespace rt {

class LoadCache {
 public:
  struct Model {
    FileStamps files;                  // the model, its buffers and images
    ImportedModel model;               // as imported, meshes included
    std::vector<Bvh> bvhs;             // per primitive, mesh by mesh (none when the load built none)
    LimitUsage used;                   // what the import counted
    std::vector<Diagnostic> warnings;  // in the file's terms, reported again at each use
  };
  struct Image {
    FileStamps file;
    Texture texture;
    uint64_t texels = 0;
  };
  struct Environment {
    FileStamps file;
    std::shared_ptr<const EnvironmentImage> image;
    uint64_t texels = 0;
  };

  // The kept item under `key` if its files are unchanged and it fits in what `usage` leaves of
  // `limits`; else null (and a changed item is forgotten). A hit is counted as kept.
  const Model* model(const std::string& key, const LimitUsage& usage, const LoadLimits& limits);
  const Image* image(const std::string& key, const LimitUsage& usage, const LoadLimits& limits);
  const Environment* environment(const std::string& key, const LimitUsage& usage, const LoadLimits& limits);

  // Keeps what was just read (counted as read).
  void keep(const std::string& key, Model m) {
    models_[key] = std::make_unique<Model>(std::move(m));
    ++read_;
  }
  void keep(const std::string& key, Image i) {
    images_[key] = std::make_unique<Image>(std::move(i));
    ++read_;
  }
  void keep(const std::string& key, Environment e) {
    environments_[key] = std::make_unique<Environment>(std::move(e));
    ++read_;
  }

  // Counts since the last call: files' items kept from an earlier load, and read afresh.
  struct Counts {
    int kept = 0, read = 0;
  };
  Counts take_counts() {
    const Counts c{kept_, read_};
    kept_ = read_ = 0;
    return c;
  }

 private:
  std::map<std::string, std::unique_ptr<Model>> models_;
  std::map<std::string, std::unique_ptr<Image>> images_;
  std::map<std::string, std::unique_ptr<Environment>> environments_;
  int kept_ = 0, read_ = 0;
};

}  // namespace rt
