//! WKT reader: arbitrary text through `io::read::wkt::read`, then validation, the algorithms and
//! the writers on what it reads (`minitri_fuzz::check_polygons`). Must never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use minitri::io::read::wkt;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(raws) = wkt::read(text) {
        assert!(!raws.is_empty(), "WKT read Ok with no polygon");
        minitri_fuzz::check_polygons(&raws);
    }
});
