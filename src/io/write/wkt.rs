//! The WKT writer: one `MULTIPOLYGON` of triangles per line, one line per triangulated polygon.
//!
//! Input contract: outcomes in order; a solved outcome carries its
//! [`Polygon`](crate::geom::polygon::Polygon) and its
//! triangles, counter-clockwise.
//!
//! Output guarantee: for each solved polygon, in input order, one line
//! `MULTIPOLYGON (((x y, x y, x y, x y)), ...)`: its triangles in the order of the JSON output,
//! each a closed counter-clockwise ring (first corner repeated), coordinates the input decimals
//! exactly ([`crate::geom::polygon::Grid::format`]); for `pseudo` and `pseudo-hull`, its
//! pseudotriangles instead, in the order of the JSON output. A polygon that failed has no line (its
//! error goes to standard error); with nothing triangulated the output is empty.
//!
//! Why lines and not one `GEOMETRYCOLLECTION`: each line is a complete WKT geometry standing for
//! one input polygon, the one-geometry-per-record form of WKT-lines files and of WKT columns in
//! delimited text (which GIS tools import), and what shell tools (`wc -l`, `grep`, `split`)
//! take; it streams with nothing to close at the end, and an empty result stays an empty file
//! (a batch input with no polygon triangulated gets no output file at all, as for every format).
//! A collection would put a whole run on one line and lose the polygon boundaries.
//!
//! Streamed: each line is written when its polygon is pushed. Complexity: linear in the output.

use super::Sink;
use crate::pipeline::Outcome;
use std::io::{self, Write};

/// Writes one `MULTIPOLYGON` line per solved polygon.
pub struct WktWriter<W: Write> {
    out: W,
}

impl<W: Write> WktWriter<W> {
    /// Starts the (headerless) document.
    pub fn new(out: W) -> WktWriter<W> {
        WktWriter { out }
    }

    /// Writes the line of one outcome (none for a failed polygon).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push(&mut self, outcome: &Outcome) -> io::Result<()> {
        let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) else {
            return Ok(());
        };
        let coordinate = |i: usize| {
            let [x, y] = polygon.coordinates(i);
            format!("{} {}", x, y)
        };
        write!(self.out, "MULTIPOLYGON (")?;
        if let Some(p) = &solved.pseudo {
            // A pseudotriangulation: its faces, each a closed counter-clockwise ring.
            for (k, face) in p.faces.iter().enumerate() {
                let separator = if k == 0 { "" } else { ", " };
                let ring: Vec<String> = face.cycle.iter().map(|&v| coordinate(v)).collect();
                let first = ring.first().cloned().unwrap_or_default();
                write!(self.out, "{separator}(({}, {first}))", ring.join(", "))?;
            }
            return writeln!(self.out, ")");
        }
        for (k, tri) in solved.triangulation.triangles.iter().enumerate() {
            let [a, b, c] = tri.map(coordinate);
            let separator = if k == 0 { "" } else { ", " };
            write!(self.out, "{separator}(({a}, {b}, {c}, {a}))")?;
        }
        writeln!(self.out, ")")
    }

    /// Ends the document and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        self.out.flush()
    }
}

impl<W: Write> Sink for WktWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        WktWriter::push(self, &outcome)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        WktWriter::finish(*self)
    }
}
