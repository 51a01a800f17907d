//! The core: structured input (an outer ring and up to 2 holes of small integer points, coordinates
//! 0..=8, at most `minitri_fuzz::SMALL` vertices in all) through validation and every algorithm
//! (`minitri_fuzz::check_polygon`: the independent checker judges each output, the exact counts
//! must agree, ear must give n + 2w - 2).
//!
//! Random rings are mostly self-intersecting, so each input is used twice: as the rings given,
//! and "grown": each ring starts from its first three points and every further point is inserted
//! after the vertex its third byte names, kept only when the polygon stays valid (as in
//! `tests/property.rs`). Both go through validation; valid ones through every algorithm.
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use minitri::io::read::RawPolygon;
use minitri::Polygon;
use minitri_fuzz::{check_polygon, ring, SMALL, SMALL_HOLES};

/// A point `(x, y)` (each taken modulo 9) and, for growing, where to insert it.
#[derive(Arbitrary, Debug, Clone, Copy)]
struct Vertex(u8, u8, u8);

#[derive(Arbitrary, Debug)]
struct Input {
    rings: Vec<Vec<Vertex>>,
}

fn point(v: Vertex) -> (i64, i64) {
    (i64::from(v.0 % 9), i64::from(v.1 % 9))
}

fn raw(rings: &[Vec<(i64, i64)>]) -> RawPolygon {
    RawPolygon {
        rings: rings.iter().map(|r| ring(r)).collect(),
        ..Default::default()
    }
}

fn valid(rings: &[Vec<(i64, i64)>]) -> Option<Polygon> {
    Polygon::from_raw_all_errors(&raw(rings))
        .ok()
        .map(|(p, _)| p)
}

fuzz_target!(|input: Input| {
    // At most 1 + SMALL_HOLES rings and SMALL vertices in all.
    let mut budget = SMALL;
    let rings: Vec<Vec<Vertex>> = input
        .rings
        .into_iter()
        .take(1 + SMALL_HOLES)
        .map(|r| {
            let r: Vec<Vertex> = r.into_iter().take(budget).collect();
            budget -= r.len();
            r
        })
        .collect();
    if rings.is_empty() {
        return;
    }

    let given: Vec<Vec<(i64, i64)>> = rings
        .iter()
        .map(|r| r.iter().map(|&v| point(v)).collect())
        .collect();
    if let Some(polygon) = valid(&given) {
        check_polygon(&polygon);
    }

    let mut grown: Vec<Vec<(i64, i64)>> = Vec::new();
    for r in &rings {
        if r.len() < 3 {
            break;
        }
        grown.push(r[..3].iter().map(|&v| point(v)).collect());
        if valid(&grown).is_none() {
            grown.pop();
            break;
        }
        for &v in &r[3..] {
            let last = grown.len() - 1;
            let at = usize::from(v.2) % grown[last].len() + 1;
            grown[last].insert(at, point(v));
            if valid(&grown).is_none() {
                grown[last].remove(at);
            }
        }
    }
    if let Some(polygon) = (!grown.is_empty()).then(|| valid(&grown)).flatten() {
        check_polygon(&polygon);
    }
});
