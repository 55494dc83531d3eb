// `rtcli watch` as a user meets it: started on a scene of their own, its page loaded in headless
// Chromium, the scene edited (saved by rename, as editors do), broken, fixed; bad requests sent
// to the server; Ctrl-C. The server is asked over HTTP with cpp-httplib's client.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include <httplib.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/watch/orbit.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"
#include "tests/support/watch_process.h"

namespace fs = std::filesystem;
using Json = nlohmann::json;
using rt::test::WatchProcess;

namespace {

// A red sphere on a grey floor; `color` replaces the sphere's colour, `extra` goes into the
// scene's render block.
std::string watch_scene(const std::string& color, const std::string& render = "\"integrator\": \"whitted\"") {
  return R"({
  // the watch test's scene
  "render": {"width": 160, "height": 120, )" +
         render + R"(},
  "camera": {"position": [0, 1, 5], "look_at": [0, 0.6, 0], "fov": 40},
  "background": [0.1, 0.1, 0.15],
  "materials": {"ball": {"kd": )" +
         color + R"(}, "floor": {"kd": 0.6}},
  "lights": [{"type": "point", "position": [3, 4, 3], "intensity": 1}],
  "nodes": [
    {"shape": "sphere", "material": "ball", "transform": {"translate": [0, 0.8, 0], "scale": 0.8}},
    {"shape": "plane", "material": "floor", "transform": {"scale": 5}}
  ]
}
)";
}

// Saves as editors that write a new file and rename it over the old one do.
void save_by_rename(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp~";
  std::ofstream(tmp) << text;
  fs::rename(tmp, path);
}

bool finished(const Json& s, uint64_t scene_version) {
  return !s["image"].is_null() && s["image"]["last"] == true && s["image"]["scene_version"] == scene_version;
}

// Chromium's DOM of the page after it has polled a while; empty when Chromium cannot run here.
std::string page_dom(const WatchProcess& w, const std::string& screenshot = "") {
  if (rt::test::run_shell("command -v chromium >/dev/null").code != 0) return "";
  const std::string chromium =
      "timeout 60 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=3000 ";
  if (!screenshot.empty())
    rt::test::run_shell(chromium + "--window-size=900,560 --screenshot='" + screenshot + "' '" + w.url() +
                        "' >/dev/null 2>&1");
  // The page's console messages (errors among them) go to stderr as "CONSOLE" lines: none allowed.
  const std::string console = rt::test::output_path("watch-console.txt");
  std::string dom =
      rt::test::run_shell(chromium + "--enable-logging=stderr --v=0 --dump-dom '" + w.url() + "' 2>'" + console + "'")
          .output;
  const std::string logged = rt::test::read_file(console);
  INFO(logged);
  if (!dom.empty()) CHECK(logged.find("CONSOLE") == std::string::npos);
  return dom;
}

}  // namespace

TEST_CASE(
    "cli: watch shows the render refining, follows edits saved by rename, shows errors located, and stops on "
    "Ctrl-C",
    "[cli][watch]") {
  const std::string folder = rt::test::fresh_folder("watch");
  const std::string scene = folder + "/ball.json";
  std::ofstream(scene) << watch_scene("[0.8, 0.1, 0.1]");
  WatchProcess w(scene, folder);

  // A first, coarse picture, then refinements until the scene's own settings.
  Json s = w.wait_for([](const Json& j) { return finished(j, 1); }, "the first render to finish");
  CHECK(s["image_version"].get<int>() >= 3);  // coarse, draft, final
  CHECK(s["image"]["width"] == 160);
  CHECK(s["image"]["film_width"] == 160);
  CHECK(s["first_image_seconds"].get<double>() >= 0.0);
  CHECK(s["load_failed"] == false);
  auto c = w.centre(folder);
  CHECK(c[0] > 2 * c[2]);  // red

  const std::string dom = page_dom(w, folder + "/watch-1-first.png");
  if (dom.empty()) {
    WARN("chromium is not installed or did not run: the page is checked over HTTP only");
  } else {
    INFO(dom);
    CHECK_THAT(dom, Catch::Contains("data-loaded-version=\""));
    CHECK_THAT(dom, Catch::Contains("id=\"samples\" data-samples=\""));
    CHECK_THAT(dom, Catch::Contains(">done<"));
  }

  // An edit, saved by rename: the new picture.
  save_by_rename(scene, watch_scene("[0.1, 0.1, 0.8]"));
  s = w.wait_for([](const Json& j) { return finished(j, 2); }, "the edited scene's render");
  CHECK_THAT(s["reload"].get<std::string>(), Catch::Contains("ball.json changed"));
  c = w.centre(folder);
  CHECK(c[2] > 2 * c[0]);  // blue

  // A mistake: the error, located, and the last good picture stays.
  save_by_rename(scene, watch_scene("[0.1, 0.1, \"blue\"]"));
  s = w.wait_for([](const Json& j) { return j["load_failed"] == true; }, "the error to show");
  REQUIRE(!s["problems"].empty());
  const std::string problem = s["problems"][0]["text"];
  CHECK_THAT(problem, Catch::Contains("ball.json:6:43: error: /materials/ball/kd/2"));
  CHECK_THAT(problem, Catch::Contains("^"));  // the excerpt with its caret
  CHECK(s["image"]["scene_version"] == 2);
  c = w.centre(folder);
  CHECK(c[2] > 2 * c[0]);                                            // still the blue one
  CHECK_THAT(w.output(), Catch::Contains("ball.json:6:43: error"));  // the terminal says it too
  const std::string error_dom = page_dom(w, folder + "/watch-3-error.png");
  if (!error_dom.empty()) {
    INFO(error_dom);
    CHECK_THAT(error_dom, Catch::Contains("ball.json:6:43: error: /materials/ball/kd/2"));
    CHECK_THAT(error_dom, Catch::Contains("data-loaded-version=\""));
  }

  // Fixed: the render again, no problems.
  save_by_rename(scene, watch_scene("[0.9, 0.8, 0.1]"));
  s = w.wait_for([](const Json& j) { return finished(j, 3); }, "the fixed scene's render");
  CHECK(s["load_failed"] == false);
  CHECK(s["problems"].empty());
  c = w.centre(folder);
  CHECK(c[1] > 2 * c[2]);  // yellow

  CHECK(w.interrupt(5.0) == 0);
  CHECK_THAT(w.output(), Catch::Contains("rtcli watch: stopped"));
}

