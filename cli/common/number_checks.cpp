#include "cli/common/number_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

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

namespace {

// "a,b,c" -> {"a", "b", "c"}; "" -> {""}.
std::vector<std::string> comma_parts(const std::string& text) {
  std::vector<std::string> parts{""};
  for (const char ch : text) {
    if (ch == ',') parts.emplace_back();
    else parts.back() += ch;
  }
  return parts;
}

}  // namespace

std::array<float, 3> parse_color(const std::string& text) {
  const std::vector<std::string> parts = comma_parts(text);
  std::array<float, 3> c{};
  for (size_t k = 0; k < 3; ++k) c[k] = std::strtof(parts[parts.size() == 3 ? k : 0].c_str(), nullptr);
  return c;  // one number: grey
}

CLI::Validator color_value() {
  const std::string expected = "expected a linear RGB colour, R,G,B or one number for grey, each from 0 to 1000";
  const CLI::Validator number = real_number(0.0, 1000.0);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::vector<std::string> parts = comma_parts(text);
        if (parts.size() != 1 && parts.size() != 3) return expected + ", found \"" + text + "\"";
        for (std::string& part : parts)
          if (!number(part).empty()) return expected + ", found \"" + text + "\"";
        return std::string();
      },
      "R,G,B");
}

}  // namespace rt
