#!/usr/bin/env python3
"""Writes a random test polygon as WKT, deterministic for given arguments.

  bench/polygon.py star N [SEED]         n vertices at random angles around the origin, random
                                         radii, on an integer grid, sorted by the angle of the
                                         rounded points (so the polygon is star-shaped and simple)
  bench/polygon.py convex N              a convex polygon (points on a parabola): every vertex
                                         pair is a chord, the Asano DP's worst case
  bench/polygon.py rectilinear N [SEED]  a random rectilinear polygon of about N vertices: a bar
                                         whose top and bottom follow random step heights from a
                                         small range, so that many horizontal edges at equal
                                         heights see each other (many degenerate triangles)
"""
import math, random, sys

kind, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1)
if kind == "star":
    scale = 10 * n + 1000
    pts = set()
    for _ in range(n):
        a = rng.random() * 2 * math.pi
        r = scale * (0.3 + 0.7 * rng.random())
        pts.add((round(r * math.cos(a)), round(r * math.sin(a))))
    pts.discard((0, 0))
    pts = sorted(pts, key=lambda p: (math.atan2(p[1], p[0]), p[0] * p[0] + p[1] * p[1]))
elif kind == "convex":
    pts = [(i, i * i) for i in range(n - 1)] + [(0, (n - 2) ** 2)]
elif kind == "rectilinear":
    columns = max(2, n // 4)
    def steps(lo, hi):
        hs = [rng.randint(lo, hi) for _ in range(columns)]
        return hs
    top, bottom = steps(6, 12), steps(0, 4)
    pts = []
    for x, h in enumerate(bottom):            # left to right along the bottom
        pts += [(x, h), (x + 1, h)]
    for x in range(columns - 1, -1, -1):      # right to left along the top
        pts += [(x + 1, top[x]), (x, top[x])]
    # Merge equal consecutive heights: drop flat vertices and repeated points.
    ring = []
    for p in pts:
        if ring and ring[-1] == p:
            continue
        ring.append(p)
    while ring[0] == ring[-1]:
        ring.pop()
    def flat(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) == 0
    changed = True
    while changed:
        changed = False
        out = []
        for i, p in enumerate(ring):
            if not flat(ring[i - 1], p, ring[(i + 1) % len(ring)]):
                out.append(p)
            else:
                changed = True
        ring = out
    pts = ring
else:
    sys.exit(f"unknown kind {kind!r}: use star, convex or rectilinear")
print("POLYGON ((" + ", ".join(f"{x} {y}" for x, y in pts + pts[:1]) + "))")
