#!/usr/bin/env python3
"""Writes a random test polygon as WKT, deterministic for given arguments.

  bench/polygon.py star N [SEED]         n vertices at random angles around the origin, random
                                         radii, on an integer grid, sorted by the angle of the
                                         rounded points (so the polygon is star-shaped and simple)
  bench/polygon.py convex N              a convex polygon (points on a parabola): every vertex
                                         pair is a chord, the Asano DP's worst case
  bench/polygon.py maze N [SEED]         a random rectilinear polygon of about N vertices: the
                                         cells of a random spanning tree of a grid (corridors one
                                         cell wide; many degenerate triangles, local visibility)
  bench/polygon.py bars N [SEED]         a random rectilinear polygon of about 0.83 N vertices: a
                                         bar whose top and bottom follow random step heights from
                                         a small range, so that an open corridor runs its whole
                                         length and Theta(N^2) vertex pairs see each other
  bench/polygon.py snake N [SEED]        a raster-like winding corridor of about N vertices:
                                         rows of unit columns (bottoms at heights 0-1, tops 5-6)
                                         joined at alternate ends, every lattice point of the
                                         boundary a vertex (long 3b-chains along the walls,
                                         degenerate triangles across the corridor)
  bench/polygon.py zigzag N [SEED]       the same corridor turning right and up alternately
                                         (segments of about sqrt(12 N) columns), so that it runs
                                         both ways and its bounding box is square
  bench/polygon.py comb N                a comb of N teeth 1 wide and 9 high, gaps 1 wide, the
                                         gap floors on one line (about 4 N vertices)
  bench/polygon.py stairs N [SEED]       a corridor climbing a random staircase (steps 1 to 3
                                         units right and up, the upper wall the lower one moved
                                         by (-1, 1)): about N vertices, corners only, many on
                                         common grid lines (degenerate triangles across and along)
  bench/polygon.py stairs-lattice N [SEED]
                                         the same corridor with every lattice point of its walls
                                         a vertex (about N vertices; long 3b-chains, step 3's
                                         hard case, like the snake)
  bench/polygon.py sliver N              a staircase of unit steps from (N 1) to (1 N) over the
                                         long sliver edge (0 0, N 1): (0 0, N 1, N-1 1, N-1 2,
                                         ..., 1 N); about 2 N vertices, every reflex corner on the
                                         line x + y = N, each seeing along it
  bench/polygon.py parabola N             the region between the parabola y = x^2 (x = N, .., 0,
                                         every point a reflex vertex) and the chord below it from
                                         (0, -N^2) to (N, 0): every vertex sees along tangent rays
                                         across the whole polygon, and the parabola's points are
                                         in convex position (long hull chains for step 1's shooter)
  bench/polygon.py notches N             N/2 thin notches cut into a regular polygon, their tips on
                                         a circle of half its radius: every tip sees every other
                                         across the middle, in two wide opposite cones (the walk of
                                         step 1 from each tip is linear, quadratic in all)
  bench/polygon.py diamonds N            a strip with a chain of N diamond holes, each touching
                                         the next at a corner (4 N + 4 vertices, N hole rings
                                         joined into one hole walk): a raster layer's touches
  bench/polygon.py diamonds-apart N      its untouched twin: the same strip and diamonds, spaced
                                         so that no two touch (same vertex and hole counts)
  bench/polygon.py hanging N             N triangular holes hanging from the top edge of a
                                         rectangle by a corner (3 N + 4 vertices, one walk)
  bench/polygon.py hanging-apart N       its untouched twin: the triangles a unit below the edge
"""
import math, random, sys

def boundary(cells):
    """The boundary of a union of unit cells (simply connected, never pinched), counter-clockwise
    from its lowest-leftmost point, every lattice point on it a vertex."""
    nxt = {}                                  # boundary unit edges, inside on the left
    for (x, y) in cells:
        if (x, y - 1) not in cells: nxt[(x, y)] = (x + 1, y)
        if (x + 1, y) not in cells: nxt[(x + 1, y)] = (x + 1, y + 1)
        if (x, y + 1) not in cells: nxt[(x + 1, y + 1)] = (x, y + 1)
        if (x - 1, y) not in cells: nxt[(x, y + 1)] = (x, y)
    start = min(nxt)
    ring, p = [start], nxt[start]
    while p != start:
        ring.append(p)
        p = nxt[p]
    return ring

kind, n = sys.argv[1], int(sys.argv[2])
holes = []
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
elif kind == "maze":
    k = max(2, round((n / 1.72) ** 0.5))
    parent = list(range(k * k))
    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    edges = [(i, j, 0) for i in range(k - 1) for j in range(k)]
    edges += [(i, j, 1) for i in range(k) for j in range(k - 1)]
    rng.shuffle(edges)
    cells = set((2 * i, 2 * j) for i in range(k) for j in range(k))
    for i, j, d in edges:                     # randomized Kruskal: a random spanning tree
        a = i * k + j
        b = (i + 1) * k + j if d == 0 else i * k + j + 1
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
            cells.add((2 * i + 1, 2 * j) if d == 0 else (2 * i, 2 * j + 1))
    ring = boundary(cells)
    m = len(ring)
    def turn(a, b, c):
        return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0
    pts = [ring[i] for i in range(m) if turn(ring[i - 1], ring[i], ring[(i + 1) % m])]
