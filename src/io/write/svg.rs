//! SVG drawing of polygons and their triangulations, for people to look at.
//!
//! What is drawn: each [`Figure`] gets its own square panel, showing
//! - the polygon, filled light, all rings in ONE path with `fill-rule="evenodd"` so holes are
//!   empty;
//! - the triangles, thin blue strokes with a light fill (one path for all of them), then the rings
//!   again as a dark stroke on top;
//! - every degenerate triangle `[a, b, c]` used, as a thick orange segment a–c and an orange disc
//!   (one `<circle>` each, and no other `<circle>` anywhere) on the middle vertex b;
//! - small dots on the vertices when n <= [`DOTS_MAX`], and the INPUT vertex numbers
//!   ([`Polygon::id`]) when n <= [`LABELS_MAX`] or [`Style::labels`] asks for them, placed
//!   outside the polygon along the bisector; each label's font fits the room around its vertex
//!   (the distance to the nearest other vertex, to within a factor of 6, found on grids of cells
//!   of side [`MAX_ROOM`], half that, ... down to [`MIN_ROOM`] pixels): at most 11 pixels, and
//!   about as wide as the room, so that even 10^5 labels leave the picture legible (and
//!   readable when zoomed in);
//! - what `--verify` found wrong ([`Figure::faults`]), in red ([`FAULT`]): the region where the
//!   triangles do not cover the polygon exactly once (gaps, overlaps, triangles outside: filled
//!   where the winding number of the triangles' boundaries minus the polygon's is not zero, with
//!   `fill-rule="nonzero"`), the stretches of boundary that do not cancel (a thick stroke, visible
//!   however small the region), each bad triangle outlined, each bad degenerate triangle as a red
//!   segment; the panel frame is then red too;
//! - under the panel a caption: the title, `n = .., w = .., d = .., triangles = .., algorithm = ..`
//!   (with `optimal` / `not proved optimal` for minimum algorithms), the alerts in red (checker
//!   problems, disagreement of the exact algorithms) and a key for the orange marks; or, when the
//!   figure carries an error, the polygon alone and the error text in red.
//!
//! Each panel is a `<g>` whose `<title>` (a tooltip, and what screen readers announce) repeats
//! the caption's title and numbers; the document's `<title>` names the first figure and the count.
//!
//! With a verification ([`write_outcomes`]) that found a problem or a disagreement, every other
//! algorithm's output gets a panel of its own after the chosen one's, with its own faults.
//!
//! Panels are laid out in rows of up to [`PER_ROW`].
//!
//! Scaling: every point is mapped here, with no SVG `transform`, into a fixed
//! [`PANEL`]x[`PANEL`] panel: aspect ratio kept, a [`MARGIN`], centred, y flipped so up is up.
//! So stroke widths, dot radii and fonts are viewport pixels, whatever the size of the polygon or
//! the magnitude of its coordinates (lines only get thinner as the vertex count grows). The map starts from the exact grid points (a uniform scaling
//! and translation of the input coordinates, translated to start at 0) rather than from
//! [`crate::geom::polygon::Grid::to_f64`], so that offsets like 10^15 lose no precision to `f64`
//! cancellation. Numbers are written with at most 2 decimals.
//!
//! Triangle corners out of range (not a vertex of the polygon) are skipped, never a panic.
//!
//! Complexity: O(n + t + d) time per figure (t triangles, d degenerate triangles), output
//! streamed through a buffer; about 45 bytes per triangle, 25 per vertex, 40 per degenerate
//! triangle; labels add O(n log(MAX_ROOM / MIN_ROOM)) time and about 100 bytes per vertex; the
//! faults of a failed check add about 45 bytes per triangle.

use crate::algo::{Pseudotriangulation, Triangulation};
use crate::geom::kernel::Point;
use crate::geom::polygon::{AnyPolygon, Polygon};
use crate::outcome::Outcome;
use crate::verify::Faults;
use std::collections::HashMap;
use std::fmt;
use std::io::{self, Write};

/// Side of the square drawing panel of one figure, in pixels.
pub const PANEL: f64 = 640.0;
/// Empty border inside a panel around the polygon, in pixels.
pub const MARGIN: f64 = 28.0;
/// Panels per row.
pub const PER_ROW: usize = 3;
/// Vertex dots are drawn up to this many vertices (above, they would only blur the picture).
pub const DOTS_MAX: usize = 2000;
/// Vertex numbers are written up to this many vertices (at any size with [`Style::labels`]).
pub const LABELS_MAX: usize = 60;
/// The largest room around a vertex that labels look for, in pixels.
pub const MAX_ROOM: f64 = 16.0;
/// The smallest room labels tell apart, in pixels; denser vertices get this room.
pub const MIN_ROOM: f64 = 1.0 / 16.0;
/// The red of what `--verify` found wrong.
pub const FAULT: &str = "#e60000";

/// Space around and between panels.
const GAP: f64 = 24.0;
/// Caption line height.
const LINE: f64 = 18.0;
/// Space between a panel and its caption, and below the caption.
const CAPTION_PAD: f64 = 6.0;
/// Characters per caption line (bold title, other lines), for 640 pixels.
const TITLE_WRAP: usize = 72;
const TEXT_WRAP: usize = 88;
/// At most this many lines of error text.
const ERROR_LINES: usize = 8;

const POLYGON_FILL: &str = "#eef3fb";
const TRIANGLE_FILL: &str = "#e2ebf9";
const TRIANGLE_STROKE: &str = "#4a78c2";
const BOUNDARY: &str = "#1f2a3a";
const DEGENERATE: &str = "#e8590c";
const FACE_FILL: &str = "#dbe7fb";
const FACE_FILL_2: &str = "#f3e3c3";
const CORNER: &str = "#2b8a3e";
const ERROR: &str = "#c92a2a";
const FRAME: &str = "#d5dbe5";
const MUTED: &str = "#555";
/// Largest label font, in pixels.
const LABEL_FONT: f64 = 11.0;

pub use crate::io::extension::Style;

/// One polygon to draw.
pub struct Figure<'a> {
    /// What it is, e.g. `shapes/u.wkt #0` (source and polygon index).
    pub title: String,
    /// The polygon.
    pub polygon: &'a Polygon,
    /// Its triangulation, if one was made (ignored when `error` is set).
    pub triangulation: Option<&'a Triangulation>,
    /// Why it could not be triangulated; drawn in red instead of triangles.
    pub error: Option<String>,
    /// Where the independent checker found the triangulation wrong; drawn in red.
    pub faults: Option<&'a Faults>,
    /// Sentences for the caption, in red: checker problems, disagreements.
    pub alerts: Vec<String>,
    /// Write the vertex numbers whatever the size.
    pub labels: bool,
    /// Its pseudotriangulation (`pseudo`, `pseudo-hull`), drawn instead of the triangles.
    pub pseudo: Option<&'a Pseudotriangulation>,
}

/// A figure's title: the outcome (`source: feature 3`), and the input feature's `id` as
/// written when it has one (`source: feature 3, id "b-1"`).
fn title(outcome: &Outcome) -> String {
    let id = outcome
        .feature
        .as_ref()
        .and_then(|f| f.feature.id.as_deref());
    match id {
        Some(id) => format!("{outcome}, id {}", id.get()),
        None => outcome.to_string(),
    }
}

