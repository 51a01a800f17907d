//! `--to svg` output parsed and rendered with resvg: it is valid SVG, and the pixels and text
//! show what they should (labels, holes, errors, faults in red exactly when `--verify` found
//! something). Set `MINITRI_PNG_DIR` to a directory to keep the renderings as PNG files.

use crate::util::{minitri, xorshift};
use minitri::io::write::svg::{FAULT, MARGIN, PANEL};
use minitri::pipeline::{CORRUPT_FOR_TESTS, CORRUPT_WITH_EAR};
use resvg::tiny_skia::{Pixmap, Transform};
use resvg::usvg;
use std::sync::{Arc, OnceLock};

/// Space around the panels (`svg.rs`): the first panel's top left corner is at (GAP, GAP).
const GAP: f64 = 24.0;

/// Runs the binary with `args` (and `env`, if any), returning (exit code, SVG on stdout).
fn svg_of(args: &[&str], stdin: Option<&str>, env: Option<&str>) -> (i32, String) {
    let mut cmd = minitri();
    cmd.args(["--to", "svg"]).args(args);
    if let Some(text) = stdin {
        cmd.write_stdin(text);
    }
    if let Some(mode) = env {
        cmd.env(CORRUPT_FOR_TESTS, mode);
    }
    let out = cmd.output().expect("run minitri");
    let svg = String::from_utf8(out.stdout).expect("UTF-8");
    (out.status.code().expect("exit code"), svg)
}

/// What resvg made of a document.
struct Rendered {
    pixmap: Pixmap,
    /// The text of every `<text>` element, in document order.
    texts: Vec<String>,
}

fn fonts() -> Arc<usvg::fontdb::Database> {
    static FONTS: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = usvg::fontdb::Database::new();
            db.load_system_fonts();
            // fontdb maps `sans-serif` to Arial; take a sans-serif face this machine has.
            let families: Vec<String> = db
                .faces()
                .flat_map(|face| face.families.iter().map(|(name, _)| name.clone()))
                .collect();
            let sans = ["DejaVu Sans", "Liberation Sans", "Noto Sans", "FreeSans"]
                .into_iter()
                .find(|f| families.iter().any(|g| g == f))
                .map(str::to_string)
                .or_else(|| families.first().cloned())
                .expect("no font installed: the picture tests read text (install e.g. fonts-dejavu-core)");
            db.set_sans_serif_family(sans);
            Arc::new(db)
        })
        .clone()
}

/// Parses (panics if the SVG is invalid) and renders at 1 pixel per SVG unit.
fn render(svg: &str, name: &str) -> Rendered {
    render_scaled(svg, name, 1.0)
}

/// Parses and renders at `scale` pixels per SVG unit (resvg's time grows with the picture's
/// height times the edges crossing each row: a 10^5-vertex star takes a minute at full size).
fn render_scaled(svg: &str, name: &str, scale: f32) -> Rendered {
    let options = usvg::Options {
        fontdb: fonts(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .expect("non-empty picture");
    let mut pixmap = Pixmap::new(size.width(), size.height()).expect("non-empty picture");
    let transform = Transform::from_scale(scale, scale);
    resvg::render(&tree, transform, &mut pixmap.as_mut());
    if let Some(dir) = std::env::var_os("MINITRI_PNG_DIR") {
        let path = std::path::Path::new(&dir).join(format!("{name}.png"));
        pixmap.save_png(&path).expect("write PNG");
    }
    let mut texts = Vec::new();
    collect_texts(tree.root(), &mut texts);
    Rendered { pixmap, texts }
}

fn collect_texts(group: &usvg::Group, texts: &mut Vec<String>) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect_texts(g, texts),
            usvg::Node::Text(t) => {
                texts.push(t.chunks().iter().map(|c| c.text()).collect());
            }
            _ => {}
        }
    }
}

impl Rendered {
    fn rgb(&self, x: u32, y: u32) -> [u8; 3] {
        let p = self.pixmap.pixel(x, y).expect("inside").demultiply();
        [p.red(), p.green(), p.blue()]
    }

