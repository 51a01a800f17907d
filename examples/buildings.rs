//! Writes `N` building-like polygons as GeoJSON Lines on standard output: the input of the
//! pipeline tests, the Spark job and the throughput figures in `docs/pipelines.md`.
//!
//! `cargo run --release --example buildings -- N [SEED]`
//!
//! Each line is a Feature with `id` `"b<k>"` and properties `{"k": k, "kind": ...}`: a
//! rectilinear footprint (a rectangle with notches cut from some corners and sides: 4 to 16
//! vertices, coordinates with one decimal), one in ten with a rectangular courtyard (a hole),
//! one in 500 invalid (a bow tie: `"kind": "invalid"`), one in 1000 a two-part MultiPolygon (a
//! building and its annex) and one in 2000 with a `null` geometry. Deterministic for a seed.

use std::io::{self, BufWriter, Write};

/// A small deterministic generator (xorshift64*), so that no crate is needed.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 33) % n
    }
}

/// Tenths as a decimal (`125` is `12.5`).
fn d(tenths: i64) -> String {
    let sign = if tenths < 0 { "-" } else { "" };
    let t = tenths.abs();
    format!("{sign}{}.{}", t / 10, t % 10)
}

/// A closed ring as GeoJSON positions.
fn ring(points: &[(i64, i64)]) -> String {
    let mut all: Vec<String> = points
        .iter()
        .map(|&(x, y)| format!("[{}, {}]", d(x), d(y)))
        .collect();
    all.push(all[0].clone());
    format!("[{}]", all.join(", "))
}

/// A rectilinear footprint at `(x0, y0)`, counter-clockwise, and its bounding size.
fn footprint(rng: &mut Rng, x0: i64, y0: i64) -> (Vec<(i64, i64)>, i64, i64) {
    let (w, h) = (
        100 + 10 * rng.below(40) as i64,
        100 + 10 * rng.below(40) as i64,
    );
    let notch = |rng: &mut Rng, size: i64| 10 + 10 * rng.below((size / 40) as u64) as i64;
    let mut p = Vec::new();
    // Corners counter-clockwise from the bottom left, each square or notched.
    let corners = [(0, 0, 1, 1), (w, 0, -1, 1), (w, h, -1, -1), (0, h, 1, -1)];
    for (k, &(cx, cy, sx, sy)) in corners.iter().enumerate() {
        if rng.below(2) == 0 {
            p.push((cx, cy));
        } else {
            let (nx, ny) = (notch(rng, w), notch(rng, h));
            // Walking counter-clockwise: bottom-left and top-right corners enter along y then
            // x; the others along x then y.
            if k % 2 == 0 {
                p.extend([
                    (cx, cy + sy * ny),
                    (cx + sx * nx, cy + sy * ny),
                    (cx + sx * nx, cy),
                ]);
            } else {
                p.extend([
                    (cx + sx * nx, cy),
                    (cx + sx * nx, cy + sy * ny),
                    (cx, cy + sy * ny),
                ]);
            }
        }
        // A notch in the middle of the side that follows (bottom side only: a U shape).
        if k == 0 && rng.below(4) == 0 {
            let (a, b) = (w / 2 - 10, w / 2 + 10);
            p.extend([(a, 0), (a, 20), (b, 20), (b, 0)]);
        }
    }
    let p = p.into_iter().map(|(x, y)| (x0 + x, y0 + y)).collect();
    (p, w, h)
}

fn main() -> io::Result<()> {
    let mut args = std::env::args().skip(1);
    let n: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(1000);
    let seed: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(1);
    let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
    let mut out = BufWriter::new(io::stdout().lock());
    for k in 0..n {
        let (x0, y0) = ((k % 1000) as i64 * 600, (k / 1000) as i64 * 600);
        let (kind, geometry) = if k % 2000 == 1999 {
            ("null", "null".to_string())
        } else if k % 500 == 499 {
            let bow = [
                (x0, y0),
                (x0 + 100, y0 + 100),
                (x0 + 100, y0),
                (x0, y0 + 100),
            ];
            (
                "invalid",
                format!(
                    "{{\"type\": \"Polygon\", \"coordinates\": [{}]}}",
                    ring(&bow)
                ),
            )
        } else if k % 1000 == 998 {
            let (a, w, _) = footprint(&mut rng, x0, y0);
            let annex = [(x0 + w + 20, y0), (x0 + w + 60, y0), (x0 + w + 60, y0 + 40)];
            let annex = [annex[0], annex[1], annex[2], (x0 + w + 20, y0 + 40)];
            (
                "two parts",
                format!(
                    "{{\"type\": \"MultiPolygon\", \"coordinates\": [[{}], [{}]]}}",
                    ring(&a),
                    ring(&annex)
                ),
            )
        } else {
            let (outer, w, h) = footprint(&mut rng, x0, y0);
            if k % 10 == 3 {
                // A courtyard well inside every notch: clockwise.
                let (a, b) = (x0 + w / 2 - 20, y0 + h / 2 - 20);
                let hole = [(a, b), (a, b + 40), (a + 40, b + 40), (a + 40, b)];
                (
                    "courtyard",
                    format!(
                        "{{\"type\": \"Polygon\", \"coordinates\": [{}, {}]}}",
                        ring(&outer),
                        ring(&hole)
                    ),
                )
            } else {
                (
                    "footprint",
                    format!(
                        "{{\"type\": \"Polygon\", \"coordinates\": [{}]}}",
                        ring(&outer)
                    ),
                )
            }
        };
        writeln!(
            out,
            "{{\"type\": \"Feature\", \"id\": \"b{k}\", \"properties\": {{\"k\": {k}, \"kind\": \"{kind}\"}}, \"geometry\": {geometry}}}"
        )?;
    }
    out.flush()
}
