//! Any bytes through the dxf reader and shape validation: must return Ok or
//! a typed error, never panic or hang. A valid shape must also survive its
//! own JSON round trip unchanged. The same bytes through profile
//! extraction: every shape it finds survives the round trip too.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::io::Format;
use medax::shape::{Drawing2d, DrawingOptions, Shape2d, ShapeOptions};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let opts = ShapeOptions::default();
    let round_trip = |shape: &Shape2d| {
        let again = Shape2d::from_json_str(&shape.to_json(), &opts).expect("a valid shape's own JSON must be valid");
        assert_eq!(again.loops(), shape.loops());
    };
    if let Ok(shape) = Shape2d::from_str_as(&text, Format::Dxf, &opts) {
        round_trip(&shape);
    }
    if let Ok(drawing) = Drawing2d::from_str_as(&text, Format::Dxf, &opts, &DrawingOptions::default()) {
        drawing.shapes.iter().for_each(round_trip);
    }
});
