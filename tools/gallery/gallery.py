#!/usr/bin/env python3
"""Renders every gallery section (tools/gallery/sections.py) with build/rtcli and writes a static,
self-contained site: index.html, style.css and the images under gallery/ (no external fonts,
scripts or CDNs). Each image's caption carries its render statistics from `rtcli render --stats`.

  gallery.py --out DIR [--fast] [--rtcli PATH]

--fast renders small images (and 4 frames of each animation) for the tests; the full mode makes
the published page in docs/.
"""
import argparse
import html
import json
import os
import shlex
import shutil
import struct
import subprocess
import time
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sections import SECTIONS  # noqa: E402
from tables import tables_html  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def load_scene(path):
    """A scene file as rtcli reads it: JSON that may hold // and /* */ comments (outside strings)."""
    with open(path) as f:
        text = f.read()
    out, i, in_string = [], 0, False
    while i < len(text):
        c = text[i]
        if in_string:
            out.append(text[i:i + 2] if c == "\\" else c)
            i += 2 if c == "\\" else 1
            in_string = c != '"'
        elif c == '"':
            out.append(c)
            in_string = True
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = len(text) if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = len(text) if end < 0 else end + 2
        else:
            out.append(c)
            i += 1
    return json.loads("".join(out))


def scene_size(scene):
    if not scene.endswith(".json"):  # a glTF model rendered on its own: rtcli's default size
        return 640, 480
    render = load_scene(os.path.join(ROOT, scene)).get("render", {})
    return render.get("width", 640), render.get("height", 480)


def render(rtcli, scene, options, out, stats, fast):
    args = [rtcli, "render", scene, "-q", "-o", out, "--stats", stats] + shlex.split(options)
    if fast:
        w, h = scene_size(scene)
        scale = 160.0 / w
        args += ["--width", "160", "--height", str(max(2, round(h * scale)))]
        if "--shadow-samples" not in args:
            args += ["--shadow-samples", "4"]
        if "--spp" not in args:  # the path tracer's samples (Whitted ignores them)
            args += ["--spp", "8"]
        if "--frames" in args:
            args[args.index("--frames") + 1] = "0-3"
    subprocess.run(args, check=True, cwd=ROOT)
    with open(stats) as f:
        return json.load(f)


def farm_render(rtcli, scene, options, out, stats, tasks, scratch, name):
    """An animation rendered as the cluster recipe does (docs/cluster.md): rtcli farm slurm on the
    Slurm cluster SLURM_CONF names, TASKS frame chunks and the dependent encode; waits for them and
    returns the tasks' figures joined, with each task's time in "farm"."""
    farm_dir = os.path.join(scratch, name + "-farm")
    args = [rtcli, "farm", "slurm", scene, "--tasks", str(tasks), "--cpus", "1", "-q", "--farm-dir", farm_dir,
            "-o", out] + shlex.split(options)
    started = time.time()
    submitted = subprocess.run(args, check=True, cwd=ROOT, capture_output=True, text=True).stdout
    jobs = ",".join(line.split()[-1] for line in submitted.splitlines() if line.split()[:1] in (["render"], ["finish"], ["submitted"]))
    while subprocess.run(["squeue", "-h", "-j", jobs], capture_output=True, text=True).stdout.strip():
        time.sleep(0.5)
    wall = time.time() - started
    if not os.path.exists(out):
        sys.exit("gallery: the farm render of %s did not finish; logs in %s" % (name, farm_dir))
    parts = []
    for i in range(tasks):
        with open(os.path.join(farm_dir, "logs", "task_%d.json" % i)) as f:
            parts.append(json.load(f))
    joined = dict(parts[0])
    joined["outputs"] = [out]
    joined["frames"] = [min(p["frames"][0] for p in parts), max(p["frames"][1] for p in parts)]
    joined["rays"] = {k: sum(p["rays"][k] for p in parts) for k in parts[0]["rays"]}
    joined["seconds"] = {k: sum(p["seconds"][k] for p in parts) for k in parts[0]["seconds"]}
    frames = joined["frames"][1] - joined["frames"][0] + 1
    joined["rays_per_pixel"] = joined["rays"]["total"] / (joined["width"] * joined["height"] * frames)
    joined["farm"] = {"tasks": tasks, "task_seconds": [round(p["seconds"]["render"] + p["seconds"]["load"], 2) for p in parts],
                      "task_frames": [p["frame_list"] for p in parts], "wall_seconds": round(wall, 1)}
    with open(stats, "w") as f:
        json.dump(joined, f, indent=2)
    return joined


def count(n):
    for unit, size in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if n >= size:
            return "%.1f %s" % (n / size, unit)
    return str(n)


