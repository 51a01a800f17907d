//! GeoJSON readers, against each other: the whole-document reader (`geojson::read`), the
//! streaming reader (`geojson_stream::stream`, through a tiny buffer so that values straddle
//! refills) and the line reader (`geojson_stream::read_line`, each line alone).
//!
//! Oracles: `read` succeeds exactly when `stream` succeeds without a failed feature, and then they
//! give the same polygons; when every line reads alone and yields a polygon, `stream` gives the
//! same polygons as the lines together. Everything read goes on through validation, the
//! algorithms and the writers (`minitri_fuzz::check_polygons`). Must never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use minitri::io::read::geojson;
use minitri::io::read::geojson_stream::{read_line, stream, Event};
use std::io::BufReader;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let whole = geojson::read(text);
    let mut streamed = Vec::new();
    let mut failures = Vec::new();
    let stopped = stream(BufReader::with_capacity(7, data), &mut |event| {
        match event {
            Event::Feature(_) => {}
            Event::Polygon(raw) => streamed.push(raw),
            Event::Failed(e) => failures.push(e),
        }
        Ok(())
    });
    match &whole {
        Ok(raws) => {
            assert!(
                stopped.is_ok() && failures.is_empty(),
                "read accepts but stream gives {stopped:?}, {failures:?}"
            );
            assert_eq!(raws, &streamed, "read and stream give different polygons");
        }
        Err(e) => assert!(
            stopped.is_err() || !failures.is_empty(),
            "read fails ({e}) but stream accepts"
        ),
    }
    for e in &failures {
        assert!(!e.to_string().is_empty());
    }

    let mut lines = Vec::new();
    let mut all_lines_read = true;
    for (k, line) in text.split('\n').enumerate() {
        match read_line(line, k + 1) {
            Ok(raws) => lines.extend(raws),
            Err(e) => {
                assert!(e.location.is_some(), "line error without location: {e}");
                all_lines_read = false;
            }
        }
    }
    if all_lines_read && !lines.is_empty() && !text.contains('\u{feff}') {
        assert!(
            stopped.is_ok() && failures.is_empty(),
            "lines read but stream fails"
        );
        assert_eq!(lines, streamed, "lines and stream give different polygons");
    }

    if let Ok(raws) = whole {
        minitri_fuzz::check_polygons(&raws);
    } else {
        minitri_fuzz::check_polygons(&streamed);
    }
});
