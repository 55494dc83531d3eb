// Base64 (RFC 4648), as glTF's data URIs hold buffers and images.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

std::string base64_encode(const std::vector<unsigned char>& bytes);
// Whitespace and missing padding are tolerated; any other character outside the alphabet gives nullopt.
std::optional<std::vector<unsigned char>> base64_decode(std::string_view text);

}  // namespace rt