def stats_line(s):
    rays = s["rays"]
    kinds = ", ".join("%s %s" % (count(rays[k]), k)
                      for k in ("camera", "shadow", "reflection", "refraction", "glossy", "bounce")
                      if rays.get(k, 0) > 0)
    frames = s["frames"][1] - s["frames"][0] + 1
    size = "%d×%d" % (s["width"], s["height"]) + (", %d frames" % frames if frames > 1 else "")
    line = "%s in %.2f s on %d threads · %s rays (%s) · %.1f rays a pixel" % (
        size, s["seconds"]["render"], s["threads"], count(rays["total"]), kinds, s["rays_per_pixel"])
    if "farm" in s:  # rendered through rtcli farm slurm: how, and each task's time
        f = s["farm"]
        line = "%s on a one-node Slurm cluster (tools/slurm/cluster.sh): rtcli farm slurm, %d tasks of frames %s, " \
               "each task %s s on 1 thread, %.1f s from submission to the GIF · %s rays (%s) · %.1f rays a pixel" % (
                   size, f["tasks"], ", ".join(f["task_frames"]), ", ".join("%.1f" % t for t in f["task_seconds"]),
                   f["wall_seconds"], count(rays["total"]), kinds, s["rays_per_pixel"])
    if "path" in s:  # path traced: its samples
        line += " · %.0f samples a pixel, %.2f M samples/s" % (s["path"]["mean_samples_per_pixel"],
                                                               s["path"]["msamples_per_second"])
    return line


def figure(name, image, full, alt, caption, stats, width):
    height = round(width * stats["height"] / stats["width"])
    if stats.get("stereo") in ("side_by_side", "top_bottom"):
        height *= 2 if stats["stereo"] == "top_bottom" else 1
    # Lazy: a visitor on a phone loads the images (and the GIFs' megabytes) as they scroll to them.
    return ('<figure id="fig-%s"><a href="%s"><img src="%s" alt="%s" width="%d" height="%d" loading="lazy"></a>'
            '<figcaption><strong>%s</strong><br><span class="stats">%s · <a href="gallery/%s.json">stats</a>'
            '</span></figcaption></figure>') % (
        name, full, image, html.escape(alt, quote=True), width, height, html.escape(caption),
        html.escape(stats_line(stats)), name)


def static_figure(file, images, alt, caption):
    """A figure of an image the docs hold (docs/images/FILE, a PNG), copied beside the renders and
    shown at its own size."""
    source = os.path.join(ROOT, "docs", "images", file)
    shutil.copy(source, os.path.join(images, file))
    with open(source, "rb") as f:
        width, height = struct.unpack(">II", f.read(24)[16:24])
    return ('<figure><a href="gallery/%s"><img src="gallery/%s" alt="%s" width="%d" height="%d" loading="lazy"></a>'
            '<figcaption><strong>%s</strong></figcaption></figure>') % (
        file, file, html.escape(alt, quote=True), width, height, html.escape(caption))


def publish(tools, rendered, images, name, photo, display_width, stats):
    """Puts the render from the scratch folder into gallery/: as JPEG when it is a photograph, with
    a thumbnail DISPLAY_WIDTH across when it is wider. Returns (shown file, full-size file)."""
    ext = ".jpg" if photo else ".png"
    full = name + ext
    if photo:
        subprocess.run([tools["thumbnail"], rendered, os.path.join(images, full)], check=True, stdout=subprocess.DEVNULL)
    else:
        shutil.copy(rendered, os.path.join(images, full))
    if stats["width"] <= display_width:
        return full, full
    small = name + "-small" + ext
    subprocess.run([tools["thumbnail"], rendered, os.path.join(images, small), str(display_width)], check=True,
                   stdout=subprocess.DEVNULL)
    return small, full


def section_html(section, figures, widths):
    scenes = [section["scene"]] if "scene" in section else []
    for scene in section.get("scenes", {}).values():
        if scene not in scenes:
            scenes.append(scene)
    out = ['<section id="%s">' % section["id"], "<h2>%s</h2>" % html.escape(section["title"]),
           "<p>%s</p>" % html.escape(section["what"]), '<p class="how">%s</p>' % html.escape(section["how"])]
    if scenes:
        out.append('<p class="scene">%s: %s</p>' % ("Scenes" if len(scenes) > 1 else "Scene",
                                                    ", ".join("<code>%s</code>" % html.escape(s) for s in scenes)))
    for path, heading, count in section.get("tables", []):
        out.append('<p class="scene">From <code>%s</code>, "%s":</p>' % (html.escape(path), html.escape(heading.lstrip("#").strip())))
        out.append(tables_html(ROOT, path, heading, count))
    compare = section.get("compare")
    rest = [f for name, f in figures.items() if not compare or name not in compare]
    grid = ['<div class="grid">%s</div>' % "".join(rest)] if rest else []
    if compare:
        # The slider is as wide as its images, so the cut falls where the handle is.
        slider = '<div class="compare" data-compare style="--width: %dpx">%s%s</div>' % (
            widths[compare[0]], figures[compare[0]], figures[compare[1]])
        # First when it compares the section's first render; after the other renders otherwise.
        grid = [slider] + grid if compare[0] == section["renders"][0][0] else grid + [slider]
    out += grid
    out.append("</section>")
    return "\n".join(out)


