"""Writes N building-like polygons as GeoJSON Lines on standard output: the input of the Spark
test and of the throughput figures in docs/pipelines.md.

    python3 tests/spark/buildings.py N [SEED] > buildings.geojsonl

Each line is a Feature with `id` "b<k>" and properties {"k": k, "kind": ...}: a rectilinear
footprint (a rectangle with notches cut from some corners and the bottom side: 4 to 16
vertices, coordinates with one decimal), one in ten with a rectangular courtyard (a hole), one
in 1000 a two-part MultiPolygon (a building and its annex); every 500th invalid (a bow tie,
"kind": "invalid") but every 2000th with a null geometry instead ("kind": "null"). Deterministic for a
seed. (Python rather than a Rust example: an example would build every dev-dependency.)
"""

import sys

MASK = (1 << 64) - 1


class Rng:
    """xorshift64*: small, deterministic, no package needed."""

    def __init__(self, seed):
        self.state = (seed * 0x9E3779B97F4A7C15 | 1) & MASK

    def below(self, n):
        x = self.state
        x ^= x >> 12
        x ^= (x << 25) & MASK
        x ^= x >> 27
        self.state = x
        return (((x * 0x2545F4914F6CDD1D) & MASK) >> 33) % n


def d(tenths):
    """Tenths as a decimal: 125 is 12.5."""
    sign = "-" if tenths < 0 else ""
    t = abs(tenths)
    return f"{sign}{t // 10}.{t % 10}"


def ring(points):
    """A closed ring as GeoJSON positions."""
    text = [f"[{d(x)}, {d(y)}]" for x, y in points]
    return "[" + ", ".join(text + text[:1]) + "]"


def footprint(rng, x0, y0):
    """A rectilinear footprint at (x0, y0), counter-clockwise, and its width and height."""
    w = 100 + 10 * rng.below(40)
    h = 100 + 10 * rng.below(40)

    def notch(size):
        return 10 + 10 * rng.below(size // 40)

    p = []
    # Corners counter-clockwise from the bottom left, each square or notched.
    corners = [(0, 0, 1, 1), (w, 0, -1, 1), (w, h, -1, -1), (0, h, 1, -1)]
    for k, (cx, cy, sx, sy) in enumerate(corners):
        if rng.below(2) == 0:
            p.append((cx, cy))
        else:
            nx, ny = notch(w), notch(h)
            # Counter-clockwise, the bottom-left and top-right corners are entered along a
            # vertical side, the others along a horizontal one.
            if k % 2 == 0:
                p += [(cx, cy + sy * ny), (cx + sx * nx, cy + sy * ny), (cx + sx * nx, cy)]
            else:
                p += [(cx + sx * nx, cy), (cx + sx * nx, cy + sy * ny), (cx, cy + sy * ny)]
        if k == 0 and rng.below(4) == 0:
            # A notch in the middle of the bottom side: a U shape.
            a, b = w // 2 - 10, w // 2 + 10
            p += [(a, 0), (a, 20), (b, 20), (b, 0)]
    return [(x0 + x, y0 + y) for x, y in p], w, h


def polygon(*rings):
    return '{"type": "Polygon", "coordinates": [' + ", ".join(map(ring, rings)) + "]}"


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    rng = Rng(seed)
    out = sys.stdout
    for k in range(n):
        x0, y0 = (k % 1000) * 600, (k // 1000) * 600
        if k % 2000 == 1999:
            kind, geometry = "null", "null"
        elif k % 500 == 499:
            bow = [(x0, y0), (x0 + 100, y0 + 100), (x0 + 100, y0), (x0, y0 + 100)]
            kind, geometry = "invalid", polygon(bow)
        elif k % 1000 == 998:
            a, w, _ = footprint(rng, x0, y0)
            annex = [(x0 + w + 20, y0), (x0 + w + 60, y0), (x0 + w + 60, y0 + 40),
                     (x0 + w + 20, y0 + 40)]
            kind = "two parts"
            geometry = ('{"type": "MultiPolygon", "coordinates": [[' + ring(a) + "], ["
                        + ring(annex) + "]]}")
        else:
            outer, w, h = footprint(rng, x0, y0)
            if k % 10 == 3:
                # A courtyard well inside every notch: clockwise.
                a, b = x0 + w // 2 - 20, y0 + h // 2 - 20
                hole = [(a, b), (a, b + 40), (a + 40, b + 40), (a + 40, b)]
                kind, geometry = "courtyard", polygon(outer, hole)
            else:
                kind, geometry = "footprint", polygon(outer)
        out.write(f'{{"type": "Feature", "id": "b{k}", "properties": {{"k": {k}, '
                  f'"kind": "{kind}"}}, "geometry": {geometry}}}\n')


if __name__ == "__main__":
    main()
