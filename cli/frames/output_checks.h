// Checks on the files a render will write, made before the render starts (a render of minutes
// must not fail at the end for want of a folder), and the names of --aa-debug's images.
#pragma once

#include <string>
#include <vector>

namespace rt {

// Refuses an output we could never write: a missing or read-only folder, a folder in its place,
// a name too long for the file system. The reason goes in `error`.
bool check_output(const std::string& path, std::string& error);

// Whether the output is one of the files the scene was read from (links resolved): then `error`.
bool output_is_an_input(const std::string& output, const std::vector<std::string>& inputs, std::string& error);

// Both: an output that can be written and is not one of the inputs.
inline bool check_new_output(const std::string& path, const std::vector<std::string>& inputs, std::string& error) {
  return check_output(path, error) && !output_is_an_input(path, inputs, error);
}

// "out.png" -> "out.aa-refined.png" for --aa-debug's images.
std::string beside(const std::string& output, const std::string& suffix);

}  // namespace rt
