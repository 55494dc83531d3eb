#!/usr/bin/env python3
"""Path-traced samples per second, rtcli against Cycles (Debian's Blender 3.4, CPU), on the same
scenes at the same size, samples and bounces, denoising off, both on the same threads.

  python3 tools/cycles/speed.py [--size 160] [--samples 64,256] [--runs 3] [--threads 2]
      [--rtcli build/rtcli] [--fixture-light NAME] [--fixture-bumps off] [NAME or SCENE.json...]

NAME: cornell (scenes/cornell_box.json), environment (scenes/environment.json) or fixture (the
Blender fixture, tests/data/blender/make_fixture.py, built and exported in Blender, rtcli rendering
the export); all three by default. A scene file of another name goes through tools/cycles/twin.py,
which refuses what it cannot twin. Each renderer renders each scene at two sample counts, N1 and
N2, alternately, `runs` times. A render's time is scene sync + N x (time of one sample over the
image): the rate comes from the difference, pixels x (N2 - N1) / (T(N2) - T(N1)), and the sync is
what is left of T(N1); so Blender's start-up, rtcli's scene loading and each one's fixed set-up
count in neither rate. To see where the fixture's time goes, --fixture-light keeps one of its
lights (Softbox, Sun or Lamp; tools/cycles/fixture.py switches the others off and exports again)
and --fixture-bumps off renders its floor without the bump map in both (Cycles' Bump node
unlinked, rtcli's --no-bumps). Times are each renderer's own: Cycles' render call (tools/cycles/twin.py,
fixture.py), rtcli's --stats (render; load apart). Prints one Markdown table row per scene
(docs/benchmark.md, "Against Cycles: samples per second"). Blender's glTF exporter (the fixture) needs
Debian's python3-numpy: run this with Debian's python3, not one that pyenv or a venv puts first on
PATH, where Blender then looks for its modules.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENES = {"cornell": "scenes/cornell_box.json", "environment": "scenes/environment.json", "fixture": None}


def run(args, **kw):
    r = subprocess.run(args, capture_output=True, text=True, cwd=ROOT, **kw)
    if r.returncode != 0:
        sys.exit("speed.py: %s failed:\n%s" % (" ".join(args[:3]), (r.stdout + r.stderr)[-3000:]))
    return r.stdout + r.stderr


def cycles_seconds(log):
    return float(re.search(r"cycles: rendered .* in ([0-9.]+) s", log).group(1))


def cycles(name, out, size, spp, threads, variant=("all", "-")):
    scene = SCENES.get(name, name)
    if name == "fixture":
        return cycles_seconds(run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                                   os.path.join(ROOT, "tests/data/blender/make_fixture.py"), "--python",
                                   os.path.join(ROOT, "tools/cycles/fixture.py"), "--",
                                   out, str(spp), str(size), str(size), *variant]))
    return cycles_seconds(run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "-P",
                               os.path.join(ROOT, "tools/cycles/twin.py"), "--", os.path.join(ROOT, scene), out, "--samples", str(spp), "--width",
                               str(size), "--height", str(size), "--threads", str(threads)]))


def rtcli(binary, scene, out, size, spp, threads, extra):
    stats = out + ".json"
    run([binary, "render", scene, "-q", "-o", out, "--width", str(size), "--height",
         str(size), "--spp", str(spp), "--threads", str(threads), "--integrator", "path", "--stats", stats, *extra])
    with open(stats) as f:
        seconds = json.load(f)["seconds"]
    return seconds["render"], seconds["load"]


def rate(pixels, n1, n2, t1, t2):
    """Samples per second over the image, and the fixed part (sync) of a render, from two counts."""
    per_sample = (t2 - t1) / (n2 - n1)
    if not per_sample > 0:
        # Tiny renders on a busy machine: the time that samples add is lost in the noise.
        sys.exit("speed.py: %d samples took %.4f s and %d took %.4f s: no time per sample to measure; "
                 "use more samples (--samples) or a larger image (--size)" % (n1, t1, n2, t2))
    return pixels / per_sample, t1 - n1 * per_sample


def span(values, fmt):
    return (fmt + " (" + fmt + "–" + fmt + ")") % (statistics.median(values), min(values), max(values))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("names", nargs="*", default=list(SCENES))
    p.add_argument("--size", type=int, default=160)
    p.add_argument("--samples", default="64,256", help="N1,N2")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--rtcli", default=os.path.join(ROOT, "build", "rtcli"))
    p.add_argument("--fixture-light", choices=["Softbox", "Sun", "Lamp"], help="the fixture with this light alone")
    p.add_argument("--fixture-bumps", choices=["on", "off"], default="on", help="off: its floor without the bump map")
    a = p.parse_args()
    variant = (a.fixture_light or "all", "no-bump" if a.fixture_bumps == "off" else "-")
    n1, n2 = (int(x) for x in a.samples.split(","))
    if not 0 < n1 < n2:
        sys.exit("speed.py: --samples wants N1,N2 with 0 < N1 < N2")
    if shutil.which("blender") is None:
        sys.exit("speed.py: error: blender is not installed (Debian: apt-get install blender python3-numpy)")
    pixels = a.size * a.size
    print("| scene | rtcli samples/s | Cycles samples/s | ratio | rtcli load | rtcli fixed | Cycles sync |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.names:
            if name not in SCENES:
                name = os.path.abspath(name)  # from here on, also keeps a leading '-' from reading as an option
            if name not in SCENES and not os.path.isfile(name):
                sys.exit("speed.py: %r is neither a scene file nor cornell, environment or fixture" % name)
            glb = os.path.join(tmp, "fixture.glb")
            extra = ["--max-depth", "10"] if name == "fixture" else []
            if name == "fixture" and a.fixture_bumps == "off":
                extra.append("--no-bumps")
            ours, theirs, ratios, loads, fixed, syncs = [], [], [], [], [], []
            for _ in range(a.runs):
                c1 = cycles(name, glb if name == "fixture" else os.path.join(tmp, "c1.png"), a.size, n1, a.threads, variant)
                c2 = cycles(name, glb if name == "fixture" else os.path.join(tmp, "c2.png"), a.size, n2, a.threads, variant)
                scene = glb if name == "fixture" else os.path.abspath(os.path.join(ROOT, SCENES.get(name, name)))
                (r1, load), (r2, _) = (rtcli(a.rtcli, scene, os.path.join(tmp, "r%d.png" % n), a.size, n, a.threads,
                                             extra) for n in (n1, n2))
                rt_rate, rt_fixed = rate(pixels, n1, n2, r1, r2)
                cy_rate, cy_sync = rate(pixels, n1, n2, c1, c2)
                ours.append(rt_rate)
                theirs.append(cy_rate)
                ratios.append(rt_rate / cy_rate)
                loads.append(load)
                fixed.append(rt_fixed)
                syncs.append(cy_sync)
            label = name
            if name == "fixture":
                parts = ([a.fixture_light + " alone"] if a.fixture_light else []) + \
                        (["no bump map"] if a.fixture_bumps == "off" else [])
                if parts:
                    label += " (%s)" % ", ".join(parts)
            print("| %s | %s | %s | %s× | %s s | %s s | %s s |" % (
                label, span([x / 1e6 for x in ours], "%.2fM"), span([x / 1e6 for x in theirs], "%.2fM"),
                span(ratios, "%.2f"), span(loads, "%.3f"), span(fixed, "%.3f"), span(syncs, "%.2f")))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
