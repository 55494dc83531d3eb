// tools/gallery.sh --fast: every section rendered small into a scratch folder, the page's images
// and links all there, and the HTML clean by Debian's tidy.
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

TEST_CASE("gallery: --fast writes a self-contained page whose images and links all resolve", "[tools][gallery]") {
  const std::string out = rt::test::output_path("gallery-fast");
  fs::remove_all(out);
  const rt::test::Run r = rt::test::run_shell("'" + rt::test::source_path("tools/gallery.sh") + "' --fast --out '" +
                                              out + "' --rtcli '" + RTCLI_BINARY + "' 2>&1");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string page = rt::test::read_file(out + "/index.html");
  CHECK(fs::exists(out + "/style.css"));
  // Every image and link inside the page resolves; nothing comes from elsewhere.
  std::set<std::string> ids;
  int images = 0;
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (size_t at = page.find(attribute); at != std::string::npos; at = page.find(attribute, at + 1)) {
      const size_t begin = at + attribute.size(), end = page.find('"', begin);
      const std::string target = page.substr(begin, end - begin);
      INFO(target);
      CHECK(target.find("://") == std::string::npos);
      if (target[0] == '#') ids.insert(target.substr(1));
      else CHECK(fs::exists(out + "/" + target));
    }
  }
  for (const std::string& id : ids) CHECK(page.find("id=\"" + id + "\"") != std::string::npos);
  CHECK(ids.size() >= 15);  // a section for each objective and extra
  // Every image has alt text, and its statistics under it.
  for (size_t at = page.find("<img "); at != std::string::npos; at = page.find("<img ", at + 1), ++images)
    CHECK(page.substr(at, page.find('>', at) - at).find("alt=\"") != std::string::npos);
  CHECK(images >= 34);  // every render of every section
  CHECK(page.find("rays a pixel") != std::string::npos);
  // Wide renders are shown as thumbnails linking to the full image; each has its stats JSON beside it.
  CHECK(page.find("<a href=\"gallery/toys.png\"><img src=\"gallery/toys-small.png\"") != std::string::npos);
  CHECK(fs::file_size(out + "/gallery/toys-small.png") < fs::file_size(out + "/gallery/toys.png"));
  const std::string stats = rt::test::read_file(out + "/gallery/toys.json");
  CHECK(stats.find("\"outputs\": [\n    \"toys.png\"") != std::string::npos);
  CHECK(stats.find("\"camera\":") != std::string::npos);
  // The speed table, today's ratios lifted from docs/benchmark.md (POV-Ray, Cycles and Embree rows).
  CHECK(page.find("<th>against</th><th>scene</th><th>measure</th><th>ratio</th><th>target</th>") != std::string::npos);
  CHECK(page.find("<td>Cycles (Blender 3.4, CPU)</td>") != std::string::npos);
  // The figures that meet a target are bold in the docs' Markdown: <strong> on the page, no "**".
  CHECK(page.find("<strong>") != std::string::npos);
  CHECK(page.find("**") == std::string::npos);
  // Each texture projection and filter, and glossy at several widths.
  for (const char* name : {"projection-uv", "projection-planar", "projection-spherical", "projection-cylindrical",
                           "filter-nearest", "filter-bilinear", "filter-trilinear", "glossy-0", "glossy-0.3"})
    CHECK(page.find(std::string("id=\"fig-") + name + "\"") != std::string::npos);
  // Sliders where the proposal compares two renders.
  CHECK(page.find("data-compare") != std::string::npos);
  // Valid HTML: tidy (tools/install-deps.sh installs it) reports neither errors nor warnings.
  if (rt::test::run_shell("command -v tidy >/dev/null").code != 0) {
    WARN("tidy is not installed: the HTML check is skipped");
    return;
  }
  const rt::test::Run tidy = rt::test::run_shell("tidy -q -e '" + out + "/index.html' 2>&1");
  INFO(tidy.output);
  // Tidy 5.6 (Debian 12's) predates the standard loading="lazy" attribute and calls it
  // proprietary; every other warning counts.
  std::istringstream lines(tidy.output);
  std::vector<std::string> problems;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line.find("proprietary attribute \"loading\"") == std::string::npos) problems.push_back(line);
  CHECK(tidy.code <= 1);  // 1: warnings only
  CHECK(problems.empty());
}

TEST_CASE("gallery: in headless Chromium every image loads, every slider moves, nothing logs an error",
          "[tools][gallery][browser]") {
  if (rt::test::run_shell("command -v chromium >/dev/null").code != 0) {
    WARN("chromium is not installed (tools/install-deps.sh installs it): the browser test is skipped");
    return;
  }
  const std::string out = rt::test::output_path("gallery-browser");
  fs::remove_all(out);
  REQUIRE(rt::test::run_shell("'" + rt::test::source_path("tools/gallery.sh") + "' --fast --out '" + out +
                              "' --rtcli '" + RTCLI_BINARY + "' >/dev/null 2>&1")
              .code == 0);
  const std::string chromium = "timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars ";
  // tests/data/gallery/check.html loads the page in a frame, checks it and writes its verdict;
  // the page's console messages (errors among them) go to stderr as "CONSOLE" lines.
  const std::string check =
      "file://" + rt::test::source_path("tests/data/gallery/check.html") + "?page=file://" + out + "/index.html";
  const rt::test::Run r =
      rt::test::run_shell(chromium + "--allow-file-access-from-files --enable-logging=stderr --v=0 --dump-dom '" +
                          check + "' 2>'" + out + "/console.txt'");
  INFO(r.output);
  if (r.output.find("gallery-check:") == std::string::npos) {
    // The browser did not run here at all (no display stack, a sandbox that refuses it): say so.
    WARN("chromium did not run (exit " << r.code << "): the browser test is skipped\n"
                                       << rt::test::read_file(out + "/console.txt").substr(0, 2000));
    return;
  }
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("gallery-check: ok images="));
  const std::string console = rt::test::read_file(out + "/console.txt");
  INFO(console);
  CHECK(console.find("CONSOLE") == std::string::npos);
  // Screenshots at a desktop's width and a phone's, for a person to look at.
  for (const auto& [name, size] :
       {std::pair<const char*, const char*>{"desktop", "1280,2400"}, {"phone", "390,2400"}}) {
    const std::string shot = out + "/screenshot-" + name + ".png";
    const rt::test::Run s = rt::test::run_shell(chromium + "--window-size=" + size + " --screenshot='" + shot +
                                                "' 'file://" + out + "/index.html' >/dev/null 2>&1");
    CHECK(s.code == 0);
    CHECK(fs::exists(shot));
    CHECK(fs::file_size(shot) > 10000);
  }
}
