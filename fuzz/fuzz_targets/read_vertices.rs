//! Vertex-list reader: arbitrary text through `io::read::vertices::read`, then validation, the
//! algorithms and the writers on what it reads (`minitri_fuzz::check_polygons`). Must never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use minitri::io::read::vertices;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(raws) = vertices::read(text) {
        assert!(!raws.is_empty(), "vertex list read Ok with no polygon");
        minitri_fuzz::check_polygons(&raws);
    }
});
