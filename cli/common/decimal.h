// A whole number typed on the command line inside a larger argument ("3/8", "1-120x10",
// "0,0,64,32"), where CLI11's validators cannot reach: decimal digits with an optional '-', at
// most 9 characters, nothing else.
#pragma once

#include <cerrno>
#include <cstdlib>
#include <optional>
#include <string>

namespace rt {

inline std::optional<long> parse_decimal(const std::string& s) {
  if (s.empty() || s.size() > 9 || s[0] == '+' || s[0] == ' ') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (errno != 0 || end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

}  // namespace rt