/// Writes one SVG document of every outcome that has a valid polygon (solved or not; inputs that
/// could not be read and invalid polygons have nothing to draw). A verification that failed
/// adds its faults and alerts, and a panel for each other algorithm's output.
///
/// # Errors
/// Only those of `out`.
pub fn write_outcomes(outcomes: &[Outcome], style: Style, out: &mut impl Write) -> io::Result<()> {
    // A wide polygon is drawn from a fast copy on a drawing grid (drawing needs no exactness).
    let drawn: Vec<_> = outcomes
        .iter()
        .map(|o| o.polygon.as_ref().map(AnyPolygon::for_drawing))
        .collect();
    let mut figures: Vec<Figure> = Vec::new();
    for (o, drawn) in outcomes.iter().zip(&drawn) {
        let Some(polygon) = drawn.as_deref() else {
            continue;
        };
        let base = |title: String| Figure {
            labels: style.labels,
            ..Figure::new(title, polygon)
        };
        let solved = match &o.result {
            Err(_) => {
                figures.push(Figure {
                    error: o.error_message(),
                    ..base(title(o))
                });
                continue;
            }
            Ok(solved) => solved,
        };
        if let Some(p) = &solved.pseudo {
            // A pseudotriangulation: one figure, the checker's problems in red in the caption.
            let check = solved
                .verification
                .as_ref()
                .and_then(|v| v.pseudotriangulation.as_ref());
            let mut alerts = Vec::new();
            if let Some(c) = check.filter(|c| !c.valid) {
                alerts.push(format!(
                    "{} output invalid:",
                    solved.triangulation.algorithm
                ));
                alerts.extend(c.problems.iter().cloned());
            }
            figures.push(Figure {
                triangulation: Some(&solved.triangulation),
                pseudo: Some(p),
                alerts,
                ..base(title(o))
            });
            continue;
        }
        let Some(v) = solved.verification.as_ref().filter(|v| !v.ok) else {
            figures.push(Figure {
                triangulation: Some(&solved.triangulation),
                ..base(title(o))
            });
            continue;
        };
        // The chosen algorithm's output is checked first (`verify_all`); then the others.
        let disagreement = v.disagreement.iter().map(|d| format!("disagreement: {d}"));
        for (k, c) in v.checks.iter().enumerate() {
            let mut alerts: Vec<String> = disagreement.clone().collect();
            if !c.check.valid {
                alerts.push(format!("{} output invalid (red):", c.algorithm));
                alerts.extend(c.check.problems.iter().cloned());
            }
            if k > 0 && alerts.is_empty() {
                continue;
            }
            let title = if k == 0 {
                o.to_string()
            } else {
                format!("{o} — {} output (--verify)", c.algorithm)
            };
            figures.push(Figure {
                triangulation: Some(if k == 0 {
                    &solved.triangulation
                } else {
                    &c.triangulation
                }),
                faults: Some(&c.check.faults),
                alerts,
                ..base(title)
            });
        }
    }
    write_svg(&figures, out)
}

/// Writes one standalone SVG document showing every figure.
///
/// # Errors
/// Only those of `out`.
pub fn write_svg(figures: &[Figure<'_>], out: &mut impl Write) -> io::Result<()> {
    let mut out = io::BufWriter::new(out);
    let captions: Vec<Vec<Line>> = figures.iter().map(caption).collect();
    let lines = captions.iter().map(Vec::len).max().unwrap_or(1);
    let layout = Layout::new(figures.len(), lines);
    let (w, h) = (Num(layout.width), Num(layout.height));
    writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#)?;
    writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">"#
    )?;
    let title = match figures {
        [] => "minitri: no polygons".to_string(),
        [one] => format!("minitri: {}", one.title),
        [first, ..] => format!("minitri: {} and {} more", first.title, figures.len() - 1),
    };
    writeln!(out, "<title>{}</title>", Esc(&title))?;
    writeln!(
        out,
        r##"<rect x="0" y="0" width="{w}" height="{h}" fill="#fff"/>"##
    )?;
    if figures.is_empty() {
        writeln!(
            out,
            r#"<text x="{GAP}" y="{}" font-size="14" fill="{MUTED}">no polygons to draw</text>"#,
            2.0 * GAP
        )?;
    }
    for (k, (figure, caption)) in figures.iter().zip(&captions).enumerate() {
        draw_figure(&mut out, figure, caption, layout.origin(k))?;
    }
    writeln!(out, "</svg>")?;
    out.flush()
}

/// Where the panels go.
struct Layout {
    cell_height: f64,
    width: f64,
    height: f64,
}

impl Layout {
    /// The grid for `count` figures whose longest caption has `lines` lines.
    fn new(count: usize, lines: usize) -> Layout {
        let columns = count.clamp(1, PER_ROW);
        let rows = count.div_ceil(PER_ROW).max(1);
        let cell_height = PANEL + 2.0 * CAPTION_PAD + lines as f64 * LINE;
        Layout {
            cell_height,
            width: GAP + columns as f64 * (PANEL + GAP),
            height: GAP + rows as f64 * (cell_height + GAP),
        }
    }

    /// The top left corner of panel `k`.
    fn origin(&self, k: usize) -> (f64, f64) {
        let (row, column) = (k / PER_ROW, k % PER_ROW);
        (
            GAP + column as f64 * (PANEL + GAP),
            GAP + row as f64 * (self.cell_height + GAP),
        )
    }
}

/// The map from grid points to panel pixels.
struct View<'a> {
    polygon: &'a Polygon,
    min: Point,
    scale: f64,
    /// Pixel position of grid point `min`.
    base: (f64, f64),
}

