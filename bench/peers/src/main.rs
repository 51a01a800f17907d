//! The plain triangulators minitri is compared with, end to end on one WKT polygon file:
//! `peers FILE.wkt [PEER]` reads the file and triangulates its polygon (holes allowed) with each
//! peer (or only PEER), printing `name <tab> triangles` for each. bench/peers.sh times one
//! process per peer and run, as it times minitri's binary: file in, triangle count out (read,
//! parse with the `wkt` crate into f64 coordinates, triangulate). The peers:
//! - `earcut` (the earcut crate, a port of mapbox/earcut: ear clipping with z-order hashing);
//! - `spade` (a constrained Delaunay triangulation of the rings' edges, bulk loaded; its count
//!   is of every finite face, inside the polygon or not, since a plain CDT covers the hull);
//! - `i_triangle` (i_triangle's float triangulation of the shape);
//! - `earcut+valid`: earcut after the `geo` crate's OGC validity check of the parsed polygon
//!   (`geo::Validation::is_valid`: simple rings, no crossings, holes inside), as a user who must
//!   reject invalid input would run it; minitri always validates, exactly. Not one of the plain
//!   peers (the table's "best peer"), but their column beside it.

fn parse(text: &str) -> geo_types::Polygon<f64> {
    let parsed: wkt::Wkt<f64> = text.trim().parse().expect("a WKT polygon");
    parsed.try_into().expect("a POLYGON")
}

fn rings(text: &str) -> Vec<Vec<[f64; 2]>> {
    rings_of(&parse(text))
}

fn rings_of(polygon: &geo_types::Polygon<f64>) -> Vec<Vec<[f64; 2]>> {
    let ring = |r: &geo_types::LineString<f64>| {
        let mut points: Vec<[f64; 2]> = r.0.iter().map(|c| [c.x, c.y]).collect();
        points.pop(); // the closing repetition of the first point
        points
    };
    std::iter::once(polygon.exterior())
        .chain(polygon.interiors())
        .map(ring)
        .collect()
}

fn earcut_run(path: &str) -> usize {
    earcut_rings(&rings(&std::fs::read_to_string(path).expect("readable")))
}

fn earcut_valid_run(path: &str) -> usize {
    use geo::Validation;
    // geo's check grows about quadratically (47 s on a star of 10^5 vertices): a watchdog thread
    // stops the process after VALID_LIMIT seconds, if set, with exit status 2. It runs inside
    // this process so that timing it adds no second program's start-up (`timeout` adds 0.7 ms).
    if let Some(limit) = std::env::var("VALID_LIMIT")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
    {
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_secs_f64(limit));
            eprintln!("{limit} s: stopped (VALID_LIMIT)");
            std::process::exit(2);
        });
    }
    let polygon = parse(&std::fs::read_to_string(path).expect("readable"));
    if !polygon.is_valid() {
        eprintln!("{path}: not a valid polygon (geo::Validation)");
        std::process::exit(1);
    }
    earcut_rings(&rings_of(&polygon))
}

fn earcut_rings(rings: &[Vec<[f64; 2]>]) -> usize {
    let mut flat = Vec::new();
    let mut holes = Vec::new();
    for (i, r) in rings.iter().enumerate() {
        if i > 0 {
            holes.push(flat.len());
        }
        flat.extend(r.iter().copied());
    }
    let mut out: Vec<usize> = Vec::new();
    earcut::Earcut::new().earcut(flat.iter().copied(), &holes, &mut out);
    out.len() / 3
}

fn spade_run(path: &str) -> usize {
    use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
    let rings = rings(&std::fs::read_to_string(path).expect("readable"));
    let mut vertices = Vec::new();
    let mut edges = Vec::new();
    for r in &rings {
        let start = vertices.len();
        for (k, p) in r.iter().enumerate() {
            vertices.push(Point2::new(p[0], p[1]));
            edges.push([start + k, start + (k + 1) % r.len()]);
        }
    }
    let cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::bulk_load_cdt(vertices, edges)
        .expect("spade accepts the polygon");
    cdt.num_inner_faces()
}

fn i_triangle_run(path: &str) -> usize {
    use i_triangle::float::triangulatable::Triangulatable;
    let rings = rings(&std::fs::read_to_string(path).expect("readable"));
    let triangulation = rings.triangulate().to_triangulation::<u32>();
    triangulation.indices.len() / 3
}

/// A peer: its name and its run (file path in, triangle count out).
type Peer = (&'static str, fn(&str) -> usize);

fn main() {
    let mut args = std::env::args().skip(1);
    let usage = "usage: peers FILE.wkt [PEER]";
    let path = args.next().expect(usage);
    let peers: [Peer; 4] = [
        ("earcut", earcut_run),
        ("spade", spade_run),
        ("i_triangle", i_triangle_run),
        ("earcut+valid", earcut_valid_run),
    ];
    let only = args.next();
    for (name, run) in peers {
        if only.as_deref().is_none_or(|o| o == name) {
            println!("{name}\t{}", run(&path));
        }
    }
}
