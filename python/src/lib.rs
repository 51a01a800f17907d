//! The Python extension `minitri._minitri`: the library's pipeline (read, validate, triangulate,
//! verify) on WKT or GeoJSON text or WKB bytes, one geometry or many in parallel. The Python
//! package (`minitri/__init__.py`) shapes the results for shapely and GeoPandas users.
//!
//! Every geometry becomes one [`Item`]: the CLI's JSON text of each solved polygon, the CLI's
//! messages (errors, warnings) without the source name, the triangles as one WKB MultiPolygon
//! and the totals. Nothing here decides a fact about the geometry: that is the library's work.

// The public API, and below it (the `internals` feature, docs/library.md) the three things the
// command line's front end does that no library function offers: reading GeoJSON Lines one line
// at a time, splitting WKB into its geometries with their floats, and the outcome of an input
// that could not be read; and the CLI's JSON text of an outcome (`io::write::json::render`).
use minitri::io::read::{self, geojson_stream};
use minitri::pipeline;
use minitri::{
    Algorithm, Coord, Error, Format, Options, Outcome, ParseError, Polygon, Triangulation,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use rayon::prelude::*;

/// One geometry's result.
#[derive(Default)]
struct Item {
    /// The CLI's JSON object of each solved polygon (its `polygons` entry).
    parts: Vec<String>,
    /// The CLI's error messages, `polygon 2: ...` (no source name).
    errors: Vec<String>,
    /// The CLI's warnings, `polygon 2: ...`.
    warnings: Vec<String>,
    /// With `verify`: why a polygon's verification failed, `polygon 2: ...`.
    failures: Vec<String>,
    /// All triangles (of every polygon, in order) as a WKB MultiPolygon, when nothing failed.
    wkb: Option<Vec<u8>>,
    triangle_count: usize,
    degenerate_count: usize,
    optimal: bool,
    lower: usize,
    upper: usize,
}

/// The input of one geometry.
enum Input<'a> {
    Text(&'a str, Format),
    Wkb(&'a [u8]),
}

/// The algorithm named `name` (triangulations only: pseudotriangulations are the CLI's).
fn algorithm(name: &str) -> PyResult<Algorithm> {
    match name {
        "minitri" => Ok(Algorithm::Minitri),
        "asano" => Ok(Algorithm::Asano),
        "ear" => Ok(Algorithm::Ear),
        other => Err(PyValueError::new_err(format!(
            "unknown algorithm {other:?}: expected \"minitri\", \"asano\" or \"ear\""
        ))),
    }
}

/// The outcomes of one input, as the CLI's pipeline makes them, each with the input floats in
/// input numbering for WKB (`None` for text, whose decimals are rounded on the way out).
fn outcomes(input: &Input<'_>, options: &Options) -> Vec<(Outcome, Option<Vec<[f64; 2]>>)> {
    match input {
        Input::Text(text, format) => text_outcomes(text, *format, options)
            .into_iter()
            .map(|outcome| (outcome, None))
            .collect(),
        Input::Wkb(bytes) => match read::wkb::polygons(bytes) {
            Ok(polygons) => polygons
                .into_iter()
                .enumerate()
                .flat_map(|(i, p)| {
                    // Several outcomes only when `--repair` splits a polygon (not offered here).
                    let floats = p.floats;
                    minitri::process_raw("-", i, p.raw, options)
                        .into_iter()
                        .map(move |outcome| (outcome, Some(floats.clone())))
                })
                .collect(),
            Err(e) => vec![(pipeline::unreadable("-", Error::Parse(e)), None)],
        },
    }
}

/// The outcomes of a text, read as the CLI reads a file or standard input: binary data refused,
/// GeoJSON Lines line by line (a bad line reported alone, the polygons numbered over the lines).
fn text_outcomes(text: &str, format: Format, options: &Options) -> Vec<Outcome> {
    if let Some(error) = read::not_text(text.as_bytes(), true) {
        return vec![pipeline::unreadable("-", Error::Parse(error))];
    }
    if format != Format::GeoJson || !geojson_stream::looks_line_delimited(text.as_bytes()) {
        return minitri::process("-", text, format, options);
    }
    let mut outcomes = Vec::new();
    let mut index = 0;
    let mut any = false;
    for (k, line) in text.split_inclusive('\n').enumerate() {
        if line.trim_matches([' ', '\t', '\n', '\r']).is_empty() {
            continue;
        }
        any = true;
        // A member of a GeometryCollection that is not a polygon is reported in its place.
        match geojson_stream::read_line_feature(line, k + 1, 0).1 {
            Err(e) => outcomes.push(pipeline::unreadable("-", Error::Parse(e))),
            Ok(parts) => {
                for part in parts {
                    match part {
                        Ok(raw) => {
                            outcomes.extend(minitri::process_raw("-", index, raw, options));
                            index += 1;
                        }
                        Err(e) => outcomes.push(pipeline::unreadable("-", Error::Parse(e))),
                    }
                }
            }
        }
    }
    if !any {
        let error = ParseError::new("empty input: no polygon found");
        outcomes.push(pipeline::unreadable("-", Error::Parse(error)));
    }
    outcomes
}

/// A message as the CLI prints it, without `minitri: SOURCE: `.
fn without_source(outcome: &Outcome, message: impl std::fmt::Display) -> String {
    match outcome.index {
        Some(i) => format!("polygon {i}: {message}"),
        None => message.to_string(),
    }
}

/// Triangulates one input and gathers its [`Item`].
fn solve(input: &Input<'_>, options: &Options, json: bool) -> Item {
    let outcomes = outcomes(input, options);
    let mut item = Item {
        optimal: true,
        ..Item::default()
    };
    let mut triangles = Vec::new();
    // Each triangle's corners' Z (NaN for none), when an input polygon has Z values.
    let mut heights: Vec<[f64; 3]> = Vec::new();
    let with_z = outcomes
        .iter()
        .any(|(o, _)| o.ordinates.as_ref().is_some_and(|z| z.dims.has_z()));
    for (outcome, floats) in &outcomes {
        for warning in &outcome.warnings {
            item.warnings.push(without_source(outcome, warning));
        }
        match (&outcome.result, &outcome.polygon) {
            (Ok(solved), Some(polygon)) => {
                let t = &solved.triangulation;
                minitri::with_polygon!(polygon, p => {
                    add(&mut item, p, t);
                    let before = triangles.len();
                    match floats {
                        Some(floats) => triangles.extend(input_triangles(p, t, floats)),
                        None => triangles.extend(minitri::geo::multi_polygon(p, t)),
                    }
                    if with_z {
                        let z = |v: usize| {
                            let value = outcome.ordinates.as_ref().and_then(|o| o.z(v));
                            value.and_then(|d| d.as_ref()).map_or(f64::NAN, |d| d.to_f64())
                        };
                        // The same triangles, in the same order, as input vertex numbers (if
                        // a triangle was skipped above, the counts differ: no Z then).
                        let corners = t.input_triangles(p);
                        if corners.len() == triangles.len() - before {
                            heights.extend(corners.iter().map(|&[a, b, c]| [z(a), z(b), z(c)]));
                        }
                    }
                });
                if json {
                    item.parts.extend(minitri::io::write::json::render(outcome));
                }
                if let Some(v) = solved.verification.as_ref().filter(|v| !v.ok) {
                    let why = v
                        .disagreement
                        .clone()
                        .unwrap_or_else(|| "an output failed the independent check".into());
                    item.failures.push(without_source(outcome, why));
                }
            }
            (Err(e), _) => {
                for message in e.messages() {
                    item.errors.push(without_source(outcome, message));
                }
            }
            (Ok(_), None) => {}
        }
    }
    if item.errors.is_empty() && with_z && heights.len() == triangles.len() {
        item.wkb = Some(multi_polygon_z(&triangles, &heights));
    } else if item.errors.is_empty() {
        let multi = geo_types::MultiPolygon::new(triangles);
        let mut out = Vec::with_capacity(wkb::writer::multi_polygon_wkb_size(&multi));
        item.wkb = wkb::writer::write_multi_polygon(&mut out, &multi, &Default::default())
            .ok()
            .map(|()| out);
    }
    item
}

/// ISO WKB (little-endian) of a MultiPolygon Z of triangles: each triangle's ring (its three
/// corners and the first again) with the corners' Z from `heights` (NaN for none).
fn multi_polygon_z(triangles: &[geo_types::Polygon<f64>], heights: &[[f64; 3]]) -> Vec<u8> {
    let mut out = Vec::with_capacity(9 + triangles.len() * (13 + 4 * 24));
    out.push(1);
    out.extend(1006u32.to_le_bytes());
    out.extend(
        u32::try_from(triangles.len())
            .unwrap_or(u32::MAX)
            .to_le_bytes(),
    );
    for (triangle, z) in triangles.iter().zip(heights) {
        out.push(1);
        out.extend(1003u32.to_le_bytes());
        out.extend(1u32.to_le_bytes());
        let ring = &triangle.exterior().0;
        out.extend(u32::try_from(ring.len()).unwrap_or(u32::MAX).to_le_bytes());
        for (k, c) in ring.iter().enumerate() {
            out.extend(c.x.to_le_bytes());
            out.extend(c.y.to_le_bytes());
            out.extend(z[k % 3].to_le_bytes());
        }
    }
    out
}

/// The triangles of `t` with corners taken from the input floats (`floats[k]` is input vertex
/// `k`): the same corners as [`minitri::geo::multi_polygon`] gives for float input (the shortest
/// decimal of a float rounds back to it), without formatting and parsing each one.
fn input_triangles<P: Coord>(
    polygon: &Polygon<P>,
    t: &Triangulation,
    floats: &[[f64; 2]],
) -> Vec<geo_types::Polygon<f64>> {
    let corner = |v: usize| floats.get(v).map(|&[x, y]| geo_types::Coord { x, y });
    t.input_triangles(polygon)
        .into_iter()
        .filter_map(|[a, b, c]| {
            Some(geo_types::Triangle::new(corner(a)?, corner(b)?, corner(c)?).to_polygon())
        })
        .collect()
}

/// Adds one solved polygon to the totals.
fn add<P: Coord>(item: &mut Item, polygon: &Polygon<P>, t: &Triangulation) {
    item.triangle_count += t.triangles.len();
    item.degenerate_count += t.degenerate.len();
    item.optimal &= t.optimal;
    let (lower, upper) = polygon.minimum_bounds();
    item.lower += lower;
    item.upper += upper;
}

fn options(algorithm_name: &str, verify: bool) -> PyResult<Options> {
    Ok(Options {
        algorithm: algorithm(algorithm_name)?,
        verify,
        ..Options::default()
    })
}

/// `(parts, errors, warnings, failures, wkb)` of one item, for the single call.
type Single<'py> = (
    Vec<String>,
    Vec<String>,
    Vec<String>,
    Vec<String>,
    Option<Bound<'py, PyBytes>>,
);

fn single<'py>(py: Python<'py>, item: Item) -> Single<'py> {
    let wkb = item.wkb.map(|b| PyBytes::new(py, &b));
    (item.parts, item.errors, item.warnings, item.failures, wkb)
}

