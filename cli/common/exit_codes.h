// Process exit codes, the same for every subcommand.
#pragma once

namespace rt {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;   // runtime failure: the output could not be written, ...
inline constexpr int kExitBadInput = 2;  // bad usage or bad input: nothing was written

}  // namespace rt
