//! The per-triangle GeoJSON writer (`--to geojson-triangles`): one RFC 7946 `FeatureCollection` of
//! triangles for the whole document (the per-feature one is [`super::features`]).
//!
//! Input contract: outcomes in order; a solved outcome carries its [`Polygon`] and a valid
//! triangulation (triangles counter-clockwise, degenerate triangles `[a, b, c]` with `b`
//! strictly inside a triangle side that contains the segment `a c`).
//!
//! Output guarantee: one Feature per triangle, one Feature per line, in input order:
//!
//! ```text
//! {"type": "FeatureCollection", "features": [
//! {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[3, 2], [4, 2], [4, 3], [3, 2]]]}, "properties": {...}},
//! ...
//! ]}
//! ```
//!
//! The geometry is the closed ring of the triangle's three corners, counter-clockwise (the
//! right-hand rule of RFC 7946), the first corner repeated at the end. Coordinates are the input
//! decimals exactly, as JSON numbers ([`crate::geom::polygon::Grid::format`]; no `f64` on the
//! way). Properties: `source`, `polygon` (its index in the source), `triangle` (its index among
//! the polygon's triangles, as in the JSON output), `vertices` (`[a, b, c]`, input vertex
//! numbers, as in the JSON output's `triangles`), `vertex_on_side` (whether a vertex of the
//! polygon lies strictly inside a side of this triangle: a T-junction) and `on_side` (those
//! vertices, sorted). A polygon that failed has no feature (its error goes to standard error);
//! with no triangle at all the document is an empty FeatureCollection. For `pseudo` and
//! `pseudo-hull`, one Feature per pseudotriangle instead (its closed counter-clockwise ring),
//! with properties `source`, `polygon`, `pseudotriangle` (its index), `cycle` and `corners`
//! (input vertex numbers, as in the JSON output).
//!
//! Streamed like the JSON writer: each polygon's features are written when it is pushed; memory
//! is one polygon's. Complexity: O((T + d) log(T + d)) per polygon of `T` triangles and `d`
//! degenerate triangles (the T-junction lookup sorts the triangle sides on their lines).

use super::json::{ids, json};
use super::Sink;
use crate::algo::Triangulation;
use crate::geom::kernel::line_through;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use crate::outcome::Outcome;
use std::io::{self, Write};

/// Writes the FeatureCollection incrementally, one polygon's features at a time.
pub struct GeoJsonWriter<W: Write> {
    out: W,
    features: usize,
}

impl<W: Write> GeoJsonWriter<W> {
    /// Starts the document.
    ///
    /// # Errors
    /// Any I/O error of `out`.
    pub fn new(mut out: W) -> io::Result<GeoJsonWriter<W>> {
        write!(out, "{{\"type\": \"FeatureCollection\", \"features\": [")?;
        Ok(GeoJsonWriter { out, features: 0 })
    }

    /// Writes the features of one outcome (none for a failed polygon).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push(&mut self, outcome: &Outcome) -> io::Result<()> {
        let (Ok(solved), Some(polygon), Some(index)) =
            (&outcome.result, &outcome.polygon, outcome.index)
        else {
            return Ok(());
        };
        let t = &solved.triangulation;
        let source = json(&outcome.source);
        let ordinates = outcome.ordinates.as_deref();
        let coordinate = |i: usize| {
            let [x, y] = polygon.coordinates(i);
            let z = ordinates
                .map(|o| o.geojson(polygon.id(i)))
                .unwrap_or_default();
            format!("[{x}, {y}{z}]")
        };
        if let Some(p) = &solved.pseudo {
            for (k, face) in p.faces.iter().enumerate() {
                let separator = if self.features == 0 { "\n" } else { ",\n" };
                self.features += 1;
                let mut ring: Vec<String> = face.cycle.iter().map(|&v| coordinate(v)).collect();
                ring.extend(ring.first().cloned());
                let cycle: Vec<usize> = face.cycle.iter().map(|&v| polygon.id(v)).collect();
                let corners: Vec<usize> = face.corners.iter().map(|&v| polygon.id(v)).collect();
                write!(
                    self.out,
                    "{separator}{{\"type\": \"Feature\", \"geometry\": {{\"type\": \"Polygon\", \
                     \"coordinates\": [[{}]]}}, \"properties\": {{\"source\": {source}, \
                     \"polygon\": {index}, \"pseudotriangle\": {k}, \"cycle\": {}, \
                     \"corners\": {}}}}}",
                    ring.join(", "),
                    json(&cycle),
                    json(&corners),
                )?;
            }
            return Ok(());
        }
        let on_sides = crate::with_polygon!(polygon, p => vertices_on_sides(p, t));
        for (k, (tri, vertices)) in t
            .triangles
            .iter()
            .zip(crate::with_polygon!(polygon, p => ids(p, &t.triangles)))
            .enumerate()
        {
            let separator = if self.features == 0 { "\n" } else { ",\n" };
            self.features += 1;
            let [a, b, c] = tri.map(coordinate);
            let mut on_side: Vec<usize> = on_sides[k].iter().map(|&v| polygon.id(v)).collect();
            on_side.sort_unstable();
            write!(
                self.out,
                "{separator}{{\"type\": \"Feature\", \"geometry\": {{\"type\": \"Polygon\", \
                 \"coordinates\": [[{a}, {b}, {c}, {a}]]}}, \"properties\": {{\"source\": {source}, \
                 \"polygon\": {index}, \"triangle\": {k}, \"vertices\": {}, \
                 \"vertex_on_side\": {}, \"on_side\": {}}}}}",
                json(&vertices),
                !on_side.is_empty(),
                json(&on_side),
            )?;
        }
        Ok(())
    }

    /// Ends the document and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        writeln!(self.out, "\n]}}")?;
        self.out.flush()
    }
}

