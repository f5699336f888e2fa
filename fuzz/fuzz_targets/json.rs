//! Any bytes through the json reader and shape validation: must return Ok or
//! a typed error, never panic or hang. A valid shape must also survive its
//! own JSON round trip unchanged, and the fast reader must agree with the
//! general one.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::io::Format;
use medax::shape::{Shape2d, ShapeOptions};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(loops) = medax::io::json::read_loops(&text) {
        assert_eq!(Ok(loops), medax::io::json::read_loops_generic(&text));
    }
    // Split reading must agree with unsplit reading, wherever it cuts.
    let whole = medax::io::json::read_loops_fast_in_pieces(data, usize::MAX / 2);
    for piece in [1, 7, 64] {
        assert_eq!(medax::io::json::read_loops_fast_in_pieces(data, piece), whole);
    }
    if let Some(loops) = whole {
        assert_eq!(Ok(loops), medax::io::json::read_loops_generic(&text));
    }
    if let Ok(shape) = Shape2d::from_str_as(&text, Format::Json, &ShapeOptions::default()) {
        let again = Shape2d::from_json_str(&shape.to_json(), &ShapeOptions::default())
            .expect("a valid shape's own JSON must be valid");
        assert_eq!(again.loops(), shape.loops());
    }
});
