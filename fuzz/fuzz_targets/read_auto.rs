//! Format detection and reading as the CLI does it on an input without a known extension:
//! `detect_start` on prefixes must agree with `detect` on the whole text (the CLI decides on
//! the first buffer), then the detected reader (GeoJSON Lines line by line when
//! `looks_line_delimited`), then validation, the algorithms and the writers
//! (`minitri_fuzz::check_polygons`). The first byte also picks a file extension, to fuzz
//! detection by name. Must never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use minitri::io::read::geojson_stream::{looks_line_delimited, read_line};
use minitri::io::read::{self, detect, detect_start, Format};

const EXTENSIONS: [&str; 10] = [
    "wkt", "GeoJSON", "json", "ndjson", "geojsonl", "txt", "xy", "vertices", "csv", "",
];

fuzz_target!(|data: &[u8]| {
    let Some((&pick, data)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let extension = EXTENSIONS.get(usize::from(pick)).copied();
    let format = detect(extension, text);
    // Prefixes ending at the first 32 characters and at the first 32 line ends, and the whole.
    let ends = text.char_indices().map(|(i, _)| i).take(32);
    let lines = text.match_indices('\n').map(|(i, _)| i).take(32);
    for end in ends.chain(lines).chain([text.len()]) {
        if let Some(early) = detect_start(extension, &text[..end]) {
            assert_eq!(
                early, format,
                "detect_start on {end} bytes disagrees with detect"
            );
        }
    }
    let raws = if format == Format::GeoJson && looks_line_delimited(data) {
        let mut raws = Vec::new();
        for (k, line) in text.split('\n').enumerate() {
            raws.extend(read_line(line, k + 1).unwrap_or_default());
        }
        raws
    } else {
        read::read(format, text).unwrap_or_default()
    };
    minitri_fuzz::check_polygons(&raws);
});
