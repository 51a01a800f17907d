#!/usr/bin/env python3
"""Writes a random test polygon as WKT, deterministic for given arguments.

  bench/polygon.py star N [SEED]    n vertices at sorted random angles, random radii, on an
                                    integer grid (collinear triples occur now and then)
  bench/polygon.py convex N         a convex polygon (points on a parabola): every vertex pair
                                    is a chord, the Asano DP's worst case
"""
import math, random, sys

kind, n = sys.argv[1], int(sys.argv[2])
if kind == "star":
    rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    angles = sorted(rng.random() * 2 * math.pi for _ in range(n))
    pts, seen = [], set()
    for a in angles:
        r = 1_000_000 * (0.3 + 0.7 * rng.random())
        p = (round(r * math.cos(a)), round(r * math.sin(a)))
        if p not in seen:
            seen.add(p)
            pts.append(p)
elif kind == "convex":
    pts = [(i, i * i) for i in range(n - 1)] + [(0, (n - 2) ** 2)]
else:
    sys.exit(f"unknown kind {kind!r}: use star or convex")
print("POLYGON ((" + ", ".join(f"{x} {y}" for x, y in pts + pts[:1]) + "))")
