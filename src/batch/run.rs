//! Running inputs: read, triangulate in parallel, write in input order.
//!
//! Every input is read as a stream of polygons (`read_input`): GeoJSON Lines line by line (each
//! line parsed in parallel with its chunk), other GeoJSON through [`geojson_stream`] (one
//! feature or value at a time), WKT and vertex lists whole (their text and polygons in memory). Polygons are gathered into chunks of at most [`CHUNK_POLYGONS`] polygons
//! or [`CHUNK_VERTICES`] vertices; each chunk is triangulated in parallel on the current rayon
//! pool and its outcomes handed on in input order, so that the output is the same for any number
//! of threads and memory holds one chunk (plus, for JSON, the error list) however large the input.
//!
//! - [`run_document`]: every input into one document (standard output, or `-o FILE`); chunks may
//!   span several inputs, so many small files are triangulated in parallel too.
//! - [`run_tree`]: each input into its own output file (`-o DIR`), inputs in parallel, each
//!   written atomically ([`AtomicFile`]); messages reported in input order.

use super::atomic::AtomicFile;
use super::dir::{Linked, NotCreated};
use super::discover::{Input, NotRegular, Unreadable};
use super::guard::{file_id, FileId};
use super::tally::Tally;
use crate::feature::{Feature, Geometry, Identity};
use crate::io::read::geojson::JSON_WHITESPACE;
use crate::io::read::geojson_stream::{self, Event, Stop};
use crate::io::read::{self, Format, ParseError, RawPolygon};
use crate::io::write::{OutputFormat, Renderer, Sink};
use crate::pipeline::{process_raw, unreadable, Error, Options, Outcome};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::io::{self, BufRead, Read};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Most polygons triangulated together before their outcomes are written.
pub const CHUNK_POLYGONS: usize = 4096;
/// Most vertices (over all polygons) triangulated together before their outcomes are written.
pub const CHUNK_VERTICES: usize = 1 << 22;

/// What a run computes and how it reads.
#[derive(Clone, Debug)]
pub struct Settings {
    /// What to compute for every polygon.
    pub options: Options,
    /// The input format, or `None` to decide by extension, then by content.
    pub from: Option<Format>,
    /// Leave warnings out of the messages.
    pub quiet: bool,
    /// The most bytes read as one WKT or vertex-list input, one streamed GeoJSON feature or
    /// top-level value, or one line of GeoJSON Lines, before it is parsed (default
    /// [`read::limits::MAX_TEXT`], 4 GiB).
    pub limit: u64,
    /// The most vertices held while reading one polygon of a WKT or vertex-list input, or one
    /// GeoJSON feature or line (all its polygons together); past it the polygon or feature is
    /// an error and the others go on (default [`read::limits::MAX_VERTICES`], 2^25).
    pub max_vertices: usize,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            options: Options::default(),
            from: None,
            quiet: false,
            limit: read::limits::MAX_TEXT,
            max_vertices: read::limits::MAX_VERTICES,
        }
    }
}

/// Told what a run does as it goes; called from worker threads.
pub trait Observer: Sync {
    /// `count` more polygons were processed (triangulated or not).
    fn polygons(&self, count: usize);
    /// One more input is finished (in any order).
    fn input_finished(&self);
    /// A line for the user about an input (a warning or an error), in input order.
    fn message(&self, line: &str);
}

/// An observer that ignores everything.
pub struct Silent;

impl Observer for Silent {
    fn polygons(&self, _: usize) {}
    fn input_finished(&self) {}
    fn message(&self, _: &str) {}
}

/// The result of [`run_document`].
#[derive(Clone, Copy, Debug)]
pub struct DocumentReport {
    /// What was done.
    pub tally: Tally,
    /// Every input was read to its end (no unreadable file, no syntax error cutting one short).
    pub complete: bool,
}