impl<W: Write> Sink for GeoJsonWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        GeoJsonWriter::push(self, &outcome)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        GeoJsonWriter::finish(*self)
    }
}

/// For each triangle (aligned with `t.triangles`), the stored vertices lying strictly inside
/// one of its sides.
///
/// Each such vertex is the middle `b` of exactly one degenerate triangle `[a, b, c]`, and the
/// side holding it is the one triangle side on the line `a c` that has `b` strictly inside (a
/// vertex lies inside at most one side). The sides of counter-clockwise triangles on one line,
/// with the triangles on one given side of it, do not overlap; so after sorting the sides by
/// (line, side of the line, lower end) a binary search finds the one holding `b`, if any, among
/// the two candidates. Exact: line keys and the order along a line are integer comparisons.
fn vertices_on_sides<P: Coord>(polygon: &Polygon<P>, t: &Triangulation) -> Vec<Vec<usize>> {
    let mut found = vec![Vec::new(); t.triangles.len()];
    if t.degenerate.is_empty() {
        return found;
    }
    let valid = |i: usize| i < polygon.len();
    let middles: Vec<(P::Line, P, usize)> = t
        .degenerate
        .iter()
        .filter(|[a, b, c]| valid(*a) && valid(*b) && valid(*c))
        .filter(|[a, _, c]| polygon.point(*a) != polygon.point(*c))
        .map(|&[a, b, c]| {
            (
                line_through(polygon.point(a), polygon.point(c)).0,
                polygon.point(b),
                b,
            )
        })
        .collect();
    let mut lines: Vec<P::Line> = middles.iter().map(|m| m.0).collect();
    lines.sort_unstable();
    lines.dedup();
    // (line, whether the side runs along the line's direction, lower end, upper end, triangle)
    let mut sides: Vec<(P::Line, bool, P, P, usize)> = Vec::new();
    for (k, tri) in t.triangles.iter().enumerate() {
        if !tri.iter().all(|&i| valid(i)) {
            continue;
        }
        for s in 0..3 {
            let (p, q) = (polygon.point(tri[s]), polygon.point(tri[(s + 1) % 3]));
            if p == q {
                continue;
            }
            let (line, forward) = line_through(p, q);
            if lines.binary_search(&line).is_ok() {
                sides.push((line, forward, p.min(q), p.max(q), k));
            }
        }
    }
    sides.sort_unstable();
    for (line, point, b) in middles {
        for forward in [false, true] {
            let below = sides.partition_point(|s| (s.0, s.1, s.2) < (line, forward, point));
            let Some(&(l, f, _, hi, k)) = below.checked_sub(1).and_then(|i| sides.get(i)) else {
                continue;
            };
            if (l, f) == (line, forward) && point < hi {
                found[k].push(b);
                break;
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::Algorithm;
    use crate::test_support::polygon;

    fn triangulation(triangles: &[[usize; 3]], degenerate: &[[usize; 3]]) -> Triangulation {
        Triangulation {
            algorithm: Algorithm::Minitri,
            triangles: triangles.to_vec(),
            degenerate: degenerate.to_vec(),
            optimal: true,
            lower_bound: None,
            stopped: None,
        }
    }

    #[test]
    fn two_t_junctions_on_one_side_whatever_the_listed_ends() {
        // Vertices 1 and 2 both lie inside side 0-3 of triangle [0, 3, 4]; the checker accepts
        // any of these lists (each segment a c lies on that side).
        let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]]);
        let minimum = [[0, 3, 4], [0, 4, 5]];
        for degenerate in [
            [[0, 1, 2], [1, 2, 3]],
            [[0, 1, 3], [0, 2, 3]],
            [[0, 1, 2], [0, 2, 3]],
        ] {
            let found = vertices_on_sides(&p, &triangulation(&minimum, &degenerate));
            assert_eq!(found, [vec![1, 2], vec![]], "{degenerate:?}");
        }
    }

    #[test]
    fn no_degenerate_triangle_no_vertex_on_a_side() {
        let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]]);
        let fan = triangulation(&[[1, 2, 3], [1, 3, 4], [1, 4, 0]], &[]);
        let none: Vec<Vec<usize>> = vec![vec![]; 3];
        assert_eq!(vertices_on_sides(&p, &fan), none);
        let minimum = triangulation(&[[0, 2, 3], [0, 3, 4]], &[[0, 1, 2]]);
        assert_eq!(vertices_on_sides(&p, &minimum), [vec![1], vec![]]);
    }
}
