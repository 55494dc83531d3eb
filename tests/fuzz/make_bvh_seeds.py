#!/usr/bin/env python3
"""Seed inputs for the bvh fuzzer: a thread byte, then float32 triangles (9 floats each), then two
rays (6 floats each). Ordinary scenes, scenes at the edge of the float range, and coincident ones."""
import random
import struct
import sys

out = sys.argv[1]
random.seed(1)
FLT_MAX = 3.4028234e38


def write(name, threads, floats):
    with open(f"{out}/seed-{name}", "wb") as f:
        f.write(bytes([threads]) + struct.pack(f"<{len(floats)}f", *floats))


def rays():
    return [0.1, 0.2, 10, 0.01, 0.02, -1, -5, 0.3, 0.1, 1, 0.05, 0.01]


for scale, name in [(1.0, "unit"), (1e19, "large"), (FLT_MAX / 2, "edge"), (1e-30, "tiny")]:
    tris = [random.uniform(-scale, scale) for _ in range(9 * 50)]
    write(name, 0, tris + rays())
    write(name + "-2threads", 1, tris + rays())
write("coincident", 0, [0, 0, 0, 1, 0, 0, 0, 1, 0] * 40 + rays())
write("far-apart", 0, [2e38, 0, 0, 2e38, 1, 0, 2e38, 0, 1] + [0, 0, 0, 1, 0, 0, 0, 1, 0] * 3 + rays())
