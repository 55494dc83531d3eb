// The frames of a render, one after another: frame f is the scene graph posed at frame f
// (SceneGraph::pose) and placed, its top-level BVH built over meshes and BVHs that every frame
// shares. The frame the loader built is kept and given back as it is, not built again.
#pragma once

#include <optional>

#include "core/scene_graph.h"

namespace rt {

class FrameScenes {
 public:
  // `built` is frame `built_frame`, already placed; both must outlive this object.
  FrameScenes(const SceneGraph& graph, int built_frame, const Scene& built, BvhBuildOptions options)
      : graph_(graph), built_frame_(built_frame), built_(built), options_(options) {}

  // Frame `frame`, valid until the next call.
  const Scene& at(int frame);
  // Time spent placing frames (their top-level BVHs), all calls together.
  double placing_seconds() const { return placing_seconds_; }

 private:
  const SceneGraph& graph_;
  const int built_frame_;
  const Scene& built_;
  const BvhBuildOptions options_;
  std::optional<Scene> current_;
  double placing_seconds_ = 0.0;
};

}  // namespace rt
