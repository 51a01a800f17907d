//! Command-line flags (clap), turned into a validated [`Config`]; the library never sees clap.

use clap::{ColorChoice, CommandFactory, FromArgMatches, Parser, ValueEnum};
use clap_complete::Shell;
use minitri::io::write::{svg, OutputFormat};
use minitri::{Algorithm, Format, Options};
use std::path::{Path, PathBuf};

/// The examples after `-h` and `--help` (a macro so that `--help` can append to it).
macro_rules! examples {
    () => {
        "Examples:
  minitri fixtures/valid/u_shape.wkt               minimum triangulation as JSON
  cat shape.wkt | minitri                          read standard input (also: minitri < shape.wkt)
  minitri a.wkt b.geojson > both.json              several inputs, one document, in input order
  minitri --to svg -o u.svg u_shape.wkt            draw it
  minitri --to svg --labels --verify big.wkt > b.svg   vertex numbers at any size, faults in red
  minitri --to geojson u_shape.wkt                 the triangles for a GIS (also --to wkt)
  minitri layer.geojson -o out.geojson             one Feature per input feature, id and properties kept
  minitri layer.geojson -o out.csv                 a row per feature: WKT, id, properties (ogr2ogr, QGIS)
  minitri --from geojson - --to geojsonl < in.geojsonl   a filter: one GeoJSON line out per line in
  minitri --from vertices points.txt               one `x y` vertex per line (also --from wkt, geojson)
  minitri --verify shapes/                         a directory, every output checked by the DP too
  minitri shapes/ -o out/ --jobs 2                 one output per input file, mirrored, 2 threads
  minitri -q shapes/ -o out/                       the same without summary, warnings or progress bar
  minitri --time-limit 60 holes.geojson            search polygons with holes up to 60 s each (0: no limit)
  minitri -a ear shape.geojson                     a plain triangulation (n + 2w - 2 triangles)
  minitri -a pseudo shape.wkt                      a minimal pseudotriangulation (also pseudo-hull)
  echo 'POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0 1))' | minitri      exact decimals: 1 triangle

Exit status: 0 all processed, 1 some input failed, 2 bad command line, 3 --verify found a problem."
    };
}

/// Appended to the examples by `--help` (not `-h`), like the flags they use.
macro_rules! shell_examples {
    () => {
        "

Shell:
  minitri --completions bash > ~/.local/share/bash-completion/completions/minitri
  minitri --completions zsh > ~/.zfunc/_minitri   (also fish, elvish, powershell)
  minitri --man > minitri.1 && man ./minitri.1

NO_COLOR set to anything but the empty string turns colour off."
    };
}

/// Triangulate polygons with the minimum number of triangles, exactly.
///
/// Reads WKT, GeoJSON, plain vertex lists or WKB (files, gzip-compressed or not, directories, or
/// standard input) and writes JSON, GeoJSON, WKT, CSV or SVG. Coordinates are exact as written in
/// decimal (WKB's doubles: their shortest decimals).
#[derive(Parser, Debug)]
#[command(name = "minitri", version, about, after_help = examples!(),
    after_long_help = concat!(examples!(), shell_examples!()))]
