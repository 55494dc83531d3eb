// tools/blender_export.py without Blender: a stand-in bpy module checks that the custom
// properties the script sets for the export do not stay on the user's objects (CI has no Blender;
// tests/data/blender/make_fixture.py runs the script in the real one).
#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

TEST_CASE("blender_export.py removes its custom properties after the export, even a failed one", "[tools][blender]") {
  const rt::test::Run r =
      rt::test::run_shell("python3 '" + rt::test::source_path("tests/data/blender/check_cleanup.py") + "' '" +
                          rt::test::output_path("") + "' 2>&1");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("blender_export cleanup: ok"));
}