TEST_CASE("cli: watch refines a path-traced scene in passes and shows its layers", "[cli][watch]") {
  const std::string folder = rt::test::fresh_folder("watch-path");
  const std::string scene = folder + "/ball.json";
  std::ofstream(scene) << watch_scene("[0.8, 0.1, 0.1]", "\"integrator\": \"path\", \"samples_per_pixel\": 24");
  WatchProcess w(scene, folder);
  const Json s = w.wait_for([](const Json& j) { return finished(j, 1); }, "the path tracer's passes");
  CHECK(s["image"]["samples"] == 24);
  CHECK(s["image"]["target_samples"] == 24);
  CHECK(s["image_version"].get<int>() >= 5);  // coarse, draft, three passes (8, 16, 24), the end
  auto c = w.client();
  for (const char* layer : {"color", "albedo", "normal", "depth", "refinement"}) {
    const auto r = c.Get((std::string("/image.png?layer=") + layer + "&exposure=1.5&tone=filmic").c_str());
    REQUIRE(r);
    CHECK(r->status == 200);
    CHECK(r->get_header_value("Content-Type") == "image/png");
  }
  const auto exr = c.Get("/save.exr");
  REQUIRE(exr);
  CHECK(exr->status == 200);
  CHECK(exr->body.compare(0, 4, "\x76\x2f\x31\x01") == 0);  // OpenEXR's magic number
  CHECK_THAT(exr->get_header_value("Content-Disposition"), Catch::Contains("ball-24spp.exr"));
  CHECK(w.interrupt(5.0) == 0);
}

TEST_CASE("cli: watch answers bad requests with errors and keeps rendering", "[cli][watch][hostile]") {
  const std::string folder = rt::test::fresh_folder("watch-hostile");
  const std::string scene = folder + "/ball.json";
  std::ofstream(scene) << watch_scene("[0.8, 0.1, 0.1]");
  WatchProcess w(scene, folder);
  w.wait_for([](const Json& j) { return finished(j, 1); }, "the first render");
  auto c = w.client();
  const auto status_of = [&](const httplib::Result& r) { return r ? r->status : -1; };
  CHECK(status_of(c.Get("/../../../etc/passwd")) == 404);
  CHECK(status_of(c.Get("/ball.json")) == 404);  // nothing from disk, not even the scene
  const auto unknown = c.Get("/nothing");
  REQUIRE(unknown);
  CHECK(unknown->body == "not found: /nothing (the page is at /)\n");
  CHECK(status_of(c.Delete("/status")) == 404);  // another method
  CHECK(status_of(c.Get("/frame")) == 404);      // a POST route asked with GET
  CHECK(status_of(c.Post("/status", "", "text/plain")) == 404);
  CHECK(status_of(c.Head("/")) == 200);
  CHECK(status_of(c.Get("/image.png?layer=secret")) == 400);
  CHECK(status_of(c.Get("/image.png?exposure=nan")) == 400);
  CHECK(status_of(c.Get("/image.png?tone=%00")) == 400);
  CHECK(status_of(c.Post("/frame?n=99999", "", "text/plain")) == 400);
  CHECK(status_of(c.Post("/frame?n=0.5", "", "text/plain")) == 400);
  CHECK(status_of(c.Post("/frame", std::string(100000, 'x'), "text/plain")) == 413);
  CHECK(status_of(c.Get("/status", {{"Host", "attacker.example:" + std::to_string(w.port())}})) == 403);
  CHECK(status_of(c.Get(("/" + std::string(20000, 'a')).c_str())) != 200);
  // Many clients at once: every one answered.
  std::atomic<int> answered{0};
  std::vector<std::thread> clients;
  for (int i = 0; i < 24; ++i)
    clients.emplace_back([&] {
      auto mine = w.client();
      if (const auto r = mine.Get("/status"); r && r->status == 200) ++answered;
    });
  for (std::thread& t : clients) t.join();
  CHECK(answered == 24);
  // And the render goes on: an edit still shows.
  save_by_rename(scene, watch_scene("[0.1, 0.1, 0.8]"));
  w.wait_for([](const Json& j) { return finished(j, 2); }, "the edited scene's render");
  CHECK(w.interrupt(5.0) == 0);
}