/// Triangulates the polygons of WKT or GeoJSON text, exactly as written.
#[pyfunction]
#[pyo3(signature = (text, format, algorithm = "minitri", verify = false))]
fn triangulate_text<'py>(
    py: Python<'py>,
    text: &str,
    format: &str,
    algorithm: &str,
    verify: bool,
) -> PyResult<Single<'py>> {
    let format = match format {
        "wkt" => Format::Wkt,
        "geojson" => Format::GeoJson,
        other => {
            return Err(PyValueError::new_err(format!(
                "unknown text format {other:?}"
            )))
        }
    };
    let options = options(algorithm, verify)?;
    let item = py.detach(|| solve(&Input::Text(text, format), &options, true));
    Ok(single(py, item))
}

/// Triangulates the Polygon or MultiPolygon of one WKB (floats as their shortest decimals).
#[pyfunction]
#[pyo3(signature = (wkb, algorithm = "minitri", verify = false))]
fn triangulate_wkb<'py>(
    py: Python<'py>,
    wkb: &[u8],
    algorithm: &str,
    verify: bool,
) -> PyResult<Single<'py>> {
    let options = options(algorithm, verify)?;
    let item = py.detach(|| solve(&Input::Wkb(wkb), &options, true));
    Ok(single(py, item))
}

