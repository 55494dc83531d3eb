#!/usr/bin/env python3
"""rtcli's path tracer against Cycles on a scene's twin (tools/cycles/twin.py): the converged
images side by side (what differs, and by how much), and the noise each leaves after the same
wall time (RMSE against its own converged reference, linear radiance).

  python3 tools/cycles/compare.py [SCENE.json] [--size 160] [--reference 1024] [--samples 32] [--out DIR]

Also rtcli's equal-time image denoised (--denoise). Needs Blender 3.4 (Debian `blender`) and
build/rtcli. Render times are each renderer's own
(rtcli's summary, Cycles' render call), both on 2 threads; Blender's start-up is not counted.
"""
import argparse
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read_png(path):
    """8-bit sRGB PNG to linear floats, through Python's zlib (no PIL needed)."""
    import struct
    import zlib
    data = open(path, "rb").read()
    pos, chunks, width = 8, [], 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, ctype = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[ctype]
            assert depth == 8
        elif kind == b"IDAT":
            chunks.append(body)
        pos += 12 + n
    raw = zlib.decompress(b"".join(chunks))
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    lut = [((v / 255) / 12.92 if v / 255 <= 0.04045 else ((v / 255 + 0.055) / 1.055) ** 2.4) for v in range(256)]
    return [[lut[row[x * channels + c]] for c in range(3)] for row in rows for x in range(width)]


def rmse(a, b):
    return math.sqrt(sum((p[c] - q[c]) ** 2 for p, q in zip(a, b) for c in range(3)) / (3 * len(a)))


def mean(a, c):
    return sum(p[c] for p in a) / len(a)


def rtcli(scene, out, size, spp, seed, *extra):
    r = subprocess.run([os.path.join(ROOT, "build/rtcli"), "render", scene, "-o", out, "--width", str(size),
                        "--height", str(size), "--spp", str(spp), "--seed", str(seed), "--threads", "2", *extra],
                       capture_output=True, text=True, check=True, cwd=ROOT)
    return float(re.search(r" in ([0-9.]+) s", r.stderr).group(1))


def cycles(scene, out, size, spp):
    r = subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "-P",
                        os.path.join(ROOT, "tools/cycles/twin.py"), "--", scene, out, "--samples", str(spp),
                        "--width", str(size), "--height", str(size), "--threads", "2"],
                       capture_output=True, text=True, check=True, cwd=ROOT)
    return float(re.search(r"cycles: rendered .* in ([0-9.]+) s", r.stdout).group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene", nargs="?", default="scenes/cornell_box.json")
    ap.add_argument("--size", type=int, default=160)
    ap.add_argument("--reference", type=int, default=1024, help="samples of each converged reference")
    ap.add_argument("--samples", type=int, default=32, help="Cycles' samples in the equal-time run")
    ap.add_argument("--out", default="/tmp/rtcli-cycles")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    p = lambda name: os.path.join(a.out, name)
    t_rt_ref = rtcli(a.scene, p("rtcli-ref.png"), a.size, a.reference, 1)
    t_cy_ref = cycles(a.scene, p("cycles-ref.png"), a.size, a.reference)
    rt_ref, cy_ref = read_png(p("rtcli-ref.png")), read_png(p("cycles-ref.png"))
    print("converged (%d samples): rtcli %.1f s, Cycles %.1f s" % (a.reference, t_rt_ref, t_cy_ref))
    print("  mean linear R, G, B: rtcli %s, Cycles %s" % (
        ", ".join("%.4f" % mean(rt_ref, c) for c in range(3)), ", ".join("%.4f" % mean(cy_ref, c) for c in range(3))))
    print("  ratio rtcli / Cycles: %s; RMSE between them %.4f" % (
        ", ".join("%.3f" % (mean(rt_ref, c) / mean(cy_ref, c)) for c in range(3)), rmse(rt_ref, cy_ref)))
    # Equal time: Cycles at --samples; rtcli at the samples that take as long (its rate measured first).
    t_cy = cycles(a.scene, p("cycles-eq.png"), a.size, a.samples)
    t_probe = rtcli(a.scene, p("rtcli-probe.png"), a.size, 16, 2)
    spp = max(1, int(16 * t_cy / t_probe))
    t_rt = rtcli(a.scene, p("rtcli-eq.png"), a.size, spp, 3)
    e_cy = rmse(read_png(p("cycles-eq.png")), cy_ref)
    e_rt = rmse(read_png(p("rtcli-eq.png")), rt_ref)
    print("equal time: Cycles %d samples in %.2f s, RMSE %.4f; rtcli %d samples in %.2f s, RMSE %.4f (%.2fx Cycles')"
          % (a.samples, t_cy, e_cy, spp, t_rt, e_rt, e_rt / e_cy))
    # The same samples denoised (rtcli's --denoise; Cycles' denoiser stays off, as above). The
    # denoiser's own time (milliseconds at this size) is not in rtcli's render time.
    rtcli(a.scene, p("rtcli-eq-denoised.png"), a.size, spp, 3, "--denoise")
    e_dn = rmse(read_png(p("rtcli-eq-denoised.png")), rt_ref)
    print("equal time, rtcli denoised: RMSE %.4f (%.2fx Cycles')" % (e_dn, e_dn / e_cy))


if __name__ == "__main__":
    sys.exit(main())
