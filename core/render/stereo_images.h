// The two eyes' images put together as the stereo mode asks (the pair mode writes them apart):
//  - anaglyph for red-cyan glasses: Dubois' least-squares projection (the default), or "color"
//    (red from the left eye, green and blue from the right);
//  - side by side, the left eye on the left (parallel viewing; swap: cross-eyed);
//  - top and bottom, the left eye on top (what VR players expect of a 360° stereo image).
// On linear RGB, before encoding.
#pragma once

#include "core/image.h"
#include "core/stereo.h"

namespace rt {

// The size of the image a mode makes from two w x h eye images (pair: one eye's).
int stereo_image_width(StereoMode mode, int width);
int stereo_image_height(StereoMode mode, int height);

// One anaglyph pixel from the two eyes' linear colours, clamped to [0, 1].
Vec3 anaglyph_pixel(Vec3 left, Vec3 right, AnaglyphKind kind);

// Both images must be the same size; `mode` is not kNone or kPair.
Image compose_stereo(const Image& left, const Image& right, const StereoSettings& stereo);

}  // namespace rt
