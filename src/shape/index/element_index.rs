//! All elements of all loops in one box tree, with global ids: the index
//! validation and the holes' containment test query.

use crate::kernel::BBox;
use crate::shape::index::box_tree::BoxTree;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ElementRef;
use crate::shape::model::per_element;

/// All elements of all loops in one box tree, with global ids.
pub(crate) struct ElementIndex {
    pub tree: BoxTree,
    /// `offsets[l]` = global id of element 0 of loop `l`; one extra entry at the end.
    pub offsets: Vec<usize>,
    /// Loop of each global id, when there are many loops: a lookup is then
    /// cheaper than a binary search over `offsets` (4 bytes per element).
    loop_of: Option<Vec<u32>>,
}

/// From this many loops on, [`ElementIndex`] keeps a loop id per element.
const LOOP_TABLE_MIN_LOOPS: usize = 16;

impl ElementIndex {
    /// Indexes elements with the given boxes (in global id order).
    pub fn with_boxes(boxes: Vec<BBox>, offsets: Vec<usize>) -> ElementIndex {
        let loop_of = (offsets.len() > LOOP_TABLE_MIN_LOOPS).then(|| {
            offsets.windows(2).enumerate().flat_map(|(l, w)| std::iter::repeat_n(l as u32, w[1] - w[0])).collect()
        });
        ElementIndex { tree: BoxTree::new(boxes), offsets, loop_of }
    }

    /// Indexes every element of `loops`.
    pub fn new(loops: &[Loop]) -> ElementIndex {
        let offsets = per_element::offsets(loops);
        let boxes = per_element::map_elements(loops, &offsets, |l, i| loops[l].element(i).bbox());
        ElementIndex::with_boxes(boxes, offsets)
    }

    /// Loop and element of a global id.
    pub fn locate(&self, id: usize) -> ElementRef {
        let l = match &self.loop_of {
            Some(t) => t[id] as usize,
            None => self.offsets.partition_point(|&o| o <= id) - 1,
        };
        ElementRef { loop_index: l, element: id - self.offsets[l] }
    }
}
