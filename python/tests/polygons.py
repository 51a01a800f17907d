"""Random building-like polygons for the tests and the benchmark: small rectilinear outlines
(a union of random grid rectangles' boundary walk, 4 to about 40 vertices) with some vertices
in the middle of straight sides (T-junction candidates), deterministic for a seed."""

import random

import shapely


def building(rng: random.Random) -> shapely.Polygon:
    """One outline: a staircase-sided block, rotated by a multiple of 90 degrees, shifted, some
    sides split by an extra collinear vertex; coordinates in metres with one decimal."""
    steps = rng.randint(1, 4)
    width = [rng.randint(2, 20) for _ in range(steps)]
    heights = [rng.randint(2, 20) for _ in range(steps)]
    # A staircase: x grows along the bottom, the top steps down.
    ring = [(0, 0)]
    x = 0
    for w in width:
        x += w
    ring.append((x, 0))
    x_right = x
    for k in reversed(range(steps)):
        top = sum(heights[: k + 1])
        ring.append((x_right, top))
        x_right -= width[k]
        ring.append((x_right, top))
    ring = ring[:-1] + [(0, ring[-1][1])]
    ring = list(dict.fromkeys(ring))
    split = []
    for a, b in zip(ring, ring[1:] + ring[:1]):
        split.append(a)
        if rng.random() < 0.3 and (abs(a[0] - b[0]) > 1 or abs(a[1] - b[1]) > 1):
            split.append(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2))
    dx, dy = rng.randint(0, 10**5) / 10, rng.randint(0, 10**5) / 10
    turn = rng.randint(0, 3)
    coords = []
    for x, y in split:
        for _ in range(turn):
            x, y = -y, x
        coords.append((round(x + dx, 1), round(y + dy, 1)))
    return shapely.Polygon(coords)


def buildings(count: int, seed: int = 1) -> list:
    rng = random.Random(seed)
    return [building(rng) for _ in range(count)]