/// Reads every input, in order, into one document written by `sink`.
///
/// # Errors
/// An I/O error of the output (the run stops there); input errors are outcomes, not errors.
///
/// # Examples
/// ```
/// use minitri::batch::{discover, run_document, Settings, Silent};
/// use minitri::io::write::OutputFormat;
/// let inputs = discover(&["fixtures/valid/u_shape.wkt".into()], None);
/// let mut out = Vec::new();
/// let sink = OutputFormat::Json.sink(&mut out)?;
/// let report = run_document(&inputs, &Settings::default(), sink, &Silent)?;
/// assert_eq!((report.tally.polygons, report.tally.triangles, report.tally.saved), (1, 5, 5));
/// assert!(String::from_utf8_lossy(&out).contains("\"triangle_count\": 5"));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn run_document(
    inputs: &[Result<Input, Unreadable>],
    settings: &Settings,
    mut sink: Box<dyn Sink + '_>,
    observer: &dyn Observer,
) -> io::Result<DocumentReport> {
    let mut tally = Tally::default();
    let mut complete = true;
    {
        let renderer = sink.renderer();
        let mut deliver = |outcome: Outcome, rendered: Option<String>| {
            tally.add(&outcome);
            for line in outcome.messages(settings.quiet) {
                observer.message(&line);
            }
            sink.push_rendered(outcome, rendered)?;
            for line in sink.warnings() {
                if !settings.quiet {
                    observer.message(&line);
                }
            }
            Ok(())
        };
        let mut chunker = Chunker::new(&settings.options, renderer, &mut deliver, observer);
        for input in inputs {
            complete &= match input {
                Ok(input) => read_input(input, settings, &mut chunker)?,
                Err(e) => {
                    chunker.push(Item::Failed(Box::new(unreadable(
                        &e.name,
                        Error::NotRead(e.message.clone()),
                    ))))?;
                    false
                }
            };
            observer.input_finished();
        }
        chunker.flush()?;
    }
    tally.files = inputs.len();
    sink.finish()?;
    Ok(DocumentReport { tally, complete })
}

/// One input of a tree run and where its output goes (see `super::plan`).
#[derive(Clone, Debug)]
pub struct TreeJob {
    /// The input file.
    pub input: Result<Input, Unreadable>,
    /// Its output file, or why it gets none.
    pub output: Result<PathBuf, String>,
}

/// Reads each input into its own output file, inputs in parallel on the current rayon pool.
///
/// An output file is written (atomically) when its input was read to the end and at least one of
/// its polygons was triangulated; otherwise it is not written, and an existing file of that name
/// is left as it was. Missing directories are created. No symbolic link below `out_dir` (the
/// directory the outputs were planned in) is followed: an output reached through one is refused
/// for that input alone, and every step of placing an output is made through its directory
/// held open (`openat`, `renameat`), so a link swapped in while the run writes is never followed
/// either. Messages reach `observer` in input order; the returned tally counts everything (an
/// output that cannot be written is an error).
///
/// # Examples
/// ```
/// use minitri::batch::{discover, plan, run_tree, Settings, Silent, TreeJob};
/// use minitri::io::write::OutputFormat;
/// let out = tempfile::tempdir()?;
/// let inputs: Vec<_> = discover(&["fixtures/valid".into()], None).into_iter().flatten().collect();
/// let jobs: Vec<TreeJob> = inputs.iter().cloned().zip(plan(&inputs, out.path(), "json"))
///     .map(|(input, output)| TreeJob { input: Ok(input), output }).collect();
/// let tally = run_tree(&jobs, out.path(), &Settings::default(), OutputFormat::Json, &Silent);
/// assert_eq!((tally.files, tally.errors), (inputs.len(), 0));
/// assert!(out.path().join("l_shape.json").is_file());
/// // u_shape.wkt, u_shape.geojson and u_shape.txt: each keeps its name.
/// assert!(out.path().join("u_shape.geojson.json").is_file());
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn run_tree(
    jobs: &[TreeJob],
    out_dir: &Path,
    settings: &Settings,
    format: OutputFormat,
    observer: &dyn Observer,
) -> Tally {
    // Every input file by identity: an output that is one of them, whatever the links of the
    // output tree, is refused (renaming over it would replace the input).
    let inputs: HashMap<FileId, &Input> = jobs
        .iter()
        .filter_map(|job| job.input.as_ref().ok())
        .filter_map(|input| Some((file_id(&input.path)?, input)))
        .collect();
    let order = Mutex::new(Reorder {
        next: 0,
        waiting: BTreeMap::new(),
        tally: Tally::default(),
    });
    jobs.par_iter().enumerate().for_each(|(k, job)| {
        let report = run_file(job, out_dir, &inputs, settings, format, observer);
        observer.input_finished();
        let mut order = order
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        order.waiting.insert(k, report);
        loop {
            let next = order.next;
            let Some(report) = order.waiting.remove(&next) else {
                break;
            };
            for line in &report.messages {
                observer.message(line);
            }
            order.tally.merge(&report.tally);
            order.next += 1;
        }
    });
    let order = order.into_inner().unwrap_or_else(|p| p.into_inner());
    order.tally
}