pub struct Flags {
    /// Input files or directories (searched recursively); none or `-` reads standard input
    pub inputs: Vec<PathBuf>,
    /// Algorithm: minitri (minimum, Chen & Chang), asano (minimum, O(n^3) DP), ear (n + 2w - 2);
    /// pseudo, pseudo-hull: pseudotriangulations (Rote, Wang, Wang & Xu)
    #[arg(short, long, value_enum, default_value = "minitri")]
    pub algorithm: AlgorithmFlag,
    /// Input format; auto decides by extension, then by content
    #[arg(long, value_enum, default_value = "auto")]
    pub from: FromFlag,
    /// Output format [default: from -o's extension (.json, .geojson, .geojsonl, .wkt, .csv,
    /// .svg), else json]
    #[arg(short, long, value_enum)]
    pub to: Option<ToFlag>,
    /// Write the output to this file instead of standard output; with a directory input or
    /// several inputs, a directory mirroring the input tree, one output file per input file
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
    /// Also run every other exact algorithm that applies and check every output independently;
    /// exit status 3 if anything disagrees or is invalid (with --to svg: drawn in red)
    #[arg(long)]
    pub verify: bool,
    /// Repair spikes, rings of fewer than 3 points or zero area, rings touching themselves at a
    /// vertex or with a vertex inside their own edge (split into polygons or holes), rings sharing
    /// edges (merged) and rings touching in a cycle (each piece of the interior a polygon),
    /// using no new points; each repair is a warning and listed under "repaired" in the JSON
    #[arg(long)]
    pub repair: bool,
    /// With --to svg: write the vertex numbers whatever the polygon's size (by default only up
    /// to 60 vertices); their font shrinks where vertices are dense
    #[arg(long)]
    pub labels: bool,
    /// Worker threads for a batch (default: all cores)
    #[arg(short, long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub jobs: Option<u32>,
    /// Largest polygon (vertices) the O(n^3)-time, O(n^2)-memory asano DP accepts
    #[arg(long, value_name = "N", default_value_t = minitri::algo::asano::DEFAULT_LIMIT)]
    pub dp_limit: usize,
    /// Seconds the exact method for one polygon may run (0: no limit): every stage of the search
    /// for a polygon with holes or touching rings, and step 1 of one without (O(n log^2 n));
    /// past it, the best triangulation found is reported with "optimal": false, a lower
    /// bound and "stopped_by": "time limit". With -a pseudo-hull: the construction; past it, the
    /// greedy of -a pseudo on the hull, "optimal": false, "stopped_by": "time limit"
    #[arg(long, value_name = "SECONDS", default_value_t = 10.0, value_parser = seconds)]
    pub time_limit: f64,
    /// Most vertices one polygon may hold while it is read, all its rings together (GeoJSON: one
    /// feature, all its polygons together), about 64 bytes each; past it the polygon is an error
    /// and the others go on
    #[arg(long, value_name = "N", default_value_t = minitri::io::read::limits::MAX_VERTICES as u64,
        value_parser = clap::value_parser!(u64).range(1..))]
    pub max_vertices: u64,
    /// No warnings, summary or progress bar on standard error (errors are still reported)
    #[arg(short, long)]
    pub quiet: bool,
    /// Print the completion script for SHELL to standard output and exit
    #[arg(
        long,
        value_name = "SHELL",
        value_enum,
        exclusive = true,
        hide_short_help = true,
        long_help = "Print the completion script for SHELL to standard output and exit. It reads \
                     no input, so it takes no other argument."
    )]
    pub completions: Option<Shell>,
    /// Print the man page (roff) to standard output and exit
    #[arg(
        long,
        exclusive = true,
        hide_short_help = true,
        long_help = "Print the man page (roff) to standard output and exit. It reads no input, so \
                     it takes no other argument."
    )]
    pub man: bool,
}

/// `--algorithm`.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum AlgorithmFlag {
    /// Chen & Chang's MINITRI (minimum)
    Minitri,
    /// Asano, Asano & Pinter's dynamic program (minimum, O(n^3))
    Asano,
    /// A plain triangulation into n + 2w - 2 triangles
    Ear,
    /// A minimal pseudotriangulation of the polygon inside a triangulation (linear greedy)
    Pseudo,
    /// A minimum pseudotriangulation of the convex hull containing the polygon's edges
    PseudoHull,
}

/// `--from`.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum FromFlag {
    /// By extension, then by content
    Auto,
    /// Well-known text
    Wkt,
    /// GeoJSON or newline-delimited GeoJSON
    Geojson,
    /// One `x y` vertex per line
    Vertices,
    /// Well-known binary (WKB, EWKB): binary, or hex text one geometry per line
    Wkb,
    /// CSV with a WKT geometry column (as --to csv writes it)
    Csv,
}

/// `--to`.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum ToFlag {
    /// The JSON document: every polygon with its triangles, counts, bounds and warnings
    Json,
    /// A GeoJSON FeatureCollection, one Feature per input feature (a GeometryCollection of its
    /// triangles as Polygons, the input's id and properties)
    Geojson,
    /// GeoJSON Lines: the same Features, one per line (a filter with GeoJSON Lines in)
    Geojsonl,
    /// A GeoJSON FeatureCollection, one Feature per triangle
    GeojsonTriangles,
    /// WKT, one GEOMETRYCOLLECTION of triangles per line and input feature (EMPTY when it failed)
    Wkt,
    /// CSV: one row per input feature, its triangles in a WKT column, its id and properties as
    /// written, ok, counts, errors
    Csv,
    /// A picture
    Svg,
}

