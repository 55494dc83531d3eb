// Small glTF files written by tests: a JSON document with its one buffer embedded as a data URI.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>

#include "io/json/document.h"
#include "tests/support/test_paths.h"

namespace rt::test {

inline std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t v = (uint8_t(bytes[i]) << 16) | (uint8_t(bytes[i + 1]) << 8) | uint8_t(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out.push_back(table[(v >> (6 * k)) & 63]);
  }
  if (i + 1 == bytes.size()) {
    const uint32_t v = uint8_t(bytes[i]) << 16;
    out += {table[(v >> 18) & 63], table[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const uint32_t v = (uint8_t(bytes[i]) << 16) | (uint8_t(bytes[i + 1]) << 8);
    out += {table[(v >> 18) & 63], table[(v >> 12) & 63], table[(v >> 6) & 63], '='};
  }
  return out;
}

template <class T>
void append(std::string& buffer, std::initializer_list<T> values) {
  for (T v : values) buffer.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A one-buffer glTF file whose buffer is embedded as a data URI.
inline std::string write_gltf(const std::string& name, const std::string& buffer, Json doc) {
  doc["asset"] = {{"version", "2.0"}};
  doc["buffers"] = {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}};
  return rt::test::write_file(name, doc.dump());
}

// Four vertices of a unit square in the XY plane.
inline std::string square_positions() {
  std::string b;
  append<float>(b, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  return b;
}

}  // namespace rt::test