/// Finished inputs waiting for the ones before them to be reported.
struct Reorder {
    next: usize,
    waiting: BTreeMap<usize, FileReport>,
    tally: Tally,
}

/// What one input of a tree run did.
struct FileReport {
    messages: Vec<String>,
    tally: Tally,
}

/// One input of a tree run, into its own output file.
fn run_file(
    job: &TreeJob,
    out_dir: &Path,
    inputs: &HashMap<FileId, &Input>,
    settings: &Settings,
    format: OutputFormat,
    observer: &dyn Observer,
) -> FileReport {
    let mut report = FileReport {
        messages: Vec::new(),
        tally: Tally {
            files: 1,
            ..Tally::default()
        },
    };
    let fail = |report: &mut FileReport, line: String| {
        report.messages.push(line);
        report.tally.errors += 1;
    };
    let input = match &job.input {
        Ok(input) => input,
        Err(e) => {
            fail(&mut report, format!("{}: {}", e.name, e.message));
            return report;
        }
    };
    let target = match &job.output {
        Ok(target) => target,
        Err(why) => {
            fail(&mut report, format!("{}: {why}", input.name()));
            return report;
        }
    };
    let cannot_write = |e: io::Error| format!("cannot write {}: {e}", target.display());
    // Every directory below `out_dir` is opened without following a link (a link in the output
    // tree, to a file or to a directory, could lead into the input tree) and the output is
    // placed through the last one held open (batch/dir.rs).
    let created = match target.strip_prefix(out_dir) {
        Ok(relative) => AtomicFile::create_beneath(out_dir, relative),
        Err(_) => AtomicFile::create(target), // not planned below `out_dir`: as given
    };
    let mut file = match created {
        Ok(file) => file,
        Err(e) => {
            let inner = e.get_ref();
            let line = if let Some(linked) = inner.and_then(|e| e.downcast_ref::<Linked>()) {
                let (name, target) = (input.name(), target.display());
                format!("{name}: not processed: its output {target} {linked}")
            } else if let Some(not_created) = inner.and_then(|e| e.downcast_ref::<NotCreated>()) {
                not_created.to_string()
            } else {
                cannot_write(e)
            };
            fail(&mut report, line);
            return report;
        }
    };
    // The file the output would replace, looked at in the directory held open: a hard link to
    // an input, or the output directory leading into the input tree, is refused.
    let overwritten = |file: &AtomicFile| {
        let other = inputs.get(&file.replaced()?)?;
        Some(format!(
            "{}: not processed: its output {} is the input {} (the same file, through a link); it would be overwritten",
            input.name(),
            target.display(),
            other.name()
        ))
    };
    if let Some(line) = overwritten(&file) {
        fail(&mut report, line);
        return report;
    }
    let written = (|| {
        let mut sink = format.sink(&mut file)?;
        let complete = {
            let renderer = sink.renderer();
            let mut deliver = |outcome: Outcome, rendered: Option<String>| {
                report.tally.add(&outcome);
                report.messages.extend(outcome.messages(settings.quiet));
                sink.push_rendered(outcome, rendered)?;
                let warnings = sink.warnings();
                if !settings.quiet {
                    report.messages.extend(warnings);
                }
                Ok(())
            };
            let mut chunker = Chunker::new(&settings.options, renderer, &mut deliver, observer);
            let complete = read_input(input, settings, &mut chunker)?;
            chunker.flush()?;
            complete
        };
        sink.finish()?;
        Ok(complete)
    })();
    match written {
        Ok(true) if report.tally.solved > 0 => {
            // Again just before the rename: a hard link may have been planted meanwhile.
            if let Some(line) = overwritten(&file) {
                fail(&mut report, line);
            } else if let Err(e) = file.commit() {
                fail(&mut report, cannot_write(e));
            }
        }
        Ok(_) => {} // nothing to write: the input's errors say why; `file` is dropped, unwritten
        Err(e) => fail(&mut report, cannot_write(e)),
    }
    report
}