impl<'a> Figure<'a> {
    /// A figure of `polygon` with nothing else: no triangulation, error, faults, alerts.
    pub fn new(title: String, polygon: &'a Polygon) -> Figure<'a> {
        Figure {
            title,
            polygon,
            triangulation: None,
            error: None,
            faults: None,
            alerts: Vec::new(),
            labels: false,
            pseudo: None,
        }
    }
}

impl<'a> View<'a> {
    /// Fits the bounding box of `polygon` into the panel whose top left corner is `origin`.
    fn new(polygon: &'a Polygon, origin: (f64, f64)) -> View<'a> {
        let points = polygon.points();
        let min_x = points.iter().map(|p| p.x).min().unwrap_or(0);
        let max_x = points.iter().map(|p| p.x).max().unwrap_or(0);
        let min_y = points.iter().map(|p| p.y).min().unwrap_or(0);
        let max_y = points.iter().map(|p| p.y).max().unwrap_or(0);
        // Grid coordinates lie in 0..=2^62, so these differences cannot overflow.
        let (width, height) = ((max_x - min_x) as f64, (max_y - min_y) as f64);
        let span = width.max(height);
        let scale = if span > 0.0 {
            (PANEL - 2.0 * MARGIN) / span
        } else {
            1.0
        };
        let base = (
            origin.0 + (PANEL - width * scale) / 2.0,
            origin.1 + (PANEL + height * scale) / 2.0,
        );
        View {
            polygon,
            min: Point::new(min_x, min_y),
            scale,
            base,
        }
    }

    /// Pixel position of stored vertex `i`, if there is such a vertex.
    fn at(&self, i: usize) -> Option<Xy> {
        (i < self.polygon.len()).then(|| self.of(self.polygon.point(i)))
    }

    /// Pixel position of a grid point.
    fn of(&self, p: Point) -> Xy {
        Xy(
            self.base.0 + (p.x - self.min.x) as f64 * self.scale,
            self.base.1 - (p.y - self.min.y) as f64 * self.scale,
        )
    }
}

/// Draws one figure with its panel origin at `origin`.
fn draw_figure(
    out: &mut impl Write,
    figure: &Figure<'_>,
    caption: &[Line],
    origin: (f64, f64),
) -> io::Result<()> {
    let polygon = figure.polygon;
    let view = View::new(polygon, origin);
    let n = polygon.len();
    // Thinner lines as the polygon gets denser: (triangle edges, boundary, vertex dots).
    let (triangle_width, boundary_width, dot_width) = match n {
        0..=100 => (1.0, 1.6, 4.0),
        101..=DOTS_MAX => (0.7, 1.1, 3.0),
        _ => (0.4, 0.7, 0.0),
    };
    let (ox, oy) = (Num(origin.0), Num(origin.1));
    let (frame, frame_width) = if figure.error.is_some() {
        (ERROR, 1.0)
    } else if !figure.alerts.is_empty() {
        (FAULT, 2.0)
    } else {
        (FRAME, 1.0)
    };
    writeln!(out, "<g>")?;
    let tooltip: Vec<&str> = caption
        .iter()
        .filter(|l| l.kind != Kind::Key)
        .map(|l| l.text.as_str())
        .collect();
    writeln!(out, "<title>{}</title>", Esc(&tooltip.join("; ")))?;
    writeln!(
        out,
        r#"<rect x="{ox}" y="{oy}" width="{PANEL}" height="{PANEL}" fill="none" stroke="{frame}" stroke-width="{frame_width}"/>"#
    )?;

    write!(
        out,
        r#"<path fill="{POLYGON_FILL}" fill-rule="evenodd" stroke="none" d=""#
    )?;
    rings(out, &view)?;
    writeln!(out, r#""/>"#)?;

    let triangulation = figure.triangulation.filter(|_| figure.error.is_none());
    let pseudo = figure.pseudo.filter(|_| figure.error.is_none());
    if let Some(p) = pseudo {
        faces(out, &view, p, triangle_width)?;
    } else if let Some(t) = triangulation.filter(|t| !t.triangles.is_empty()) {
        write!(
            out,
            r#"<path fill="{TRIANGLE_FILL}" stroke="{TRIANGLE_STROKE}" stroke-width="{triangle_width}" stroke-linejoin="round" d=""#
        )?;
        for &[a, b, c] in &t.triangles {
            if let (Some(a), Some(b), Some(c)) = (view.at(a), view.at(b), view.at(c)) {
                write!(out, "M{a}L{b} {c}Z")?;
            }
        }
        writeln!(out, r#""/>"#)?;
    }

    write!(
        out,
        r#"<path fill="none" stroke="{BOUNDARY}" stroke-width="{boundary_width}" stroke-linejoin="round" d=""#
    )?;
    rings(out, &view)?;
    writeln!(out, r#""/>"#)?;

    let degenerate = triangulation.map_or(&[][..], |t| &t.degenerate[..]);
    if !degenerate.is_empty() {
        write!(
            out,
            r#"<path fill="none" stroke="{DEGENERATE}" stroke-width="3" stroke-linecap="round" d=""#
        )?;
        for &[a, _, c] in degenerate {
            if let (Some(a), Some(c)) = (view.at(a), view.at(c)) {
                write!(out, "M{a}L{c}")?;
            }
        }
        writeln!(out, r#""/>"#)?;
    }

    if n <= DOTS_MAX && n > 0 {
        // A zero-length segment with round caps is a dot: far smaller than one <circle> each.
        write!(
            out,
            r#"<path fill="none" stroke="{BOUNDARY}" stroke-width="{dot_width}" stroke-linecap="round" d=""#
        )?;
        for i in 0..n {
            write!(out, "M{}h0", view.of(polygon.point(i)))?;
        }
        writeln!(out, r#""/>"#)?;
    }

    if !degenerate.is_empty() {
        writeln!(
            out,
            r##"<g fill="{DEGENERATE}" stroke="#fff" stroke-width="1.5">"##
        )?;
        for &[_, b, _] in degenerate {
            if let Some(Xy(x, y)) = view.at(b) {
                writeln!(out, r#"<circle cx="{}" cy="{}" r="3.5"/>"#, Num(x), Num(y))?;
            }
        }
        writeln!(out, "</g>")?;
    }

    if let (Some(t), Some(faults)) = (triangulation, figure.faults) {
        draw_faults(out, &view, t, faults)?;
    }

    if let Some(p) = pseudo.filter(|_| n <= DOTS_MAX) {
        corners(out, &view, p)?;
    }

    if n <= LABELS_MAX || figure.labels {
        labels(out, &view)?;
    }

    draw_caption(out, caption, origin)?;
    writeln!(out, "</g>")
}

/// The faces of a pseudotriangulation, shaded in two alternating tones.
fn faces(
    out: &mut impl Write,
    view: &View<'_>,
    p: &Pseudotriangulation,
    width: f64,
) -> io::Result<()> {
    for (tone, fill) in [FACE_FILL, FACE_FILL_2].into_iter().enumerate() {
        write!(
            out,
            r#"<path fill="{fill}" stroke="{TRIANGLE_STROKE}" stroke-width="{width}" stroke-linejoin="round" d=""#
        )?;
        for face in p.faces.iter().skip(tone).step_by(2) {
            let points: Vec<Xy> = face.cycle.iter().filter_map(|&v| view.at(v)).collect();
            if let Some((first, rest)) = points.split_first() {
                write!(out, "M{first}L")?;
                for (k, q) in rest.iter().enumerate() {
                    write!(out, "{}{q}", if k == 0 { "" } else { " " })?;
                }
                write!(out, "Z")?;
            }
        }
        writeln!(out, r#""/>"#)?;
    }
    Ok(())
}

/// A dot just inside each corner of each face, on the bisector of its angle.
fn corners(out: &mut impl Write, view: &View<'_>, p: &Pseudotriangulation) -> io::Result<()> {
    writeln!(out, r##"<g fill="{CORNER}" stroke="none">"##)?;
    for face in &p.faces {
        let k = face.cycle.len();
        for (i, &v) in face.cycle.iter().enumerate() {
            if !face.corners.contains(&v) {
                continue;
            }
            let (Some(Xy(x, y)), Some(Xy(px, py)), Some(Xy(nx, ny))) = (
                view.at(v),
                view.at(face.cycle[(i + k - 1) % k]),
                view.at(face.cycle[(i + 1) % k]),
            ) else {
                continue;
            };
            let unit = |dx: f64, dy: f64| {
                let length = dx.hypot(dy);
                if length > 0.0 {
                    (dx / length, dy / length)
                } else {
                    (0.0, 0.0)
                }
            };
            let (a, b) = (unit(px - x, py - y), unit(nx - x, ny - y));
            let (bx, by) = unit(a.0 + b.0, a.1 + b.1);
            let (cx, cy) = (Num(x + 7.0 * bx), Num(y + 7.0 * by));
            writeln!(out, r#"<circle cx="{cx}" cy="{cy}" r="2.5"/>"#)?;
        }
    }
    writeln!(out, "</g>")
}

/// Path data of every ring: one closed subpath each.
fn rings(out: &mut impl Write, view: &View<'_>) -> io::Result<()> {
    let polygon = view.polygon;
    for r in 0..=polygon.holes() {
        subpath(out, view, polygon.ring_range(r))?;
    }
    Ok(())
}

/// Path data of one closed subpath through these stored vertices (nothing for none).
fn subpath(
    out: &mut impl Write,
    view: &View<'_>,
    mut vertices: impl Iterator<Item = usize>,
) -> io::Result<()> {
    let polygon = view.polygon;
    if let Some(first) = vertices.next() {
        write!(out, "M{}L", view.of(polygon.point(first)))?;
        for (k, i) in vertices.enumerate() {
            let separator = if k == 0 { "" } else { " " };
            write!(out, "{separator}{}", view.of(polygon.point(i)))?;
        }
        write!(out, "Z")?;
    }
    Ok(())
}

/// Draws in red what the checker found wrong with `t` (see the module documentation).
fn draw_faults(
    out: &mut impl Write,
    view: &View<'_>,
    t: &Triangulation,
    faults: &Faults,
) -> io::Result<()> {
    let polygon = view.polygon;
    if !faults.stretches.is_empty() {
        // Winding number of (triangle boundaries) - (polygon boundary): nonzero exactly where the
        // cover is not once (away from the segments). Rings are reversed to subtract them.
        write!(
            out,
            r#"<path fill="{FAULT}" fill-opacity="0.4" fill-rule="nonzero" stroke="none" d=""#
        )?;
        for &[a, b, c] in &t.triangles {
            if let (Some(a), Some(b), Some(c)) = (view.at(a), view.at(b), view.at(c)) {
                write!(out, "M{a}L{b} {c}Z")?;
            }
        }
        for r in 0..=polygon.holes() {
            subpath(out, view, polygon.ring_range(r).rev())?;
        }
        writeln!(out, r#""/>"#)?;
        write!(
            out,
            r#"<path fill="none" stroke="{FAULT}" stroke-width="3" stroke-linecap="round" d=""#
        )?;
        for &[from, to] in &faults.stretches {
            write!(out, "M{}L{}", view.of(from), view.of(to))?;
        }
        writeln!(out, r#""/>"#)?;
    }
    let bad_triangles = faults.triangles.iter().filter_map(|&k| t.triangles.get(k));
    let bad_degenerate = faults
        .degenerate
        .iter()
        .filter_map(|&k| t.degenerate.get(k));
    let mut bad = bad_triangles.chain(bad_degenerate).peekable();
    if bad.peek().is_some() {
        write!(
            out,
            r#"<path fill="{FAULT}" fill-opacity="0.4" stroke="{FAULT}" stroke-width="2.5" stroke-linejoin="round" stroke-linecap="round" d=""#
        )?;
        for &[a, b, c] in bad {
            if let (Some(a), Some(b), Some(c)) = (view.at(a), view.at(b), view.at(c)) {
                write!(out, "M{a}L{b} {c}Z")?;
            }
        }
        writeln!(out, r#""/>"#)?;
    }
    Ok(())
}

/// The room around each point, in pixels: the largest `s` among [`MAX_ROOM`], [`MAX_ROOM`]/2, ...
/// down to [`MIN_ROOM`] (which every point gets at least) such that no other point lies in the
/// 3 x 3 block of grid cells of side `s` around the point's cell. Then no other point lies within
/// distance `s`; and below [`MAX_ROOM`], one lies within `4 sqrt(2) s` (in the 3 x 3 block of side
/// `2s`): the room is the nearest-neighbour distance up to a factor of 6.
/// O(n) hashing per level, O(n log(MAX_ROOM / MIN_ROOM)) in all.
fn label_rooms(points: &[Xy]) -> Vec<f64> {
    let mut room = vec![MIN_ROOM; points.len()];
    let mut undecided: Vec<usize> = (0..points.len()).collect();
    let mut side = MAX_ROOM;
    while side >= MIN_ROOM && !undecided.is_empty() {
        let cell = |Xy(x, y): Xy| ((x / side).floor() as i64, (y / side).floor() as i64);
        let mut counts: HashMap<(i64, i64), u32> = HashMap::with_capacity(points.len());
        for &p in points {
            *counts.entry(cell(p)).or_default() += 1;
        }
        undecided.retain(|&i| {
            let (cx, cy) = cell(points[i]);
            let alone = (-1..=1).all(|dx| {
                (-1..=1).all(|dy| {
                    let own = u32::from(dx == 0 && dy == 0);
                    counts.get(&(cx + dx, cy + dy)).copied().unwrap_or(0) == own
                })
            });
            if alone {
                room[i] = side;
            }
            !alone
        });
        side /= 2.0;
    }
    room
}

/// The input number of every vertex, just outside the polygon along the bisector of the outward
/// normals of its two edges, in a font that fits the room around the vertex ([`label_rooms`]):
/// [`LABEL_FONT`] pixels at most, and small enough that the number is about as wide as the room.
fn labels(out: &mut impl Write, view: &View<'_>) -> io::Result<()> {
    let polygon = view.polygon;
    let points: Vec<Xy> = polygon.points().iter().map(|&p| view.of(p)).collect();
    let rooms = label_rooms(&points);
    writeln!(
        out,
        r##"<g fill="{BOUNDARY}" text-anchor="middle" stroke="#fff" stroke-linejoin="round" paint-order="stroke">"##
    )?;
    for i in 0..polygon.len() {
        let Xy(x, y) = points[i];
        let Xy(px, py) = view.of(polygon.point(polygon.prev(i)));
        let Xy(nx, ny) = view.of(polygon.point(polygon.next(i)));
        // In pixels (y down) the interior lies right of each edge (dx, dy), so (-dy, dx) points out.
        let outward = |dx: f64, dy: f64| {
            let length = dx.hypot(dy);
            if length > 0.0 {
                (-dy / length, dx / length)
            } else {
                (0.0, 0.0)
            }
        };
        let (a, b) = (outward(x - px, y - py), outward(nx - x, ny - y));
        let (mut ux, mut uy) = (a.0 + b.0, a.1 + b.1);
        let length = ux.hypot(uy);
        if length > 1e-9 {
            (ux, uy) = (ux / length, uy / length);
        } else {
            (ux, uy) = a;
        }
        let id = polygon.id(i);
        let digits = id.to_string().len() as f64;
        // A digit is about 0.6 em wide: the number fits about its room.
        let font = LABEL_FONT.min(rooms[i] / (0.6 * digits.max(1.5)));
        let scale = font / LABEL_FONT;
        let distance = scale * (8.0 + 3.3 * digits * ux.abs());
        let (lx, ly) = (Fine(x + distance * ux), Fine(y + distance * uy));
        writeln!(
            out,
            r#"<text x="{lx}" y="{ly}" font-size="{}" stroke-width="{}" dy="0.35em">{id}</text>"#,
            Fine(font),
            Fine(3.0 * scale)
        )?;
    }
    writeln!(out, "</g>")
}

/// What a caption line is, which decides how it is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Title,
    Stats,
    Key,
    Error,
    Alert,
    Note,
}

/// One line of a caption.
struct Line {
    kind: Kind,
    text: String,
}

/// The caption lines of a figure.
fn caption(figure: &Figure<'_>) -> Vec<Line> {
    let line = |kind, text: String| Line { kind, text };
    let mut lines: Vec<Line> = wrap(&figure.title, TITLE_WRAP)
        .into_iter()
        .map(|t| line(Kind::Title, t))
        .collect();
    let polygon = figure.polygon;
    let mut stats = format!("n = {}, w = {}", polygon.len(), polygon.holes());
    match (&figure.error, figure.triangulation) {
        (Some(error), _) => {
            lines.push(line(Kind::Stats, stats));
            let mut wrapped = wrap(error, TEXT_WRAP);
            if wrapped.len() > ERROR_LINES {
                wrapped.truncate(ERROR_LINES);
                if let Some(last) = wrapped.last_mut() {
                    last.push_str(" …");
                }
            }
            lines.extend(wrapped.into_iter().map(|t| line(Kind::Error, t)));
        }
        (None, Some(t)) if figure.pseudo.is_some() => {
            if let Some(p) = figure.pseudo {
                stats += &format!(
                    ", pseudotriangles = {}, edges = {}, algorithm = {}",
                    p.faces.len(),
                    p.edge_count,
                    t.algorithm
                );
                if let Some(stopped) = p.stopped {
                    stats += &format!(", not proved minimum (stopped by {})", stopped.name());
                }
            }
            lines.push(line(Kind::Stats, stats));
            let key =
                "shaded: pseudotriangles; green dot: a corner (angle < π) of the face it lies in";
            lines.push(line(Kind::Key, key.to_string()));
        }
        (None, Some(t)) => {
            let alerts = figure.alerts.iter().flat_map(|a| wrap(a, TEXT_WRAP));
            let mut alerts: Vec<String> = alerts.collect();
            if alerts.len() > ERROR_LINES {
                alerts.truncate(ERROR_LINES);
                if let Some(last) = alerts.last_mut() {
                    last.push_str(" …");
                }
            }
            stats += &format!(
                ", d = {}, triangles = {}, algorithm = {}",
                t.degenerate.len(),
                t.triangles.len(),
                t.algorithm
            );
            if t.algorithm.is_minimum() {
                stats += if t.optimal {
                    ", optimal"
                } else {
                    ", not proved optimal"
                };
            }
            lines.push(line(Kind::Stats, stats));
            lines.extend(alerts.into_iter().map(|t| line(Kind::Alert, t)));
            let key = "orange: degenerate triangle a–c, dot = middle vertex b";
            lines.push(line(Kind::Key, key.to_string()));
        }
        (None, None) => {
            lines.push(line(Kind::Stats, stats));
            lines.push(line(Kind::Note, "not triangulated".to_string()));
        }
    }
    lines
}

/// Draws the caption lines under the panel whose top left corner is `origin`.
fn draw_caption(out: &mut impl Write, caption: &[Line], origin: (f64, f64)) -> io::Result<()> {
    let x = origin.0;
    let mut baseline = origin.1 + PANEL + CAPTION_PAD;
    for line in caption {
        baseline += LINE;
        let (text, y) = (Esc(&line.text), Num(baseline - 4.0));
        let at = |dx: f64| Num(x + dx);
        match line.kind {
            Kind::Title => writeln!(
                out,
                r#"<text x="{}" y="{y}" font-size="14" font-weight="bold" fill="{BOUNDARY}">{text}</text>"#,
                at(0.0)
            )?,
            Kind::Stats => writeln!(
                out,
                r##"<text x="{}" y="{y}" font-size="12.5" fill="#333">{text}</text>"##,
                at(0.0)
            )?,
            Kind::Error => writeln!(
                out,
                r#"<text x="{}" y="{y}" font-size="12.5" fill="{ERROR}">{text}</text>"#,
                at(0.0)
            )?,
            Kind::Alert => writeln!(
                out,
                r#"<text x="{}" y="{y}" font-size="12.5" fill="{FAULT}">{text}</text>"#,
                at(0.0)
            )?,
            Kind::Note => writeln!(
                out,
                r#"<text x="{}" y="{y}" font-size="12" fill="{MUTED}">{text}</text>"#,
                at(0.0)
            )?,
            Kind::Key => {
                let mid = Num(baseline - 8.0);
                writeln!(
                    out,
                    r#"<path fill="none" stroke="{DEGENERATE}" stroke-linecap="round" stroke-width="3" d="M{} {mid}L{} {mid}"/>"#,
                    at(2.0),
                    at(24.0)
                )?;
                writeln!(
                    out,
                    r#"<path fill="none" stroke="{DEGENERATE}" stroke-linecap="round" stroke-width="7" d="M{} {mid}h0"/>"#,
                    at(13.0)
                )?;
                writeln!(
                    out,
                    r#"<text x="{}" y="{y}" font-size="12" fill="{MUTED}">{text}</text>"#,
                    at(32.0)
                )?;
            }
        }
    }
    Ok(())
}

/// Splits `text` into lines of at most `width` characters, at spaces where possible.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    for paragraph in text.lines() {
        let mut line = String::new();
        let mut length = 0;
        let words = paragraph.split_whitespace().flat_map(|word| {
            let chars: Vec<char> = word.chars().collect();
            chars
                .chunks(width.max(1))
                .map(|c| c.iter().collect::<String>())
                .collect::<Vec<_>>()
        });
        for word in words {
            let count = word.chars().count();
            if length > 0 && length + 1 + count > width {
                lines.push(std::mem::take(&mut line));
                length = 0;
            }
            if length > 0 {
                line.push(' ');
                length += 1;
            }
            line.push_str(&word);
            length += count;
        }
        if !line.is_empty() {
            lines.push(line);
        }
    }
    if lines.is_empty() {
        lines.push(String::new());
    }
    lines
}

/// A pixel coordinate, written with at most 2 decimals and no trailing zeros.
#[derive(Clone, Copy)]
struct Num(f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let hundredths = if self.0.is_finite() {
            (self.0 * 100.0).round() as i64
        } else {
            0
        };
        let sign = if hundredths < 0 { "-" } else { "" };
        let magnitude = hundredths.unsigned_abs();
        let (int, frac) = (magnitude / 100, magnitude % 100);
        if frac == 0 {
            write!(f, "{sign}{int}")
        } else if frac % 10 == 0 {
            write!(f, "{sign}{int}.{}", frac / 10)
        } else {
            write!(f, "{sign}{int}.{frac:02}")
        }
    }
}

/// A pixel size or coordinate written with at most 4 decimals (labels may be tiny).
#[derive(Clone, Copy)]
struct Fine(f64);

impl fmt::Display for Fine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = if self.0.is_finite() { self.0 } else { 0.0 };
        let text = format!("{v:.4}");
        let text = text.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if text == "-0" { "0" } else { text })
    }
}

/// A pixel point, written `x y` for path data.
#[derive(Clone, Copy)]
struct Xy(f64, f64);

impl fmt::Display for Xy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", Num(self.0), Num(self.1))
    }
}

/// Text escaped for XML content and attribute values; characters XML 1.0 forbids become `?`.
struct Esc<'a>(&'a str);

impl fmt::Display for Esc<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in self.0.chars() {
            match c {
                '&' => f.write_str("&amp;")?,
                '<' => f.write_str("&lt;")?,
                '>' => f.write_str("&gt;")?,
                '"' => f.write_str("&quot;")?,
                '\'' => f.write_str("&apos;")?,
                '\t' | '\n' | '\r' => f.write_str(" ")?,
                c if c < ' ' || c == '\u{fffe}' || c == '\u{ffff}' => f.write_str("?")?,
                c => write!(f, "{c}")?,
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::Algorithm;
    use crate::io::read::RawPolygon;
    use crate::test_support::{d, polygon, U_SHAPE};

    /// The U shape with every coordinate mapped by `map`.
    fn u_shape(map: impl Fn(i64) -> String) -> Polygon {
        let rings = vec![U_SHAPE
            .iter()
            .map(|&(x, y)| [d(&map(x)), d(&map(y))])
            .collect()];
        let (p, _) = Polygon::from_raw(&RawPolygon {
            rings,
            ordinates: None,
        })
        .unwrap();
        assert!((0..12).all(|i| p.id(i) == i), "stored in input order");
        p
    }

    /// A minimum triangulation of the U: the bottom bar is two triangles with T-junctions at
    /// 1, 2 (on side 0–3) and 8, 7 (on side 11–4), each arm two triangles.
    fn u_triangulation() -> Triangulation {
        Triangulation {
            algorithm: Algorithm::Asano,
            triangles: vec![
                [0, 3, 11],
                [3, 4, 11],
                [11, 8, 9],
                [11, 9, 10],
                [7, 4, 5],
                [7, 5, 6],
            ],
            degenerate: vec![[0, 1, 3], [1, 2, 3], [11, 8, 4], [8, 7, 4]],
            optimal: true,
            lower_bound: None,
            stopped: None,
        }
    }

    /// A "pie": vertex 0 at the origin, then vertices at increasing angles up to 338 degrees and
    /// random radii; every 25th direction carries two vertices on one ray (near, then far),
    /// giving the degenerate triangle [0, near, far]. The fan from vertex 0 triangulates it.
    fn pie(slots: usize) -> (Polygon, Triangulation) {
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut ring = vec![(0, 0)];
        let mut near = Vec::new();
        for s in 0..slots {
            let angle = 5.9 * s as f64 / (slots - 1) as f64;
            let (cos, sin) = (angle.cos(), angle.sin());
            if s % 25 == 12 {
                let d = ((500.0 * cos).round() as i64, (500.0 * sin).round() as i64);
                near.push(ring.len());
                ring.push((2 * d.0, 2 * d.1));
                ring.push((5 * d.0, 5 * d.1));
            } else {
                let r = 1000.0 + (random() % 2000) as f64;
                ring.push(((r * cos).round() as i64, (r * sin).round() as i64));
            }
        }
        let p = polygon(&[&ring]);
        let n = p.len();
        assert!(
            n == ring.len() && (0..n).all(|i| p.id(i) == i),
            "stored in input order"
        );
        let t = Triangulation {
            algorithm: Algorithm::Asano,
            triangles: (1..n - 1)
                .filter(|k| !near.contains(k))
                .map(|k| [0, k, k + 1])
                .collect(),
            degenerate: near.iter().map(|&k| [0, k, k + 1]).collect(),
            optimal: false,
            lower_bound: None,
            stopped: None,
        };
        (p, t)
    }

    fn figure<'a>(
        title: &str,
        polygon: &'a Polygon,
        triangulation: Option<&'a Triangulation>,
    ) -> Figure<'a> {
        Figure {
            triangulation,
            ..Figure::new(title.to_string(), polygon)
        }
    }

    fn render(figures: &[Figure<'_>]) -> String {
        let mut bytes = Vec::new();
        write_svg(figures, &mut bytes).unwrap();
        String::from_utf8(bytes).unwrap()
    }

    /// Every `&` starts one of the five named entities.
    fn check_entities(text: &str) {
        for (i, _) in text.match_indices('&') {
            let tail = &text[i..];
            let ok = ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"]
                .iter()
                .any(|e| tail.starts_with(e));
            assert!(ok, "raw & in {text:?}");
        }
    }

    /// `name="value" ...`: names unique, values without `<`, entities only.
    fn check_attributes(attributes: &str) {
        let mut names = Vec::new();
        let mut rest = attributes.trim_start();
        while !rest.is_empty() {
            let eq = rest
                .find("=\"")
                .unwrap_or_else(|| panic!("attribute without =\" in {rest:?}"));
            let name = &rest[..eq];
            assert!(
                !name.is_empty()
                    && name
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == ':')
            );
            assert!(!names.contains(&name), "duplicate attribute {name}");
            names.push(name);
            let after = &rest[eq + 2..];
            let close = after
                .find('"')
                .unwrap_or_else(|| panic!("unterminated value in {rest:?}"));
            let value = &after[..close];
            assert!(!value.contains('<'), "< in attribute {value:?}");
            check_entities(value);
            rest = &after[close + 1..];
            assert!(
                rest.is_empty() || rest.starts_with(char::is_whitespace),
                "no space after {name}"
            );
            rest = rest.trim_start();
        }
    }

    /// A small well-formedness check: balanced tags, one root `svg`, sane attributes, entities.
    fn assert_well_formed(svg: &str) {
        let mut stack: Vec<&str> = Vec::new();
        let mut roots = Vec::new();
        let mut rest = svg;
        while let Some(start) = rest.find('<') {
            let text = &rest[..start];
            check_entities(text);
            assert!(!text.contains('>'), "stray > in {text:?}");
            assert!(
                !stack.is_empty() || text.trim().is_empty(),
                "text outside the root: {text:?}"
            );
            rest = &rest[start..];
            if let Some(tail) = rest.strip_prefix("<?") {
                assert!(
                    stack.is_empty() && roots.is_empty(),
                    "declaration inside the document"
                );
                rest = &tail[tail.find("?>").expect("unclosed <?") + 2..];
                continue;
            }
            let end = rest.find('>').expect("unclosed tag");
            let tag = &rest[1..end];
            rest = &rest[end + 1..];
            if let Some(name) = tag.strip_prefix('/') {
                assert_eq!(stack.pop(), Some(name.trim()), "mismatched </{name}>");
                continue;
            }
            let self_closed = tag.ends_with('/');
            let body = tag.strip_suffix('/').unwrap_or(tag);
            let name = body.split(char::is_whitespace).next().unwrap_or("");
            assert!(
                !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric()),
                "bad tag <{tag}>"
            );
            check_attributes(&body[name.len()..]);
            if stack.is_empty() {
                roots.push(name);
            }
            if !self_closed {
                stack.push(name);
            }
        }
        assert!(rest.trim().is_empty(), "text after the root");
        assert!(stack.is_empty(), "unclosed {stack:?}");
        assert_eq!(roots, ["svg"]);
    }

    /// The value of attribute `name` in the opening tag starting at `tag`.
    fn attribute<'s>(tag: &'s str, name: &str) -> Option<&'s str> {
        let tag = &tag[..tag.find('>')?];
        let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(&tag[start..start + tag[start..].find('"')?])
    }

