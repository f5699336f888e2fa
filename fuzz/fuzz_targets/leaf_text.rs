//! The leaf text reader (`plane::leaf_text`) on arbitrary text: no panic,
//! and what it accepts writes back to text that reads as the same leaf.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::plane::internals::{read_leaf, write_leaf};
use medax::shape::{samples, Shape2d, ShapeOptions};
use std::sync::OnceLock;

fn shape() -> &'static Shape2d {
    static SHAPE: OnceLock<Shape2d> = OnceLock::new();
    SHAPE.get_or_init(|| Shape2d::from_bulge_loops(samples::star_polygon(64, 1), &ShapeOptions::default()).unwrap())
}

fuzz_target!(|text: &str| {
    if let Ok((s, cuts)) = read_leaf(shape(), text) {
        let again = read_leaf(shape(), &write_leaf(&s, &cuts)).expect("written leaves read back");
        assert_eq!(again.0, s);
        assert_eq!(again.1.len(), cuts.len());
    }
});
