#!/usr/bin/env python3
"""rtcli against POV-Ray 3.7 (Debian's povray) on like-for-like scenes: each scene's twin written
by twin.py, both renderers run alternately on the same size and thread count, the whole process
timed (wall) and each renderer's own render time (rtcli's --stats, POV-Ray's "Trace Time"), the
median of N runs with min-max, and how far the two images are apart (build/imagediff).

  compare.py [--width 1920] [--height 1440] [--threads 2] [--runs 3] [--without-transmissive] SCENE.json...

Prints one Markdown table row per scene (docs/benchmark.md, "Against POV-Ray"). To see where a
scene's time goes, --without-transmissive compares it without its glass: the nodes whose material
(one of the scene file's own "materials") has a transmission above 0 are left out, children and
all, from a copy written beside the scene (so that its relative paths still resolve) and removed
afterwards. A scene with no such node is refused before anything is rendered.
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
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def timed(args, **kw):
    start = time.monotonic()
    r = subprocess.run(args, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit("compare.py: %s failed:\n%s" % (args[0], r.stdout + r.stderr))
    return time.monotonic() - start, r.stdout + r.stderr


def transmissive(material):
    t = material.get("transmission", 0) if isinstance(material, dict) else 0
    return any(x > 0 for x in (t if isinstance(t, list) else [t]) if isinstance(x, (int, float)))


def without_transmissive(scene):
    """The scene file's description without its transmissive nodes, and how many it left out."""
    try:
        with open(scene) as f:
            description = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit("compare.py: error: %s: %s" % (scene, e))
    materials = description.get("materials") if isinstance(description, dict) else None
    glass = {name for name, m in materials.items() if transmissive(m)} if isinstance(materials, dict) else set()
    dropped = 0

    def kept(nodes):
        nonlocal dropped
        out = []
        for node in nodes:
            if isinstance(node, dict) and isinstance(node.get("material"), str) and node["material"] in glass:
                dropped += 1
                continue
            if isinstance(node, dict) and isinstance(node.get("children"), list):
                node = dict(node, children=kept(node["children"]))
            out.append(node)
        return out

    if glass and isinstance(description.get("nodes"), list):
        description["nodes"] = kept(description["nodes"])
    return description, dropped


def span(values, unit="s"):
    return "%.2f %s (%.2f–%.2f)" % (statistics.median(values), unit, min(values), max(values))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scenes", nargs="+")
    p.add_argument("--width", type=int, default=1920)
    p.add_argument("--height", type=int, default=1440)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--rtcli", default=os.path.join(ROOT, "build", "rtcli"))
    p.add_argument("--without-transmissive", action="store_true",
                   help="compare each scene without its transmissive nodes (see above)")
    a = p.parse_args()
    if shutil.which("povray") is None:
        sys.exit("compare.py: error: povray is not installed (Debian: apt-get install povray)")
    # (the scene's name, the file rendered, the row's label); also keeps a name starting with '-'
    # from reading as an option
    scenes = [(name_of(s), os.path.abspath(s), name_of(s)) for s in a.scenes]
    copies = []  # the scenes written without their glass, removed whatever happens
    try:
        if a.without_transmissive:
            scenes = [without_glass_copy(name, scene, copies) for name, scene, _ in scenes]
        compare(a, scenes)
    finally:
        for path in copies:
            os.remove(path)


def name_of(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def without_glass_copy(name, scene, copies):
    """The scene without its glass, written beside it (its relative paths still resolve)."""
    description, dropped = without_transmissive(scene)
    if dropped == 0:
        sys.exit("compare.py: error: %s has no node of a transmissive material to leave out" % scene)
    try:
        fd, copy = tempfile.mkstemp(prefix=".%s-without-transmissive-" % name, suffix=".json",
                                    dir=os.path.dirname(scene))
    except OSError as e:
        sys.exit("compare.py: error: a copy of %s without its glass goes beside it: %s" % (scene, e))
    copies.append(copy)
    with os.fdopen(fd, "w") as f:
        json.dump(description, f)
    return name, copy, "%s (without its %d transmissive node%s)" % (name, dropped, "" if dropped == 1 else "s")


def compare(a, scenes):
    print("| scene | rtcli wall | POV-Ray wall | ratio | rtcli render | POV-Ray trace | ratio | RMS apart |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, label in scenes:
            pov = os.path.join(tmp, name + ".pov")
            twin = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "povray", "twin.py"), scene, pov,
                                   "--width", str(a.width), "--height", str(a.height)], capture_output=True, text=True)
            if twin.returncode != 0:
                sys.exit("compare.py: twin.py failed on %s:\n%s" % (label, twin.stdout + twin.stderr))
            command = twin.stdout.split()
            command = [c.replace("+WT2", "+WT%d" % a.threads) for c in command]
            ours = [a.rtcli, "render", scene, "-q", "-o", os.path.join(tmp, name + "-rtcli.png"), "--width",
                    str(a.width), "--height", str(a.height), "--threads", str(a.threads), "--stats",
                    os.path.join(tmp, name + ".json")]
            walls = {"rtcli": [], "pov": []}
            renders = {"rtcli": [], "pov": []}
            for _ in range(a.runs):
                wall, _ = timed(ours)
                walls["rtcli"].append(wall)
                with open(os.path.join(tmp, name + ".json")) as f:
                    renders["rtcli"].append(json.load(f)["seconds"]["render"])
                wall, log = timed(command, cwd=tmp)
                walls["pov"].append(wall)
                trace = re.search(r"Trace Time:.*\(([\d.]+) seconds\)", log)
                renders["pov"].append(float(trace.group(1)) if trace else float("nan"))
            diff = subprocess.run([os.path.join(os.path.dirname(a.rtcli), "imagediff"),
                                   os.path.join(tmp, name + "-rtcli.png"), pov[:-4] + ".png"],
                                  capture_output=True, text=True).stdout.split(" levels")[0]
            print("| %s | %s | %s | %.2f× | %s | %s | %.2f× | %s |" % (
                label, span(walls["rtcli"]), span(walls["pov"]),
                statistics.median(walls["rtcli"]) / statistics.median(walls["pov"]),
                span(renders["rtcli"]), span(renders["pov"]),
                statistics.median(renders["rtcli"]) / statistics.median(renders["pov"]), diff))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
