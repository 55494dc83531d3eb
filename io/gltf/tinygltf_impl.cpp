// tinygltf's implementation, compiled here from Debian's header rather than linked from Debian's
// shared library, so that sanitizers and the fuzzers see (and instrument) the code that parses
// untrusted files. The TINYGLTF_NO_* switches (set for the whole target in io/CMakeLists.txt)
// keep out its image decoding and its file system: every file goes through io/base/input_file.h.
#include <fstream>  // its writer needs it even with TINYGLTF_NO_FS (tinygltf 2.7 omits the include)

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
