// What glTF cannot carry, read from `extras` (Blender exports custom properties as extras;
// tools/blender_export.py writes these for the open scene):
//   node extras     rtcli_area_light = {shape, size [x, y], color [r, g, b], power (W), two_sided, camera}
//                   -> a RectLight centred on the node, in its XY plane, emitting down its -Z (as
//                      Blender's area lights, and glTF's lights, do). DISK and ELLIPSE shapes are
//                      drawn as the rectangle of the same size (a warning says so). camera
//                      (default true): false hides its face from camera rays, as Cycles hides
//                      Blender's lights unless Object > Visibility > Camera is on.
//                      Units, by the rule of io/gltf/lights.h: a one-sided Lambertian emitter of
//                      P watts sends P / pi W/sr along its normal, so colour = color x P / pi^2
//                      with 1/d^2 falloff (a Blender point light of P watts gets P / (4 pi^2)).
//   material extras rtcli_bump = {image, strength, epsilon}
//                   -> a bump map: `image` a file beside the glTF file (read as data), heights
//                      = texel x strength in scene units. Blender's exporter also writes the Bump
//                      node's image as the material's normalTexture; with rtcli_bump that
//                      normalTexture is dropped (a Principled BSDF has one Normal input).
//   scene extras    rtcli_world = {color [r, g, b], strength} or {image, strength, rotation (degrees)}
//                   -> the world of a model rendered on its own (Blender's World: its Background
//                      colour, or its Environment Texture's image, beside the glTF file, turned
//                      about +Y, in rtcli's convention): seen behind the model and, in the path
//                      tracer, lighting it. A scene file's background wins over it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/lights/rect_light.h"
#include "core/material.h"
#include "io/base/reporter.h"
#include "io/gltf/imported_model.h"

namespace tinygltf {
class Value;
}

namespace rt {

class ImageDecoder;

// The area light a node's extras describe, or nullopt (none, or unusable: a warning at `at` says why).
std::optional<RectLight> area_light_from_extras(const tinygltf::Value& extras, const std::string& where,
                                                const std::string& at, Reporter& report);

// Applies a material's rtcli_bump extras, if any, to `material`.
void apply_material_extras(const tinygltf::Value& extras, ImageDecoder& images, const std::string& where,
                           const std::string& at, Material& material, Reporter& report);

// The world a scene's extras describe, or nullopt (none, or unusable: a warning at `at` says why;
// an image outside `base_dir` without `outside_files` is an error).
std::optional<ImportedWorld> world_from_extras(const tinygltf::Value& extras, const std::string& base_dir,
                                               bool outside_files, const std::string& at, Reporter& report);

}  // namespace rt