/// What the readers hand to the chunker.
enum Item {
    /// A polygon to triangulate.
    Polygon {
        source: Arc<str>,
        index: usize,
        raw: RawPolygon,
        feature: Option<Identity>,
        /// Its SRID, from EWKT or EWKB.
        srid: Option<u32>,
    },
    /// Something that failed already (an unreadable input or part of one).
    Failed(Box<Outcome>),
    /// Line `number` of a GeoJSON Lines input, read (in parallel) with the chunk; its polygons
    /// are numbered on from the source's previous ones.
    Line {
        source: Arc<str>,
        number: usize,
        feature: usize,
        text: String,
        max_vertices: usize,
    },
}

/// An item after the parallel reading of lines, before its polygons are numbered.
enum Parsed {
    Ready(Item),
    Line(Arc<str>, Feature, Result<geojson_stream::Parts, ParseError>),
}

/// Where a chunk's outcomes go, in order, each with what the sink's renderer made of it.
type Deliver<'a> = dyn FnMut(Outcome, Option<String>) -> io::Result<()> + 'a;

/// Gathers items into chunks, triangulates (and renders) each chunk in parallel, delivers
/// outcomes in order.
struct Chunker<'a> {
    options: &'a Options,
    renderer: Option<Renderer>,
    items: Vec<Item>,
    vertices: usize,
    /// The source of the last line numbered, and the index its next polygon gets.
    lines: Option<(Arc<str>, usize)>,
    deliver: &'a mut Deliver<'a>,
    observer: &'a dyn Observer,
}