/// The columns of [`triangulate_wkb_many`]: triangle and degenerate counts, optimal, lower and
/// upper bounds, the WKB of the triangles (`None` on error), the first error (`None` if none),
/// the warnings, whether the error is a failed verification.
type Columns<'py> = (
    Vec<i64>,
    Vec<i64>,
    Vec<bool>,
    Vec<i64>,
    Vec<i64>,
    Vec<Option<Bound<'py, PyBytes>>>,
    Vec<Option<String>>,
    Vec<Vec<String>>,
    Vec<bool>,
);

/// Triangulates many WKB geometries in parallel (the GIL released, on rayon's pool of `jobs`
/// threads, all cores when `None`). A geometry that is `None` (missing) or fails gets counts
/// of -1 and its error.
#[pyfunction]
#[pyo3(signature = (wkbs, algorithm = "minitri", verify = false, jobs = None))]
fn triangulate_wkb_many<'py>(
    py: Python<'py>,
    wkbs: Vec<Option<Bound<'py, PyBytes>>>,
    algorithm: &str,
    verify: bool,
    jobs: Option<usize>,
) -> PyResult<Columns<'py>> {
    let options = options(algorithm, verify)?;
    // Bytes objects are immutable: their contents may be read without the GIL.
    let slices: Vec<Option<&[u8]>> = wkbs
        .iter()
        .map(|b| b.as_ref().map(|b| b.as_bytes()))
        .collect();
    let run = || -> Vec<Option<Item>> {
        slices
            .par_iter()
            .map(|bytes| bytes.map(|b| solve(&Input::Wkb(b), &options, false)))
            .collect()
    };
    let items = py.detach(|| match jobs {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map(|pool| pool.install(run))
            .map_err(|e| e.to_string()),
        None => Ok(run()),
    });
    let items = items.map_err(PyValueError::new_err)?;
    let mut columns: Columns<'py> = Default::default();
    for item in items {
        let Some(item) = item else {
            push(
                &mut columns,
                None,
                None,
                Some("missing geometry (None)".into()),
                vec![],
            );
            columns.8.push(false);
            continue;
        };
        let ok = item.errors.is_empty() && item.failures.is_empty();
        let wkb = item.wkb.as_ref().map(|b| PyBytes::new(py, b));
        let error = item.errors.first().or(item.failures.first()).cloned();
        push(
            &mut columns,
            ok.then_some(&item),
            wkb,
            error,
            item.warnings.clone(),
        );
        columns
            .8
            .push(item.errors.is_empty() && !item.failures.is_empty());
    }
    Ok(columns)
}

fn push<'py>(
    c: &mut Columns<'py>,
    item: Option<&Item>,
    wkb: Option<Bound<'py, PyBytes>>,
    error: Option<String>,
    warnings: Vec<String>,
) {
    let count = |f: fn(&Item) -> usize| item.map_or(-1, |i| i64::try_from(f(i)).unwrap_or(-1));
    c.0.push(count(|i| i.triangle_count));
    c.1.push(count(|i| i.degenerate_count));
    c.2.push(item.is_some_and(|i| i.optimal));
    c.3.push(count(|i| i.lower));
    c.4.push(count(|i| i.upper));
    c.5.push(wkb);
    c.6.push(error);
    c.7.push(warnings);
}

/// The module `minitri._minitri`.
#[pymodule]
fn _minitri(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(triangulate_text, m)?)?;
    m.add_function(wrap_pyfunction!(triangulate_wkb, m)?)?;
    m.add_function(wrap_pyfunction!(triangulate_wkb_many, m)?)?;
    Ok(())
}
