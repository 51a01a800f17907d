//! Algorithm MINITRI: the minimum triangulation of a polygon without holes.
//!
//! C. Chen and R.-C. Chang, "On the minimality of polygon triangulation", *BIT* 30 (1990)
//! 570-582, §3 (`papers/chen-chang-1990-minimality-of-polygon-triangulation.txt`).
//!
//! The minimum number of triangles is `n - 2 - d`, `d` the size of a maximum set of mutually
//! independent minimally degenerate triangles (Theorem 2). Departures from the paper: flat
//! vertices are allowed (each is the middle of the degenerate triangle formed with its two
//! neighbours), and collinear runs of any length.
//!
//! # Overview
//! 1. [`degenerate`]: all minimally degenerate triangles, of types (i), (ii), (iii) and flat.
//! 2. [`circle`]: the circular representation C(P), endpoints at a shared vertex ordered by angle.
//! 3. [`mis`]: a maximum independent set, by the circle-graph recurrence extended to 3b-chains
//!    (Algorithm MISMDT).
//! 4. and 5. [`partition`]: cut P along the chosen triangles and triangulate every piece.

pub mod circle;
pub mod degenerate;
pub mod expansion;
pub mod mis;
pub mod partition;

use super::{Algorithm, TriangulateError, Triangulation};
use crate::geom::polygon::Polygon;

/// The minimum triangulation of a polygon without holes.
///
/// # Errors
/// [`TriangulateError::HolesUnsupported`] for a polygon with holes.
pub fn triangulate(polygon: &Polygon) -> Result<Triangulation, TriangulateError> {
    if polygon.holes() > 0 {
        return Err(TriangulateError::HolesUnsupported {
            algorithm: Algorithm::Minitri,
            holes: polygon.holes(),
        });
    }
    let mdts = degenerate::minimally_degenerate(polygon);
    let circle = circle::circle(polygon, &mdts);
    let chains = mis::chains(polygon, &mdts);
    let chosen: Vec<degenerate::Degenerate> = mis::maximum_independent_set(&circle, &chains)
        .into_iter()
        .map(|t| mdts[t])
        .collect();
    let triangles = partition::triangulate_pieces(polygon, &chosen);
    let degenerate = chosen.iter().map(|m| [m.a, m.b, m.c]).collect();
    Ok(Triangulation {
        algorithm: Algorithm::Minitri,
        triangles,
        degenerate,
        optimal: true,
    })
}

#[cfg(test)]
mod tests;
