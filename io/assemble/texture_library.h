// The scene's images as the builder loads them: its textures, each file once per encoding (a
// colour texture is decoded from sRGB, a height map not), and its environment image. Every texel
// is counted against the scene's budget (LoadLimits::scene_texels, mip levels included) from the
// image's header, before it is decoded.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/lights/environment.h"
#include "core/texture/texture.h"
#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/scene/texture_parser.h"

namespace rt {

class TextureLibrary {
 public:
  // `cache` (may be null) keeps decoded files between loads (io/assemble/load_cache.h).
  TextureLibrary(std::vector<Texture>& textures, const LoadLimits& limits, LimitUsage& usage, LoadCache* cache)
      : textures_(textures), limits_(limits), usage_(usage), cache_(cache) {}

  // The index of the file's texture, loading it the first time; kNoTexture when it cannot be
  // used, reported at ref.pointer the first time (past the texel budget: report.over_limit).
  // `files` receives the path of a file read.
  uint32_t load(const TextureFileReference& ref, Reporter& report, std::vector<std::string>& files);
  // Appends a texture decoded elsewhere, its texels already counted (a glTF file's); returns its index.
  uint32_t add(Texture texture);
  // An environment image: kept from an earlier load (watch) or read; counted against the texel
  // budget and its path added to `files` either way. Null, with `why`, if it cannot be used.
  std::shared_ptr<const EnvironmentImage> environment(const std::string& path, std::string& why,
                                                      std::vector<std::string>& files);

 private:
  std::vector<Texture>& textures_;
  const LoadLimits& limits_;
  LimitUsage& usage_;
  LoadCache* cache_;
  std::map<std::string, uint32_t> indices_;  // resolved path + encoding -> index (kNoTexture: failed)
};

}  // namespace rt