impl<'a> Chunker<'a> {
    fn new(
        options: &'a Options,
        renderer: Option<Renderer>,
        deliver: &'a mut Deliver<'a>,
        observer: &'a dyn Observer,
    ) -> Chunker<'a> {
        Chunker {
            options,
            renderer,
            items: Vec::new(),
            vertices: 0,
            lines: None,
            deliver,
            observer,
        }
    }

    fn push(&mut self, item: Item) -> io::Result<()> {
        match &item {
            Item::Polygon { raw, .. } => {
                self.vertices += raw.rings.iter().map(Vec::len).sum::<usize>();
            }
            // About one vertex per 8 bytes of GeoJSON ("[12, 34], ").
            Item::Line { text, .. } => self.vertices += text.len() / 8,
            Item::Failed(_) => {}
        }
        self.items.push(item);
        if self.items.len() >= CHUNK_POLYGONS || self.vertices >= CHUNK_VERTICES {
            self.flush()?;
        }
        Ok(())
    }

    /// Reads the lines among `items` in parallel and numbers their polygons, in order.
    fn read_lines(&mut self, items: Vec<Item>) -> Vec<Item> {
        let parsed: Vec<Parsed> = items
            .into_par_iter()
            .map(|item| match item {
                Item::Line {
                    source,
                    number,
                    feature,
                    text,
                    max_vertices,
                } => {
                    let (read, result) = geojson_stream::read_line_feature_within(
                        &text,
                        number,
                        feature,
                        max_vertices,
                    );
                    // Not JSON: a feature of which nothing is known but its place.
                    let read = read.unwrap_or(Feature {
                        number: feature,
                        line: Some(number),
                        id: None,
                        properties: None,
                        geometry: Geometry::Failed,
                        collection: None,
                    });
                    Parsed::Line(source, read, result)
                }
                other => Parsed::Ready(other),
            })
            .collect();
        let mut items = Vec::with_capacity(parsed.len());
        for parsed in parsed {
            match parsed {
                Parsed::Ready(item) => items.push(item),
                Parsed::Line(source, feature, Err(e)) => {
                    let outcome = unreadable(&source, Error::Parse(e));
                    items.push(failed_feature(outcome, &Arc::new(feature)));
                }
                Parsed::Line(source, feature, Ok(parts)) => {
                    let feature = Arc::new(feature);
                    if let Some(item) = no_parts(&source, &feature) {
                        items.push(item);
                        continue;
                    }
                    let next = match &mut self.lines {
                        Some((last, next)) if Arc::ptr_eq(last, &source) => next,
                        lines => &mut lines.insert((Arc::clone(&source), 0)).1,
                    };
                    for (part, read) in parts.into_iter().enumerate() {
                        let identity = Identity {
                            feature: Arc::clone(&feature),
                            part,
                        };
                        let raw = match read {
                            Ok(raw) => raw,
                            // A member of a GeometryCollection that is not a polygon.
                            Err(e) => {
                                items.push(failed_part(&source, e, identity));
                                continue;
                            }
                        };
                        let index = *next;
                        *next += 1;
                        let source = Arc::clone(&source);
                        items.push(Item::Polygon {
                            source,
                            index,
                            raw,
                            feature: Some(identity),
                            srid: None,
                        });
                    }
                }
            }
        }
        items
    }

    fn flush(&mut self) -> io::Result<()> {
        let mut items = std::mem::take(&mut self.items);
        self.vertices = 0;
        if items.iter().any(|item| matches!(item, Item::Line { .. })) {
            items = self.read_lines(items);
        }
        let (options, renderer) = (self.options, self.renderer);
        let outcomes: Vec<(Outcome, Option<String>)> = items
            .into_par_iter()
            .flat_map_iter(|item| {
                let outcomes = match item {
                    Item::Polygon {
                        source,
                        index,
                        raw,
                        feature,
                        srid,
                    } => {
                        let mut outcomes = process_raw(&source, index, raw, options);
                        for outcome in &mut outcomes {
                            outcome.feature = feature.clone();
                            outcome.srid = srid;
                        }
                        outcomes
                    }
                    Item::Failed(outcome) => vec![*outcome],
                    Item::Line { source, .. } => {
                        vec![unreadable(&source, Error::Read("line not read".into()))]
                    }
                };
                outcomes.into_iter().map(move |outcome| {
                    let rendered = renderer.and_then(|render| render(&outcome));
                    (outcome, rendered)
                })
            })
            .collect();
        // A repaired polygon split into pieces counts once.
        let polygons = outcomes
            .iter()
            .filter(|(o, _)| o.index.is_some() && o.piece.unwrap_or(0) == 0)
            .count();
        self.observer.polygons(polygons);
        for (outcome, rendered) in outcomes {
            (self.deliver)(outcome, rendered)?;
        }
        Ok(())
    }
}

/// Reads one input into the chunker; returns whether it was read to its end.
///
/// Errors of the input become outcomes; the `Err` is the output's (from delivering).
fn read_input(input: &Input, settings: &Settings, chunker: &mut Chunker) -> io::Result<bool> {
    let source: Arc<str> = Arc::from(input.name());
    let failed = |chunker: &mut Chunker, error: Error| {
        chunker
            .push(Item::Failed(Box::new(unreadable(&source, error))))
            .map(|()| false)
    };
    let reader: Box<dyn Read> = if input.is_stdin() {
        Box::new(io::stdin())
    } else {
        match input.open() {
            Ok(file) => Box::new(file),
            // A walked input that is no longer a regular file: the message says it all.
            Err(e) if e.get_ref().is_some_and(|e| e.is::<NotRegular>()) => {
                return failed(chunker, Error::NotRead(e.to_string()))
            }
            Err(e) => return failed(chunker, Error::Read(e.to_string())),
        }
    };
    let path = (!input.is_stdin()).then_some(input.path.as_path());
    let opened = read::open(
        reader,
        path,
        settings.from,
        settings.limit,
        settings.max_vertices,
    );
    match opened {
        Ok(read::Opened::Parts(parts)) => push_parts(&source, parts, chunker),
        Ok(read::Opened::Lines(reader)) => read_lines(&source, reader, settings, chunker),
        Ok(read::Opened::GeoJson(reader)) => stream_geojson(&source, reader, settings, chunker),
        Ok(read::Opened::GeoJsonText(text)) => {
            stream_geojson(&source, text.as_bytes(), settings, chunker)
        }
        Err(read::limits::NotRead::Io(e)) => failed(chunker, Error::Read(e.to_string())),
        Err(read::limits::NotRead::Parse(e)) => failed(chunker, Error::Parse(e)),
    }
}

