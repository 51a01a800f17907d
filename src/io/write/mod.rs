//! Writers: JSON, GeoJSON, WKT, CSV and SVG. They consume results and never call algorithms.
//!
//! [`OutputFormat::sink`] gives a [`Sink`] that takes outcomes one at a time, in order: the JSON
//! and per-triangle GeoJSON sinks write each polygon at once, the per-feature sinks (GeoJSON,
//! GeoJSON Lines, WKT, CSV) each input feature as soon as its last part is in ([`group`]), all
//! streamed; the SVG sink keeps them and draws the picture at the end (a layout needs every
//! panel, and a picture of a huge batch is not useful anyway).
pub mod csv;
pub mod features;
pub mod geojson;
pub mod group;
pub mod json;
pub mod svg;
pub mod wkt;

use crate::outcome::Outcome;
use std::io::{self, Write};

pub use super::extension::OutputFormat;

impl OutputFormat {
    /// A sink writing this format to `out`.
    ///
    /// # Errors
    /// Any I/O error of `out` (the JSON, GeoJSON and CSV sinks write their first line at once).
    pub fn sink<'w, W: Write + 'w>(self, out: W) -> io::Result<Box<dyn Sink + 'w>> {
        Ok(match self {
            OutputFormat::Json => Box::new(json::JsonWriter::new(out)?),
            OutputFormat::GeoJson => Box::new(features::FeatureWriter::new(out, false)?),
            OutputFormat::GeoJsonLines => Box::new(features::FeatureWriter::new(out, true)?),
            OutputFormat::GeoJsonTriangles => Box::new(geojson::GeoJsonWriter::new(out)?),
            OutputFormat::Wkt => Box::new(wkt::WktWriter::new(out)),
            OutputFormat::Csv => Box::new(csv::CsvWriter::new(out)?),
            OutputFormat::Svg(style) => Box::new(SvgSink {
                out,
                style,
                outcomes: Vec::new(),
            }),
        })
    }
}

/// Takes outcomes in order and writes a document of them.
pub trait Sink {
    /// Takes the next outcome.
    ///
    /// # Errors
    /// Any I/O error of the output.
    fn push(&mut self, outcome: Outcome) -> io::Result<()>;

    /// What this sink can make of an outcome before taking it, on any thread and in any order
    /// (a batch renders its outcomes in parallel): by default nothing.
    fn renderer(&self) -> Option<Renderer> {
        None
    }

    /// Takes the next outcome with what [`Sink::renderer`] made of it.
    ///
    /// # Errors
    /// Any I/O error of the output.
    fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let _ = rendered;
        self.push(outcome)
    }

    /// Warnings about what was written since the last call (each a line for standard error,
    /// `warning: SOURCE: ...`): by default none.
    fn warnings(&mut self) -> Vec<String> {
        Vec::new()
    }

    /// Ends the document and flushes the output.
    ///
    /// # Errors
    /// Any I/O error of the output.
    fn finish(self: Box<Self>) -> io::Result<()>;
}

/// Text made of an outcome ahead of writing it ([`Sink::renderer`]).
pub type Renderer = fn(&Outcome) -> Option<String>;

impl<W: Write> Sink for json::JsonWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        json::JsonWriter::push(self, &outcome)
    }

    fn renderer(&self) -> Option<Renderer> {
        Some(json::render)
    }

    fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        json::JsonWriter::push_rendered(self, &outcome, rendered)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        json::JsonWriter::finish(*self)
    }
}

/// The SVG sink: keeps the outcomes, draws them all at the end.
struct SvgSink<W: Write> {
    out: W,
    style: svg::Style,
    outcomes: Vec<Outcome>,
}

impl<W: Write> Sink for SvgSink<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        self.outcomes.push(outcome);
        Ok(())
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        let SvgSink {
            mut out,
            style,
            outcomes,
        } = *self;
        svg::write_outcomes(&outcomes, style, &mut out)?;
        out.flush()
    }
}
