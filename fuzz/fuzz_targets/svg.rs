//! Any bytes through the svg reader and shape validation: must return Ok or
//! a typed error, never panic or hang. A valid shape must also survive its
//! own JSON round trip unchanged.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::io::Format;
use medax::shape::{Shape2d, ShapeOptions};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(shape) = Shape2d::from_str_as(&text, Format::Svg, &ShapeOptions::default()) {
        let again = Shape2d::from_json_str(&shape.to_json(), &ShapeOptions::default())
            .expect("a valid shape's own JSON must be valid");
        assert_eq!(again.loops(), shape.loops());
    }
});
