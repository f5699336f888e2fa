//! Maximal disks (thesis 2.2.1, Algorithm 1) and `maxdisk*`, the slide
//! along a bisector to the next disk touching a third part (2.2.2.1).

pub(crate) mod maximal;
pub(crate) mod slide;
