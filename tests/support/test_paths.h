// Where tests find the source tree, the rtcli binary and a scratch folder (set by CMake).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace rt::test {

inline std::string source_path(const std::string& relative) { return std::string(RTCLI_SOURCE_DIR) + "/" + relative; }

// The shared glTF sample models (../shared/gltf next to the repository).
inline std::string sample_model(const std::string& relative) { return source_path("../shared/gltf/" + relative); }
inline bool have_sample_models() { return std::filesystem::is_directory(sample_model("")); }

// A scratch folder per test binary run; created on first use.
inline std::string output_path(const std::string& name) {
  std::filesystem::create_directories(RTCLI_TEST_OUTPUT_DIR);
  return std::string(RTCLI_TEST_OUTPUT_DIR) + "/" + name;
}

// An empty folder `name` under the scratch folder (removed first if a run before left it).
inline std::string fresh_folder(const std::string& name) {
  const std::string dir = output_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = output_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace rt::test
