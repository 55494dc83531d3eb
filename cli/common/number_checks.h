// Checks for numeric command-line options that say what was wrong. CLI11 2.1's own ranges let
// "nan" through a float range, wrap "-1" and numbers past 2^64 into an unsigned option, and call
// "1e3" "not in range"; these accept decimal numbers only and name what they expected.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace rt {

// A whole number written in decimal digits (a leading '-' where min < 0), from min to max.
CLI::Validator whole_number(int64_t min, uint64_t max);
// A finite number from min to max ("nan" and "inf" are not numbers here).
CLI::Validator real_number(double min, double max);

// A linear RGB colour, "R,G,B" or one number for grey, each finite and from 0 to 1000.
CLI::Validator color_value();
// The colour a text color_value() accepted.
std::array<float, 3> parse_color(const std::string& text);

}  // namespace rt
