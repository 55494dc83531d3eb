#include "cli/number_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace rt {
namespace {

std::string range_text(const std::string& low, const std::string& high) { return " from " + low + " to " + high; }

std::string format(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

CLI::Validator whole_number(int64_t min, uint64_t max) {
  const std::string expected = "expected a whole number" + range_text(std::to_string(min), std::to_string(max));
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const bool negative = !text.empty() && text[0] == '-';
        const std::string digits = negative ? text.substr(1) : text;
        const bool decimal = !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
        if (!decimal) return expected + ", found \"" + text + "\", which is not a whole number in decimal digits";
        errno = 0;
        if (negative) {
          const long long v = std::strtoll(text.c_str(), nullptr, 10);
          if (errno == ERANGE || v < min) return expected + ", found " + text;
        } else {
          const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
          if (errno == ERANGE || v > max || (min > 0 && v < static_cast<uint64_t>(min)))
            return expected + ", found " + text;
        }
        return std::string();
      },
      "INT in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

CLI::Validator real_number(double min, double max) {
  const std::string expected = "expected a number" + range_text(format(min), format(max));
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size())
          return expected + ", found \"" + text + "\", which is not a number";
        if (!std::isfinite(v) || errno == ERANGE) return expected + ", found " + text + ", which is not finite";
        if (v < min || v > max) return expected + ", found " + text;
        return std::string();
      },
      "FLOAT in [" + format(min) + " - " + format(max) + "]");
}

}  // namespace rt