elif kind == "bars":
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
elif kind == "snake":
    rows = max(2, round(n ** 0.5 / 8))
    columns = max(3, round(n / (3 * rows)))
    cells = set()
    for r in range(rows):
        y0 = 10 * r
        for x in range(columns):
            f, c = rng.choice([0, 1]), rng.choice([5, 6])
            cells.update((x, y0 + y) for y in range(f, c))
        if r + 1 < rows:                      # the connector to the next corridor
            x = columns - 1 if r % 2 == 0 else 0
            cells.update((x, y) for y in range(y0 + 1, y0 + 12))
    pts = boundary(cells)                     # every lattice point of the boundary a vertex
elif kind == "zigzag":
    length = max(12, round((12 * n) ** 0.5))  # columns per segment; about 3 vertices per column
    segments = max(2, round(n / (3 * length)))
    cells, x0, y0 = set(), 0, 0
    for s in range(segments):
        for t in range(length):
            f, c = rng.choice([0, 1]), rng.choice([5, 6])
            if s % 2 == 0:                    # along x, from (x0, y0)
                cells.update((x0 + t, y0 + y) for y in range(f, c))
            else:                             # along y
                cells.update((x0 + x, y0 + t) for x in range(f, c))
        if s % 2 == 0:
            x0 += length - 6
        else:
            y0 += length - 6
    pts = boundary(cells)
elif kind == "comb":
    pts = [(0, 0), (2 * n - 1, 0)]
    for i in range(n - 1, -1, -1):
        pts += [(2 * i + 1, 10), (2 * i, 10)]
        if i > 0:
            pts += [(2 * i, 1), (2 * i - 1, 1)]
elif kind == "sliver":
    pts = [(0, 0), (n, 1)]
    for k in range(1, n):
        pts += [(n - k, k), (n - k, k + 1)]
elif kind == "stairs":
    # A corridor climbing a random staircase: the lower wall steps right and up by 1 to 3 units
    # at random, the upper wall is the lower one moved by (-1, 1); about n vertices, corners
    # only (no vertex inside a step), many of them on common lines of the grid.
    lower = [(0, 0)]
    for _ in range(max(1, (n - 2) // 4)):
        x, y = lower[-1]
        x += rng.randint(1, 3)
        lower.append((x, y))
        lower.append((x, y + rng.randint(1, 3)))
    pts = lower + [(x - 1, y + 1) for x, y in reversed(lower)]
elif kind == "stairs-lattice":
    # The same corridor with every lattice point of its walls a vertex (about n vertices):
    # long collinear runs, 3b-chains along every step.
    lower = [(0, 0)]
    for _ in range(max(1, n // 8)):
        x, y = lower[-1]
        x += rng.randint(1, 3)
        lower.append((x, y))
        lower.append((x, y + rng.randint(1, 3)))
    corners = lower + [(x - 1, y + 1) for x, y in reversed(lower)]
    pts = []
    for (x, y), (u, v) in zip(corners, corners[1:] + corners[:1]):
        steps = max(abs(u - x), abs(v - y)) if x == u or y == v else 1
        pts += [(x + (u - x) * k // steps, y + (v - y) * k // steps) for k in range(steps)]
elif kind == "parabola":
    pts = [(0, -n * n), (n, 0)] + [(k, k * k) for k in range(n, -1, -1)]
elif kind == "notches":
    m = max(3, n // 2)
    r = 20 * m
    pts = []
    for i in range(m):
        a, b = 2 * math.pi * i / m, 2 * math.pi * (i + 0.5) / m
        pts += [(round(r * math.cos(a)), round(r * math.sin(a))),
                (round(r / 2 * math.cos(b)), round(r / 2 * math.sin(b)))]
elif kind in ("diamonds", "diamonds-apart"):
    gap = 2 if kind == "diamonds" else 4          # centre to centre; 2 makes them touch
    pts = [(0, 0), (gap * n + 8, 0), (gap * n + 8, 8), (0, 8)]
    for k in range(n):
        cx = gap * k + 4
        holes.append([(cx - 1, 4), (cx, 5), (cx + 1, 4), (cx, 3)])
elif kind in ("hanging", "hanging-apart"):
    top = 10 if kind == "hanging" else 9         # 10: the hole's corner on the rectangle's edge
    pts = [(0, 0), (4 * n + 4, 0), (4 * n + 4, 10), (0, 10)]
    for k in range(n):
        holes.append([(4 * k + 4, top), (4 * k + 5, 7), (4 * k + 3, 7)])
else:
    sys.exit(f"unknown kind {kind!r}: use star, convex, maze, bars, snake, zigzag, comb, sliver, parabola, stairs, stairs-lattice, diamonds(-apart) or hanging(-apart)")
ring = lambda r: "(" + ", ".join(f"{x} {y}" for x, y in r + r[:1]) + ")"
print("POLYGON (" + ", ".join(ring(r) for r in [pts] + holes) + ")")