    /// Pixels in the rectangle `[x0, x1) x [y0, y1)` satisfying `test`.
    fn count(
        &self,
        (x0, y0, x1, y1): (u32, u32, u32, u32),
        test: impl Fn([u8; 3]) -> bool,
    ) -> usize {
        let (x1, y1) = (x1.min(self.pixmap.width()), y1.min(self.pixmap.height()));
        (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .filter(|&(x, y)| test(self.rgb(x, y)))
            .count()
    }

    fn all(&self) -> (u32, u32, u32, u32) {
        (0, 0, self.pixmap.width(), self.pixmap.height())
    }

    fn has_text(&self, text: &str) -> bool {
        self.texts.iter().any(|t| t == text)
    }
}

/// The inside of panel `k` of the first row, 4 pixels clear of its frame.
fn panel(k: u32) -> (u32, u32, u32, u32) {
    let left = (GAP + f64::from(k) * (PANEL + GAP)) as u32;
    let top = GAP as u32;
    let side = PANEL as u32;
    (left + 4, top + 4, left + side - 4, top + side - 4)
}

/// The red of faults, [`FAULT`], and nothing else drawn (orange, the error red, blues, greys):
/// strongly red with hardly any green or blue.
fn red([r, g, b]: [u8; 3]) -> bool {
    r >= 200 && g <= 30 && b <= 30
}

#[test]
fn the_fault_red_is_what_red_detects() {
    let hex = |i: usize| u8::from_str_radix(&FAULT[i..i + 2], 16).unwrap();
    assert!(red([hex(1), hex(3), hex(5)]));
    // Orange (degenerate), the error red, the boundary, the triangle blue: not fault red.
    for colour in [
        [0xe8, 0x59, 0x0c],
        [0xc9, 0x2a, 0x2a],
        [0x1f, 0x2a, 0x3a],
        [0x4a, 0x78, 0xc2],
    ] {
        assert!(!red(colour), "{colour:?}");
    }
}

/// Whether a pixel is the orange of degenerate triangles (anti-aliasing aside).
fn orange([r, g, b]: [u8; 3]) -> bool {
    r >= 200 && (60..=120).contains(&g) && b <= 40
}

#[test]
fn u_shape_has_title_caption_labels_markers_and_no_red() {
    let (code, svg) = svg_of(&["fixtures/valid/u_shape.wkt"], None, None);
    assert_eq!(code, 0);
    assert!(svg.contains("<title>minitri: fixtures/valid/u_shape.wkt: polygon 0</title>"));
    // The panel's tooltip repeats the caption's title and numbers.
    assert!(svg.contains(
        "<title>fixtures/valid/u_shape.wkt: polygon 0; n = 12, w = 0, d = 5, triangles = 5, \
         algorithm = minitri, optimal</title>"
    ));
    let picture = render(&svg, "u_shape");
    assert!(picture.has_text("n = 12, w = 0, d = 5, triangles = 5, algorithm = minitri, optimal"));
    // 12 vertices: labelled automatically with the input numbers 0..11, and no other number.
    for id in 0..12 {
        assert!(picture.has_text(&id.to_string()), "label {id}");
    }
    assert!(!picture.has_text("12"));
    assert_eq!(
        picture.count(picture.all(), red),
        0,
        "nothing wrong, nothing red"
    );
    assert!(
        picture.count(panel(0), orange) > 50,
        "5 orange degenerate marks"
    );
    assert_eq!(picture.rgb(2, 2), [255, 255, 255], "white background");
}

#[test]
fn a_hole_is_left_empty() {
    // The square 0..4 with the hole 1..3: the hole's centre is the panel's centre.
    let (code, svg) = svg_of(&["fixtures/holes/square_with_hole.wkt"], None, None);
    assert_eq!(code, 0);
    let picture = render(&svg, "square_with_hole");
    assert!(picture.has_text("n = 8, w = 1, d = 0, triangles = 8, algorithm = minitri, optimal"));
    let centre = (GAP + PANEL / 2.0) as u32;
    assert_eq!(
        picture.rgb(centre, centre),
        [255, 255, 255],
        "the hole is empty"
    );
    // (0.5, 2), inside the polygon, halfway between its left side and the hole: filled light blue.
    let scale = (PANEL - 2.0 * MARGIN) / 4.0;
    let x = (GAP + MARGIN + 0.5 * scale) as u32;
    let [r, g, b] = picture.rgb(x, centre);
    assert!(b > r && r < 245 && g < 250, "({r}, {g}, {b})");
    assert_eq!(picture.count(picture.all(), red), 0);
}

#[test]
fn an_error_figure_shows_the_polygon_and_the_error_in_the_error_red() {
    // asano refuses a polygon above --dp-limit: the polygon is drawn with the message.
    let (code, svg) = svg_of(
        &[
            "-a",
            "asano",
            "--dp-limit",
            "5",
            "fixtures/valid/u_shape.wkt",
        ],
        None,
        None,
    );
    assert_eq!(code, 1);
    let picture = render(&svg, "error");
    assert!(picture.has_text("n = 12, w = 0"));
    assert!(
        picture.texts.iter().any(|t| t.contains("--dp-limit")),
        "the error text: {:?}",
        picture.texts
    );
    // No triangles: the triangle blue strokes are absent; the error frame is drawn, not fault red.
    let blue = |[r, g, b]: [u8; 3]| b >= 150 && r <= 110 && g <= 150;
    assert_eq!(picture.count(panel(0), blue), 0);
    assert_eq!(picture.count(picture.all(), red), 0);
    let error_red =
        |[r, g, b]: [u8; 3]| r >= 180 && (20..=70).contains(&g) && (20..=70).contains(&b);
    assert!(
        picture.count(picture.all(), error_red) > 500,
        "the red frame and text"
    );
}

#[test]
fn verify_failures_are_red_and_each_algorithm_gets_a_panel() {
    let args = ["--verify", "fixtures/valid/u_shape.wkt"];
    let width = |svg: &str| {
        let start = svg.find(" width=\"").expect("width") + 8;
        svg[start..start + svg[start..].find('"').unwrap()]
            .parse::<f64>()
            .unwrap()
    };
    // Clean: one panel, nothing red.
    let (code, svg) = svg_of(&args, None, None);
    assert_eq!(code, 0);
    assert_eq!(width(&svg), 2.0 * GAP + PANEL);
    let picture = render(&svg, "verify_ok");
    assert_eq!(picture.count(picture.all(), red), 0);

    // One triangle dropped from minitri's output: invalid, and asano's count differs.
    let (code, svg) = svg_of(&args, None, Some("1"));
    assert_eq!(code, 3);
    assert_eq!(
        width(&svg),
        3.0 * GAP + 2.0 * PANEL,
        "minitri's and asano's panels"
    );
    let picture = render(&svg, "verify_dropped");
    assert!(picture.has_text("disagreement: minitri gives 4 triangles but asano gives 5"));
    assert!(picture.has_text("minitri output invalid (red):"));
    assert!(picture.has_text("fixtures/valid/u_shape.wkt: polygon 0 — asano output (--verify)"));
    // Red inside minitri's panel (the uncovered triangle and its sides), not only on the frame;
    // asano's output is valid: inside its panel nothing is red.
    assert!(
        picture.count(panel(0), red) > 100,
        "{}",
        picture.count(panel(0), red)
    );
    assert_eq!(picture.count(panel(1), red), 0);

    // A valid but not minimal output labelled minitri: every check passes, the counts disagree.
    let (code, svg) = svg_of(&args, None, Some(CORRUPT_WITH_EAR));
    assert_eq!(code, 3);
    assert_eq!(width(&svg), 3.0 * GAP + 2.0 * PANEL);
    let picture = render(&svg, "verify_disagreement");
    assert!(picture.has_text("disagreement: minitri gives 10 triangles but asano gives 5"));
    assert!(!picture.texts.iter().any(|t| t.contains("invalid")));
    // Red frames (and text), but no fault inside either panel.
    assert!(picture.count(picture.all(), red) > 1000);
    assert_eq!(picture.count(panel(0), red), 0);
    assert_eq!(picture.count(panel(1), red), 0);
}

/// A star-shaped polygon of `n` vertices: evenly spaced directions, random radii from 3 to 10
/// million (so consecutive vertices are hundreds of units apart along the arc and the angular
/// order is the ring order: simple).
fn star(n: usize) -> String {
    let mut random = xorshift(7);
    let mut wkt = String::from("POLYGON ((");
    for k in 0..n {
        let angle = std::f64::consts::TAU * k as f64 / n as f64;
        let r = (3_000_000 + random(7_000_000)) as f64;
        let sep = if k == 0 { "" } else { ", " };
        wkt += &format!(
            "{sep}{} {}",
            (r * angle.cos()).round(),
            (r * angle.sin()).round()
        );
    }
    wkt + "))"
}

#[test]
fn labels_on_request_shrink_with_density_and_keep_the_picture_legible() {
    // 4 vertices: labels at full size anyway. 1000 vertices: none by default, all with --labels.
    let square = "POLYGON ((0 0, 10 0, 10 10, 0 10))";
    let (_, svg) = svg_of(&[], Some(square), None);
    let picture = render(&svg, "labels_4");
    assert!((0..4).all(|id| picture.has_text(&id.to_string())));
    assert!(svg.contains(r#"font-size="11" stroke-width="3" dy="0.35em">0</text>"#));

    let thousand = star(1000);
    let (_, plain) = svg_of(&[], Some(&thousand), None);
    let (_, labelled) = svg_of(&["--labels"], Some(&thousand), None);
    assert!(!plain.contains("0.35em"));
    assert_eq!(labelled.matches("0.35em").count(), 1000);
    let picture = render(&labelled, "labels_1000");
    assert!(picture.has_text("999") && picture.has_text("0"));

    // 3000 vertices: every label is there, tiny; the picture is hardly darker than without.
    let dense = star(3000);
    let (_, plain) = svg_of(&[], Some(&dense), None);
    let (_, labelled) = svg_of(&["--labels"], Some(&dense), None);
    let dark = |[r, g, b]: [u8; 3]| u32::from(r) + u32::from(g) + u32::from(b) < 3 * 128;
    let plain = render(&plain, "star_3000");
    let labelled = render(&labelled, "star_3000_labels");
    assert!(labelled.has_text("2999") && labelled.has_text("0"));
    let numbers = labelled.texts.iter().filter(|t| t.parse::<usize>().is_ok());
    assert_eq!(numbers.count(), 3000);
    let (before, after) = (plain.count(panel(0), dark), labelled.count(panel(0), dark));
    assert!(
        after <= before + before / 4,
        "{after} dark pixels with labels, {before} without"
    );
    assert_eq!(labelled.count(labelled.all(), red), 0);
}

#[test]
fn a_100000_vertex_star_renders_and_its_labels_are_tiny() {
    let huge = star(100_000);
    let (code, plain) = svg_of(&[], Some(&huge), None);
    assert_eq!(code, 0);
    assert!(plain.len() < 100 * 100_000, "{} bytes", plain.len());
    let picture = render_scaled(&plain, "star_100000", 0.25);
    assert!(picture
        .has_text("n = 100000, w = 0, d = 0, triangles = 99998, algorithm = minitri, optimal"));
    assert_eq!(picture.count(picture.all(), red), 0);
    // (Rendering 10^5 labels takes resvg minutes: here they are only read.) Every vertex has
    // its number, and with about 0.02 pixels between vertices on the rim, no label is larger
    // than the room of a dense vertex allows.
    let (code, labelled) = svg_of(&["--labels"], Some(&huge), None);
    assert_eq!(code, 0);
    let sizes: Vec<f64> = labelled
        .match_indices(" font-size=\"")
        .map(|(i, _)| {
            let rest = &labelled[i + 12..];
            rest[..rest.find('"').unwrap()].parse().unwrap()
        })
        .collect();
    let labels = labelled.matches("0.35em").count();
    assert_eq!(labels, 100_000);
    let small = sizes.iter().filter(|&&s| s < 1.0).count();
    assert!(
        small * 10 >= labels * 9,
        "{small} of {labels} labels under 1 pixel"
    );
}

#[test]
fn labels_only_apply_to_svg() {
    let out = minitri()
        .args(["--labels", "fixtures/valid/u_shape.wkt"])
        .output()
        .expect("run");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--labels only applies to --to svg"));
}

/// Renders the SVG file named by `MINITRI_SVG_FILE` (with `MINITRI_PNG_DIR`, to a PNG of the same
/// name): `cargo test --test main render_file -- --ignored`.
#[test]
#[ignore]
fn render_file() {
    let path = std::env::var("MINITRI_SVG_FILE").expect("MINITRI_SVG_FILE");
    let svg = std::fs::read_to_string(&path).expect("read the SVG");
    let name = std::path::Path::new(&path)
        .file_stem()
        .unwrap()
        .to_string_lossy();
    render(&svg, &name);
}
