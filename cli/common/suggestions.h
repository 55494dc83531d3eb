// "Did you mean" on the command line, as scene files have it (closest_match, io/json/reader.h):
// a misspelt subcommand, option or option value is answered with the nearest real one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace rt {

// " (did you mean "x"?)" for the candidate nearest to `word`, or "" when none is near.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

// For a command line CLI11 refused: the message naming its first unknown subcommand or option
// with the nearest real one, or nothing (then CLI11's own message serves).
std::optional<std::string> unknown_argument_message(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace rt