/// Pushes the parts of an input read whole into the chunker; returns that it was read to its
/// end. A member of a collection that is not a polygon is reported in its place; the polygons
/// are numbered without it.
fn push_parts(
    source: &Arc<str>,
    (parts, srids): read::wkb::PartsAndSrids,
    chunker: &mut Chunker,
) -> io::Result<bool> {
    let mut index = 0;
    for (part, srid) in parts.into_iter().zip(srids) {
        let source = Arc::clone(source);
        match part {
            Ok(raw) => {
                chunker.push(Item::Polygon {
                    source,
                    index,
                    raw,
                    feature: None,
                    srid,
                })?;
                index += 1;
            }
            Err(e) => chunker.push(Item::Failed(Box::new(unreadable(&source, Error::Parse(e)))))?,
        }
    }
    Ok(true)
}

/// Reads a GeoJSON Lines input into the chunker, line by line (the lines are parsed in parallel
/// with their chunk); returns whether it was read to its end. Each line stands alone: a line that
/// is not JSON, or not a polygon, is reported and the others go on. Reading stops at a line of
/// more than `settings.limit` bytes (an endless line), and at a line holding a NUL byte (binary
/// data, never text: an endless stream of it would be reported line after line). A line of more
/// than `settings.max_vertices` positions fails alone.
fn read_lines(
    source: &Arc<str>,
    mut reader: impl BufRead,
    settings: &Settings,
    chunker: &mut Chunker,
) -> io::Result<bool> {
    let limit = settings.limit;
    let mut number = 0;
    let mut features = 0;
    let mut any = false;
    let mut offset = 0u64; // bytes of the input before this line
    let mut bytes = Vec::new();
    loop {
        let read = match read::limits::read_line(&mut reader, &mut bytes, limit) {
            Ok(read) if read.bytes == 0 => break,
            Ok(read) => read,
            Err(e) => {
                let error = Error::Read(e.to_string());
                chunker.push(Item::Failed(Box::new(unreadable(source, error))))?;
                return Ok(false);
            }
        };
        number += 1;
        let mut failed = |error: ParseError| {
            let feature = Arc::new(Feature {
                number: features,
                line: Some(number),
                id: None,
                properties: None,
                geometry: Geometry::Failed,
                collection: None,
            });
            features += 1;
            let outcome = unreadable(source, Error::Parse(error));
            chunker.push(failed_feature(outcome, &feature))
        };
        if read.too_long && !read.binary {
            let what = "one line of GeoJSON Lines";
            let message = read::limits::too_large(limit, what, offset + limit + 1);
            failed(ParseError::new(format!("line {number}: {message}")))?;
            return Ok(false);
        }
        offset += read.bytes;
        // A line that is not UTF-8 is reported alone, like any other bad line.
        let text = match read::not_text(&bytes, true) {
            Some(mut error) => {
                if let Some(location) = &mut error.location {
                    location.line = number;
                }
                failed(error)?;
                if read.binary {
                    return Ok(false);
                }
                continue;
            }
            // Valid UTF-8 (checked just above): taken as it is, without a copy.
            None => String::from_utf8(std::mem::take(&mut bytes))
                .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned()),
        };
        if text.trim_matches(JSON_WHITESPACE).is_empty() {
            continue;
        }
        any = true;
        let source = Arc::clone(source);
        chunker.push(Item::Line {
            source,
            number,
            feature: features,
            text,
            max_vertices: settings.max_vertices,
        })?;
        features += 1;
    }
    if !any {
        let error = ParseError::new("empty input: no polygon found");
        chunker.push(Item::Failed(Box::new(unreadable(
            source,
            Error::Parse(error),
        ))))?;
        return Ok(false);
    }
    Ok(true)
}

