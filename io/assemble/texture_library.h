// The scene's textures as the builder loads them: each file once per encoding (a colour texture
// is decoded from sRGB, a height map not), every texel counted against the scene's budget
// (LoadLimits::scene_texels, mip levels included) from the image's header, before it is decoded.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

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

 private:
  std::vector<Texture>& textures_;
  const LoadLimits& limits_;
  LimitUsage& usage_;
  LoadCache* cache_;
  std::map<std::string, uint32_t> indices_;  // resolved path + encoding -> index (kNoTexture: failed)
};

}  // namespace rt