TEST_CASE("cli: watch refuses what it cannot serve", "[cli][watch]") {
  const rt::test::Run r = rt::test::rtcli_bounded("watch scenes/default.json --port 70000");
  CHECK(r.code == 2);
  const rt::test::Run bad = rt::test::rtcli_bounded("watch scenes/default.json --bind 203.0.113.1 --port 0");
  CHECK(bad.code == 1);
  CHECK_THAT(bad.output, Catch::Contains("could not listen on 203.0.113.1"));
}

TEST_CASE("cli: watch follows the files a scene includes and its textures", "[cli][watch][include]") {
  const std::string folder = rt::test::fresh_folder("watch-include");
  std::filesystem::copy_file(rt::test::source_path("scenes/textures/checker.png"), folder + "/paint.png");
  std::ofstream(folder + "/paint.json") << R"({"materials": {"floor": {"kd": 0.6}, "ball": {"kd": [0.8, 0.1, 0.1]}}})";
  const std::string scene = folder + "/ball.json";
  std::ofstream(scene) << R"({
  "include": ["paint.json"],
  "render": {"width": 160, "height": 120},
  "camera": {"position": [0, 1, 5], "look_at": [0, 0.6, 0], "fov": 40},
  "materials": {"floor": {"texture": "paint.png"}},
  "lights": [{"type": "point", "position": [3, 4, 3], "intensity": 1}],
  "nodes": [
    {"shape": "sphere", "material": "ball", "transform": {"translate": [0, 0.8, 0], "scale": 0.8}},
    {"shape": "plane", "material": "floor", "transform": {"scale": 5}}
  ]
})";
  WatchProcess w(scene, folder);
  w.wait_for([](const Json& j) { return finished(j, 1); }, "the first render");
  auto c = w.centre(folder);
  CHECK(c[0] > 2 * c[2]);  // red, from the included file
  save_by_rename(folder + "/paint.json", R"({"materials": {"floor": {"kd": 0.6}, "ball": {"kd": [0.1, 0.1, 0.8]}}})");
  Json s = w.wait_for([](const Json& j) { return finished(j, 2); }, "the included file's change");
  CHECK_THAT(s["reload"].get<std::string>(), Catch::Contains("paint.json changed"));
  CHECK_THAT(s["reload"].get<std::string>(), Catch::Contains("1 file kept, 0 read"));  // the texture
  c = w.centre(folder);
  CHECK(c[2] > 2 * c[0]);  // blue
  // The texture replaced: read again, the rest kept.
  std::filesystem::copy_file(rt::test::source_path("scenes/textures/uv_grid.png"), folder + "/paint.new.png");
  std::filesystem::rename(folder + "/paint.new.png", folder + "/paint.png");
  s = w.wait_for([](const Json& j) { return finished(j, 3); }, "the texture's change");
  CHECK_THAT(s["reload"].get<std::string>(), Catch::Contains("paint.png changed; loaded in"));
  CHECK_THAT(s["reload"].get<std::string>(), Catch::Contains("0 files kept, 1 read"));
  CHECK(w.interrupt(5.0) == 0);
}

