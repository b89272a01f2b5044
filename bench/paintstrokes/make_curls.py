#!/usr/bin/env python3
"""Writes the benchmark's `curls` stroke list (formats/paintstroke-input.md): N helical strokes of
varying radius and pitch around a unit sphere, deterministic (a fixed linear congruential sequence),
so the view-dependent tessellation meets tight curvature, strokes seen end-on and overlaps."""
import json
import math
import sys


def lcg(seed):
    state = seed
    while True:
        state = (6364136223846793005 * state + 1442695040888963407) % (1 << 64)
        yield (state >> 11) / float(1 << 53)


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    rand = lcg(7)
    strokes = []
    for _ in range(count):
        # A random root direction on the sphere, a local frame, and a helix leaving it.
        z = 2 * next(rand) - 1
        phi = 2 * math.pi * next(rand)
        s = math.sqrt(max(0.0, 1 - z * z))
        n = (s * math.cos(phi), s * math.sin(phi), z)
        t = (-math.sin(phi), math.cos(phi), 0.0)
        b = (n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0])
        turns = 0.5 + 1.5 * next(rand)
        coil = 0.04 + 0.08 * next(rand)
        length = 0.3 + 0.4 * next(rand)
        radius = 0.004 + 0.012 * next(rand)
        colour = [0.3 + 0.6 * next(rand), 0.25 + 0.5 * next(rand), 0.2 + 0.3 * next(rand)]
        points = []
        steps = 8
        for k in range(steps):
            u = k / (steps - 1)
            a = 2 * math.pi * turns * u
            p = [n[i] * (1 + length * u) + coil * (math.cos(a) * t[i] + math.sin(a) * b[i]) for i in range(3)]
            points.append({"p": [round(v, 6) for v in p], "r": round(radius * (1 - 0.6 * u), 6),
                           "colour": [round(c, 4) for c in colour], "normal": [round(v, 6) for v in n],
                           "depth": round(1 - u, 4)})
        strokes.append({"points": points})
    json.dump({"version": 1, "units": "m",
               "styles": [{"name": "curl", "centreOpacity": 1, "edgeOpacity": 1, "volumeOpacity": [1, 1],
                           "specular": [0.3, 0.3, 0.3], "shininess": 40}],
               "strokes": strokes}, sys.stdout, separators=(",", ":"))


if __name__ == "__main__":
    main()
