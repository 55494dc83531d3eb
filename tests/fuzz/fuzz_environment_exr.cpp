// libFuzzer entry point: tools/fuzz.sh environment_exr SECONDS. An input that breaks an invariant aborts.
#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return rt::fuzz::abort_on_problem(rt::fuzz::environment_exr(data, size));
}