/// Streams a GeoJSON input into the chunker, at most `settings.limit` bytes and
/// `settings.max_vertices` positions a feature or top-level value; returns whether it was read
/// to its end.
fn stream_geojson(
    source: &Arc<str>,
    reader: impl BufRead,
    settings: &Settings,
    chunker: &mut Chunker,
) -> io::Result<bool> {
    let mut index = 0;
    // The feature being read, and the number of its next part.
    let mut current: Option<(Arc<Feature>, usize)> = None;
    let mut emit = |event: Event| match event {
        Event::Feature(feature) => {
            current = None;
            match no_parts(source, &feature) {
                Some(item) => chunker.push(item),
                None => {
                    current = Some((feature, 0));
                    Ok(())
                }
            }
        }
        Event::Polygon(raw) => {
            index += 1;
            let feature = current.as_mut().map(|(feature, part)| {
                *part += 1;
                Identity {
                    feature: Arc::clone(feature),
                    part: *part - 1,
                }
            });
            chunker.push(Item::Polygon {
                source: Arc::clone(source),
                index: index - 1,
                raw,
                feature,
                srid: None,
            })
        }
        Event::Failed(e) => match &mut current {
            // A part of the feature that is not a polygon (a member of a GeometryCollection).
            Some((feature, part)) if matches!(feature.geometry, Geometry::Parts(k) if *part < k) => {
                *part += 1;
                let identity = Identity {
                    feature: Arc::clone(feature),
                    part: *part - 1,
                };
                chunker.push(failed_part(source, e, identity))
            }
            _ => {
                let outcome = unreadable(source, Error::Parse(e));
                match current.take() {
                    Some((feature, _)) if feature.geometry == Geometry::Failed => {
                        chunker.push(failed_feature(outcome, &feature))
                    }
                    _ => chunker.push(Item::Failed(Box::new(outcome))),
                }
            }
        },
    };
    let (limit, max_vertices) = (settings.limit, settings.max_vertices);
    let stop = match geojson_stream::stream_within(reader, limit, max_vertices, &mut emit) {
        Ok(()) => return Ok(true),
        Err(Stop::Output(e)) => return Err(e),
        Err(Stop::Parse(e)) => Error::Parse(e),
        Err(Stop::Read(e)) => Error::Read(e.to_string()),
    };
    chunker
        .push(Item::Failed(Box::new(unreadable(source, stop))))
        .map(|()| false)
}

/// A failed outcome of `feature` (its only one).
fn failed_feature(mut outcome: Outcome, feature: &Arc<Feature>) -> Item {
    outcome.feature = Some(Identity {
        feature: Arc::clone(feature),
        part: 0,
    });
    Item::Failed(Box::new(outcome))
}

/// A failed part of a feature: a member of a GeometryCollection that is not a polygon, one
/// outcome among the feature's parts (without index: the polygons are numbered without it).
fn failed_part(source: &str, error: ParseError, identity: Identity) -> Item {
    let mut outcome = unreadable(source, Error::Parse(error));
    outcome.feature = Some(identity);
    Item::Failed(Box::new(outcome))
}

/// The error of a feature with nothing to triangulate (a `null` or empty geometry), if it is
/// one: reported, never skipped silently, so that every input feature has an outcome.
fn no_parts(source: &str, feature: &Arc<Feature>) -> Option<Item> {
    let why = match feature.geometry {
        Geometry::Null => Feature::null_message(),
        Geometry::Parts(0) => "the geometry is empty: nothing to triangulate",
        Geometry::Parts(_) | Geometry::Failed => return None,
    };
    let message = match feature.line {
        Some(line) => format!("line {line}: {why}"),
        None => format!("feature {}: {why}", feature.number),
    };
    let outcome = unreadable(source, Error::Parse(ParseError::new(message)));
    Some(failed_feature(outcome, feature))
}
