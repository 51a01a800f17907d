#!/usr/bin/env python3
"""Writes the batch benchmark's small polygons as GeoJSON Lines, byte for byte the file that
`cargo bench --bench batch -- --count N --seed S --write PATH` times (benches/common's
`small_rectilinear`: 2 to 10 unit columns, bottoms at heights 0-2, tops at 4-6, flat vertices
kept; 20.6 vertices on average), without building the bench.

    bench/batch_polygons.py [N] [SEED] > polygons.ndjson      (default 100000 1)
"""
import sys

MASK = (1 << 64) - 1


class Rng:
    """splitmix64, as benches/common's Rng."""

    def __init__(self, seed):
        self.state = seed & MASK

    def next_u64(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def range(self, lo, hi):
        """Uniform in lo..=hi."""
        return lo + self.next_u64() % (hi - lo + 1)


def small_rectilinear(seed):
    """The ring of benches/common's small_rectilinear(seed), counter-clockwise, not closed."""
    rng = Rng(seed)
    columns = rng.range(2, 10)
    bottom = [rng.range(0, 2) for _ in range(columns)]
    top = [rng.range(4, 6) for _ in range(columns)]
    ring = []
    for x, h in enumerate(bottom):
        ring += [(x, h), (x + 1, h)]
    for x in reversed(range(columns)):
        ring += [(x + 1, top[x]), (x, top[x])]
    out = []
    for p in ring:
        if not out or out[-1] != p:
            out.append(p)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    write = sys.stdout.write
    for k in range(count):
        ring = small_rectilinear((seed * 1_000_003 + k) & MASK)
        write('{"type": "Polygon", "coordinates": [[' + ", ".join(f"[{x}, {y}]" for x, y in ring) + "]]}\n")


main()