impl ToFlag {
    /// The flag's value as written on the command line.
    pub fn name(self) -> String {
        self.to_possible_value()
            .map(|v| v.get_name().to_string())
            .unwrap_or_default()
    }
}

/// The validated configuration the binary runs with.
#[derive(Debug)]
pub struct Config {
    /// Input paths; `-` is standard input.
    pub inputs: Vec<PathBuf>,
    /// Forced input format, or `None` for auto-detection.
    pub from: Option<Format>,
    /// Output format.
    pub to: OutputFormat,
    /// Output file, or `None` for standard output.
    pub output: Option<PathBuf>,
    /// What to compute.
    pub options: Options,
    /// Worker threads, or `None` for all cores.
    pub jobs: Option<usize>,
    /// Suppress warnings, the summary and the progress bar.
    pub quiet: bool,
    /// The most vertices one polygon (GeoJSON: one feature) may hold while it is read.
    pub max_vertices: usize,
}

impl Flags {
    /// The clap command, uncoloured when `NO_COLOR` is set to a non-empty value
    /// (<https://no-color.org>), whatever the terminal or `CLICOLOR_FORCE`.
    pub fn command_for_env() -> clap::Command {
        let cmd = Flags::command();
        if std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty()) {
            cmd.color(ColorChoice::Never)
        } else {
            cmd
        }
    }

    /// Parses the process arguments; on a bad command line, or for `--help` and `--version`,
    /// prints and exits as clap does (status 2, or 0).
    pub fn from_env() -> Flags {
        let mut cmd = Flags::command_for_env();
        // clap would suggest `--from` for `--format`; the output format is what is meant most.
        let format = std::env::args_os()
            .skip(1)
            .take_while(|a| a != "--")
            .any(|a| a == "--format" || a.to_string_lossy().starts_with("--format="));
        if format {
            cmd.error(
                clap::error::ErrorKind::UnknownArgument,
                "there is no --format: the output format is --to (json, geojson, geojsonl, geojson-triangles, wkt, csv, svg), \
                 the input format --from (auto, wkt, geojson, vertices, wkb, csv)",
            )
            .exit();
        }
        let matches = cmd.get_matches_mut();
        let flags = Flags::from_arg_matches(&matches).unwrap_or_else(|e| e.format(&mut cmd).exit());
        if let Err(message) = flags.output_format() {
            cmd.error(clap::error::ErrorKind::ArgumentConflict, message)
                .exit();
        }
        if flags.labels && flags.output_format().ok() != Some(ToFlag::Svg) {
            cmd.error(
                clap::error::ErrorKind::ArgumentConflict,
                "--labels only applies to --to svg",
            )
            .exit();
        }
        flags
    }

    /// The output format: `--to`, or else `-o`'s extension when it names one output file, or
    /// else JSON. A directory's name decides nothing ([`is_tree`]: the same for a directory that
    /// exists and one that a batch creates).
    ///
    /// # Errors
    /// When `--to` and `-o`'s extension name different formats.
    pub fn output_format(&self) -> Result<ToFlag, String> {
        let inputs = self.input_paths();
        let by_name = self
            .output
            .as_deref()
            .filter(|out| !is_tree(&inputs, out))
            .and_then(|out| out.extension())
            .and_then(|e| e.to_str())
            .and_then(|e| OutputFormat::from_extension(e).map(|f| (e, f)));
        let named = by_name.map(|(_, format)| match format {
            OutputFormat::Json => ToFlag::Json,
            OutputFormat::GeoJson | OutputFormat::GeoJsonTriangles => ToFlag::Geojson,
            OutputFormat::GeoJsonLines => ToFlag::Geojsonl,
            OutputFormat::Wkt => ToFlag::Wkt,
            OutputFormat::Csv => ToFlag::Csv,
            OutputFormat::Svg(_) => ToFlag::Svg,
        });
        let agrees = |to: ToFlag, named: ToFlag| {
            to == named || (to == ToFlag::GeojsonTriangles && named == ToFlag::Geojson)
        };
        match (self.to, named, by_name) {
            (Some(to), Some(named), Some((extension, _))) if !agrees(to, named) => Err(format!(
                "--to {} conflicts with the output file's extension .{extension} (which stands \
                 for --to {}): change one, or drop --to",
                to.name(),
                named.name()
            )),
            (Some(to), _, _) => Ok(to),
            (None, Some(named), _) => Ok(named),
            (None, None, _) => Ok(ToFlag::Json),
        }
    }

    /// The inputs as given, standard input (`-`) when none.
    fn input_paths(&self) -> Vec<PathBuf> {
        if self.inputs.is_empty() {
            vec![PathBuf::from("-")]
        } else {
            self.inputs.clone()
        }
    }

    /// Validates the flags into a [`Config`].
    pub fn into_config(self) -> Config {
        let to = self.output_format().unwrap_or(ToFlag::Json);
        let algorithm = match self.algorithm {
            AlgorithmFlag::Minitri => Algorithm::Minitri,
            AlgorithmFlag::Asano => Algorithm::Asano,
            AlgorithmFlag::Ear => Algorithm::Ear,
            AlgorithmFlag::PseudoHull => Algorithm::PseudoHull,
            AlgorithmFlag::Pseudo => Algorithm::Pseudo,
        };
        let from = match self.from {
            FromFlag::Auto => None,
            FromFlag::Wkt => Some(Format::Wkt),
            FromFlag::Geojson => Some(Format::GeoJson),
            FromFlag::Vertices => Some(Format::Vertices),
            FromFlag::Wkb => Some(Format::Wkb),
            FromFlag::Csv => Some(Format::Csv),
        };
        let inputs = self.input_paths();
        Config {
            inputs,
            from,
            to: match to {
                ToFlag::Json => OutputFormat::Json,
                ToFlag::Geojson => OutputFormat::GeoJson,
                ToFlag::Geojsonl => OutputFormat::GeoJsonLines,
                ToFlag::GeojsonTriangles => OutputFormat::GeoJsonTriangles,
                ToFlag::Wkt => OutputFormat::Wkt,
                ToFlag::Csv => OutputFormat::Csv,
                ToFlag::Svg => OutputFormat::Svg(svg::Style {
                    labels: self.labels,
                }),
            },
            output: self.output,
            options: Options {
                algorithm,
                dp_limit: self.dp_limit,
                time_limit: (self.time_limit > 0.0)
                    .then(|| std::time::Duration::from_secs_f64(self.time_limit)),
                verify: self.verify,
                repair: self.repair,
            },
            jobs: self.jobs.map(|n| n as usize),
            quiet: self.quiet,
            max_vertices: usize::try_from(self.max_vertices).unwrap_or(usize::MAX),
        }
    }
}

