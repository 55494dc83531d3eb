// The parts built as modules (io/base/loadable_module.h): the executable does not link their
// libraries, finds them beside itself, and says where it looked when one is missing or unusable.
#include <string>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

std::string binary_folder() {
  const std::string binary = RTCLI_BINARY;
  return binary.substr(0, binary.find_last_of('/'));
}

}  // namespace

TEST_CASE("cli: the modules link OpenColorIO, cpp-httplib and OpenSSL, and rtcli does not", "[cli][modules]") {
  const auto needed = rt::test::run_shell("readelf -d '" + std::string(RTCLI_BINARY) + "' 2>&1");
  if (needed.code != 0) {
    WARN("skipped: readelf (binutils) did not run: " << needed.output);
    return;
  }
  CHECK_THAT(needed.output, Catch::Contains("libz.so"));  // what the executable does link is listed
  for (const char* lib : {"OpenColorIO", "httplib", "libssl", "libcrypto", "brotli"})
    CHECK_THAT(needed.output, !Catch::Contains(lib));
  const auto ocio = rt::test::run_shell("readelf -d '" + binary_folder() + "/librtcli-ocio.so' 2>&1");
  CHECK_THAT(ocio.output, Catch::Contains("OpenColorIO"));
  const auto http = rt::test::run_shell("readelf -d '" + binary_folder() + "/librtcli-http.so' 2>&1");
  CHECK_THAT(http.output, Catch::Contains("httplib"));
}

TEST_CASE("cli: a module missing or not rtcli's is refused, with where it was looked for", "[cli][modules][hostile]") {
  const std::string dir = rt::test::fresh_folder("modules/bin");
  REQUIRE(rt::test::run_shell("cp '" + std::string(RTCLI_BINARY) + "' '" + dir + "/rtcli'").code == 0);
  const std::string rtcli = "cd '" + std::string(RTCLI_SOURCE_DIR) + "' && timeout 20 '" + dir + "/rtcli' ";
  const std::string scene = rt::test::write_file(
      "modules/sky.json",
      R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "background": 0.5, "nodes": []})");
  const std::string config = rt::test::write_file("modules/any.ocio", "ocio_profile_version: 1\n");
  const std::string view = "render " + scene + " -q --width 4 --height 4 -o " + dir +
                           "/x.png --view-transform half "
                           "--ocio-config " +
                           config + " 2>&1";

  // Without its modules, a render still renders; only what needs one fails, saying so.
  const auto plain =
      rt::test::run_shell(rtcli + "render " + scene + " -q --width 4 --height 4 -o " + dir + "/ok.png 2>&1");
  CHECK(plain.code == 0);
  const auto no_ocio = rt::test::run_shell(rtcli + view);
  CHECK(no_ocio.code == 2);
  CHECK_THAT(no_ocio.output, Catch::Contains("OpenColorIO is not available: librtcli-ocio.so not found in " + dir));
  const auto no_http = rt::test::run_shell(rtcli + "watch " + scene + " --port 0 2>&1");
  CHECK(no_http.code == 1);
  CHECK_THAT(no_http.output, Catch::Contains("HTTP server is not available: librtcli-http.so not found in " + dir));

  // A file of that name that is not a shared object, or one that is not this module.
  rt::test::write_file("modules/bin/librtcli-ocio.so", "not a library");
  const auto junk = rt::test::run_shell(rtcli + view);
  CHECK(junk.code == 2);
  CHECK_THAT(junk.output, Catch::Contains("could not load " + dir + "/librtcli-ocio.so"));
  REQUIRE(rt::test::run_shell("cp '" + binary_folder() + "/librtcli-http.so' '" + dir + "/librtcli-ocio.so'").code ==
          0);
  const auto other = rt::test::run_shell(rtcli + view);
  CHECK(other.code == 2);
  CHECK_THAT(other.output, Catch::Contains("librtcli-ocio.so has no function rtcli_open_ocio_view"));
}