    /// The points of absolute path data made of `M`, `L` (implicit repeats), `h0` and `Z`.
    fn path_points(d: &str) -> Vec<[f64; 2]> {
        let mut points = Vec::new();
        let mut commands: Vec<(char, Vec<f64>)> = Vec::new();
        let mut token = String::new();
        let finish = |token: &mut String, commands: &mut Vec<(char, Vec<f64>)>| {
            if !token.is_empty() {
                let value = token
                    .parse()
                    .unwrap_or_else(|_| panic!("bad number {token:?} in {d:?}"));
                commands
                    .last_mut()
                    .expect("number before any command")
                    .1
                    .push(value);
                token.clear();
            }
        };
        for c in d.chars() {
            if c.is_ascii_alphabetic() {
                finish(&mut token, &mut commands);
                commands.push((c, Vec::new()));
            } else if c == ' ' {
                finish(&mut token, &mut commands);
            } else {
                token.push(c);
            }
        }
        finish(&mut token, &mut commands);
        for (command, numbers) in commands {
            match command {
                'M' | 'L' => {
                    assert!(!numbers.is_empty() && numbers.len() % 2 == 0, "{d:?}");
                    points.extend(numbers.chunks(2).map(|c| [c[0], c[1]]));
                }
                'h' => assert_eq!(numbers, [0.0]),
                'Z' => assert!(numbers.is_empty()),
                other => panic!("unexpected path command {other} in {d:?}"),
            }
        }
        points
    }

