#!/usr/bin/env python3
"""Writes a random star-shaped polygon as WKT: n vertices at sorted random angles around the
origin, random radii, rounded to an integer grid (so collinear triples occur now and then).
Usage: bench/star.py N [SEED] > star.wkt   (deterministic for a given N and SEED)."""
import math, random, sys

n = int(sys.argv[1])
rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
scale = 1_000_000
angles = sorted(rng.random() * 2 * math.pi for _ in range(n))
pts, seen = [], set()
for a in angles:
    r = scale * (0.3 + 0.7 * rng.random())
    p = (round(r * math.cos(a)), round(r * math.sin(a)))
    if p not in seen:
        seen.add(p)
        pts.append(p)
ring = ", ".join(f"{x} {y}" for x, y in pts + pts[:1])
print(f"POLYGON (({ring}))")
