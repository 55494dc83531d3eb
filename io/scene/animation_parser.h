// The scene file's "animation": frame rate, frame range and keyframed tracks on named nodes
// (schemas/scene.schema.json, docs/scene-format.md, "Animation"). Key values are written as the node's own
// transform keys are: translate [x, y, z]; scale one number or [x, y, z]; rotate Euler degrees
// [x, y, z], {"axis": [x, y, z], "degrees": d} or {"quaternion": [x, y, z, w]}. Rotations
// interpolate by slerp; degrees mean what they say, so a linear track from 0 to 360 degrees turns
// a full circle (keys are added between written keys more than 90 degrees apart, which slerp
// follows exactly about one axis). All tracks together hold at most `max_keys` keys, the added
// ones included (LoadLimits::animation_keys), counted before they are made. Node names are
// resolved by the builder.
#pragma once

#include <optional>

#include "io/json/reader.h"
#include "io/scene/description.h"

namespace rt {

std::optional<AnimationDescription> parse_animation(const JsonReader& r, const Json& value, const std::string& pointer,
                                                    uint64_t max_keys);

}  // namespace rt
