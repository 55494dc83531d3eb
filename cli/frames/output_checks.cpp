#include "cli/frames/output_checks.h"

#include <unistd.h>
#include <climits>

#include <filesystem>

namespace rt {

// Refuses an output we could never write before spending minutes on the render: a missing or
// read-only folder, a folder in its place, a name too long for the file system.
bool check_output(const std::string& path, std::string& error) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    error = "cannot write \"" + path + "\": the folder \"" + folder.string() + "\" does not exist";
    return false;
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    error = "cannot write \"" + path + "\": the folder \"" + folder.string() + "\" is not writable";
    return false;
  }
  if (fs::is_directory(p, ec)) {
    error = "cannot write \"" + path + "\": it is a folder";
    return false;
  }
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::string name = p.filename().string();
  if (name_max > 0 && name.size() > static_cast<size_t>(name_max)) {
    error = "cannot write \"" + path + "\": its name is " + std::to_string(name.size()) + " bytes, more than the " +
            std::to_string(name_max) + " the file system allows";
    return false;
  }
  if (path.size() >= PATH_MAX) {
    error = "cannot write \"" + path.substr(0, 60) + "...\": its path is " + std::to_string(path.size()) +
            " bytes, more than the " + std::to_string(PATH_MAX - 1) + " the system allows";
    return false;
  }
  return true;
}

// The image must not replace a file the scene was read from (the same file, links resolved).
bool output_is_an_input(const std::string& output, const std::vector<std::string>& inputs, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::exists(output, ec)) return false;
  for (const std::string& input : inputs) {
    if (std::filesystem::equivalent(output, input, ec)) {
      error = "refusing to write the image to \"" + output + "\": it is the input file \"" + input +
              "\" (choose another name with -o)";
      return true;
    }
  }
  return false;
}

// "out.png" -> "out.aa-refined.png" for --aa-debug's images.
std::string beside(const std::string& output, const std::string& suffix) {
  std::filesystem::path p(output);
  p.replace_extension(suffix + ".png");
  return p.string();
}

}  // namespace rt
