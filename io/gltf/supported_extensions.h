// The glTF extensions rtcli reads: a file may list these in extensionsRequired (io/gltf/file.cpp
// refuses any other). One list, at the bottom of io/gltf/, so that the file check and the readers
// of each extension agree without including one another.
#pragma once

#include <string>
#include <vector>

namespace rt {

const std::vector<std::string>& supported_gltf_extensions();

}  // namespace rt