/// A number of seconds: finite, not negative, at most a year. A positive number too small for
/// a double (`1e-400`, which `f64` rounds to 0, "no limit") or for a nanosecond is the smallest
/// limit, one nanosecond; a negative one that rounds to `-0` is refused like any negative.
fn seconds(text: &str) -> Result<f64, String> {
    let refused =
        || format!("expected a number of seconds from 0 (no limit) to 32000000, got {text:?}");
    let v = text.parse::<f64>().map_err(|_| refused())?;
    if !v.is_finite() || !(0.0..=3.2e7).contains(&v) {
        return Err(refused());
    }
    // Any digit but 0 before the exponent: the number written is not zero.
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let nonzero = mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b));
    if nonzero && text.trim_start().starts_with('-') {
        return Err(refused());
    }
    if nonzero && std::time::Duration::from_secs_f64(v).is_zero() {
        return Ok(SMALLEST_LIMIT);
    }
    Ok(v)
}

/// The smallest time limit, one nanosecond: what a positive `--time-limit` below it means.
const SMALLEST_LIMIT: f64 = 1e-9;

/// Does `-o out` name a directory mirroring the inputs (rather than one output file)? With a
/// directory input, several inputs, or an existing directory as `out`.
pub fn is_tree(inputs: &[PathBuf], out: &Path) -> bool {
    inputs.len() > 1 || inputs.iter().any(|p| p.is_dir()) || out.is_dir()
}