    /// Every coordinate drawn (path data, x, y, cx, cy) lies inside the viewBox.
    fn assert_inside_view_box(svg: &str) -> usize {
        let root = &svg[svg.find("<svg").unwrap()..];
        let view_box: Vec<f64> = attribute(root, "viewBox")
            .unwrap()
            .split(' ')
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(view_box[..2], [0.0, 0.0]);
        assert_eq!(
            attribute(root, "width").unwrap().parse::<f64>().unwrap(),
            view_box[2]
        );
        let (width, height) = (view_box[2], view_box[3]);
        let inside = |[x, y]: [f64; 2]| {
            assert!(
                (0.0..=width).contains(&x) && (0.0..=height).contains(&y),
                "({x}, {y}) outside {width}x{height}"
            );
        };
        let mut checked = 0;
        for (start, _) in svg.match_indices('<') {
            let tag = &svg[start..];
            if let Some(d) = attribute(tag, "d") {
                path_points(d).into_iter().for_each(inside);
                checked += 1;
            }
            for (x, y) in [("x", "y"), ("cx", "cy")] {
                if let (Some(x), Some(y)) = (attribute(tag, x), attribute(tag, y)) {
                    inside([x.parse().unwrap(), y.parse().unwrap()]);
                    checked += 1;
                }
            }
        }
        checked
    }

