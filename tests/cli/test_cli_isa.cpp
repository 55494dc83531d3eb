// --isa and RTCLI_ISA: each instruction set's BVH kernels forced in turn render the same bytes;
// a name that is not one, or a set this CPU lacks, is refused with exit 2.
#include <string>

#include <catch2/catch.hpp>

#include "core/accel/isa.h"
#include "io/json/document.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;

TEST_CASE("cli: --isa forces each instruction set this CPU runs, and every one renders the same bytes",
          "[cli][isa][determinism]") {
  // Shapes, CSG, a mesh with quads in its leaves, an alpha-masked glTF model, and an area light's
  // shadow rays in packets (walked together with AVX, one by one with SSE).
  for (const char* scene :
       {"scenes/primitives.json", "scenes/csg.json", "scenes/models/knot.glb", "scenes/soft_shadows.json",
        "../shared/gltf/TextureCoordinateTest/glTF-Binary/TextureCoordinateTest.glb"}) {
    INFO(scene);
    if (std::string(scene).rfind("../shared/", 0) == 0 && !rt::test::have_sample_models()) {
      WARN("../shared/gltf not found: " << scene << " skipped");
      continue;
    }
    const std::string args = std::string("render ") + scene + " --width 96 --height 64 --threads 2 -o '";
    const std::string baseline = output_path("isa-sse.png");
    Run r = rtcli(args + baseline + "' --isa sse");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.output, Catch::Contains("2 threads, sse\n"));
    for (const rt::Isa isa : {rt::Isa::kAvx2, rt::Isa::kAvx512}) {
      const std::string name = rt::isa_name(isa), out = output_path("isa-" + name + ".png");
      r = rtcli(args + out + "' --isa " + name);
      if (!rt::isa_supported(isa)) {
        WARN("this CPU does not run " << name << ": refused as it should be, its image not compared here");
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("--isa " + name + ": this CPU does not run " + name + " (it runs sse"));
        continue;
      }
      REQUIRE(r.code == 0);
      CHECK_THAT(r.output, Catch::Contains("2 threads, " + name + "\n"));
      CHECK(read_file(out) == read_file(baseline));
    }
  }
}

TEST_CASE("cli: RTCLI_ISA picks the kernels unless --isa is given, auto is the best, bad names exit 2", "[cli][isa]") {
  const std::string png = output_path("isa-env.png"), stats = output_path("isa-env.json");
  const std::string render = "render scenes/default.json --width 32 --height 20 -o '" + png + "'";
  const std::string best = rt::isa_name(rt::best_isa());
  Run r = rtcli(render + " --stats '" + stats + "'", RTCLI_SOURCE_DIR, "RTCLI_ISA=sse");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains(", sse\n"));
  CHECK(rt::Json::parse(read_file(stats))["isa"] == "sse");
  r = rtcli(render + " --isa auto", RTCLI_SOURCE_DIR, "RTCLI_ISA=sse");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains(", " + best + "\n"));
  r = rtcli(render, RTCLI_SOURCE_DIR, "RTCLI_ISA=auto");
  CHECK_THAT(r.output, Catch::Contains(", " + best + "\n"));
  r = rtcli(render + " --isa avx3");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("rtcli: error: --isa avx3: expected sse, avx2, avx512 or auto"));
  r = rtcli(render, RTCLI_SOURCE_DIR, "RTCLI_ISA=neon");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("rtcli: error: RTCLI_ISA=neon: expected sse, avx2, avx512 or auto"));
  // The bench names the kernels it measures.
  r = rtcli("bench scenes/models/knot.glb --scene '' --path-scene '' --repeats 1 --isa sse");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("BVH kernels: sse (of sse"));
  CHECK(rtcli("bench --isa avx3").code == 2);
}