TEST_CASE("cli: watch moves an animated scene to the frame the page asks for", "[cli][watch]") {
  const std::string folder = rt::test::fresh_folder("watch-frames");
  const std::string scene = folder + "/ball.json";
  std::string text = watch_scene("[0.8, 0.1, 0.1]");
  text.replace(text.rfind('}'), 1,
               R"(, "animation": {"fps": 10, "tracks": [{"node": "ball", "property": "translate",
    "keys": [{"frame": 0, "value": [0, 0.8, 0]}, {"frame": 20, "value": [1, 0.8, 0]}]}]}})");
  text.replace(text.find("{\"shape\": \"sphere\""), 1, "{\"name\": \"ball\", ");
  std::ofstream(scene) << text;
  WatchProcess w(scene, folder);
  Json s = w.wait_for([](const Json& j) { return finished(j, 1); }, "the first frame");
  CHECK(s["animated"] == true);
  CHECK(s["first_frame"] == 0);
  CHECK(s["last_frame"] == 20);
  CHECK(s["image"]["frame"] == 0);
  auto c = w.client();
  const auto moved = c.Post("/frame?n=20", "", "text/plain");
  REQUIRE(moved);
  CHECK(moved->status == 204);
  s = w.wait_for([](const Json& j) { return j["image"]["frame"] == 20 && j["image"]["last"] == true; }, "frame 20");
  const auto beyond = c.Post("/frame?n=21", "", "text/plain");
  REQUIRE(beyond);
  CHECK(beyond->status == 400);
  // An edit keeps the frame shown.
  save_by_rename(scene, text.replace(text.find("[0.8, 0.1, 0.1]"), 15, "[0.1, 0.1, 0.8]"));
  s = w.wait_for([](const Json& j) { return finished(j, 2); }, "the edit");
  CHECK(s["image"]["frame"] == 20);
  CHECK(w.interrupt(5.0) == 0);
}

TEST_CASE("cli: watch orbits the preview's camera without touching the file", "[cli][watch]") {
  const std::string folder = rt::test::fresh_folder("watch-orbit");
  const std::string scene = folder + "/ball.json";
  const std::string text = watch_scene("[0.8, 0.1, 0.1]");
  std::ofstream(scene) << text;
  WatchProcess w(scene, folder);
  w.wait_for([](const Json& j) { return finished(j, 1); }, "the first render");
  auto c = w.client();
  const auto turned = c.Post("/view?yaw=180&pitch=0", "", "text/plain");
  REQUIRE(turned);
  CHECK(turned->status == 204);
  Json s = w.wait_for([](const Json& j) { return j["image"]["yaw"] == 180.0 && j["image"]["last"] == true; },
                      "the orbited render");
  // From behind, the ball still sits in the middle (the orbit turns about the point looked at),
  // its unlit side towards us: dark, not the blue-grey background.
  auto centre = w.centre(folder);
  CHECK(centre[0] + centre[1] + centre[2] < 60);
  CHECK(rt::test::read_file(scene) == text);
  const auto bad = c.Post("/view?yaw=0&pitch=95", "", "text/plain");
  REQUIRE(bad);
  CHECK(bad->status == 400);
  // Reset: the file's camera again.
  REQUIRE(c.Post("/view?yaw=0&pitch=0", "", "text/plain"));
  s = w.wait_for([](const Json& j) { return j["image"]["yaw"] == 0.0 && j["image"]["last"] == true; }, "the reset");
  CHECK(w.interrupt(5.0) == 0);
}

TEST_CASE("watch: the orbit turns the camera about the point it looks at, keeping its distance", "[watch][camera]") {
  rt::Camera cam = rt::Camera::look_at(rt::Vec3(0, 1, 5), rt::Vec3(0, 1, 0), rt::Vec3(0, 1, 0), 40.0f);
  cam.focus_distance = 5.0f;
  const rt::Camera same = rt::orbit(cam, 0.0f, 0.0f);
  CHECK(same.position == cam.position);
  const rt::Camera behind = rt::orbit(cam, 180.0f, 0.0f);
  CHECK(behind.position.x == Approx(0.0f).margin(1e-5));
  CHECK(behind.position.y == Approx(1.0f).margin(1e-5));
  CHECK(behind.position.z == Approx(-5.0f).margin(1e-5));
  CHECK(behind.forward.z == Approx(1.0f).margin(1e-5));  // still looking at (0, 1, 0)
  const rt::Camera above = rt::orbit(cam, 0.0f, 60.0f);
  CHECK(glm::length(above.position - rt::Vec3(0, 1, 0)) == Approx(5.0f));
  CHECK(above.position.y == Approx(1.0f + 5.0f * std::sin(rt::radians(60.0f))).margin(1e-4));  // raised
  CHECK(glm::dot(above.forward, glm::normalize(rt::Vec3(0, 1, 0) - above.position)) == Approx(1.0f));
  CHECK(above.vertical_fov_degrees == cam.vertical_fov_degrees);
}
