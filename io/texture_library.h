// The scene's textures as the builder loads them: each file once per encoding (a colour texture
// is decoded from sRGB, a height map not), every texel counted against the scene's budget
// (LoadLimits::scene_texels, mip levels included).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/texture/texture.h"
#include "io/load_options.h"
#include "io/texture_parser.h"

namespace rt {

class TextureLibrary {
 public:
  TextureLibrary(std::vector<Texture>& textures, const LoadLimits& limits) : textures_(textures), limits_(limits) {}

  // The index of the file's texture, loading it the first time; kNoTexture when it cannot be
  // used, with the message (to locate at ref.pointer) in `error` the first time. `files`
  // receives the path of a file read.
  uint32_t load(const TextureFileReference& ref, std::string& error, std::vector<std::string>& files);
  // Appends a texture decoded elsewhere (a glTF file's); returns its index.
  uint32_t add(Texture texture);
  bool within_budget() const { return texels_ <= limits_.scene_texels; }

 private:
  void count(const Texture& t);

  std::vector<Texture>& textures_;
  const LoadLimits& limits_;
  std::map<std::string, uint32_t> indices_;  // resolved path + encoding -> index (kNoTexture: failed)
  uint64_t texels_ = 0;                      // in textures_, mip levels included
};

}  // namespace rt