    #[test]
    fn u_shape_legend_markers_and_well_formed() {
        let p = u_shape(|v| v.to_string());
        let t = u_triangulation();
        let svg = render(&[figure("shapes/u.wkt #0", &p, Some(&t))]);
        assert_well_formed(&svg);
        assert!(svg.starts_with("<?xml"));
        assert!(svg.contains(r#"<svg xmlns="http://www.w3.org/2000/svg" "#));
        assert!(svg.contains(">shapes/u.wkt #0</text>"));
        assert!(
            svg.contains(">n = 12, w = 0, d = 4, triangles = 6, algorithm = asano, optimal</text>"),
            "{svg}"
        );
        assert!(svg.contains("orange: degenerate triangle a–c, dot = middle vertex b"));
        assert_eq!(
            svg.matches("<circle").count(),
            4,
            "one marker per degenerate triangle"
        );
        // The markers sit on the middle vertices: 1 = (4, 2) is one third along the bottom.
        let circles: Vec<[f64; 2]> = svg
            .match_indices("<circle")
            .map(|(i, _)| {
                let tag = &svg[i..];
                [
                    attribute(tag, "cx").unwrap().parse().unwrap(),
                    attribute(tag, "cy").unwrap().parse().unwrap(),
                ]
            })
            .collect();
        let view = View::new(&p, (GAP, GAP));
        for (circle, [_, b, _]) in circles.iter().zip(&t.degenerate) {
            let Xy(x, y) = view.at(*b).unwrap();
            assert!((circle[0] - x).abs() < 0.01 && (circle[1] - y).abs() < 0.01);
        }
        // Up is up: vertex 10 = (3, 4) is drawn above vertex 0 = (3, 2).
        assert!(view.at(10).unwrap().1 < view.at(0).unwrap().1);
        // Every triangle once; vertex dots; labels with input numbers.
        let triangles = svg.lines().find(|l| l.contains(TRIANGLE_STROKE)).unwrap();
        assert_eq!(triangles.matches('Z').count(), 6);
        assert_eq!(
            svg.matches("h0").count(),
            12 + 1,
            "12 vertex dots and the key's dot"
        );
        for id in 0..12 {
            assert!(svg.contains(&format!(r#"dy="0.35em">{id}</text>"#)));
        }
        assert!(assert_inside_view_box(&svg) > 20);
    }

    #[test]
    fn huge_and_tiny_coordinates_stay_inside_the_view_box() {
        let huge = u_shape(|v| (1_000_000_000_000_000i64 + v).to_string());
        let tiny = u_shape(|v| format!("{v}e-6"));
        let t = u_triangulation();
        for p in [&huge, &tiny] {
            let svg = render(&[figure("u", p, Some(&t))]);
            assert_well_formed(&svg);
            assert!(assert_inside_view_box(&svg) > 20);
            // Same picture as the plain U: the offset and the scale change nothing.
            let plain = u_shape(|v| v.to_string());
            assert_eq!(svg, render(&[figure("u", &plain, Some(&t))]));
        }
        // Several panels in a grid (2 rows), a hole, an error and no triangulation.
        let (star, star_t) = pie(100);
        let holed = square_with_hole();
        let mut figures: Vec<Figure<'_>> = vec![
            figure("huge", &huge, Some(&t)),
            figure("tiny", &tiny, Some(&t)),
            figure("star", &star, Some(&star_t)),
            figure("holed", &holed, None),
        ];
        figures.push(Figure {
            error: Some("it failed".into()),
            ..figure("bad", &tiny, Some(&t))
        });
        let svg = render(&figures);
        assert_well_formed(&svg);
        assert!(
            svg.contains(r#"width="2016" height="#),
            "three panels per row"
        );
        assert!(assert_inside_view_box(&svg) > 100);
    }

    fn square_with_hole() -> Polygon {
        polygon(&[
            &[(0, 0), (10, 0), (10, 10), (0, 10)],
            &[(3, 3), (3, 7), (7, 7), (7, 3)],
        ])
    }

    #[test]
    fn holes_are_drawn_empty_with_evenodd() {
        let p = square_with_hole();
        let svg = render(&[figure("holed", &p, None)]);
        assert_well_formed(&svg);
        let fill = svg
            .lines()
            .find(|l| l.contains(r#"fill-rule="evenodd""#))
            .expect("an evenodd path");
        let d = attribute(fill, "d").unwrap();
        assert_eq!(
            (d.matches('M').count(), d.matches('Z').count()),
            (2, 2),
            "both rings in one path"
        );
        assert_eq!(path_points(d).len(), 8);
        assert!(svg.contains(">n = 8, w = 1</text>") && svg.contains(">not triangulated</text>"));
        assert!(!svg.contains("<circle") && !svg.contains(TRIANGLE_STROKE));
    }

    #[test]
    fn text_is_escaped() {
        let p = u_shape(|v| v.to_string());
        let t = u_triangulation();
        let title = r#"a<b & "c" 'd'>"#;
        let svg = render(&[
            figure(title, &p, Some(&t)),
            Figure {
                error: Some("x < y & z\u{1}".into()),
                ..figure("e", &p, Some(&t))
            },
        ]);
        assert_well_formed(&svg);
        assert!(
            svg.contains(">a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;</text>"),
            "{svg}"
        );
        assert!(!svg.contains("a<b"));
        // The error replaces the triangles and is written in red.
        assert!(svg.contains(&format!(r#"fill="{ERROR}">x &lt; y &amp; z?</text>"#)));
        assert_eq!(
            svg.matches(TRIANGLE_STROKE).count(),
            1,
            "only the first figure has triangles"
        );
        assert_eq!(
            svg.matches("<circle").count(),
            4,
            "only the first figure has markers"
        );
    }

    #[test]
    fn numbers_and_wrapping() {
        let text = |v: f64| Num(v).to_string();
        assert_eq!(
            [
                text(1.0),
                text(1.5),
                text(1.25),
                text(-0.001),
                text(-2.349),
                text(f64::NAN)
            ],
            ["1", "1.5", "1.25", "0", "-2.35", "0"]
        );
        assert_eq!(wrap("aaa bb cc", 6), ["aaa bb", "cc"]);
        assert_eq!(wrap("abcdefgh", 3), ["abc", "def", "gh"]);
        assert_eq!(wrap("", 5), [""]);
        assert_eq!(wrap("one\ntwo", 80), ["one", "two"]);
        let long = "word ".repeat(500);
        let p = u_shape(|v| v.to_string());
        let caption = caption(&Figure {
            error: Some(long),
            ..figure("t", &p, None)
        });
        assert_eq!(
            caption.iter().filter(|l| l.kind == Kind::Error).count(),
            ERROR_LINES
        );
        assert!(caption
            .iter()
            .all(|l| l.text.chars().count() <= TEXT_WRAP + 2));
    }

    #[test]
    fn large_polygons_stay_small_and_legible() {
        let (p, t) = pie(3000);
        assert!(p.len() > DOTS_MAX);
        let svg = render(&[figure("pie", &p, Some(&t))]);
        assert_well_formed(&svg);
        assert!(!svg.contains("0.35em"), "no labels");
        assert_eq!(
            svg.matches("h0").count(),
            1,
            "no vertex dots, only the key's"
        );
        assert_eq!(svg.matches("<circle").count(), t.degenerate.len());
        assert!(
            svg.len() < 80 * p.len() + 4000,
            "{} bytes for {} vertices",
            svg.len(),
            p.len()
        );
        assert!(assert_inside_view_box(&svg) > 100);
        assert!(render(&[]).contains("no polygons to draw"));
        assert_well_formed(&render(&[]));
    }

    #[test]
    fn label_rooms_bound_the_nearest_neighbour_distance() {
        // Far from everything: the largest room. Two points 0.3 apart: cells of 0.25 put them in
        // neighbouring columns (802 and 803), cells of 0.125 two columns apart (1604, 1606).
        let rooms = label_rooms(&[Xy(0.5, 0.5), Xy(200.5, 200.5), Xy(200.8, 200.5)]);
        assert_eq!(rooms, [MAX_ROOM, 0.125, 0.125]);
        // Coincident points get the smallest room.
        assert_eq!(label_rooms(&[Xy(3.0, 3.0), Xy(3.0, 3.0)]), [MIN_ROOM; 2]);
        // Random clouds of every density, against the brute-force nearest neighbour.
        let mut random = crate::test_support::xorshift(11);
        for spread in [5, 50, 500, 5000] {
            let points: Vec<Xy> = (0..300)
                .map(|_| {
                    Xy(
                        random(spread * 100) as f64 / 100.0,
                        random(spread * 100) as f64 / 100.0,
                    )
                })
                .collect();
            let rooms = label_rooms(&points);
            for (i, &Xy(x, y)) in points.iter().enumerate() {
                let nearest = points
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, &Xy(u, v))| (u - x).hypot(v - y))
                    .fold(f64::INFINITY, f64::min);
                let room = rooms[i];
                assert!((MIN_ROOM..=MAX_ROOM).contains(&room));
                assert!(room == MIN_ROOM || nearest >= room, "{nearest} < {room}");
                assert!(
                    room == MAX_ROOM || nearest <= 6.0 * room,
                    "{nearest} > 6 x {room}"
                );
            }
        }
    }

    #[test]
    fn faults_are_drawn_in_red_over_the_figure() {
        let p = u_shape(|v| v.to_string());
        let mut t = u_triangulation();
        t.triangles.pop();
        t.triangles[0] = [0, 11, 3]; // clockwise
        let check = crate::verify::check(&p, &t);
        assert!(!check.valid && check.faults.triangles == [0]);
        let svg = render(&[Figure {
            faults: Some(&check.faults),
            alerts: vec!["disagreement: it is wrong".into()],
            ..figure("faulty", &p, Some(&t))
        }]);
        assert_well_formed(&svg);
        // The region path: the 5 triangles and the ring reversed, one subpath each.
        let region = svg
            .lines()
            .find(|l| l.contains(r#"fill-rule="nonzero""#))
            .expect("the region covered other than once");
        assert!(region.contains(FAULT));
        let d = attribute(region, "d").unwrap();
        assert_eq!(d.matches('M').count(), 5 + 1);
        let ring = path_points(&d[d.rfind('M').unwrap()..]);
        let view = View::new(&p, (GAP, GAP));
        let reversed: Vec<[f64; 2]> = (0..12)
            .rev()
            .map(|i| {
                let Xy(x, y) = view.at(i).unwrap();
                [x, y]
            })
            .collect();
        for (a, b) in ring.iter().zip(&reversed) {
            assert!((a[0] - b[0]).abs() < 0.01 && (a[1] - b[1]).abs() < 0.01);
        }
        // One stroke per uncancelled stretch; the clockwise triangle outlined.
        let stretches = svg
            .lines()
            .find(|l| l.contains(&format!(r#"<path fill="none" stroke="{FAULT}""#)))
            .unwrap();
        assert_eq!(
            attribute(stretches, "d").unwrap().matches('M').count(),
            check.faults.stretches.len()
        );
        assert!(svg.contains(&format!(
            r#"<path fill="{FAULT}" fill-opacity="0.4" stroke="{FAULT}""#
        )));
        // Red frame, red alert text.
        assert!(svg.contains(&format!(r#"stroke="{FAULT}" stroke-width="2"/>"#)));
        assert!(svg.contains(&format!(
            r#"fill="{FAULT}">disagreement: it is wrong</text>"#
        )));
        // A valid triangulation with empty faults draws nothing red.
        let clean = crate::verify::check(&p, &u_triangulation());
        let svg = render(&[Figure {
            faults: Some(&clean.faults),
            ..figure("clean", &p, Some(&u_triangulation()))
        }]);
        assert!(!svg.contains(FAULT));
    }

    /// Writes sample drawings to the temporary directory, to look at (`--ignored`).
    #[test]
    #[ignore]
    fn render_samples() {
        let dir = std::env::temp_dir();
        let u = u_shape(|v| v.to_string());
        let t = u_triangulation();
        let (star, star_t) = pie(500);
        let holed = square_with_hole();
        let samples: [(&str, Vec<Figure<'_>>); 3] = [
            ("u.svg", vec![figure("shapes/u.wkt #0", &u, Some(&t))]),
            ("star.svg", vec![figure("random pie #0 (500 directions)", &star, Some(&star_t))]),
            (
                "grid.svg",
                vec![
                    figure("shapes/u.wkt #0", &u, Some(&t)),
                    figure("holed.wkt #0", &holed, None),
                    Figure {
                        error: Some("the minitri algorithm is not implemented yet; use --algorithm asano (exact minimum) or --algorithm ear".into()),
                        ..figure("star <pie> & co #1", &star, Some(&star_t))
                    },
                    figure("random pie #0", &star, Some(&star_t)),
                ],
            ),
        ];
        for (name, figures) in samples {
            let svg = render(&figures);
            assert_well_formed(&svg);
            std::fs::write(dir.join(name), svg).unwrap();
        }
    }
}