SLIDER_JS = """
// Before/after sliders: the second image over the first, cut at the handle. Without JavaScript
// the two figures stay side by side.
document.querySelectorAll('[data-compare]').forEach(function (box) {
  var figures = box.querySelectorAll('figure');
  if (figures.length !== 2) return;
  box.classList.add('slider');
  var range = document.createElement('input');
  range.type = 'range'; range.min = 0; range.max = 100; range.value = 50;
  range.setAttribute('aria-label', 'Move to compare the two images');
  var set = function () { figures[1].style.clipPath = 'inset(0 0 0 ' + range.value + '%)'; };
  range.addEventListener('input', set);
  box.appendChild(range);
  // The two captions under the slider, left and right, instead of over each other.
  var captions = document.createElement('div');
  captions.className = 'slider-captions';
  figures.forEach(function (f) { var c = f.querySelector('figcaption'); if (c) captions.appendChild(c); });
  box.appendChild(captions);
  set();
});
"""


def write_site(out_dir, body_sections, nav):
    page = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>rtcli: a ray tracer driven by data</title>
<link rel="stylesheet" href="style.css">
</head>
<body>
<header>
<h1>rtcli</h1>
<p>A ray tracer driven by data: scenes are JSON and glTF files, never code. Each objective of the
proposal, how it is done, its test scene, and the comparisons it asks for; every image with what
it cost to render.</p>
<nav>%s</nav>
</header>
<main>
%s
</main>
<footer><p>Generated by <code>tools/gallery.sh</code> from the scenes in <code>scenes/</code>.</p></footer>
<script>%s</script>
</body>
</html>
""" % (nav, "\n".join(body_sections), SLIDER_JS)
    with open(os.path.join(out_dir, "index.html"), "w") as f:
        f.write(page)
    shutil.copy(os.path.join(os.path.dirname(os.path.abspath(__file__)), "style.css"), os.path.join(out_dir, "style.css"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="the folder to write the site into")
    parser.add_argument("--fast", action="store_true", help="small images and 4 frames: for tests")
    parser.add_argument("--rtcli", default=os.path.join(ROOT, "build", "rtcli"))
    parser.add_argument("--farm", action="store_true",
                        help="render the sections that say farm_tasks through rtcli farm slurm (SLURM_CONF's cluster)")
    args = parser.parse_args()
    images = os.path.join(args.out, "gallery")
    shutil.rmtree(images, ignore_errors=True)  # what the sections no longer render goes too
    os.makedirs(images)
    body, nav = [], []
    # The thumbnail tool is built beside rtcli (tools/CMakeLists.txt).
    tools = {"thumbnail": os.path.join(os.path.dirname(os.path.abspath(args.rtcli)), "thumbnail")}
    display_width = 120 if args.fast else 800
    with tempfile.TemporaryDirectory() as scratch:
        for section in SECTIONS:
            figures, widths = {}, {}
            for name, options, alt, caption in section.get("renders", []):
                scene = section.get("scenes", {}).get(name, section["scene"])
                stats_file = os.path.join(images, name + ".json")
                if "--frames" in options:  # an animation: the GIF as it is, shown full size
                    file = name + ".gif"
                    if args.farm and section.get("farm_tasks") and not args.fast:
                        stats = farm_render(args.rtcli, scene, options, os.path.join(images, file), stats_file,
                                            section["farm_tasks"], scratch, name)
                    else:
                        stats = render(args.rtcli, scene, options, os.path.join(images, file), stats_file, args.fast)
                    widths[name] = stats["width"]
                    figures[name] = figure(name, "gallery/" + file, "gallery/" + file, alt, caption, stats,
                                           widths[name])
                else:
                    rendered = os.path.join(scratch, name + ".png")
                    stats = render(args.rtcli, scene, options, rendered, stats_file, args.fast)
                    if "--aa-debug" in options:  # show the refined pixels
                        rendered = os.path.join(scratch, name + ".aa-refined.png")
                    # The published page keeps photographs as JPEG (docs/ stays small); the
                    # anti-aliasing debug image and fast renders stay PNG.
                    photo = not args.fast and "--aa-debug" not in options and stats["width"] >= 640
                    shown, file = publish(tools, rendered, images, name, photo, display_width, stats)
                    widths[name] = min(stats["width"], display_width)
                    if name in section.get("compare", ()) and 2 * stats["width"] <= display_width:
                        widths[name] = 2 * stats["width"]  # small renders compared: shown at 2x, pixels sharp
                    figures[name] = figure(name, "gallery/" + shown, "gallery/" + file, alt, caption, stats,
                                           widths[name])
                # The statistics as published: the file they describe, no paths of this machine.
                stats["outputs"] = [file]
                with open(stats_file, "w") as f:
                    json.dump(stats, f, indent=2)
                    f.write("\n")
                print("rendered %s: %s" % (file, stats_line(stats)))
            for file, alt, caption in section.get("images", []):
                figures[file] = static_figure(file, images, alt, caption)
            body.append(section_html(section, figures, widths))
            nav.append('<a href="#%s">%s</a>' % (section["id"], html.escape(section["title"])))
    write_site(args.out, body, " ".join(nav))
    print("wrote %s" % os.path.join(args.out, "index.html"))


if __name__ == "__main__":
    main()
