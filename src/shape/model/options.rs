//! Tolerances used when a shape is built and validated.

/// Tolerances for building a [`Shape2d`](crate::shape::shape2d::Shape2d). All lengths are in
/// model units; `None` means "relative to the input's bounding-box diagonal".
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeOptions {
    /// Elements closer than this count as touching, and elements shorter than
    /// this are degenerate. Default: `relative_tolerance × diagonal` of the
    /// vertices' bounding box. Never below
    /// [`MIN_RELATIVE_TOLERANCE`](crate::shape::MIN_RELATIVE_TOLERANCE) × the largest
    /// coordinate magnitude (smaller values, 0 included, are raised to it).
    pub tolerance: Option<f64>,
    /// Relative tolerance used when `tolerance` is `None`. Default 1e-9.
    pub relative_tolerance: f64,
    /// Joints whose tangent directions differ by at most this angle (radians)
    /// are smooth; larger left turns are convex corners, right turns reflex
    /// corners (for the normalised orientation, interior on the left).
    /// Turns within this angle of ±π are cusps and rejected. Default 1e-6,
    /// which accepts biarc data written with about 7 significant digits.
    pub angle_tolerance: f64,
    /// Arcs whose sagitta (largest distance from their chord) is at most this,
    /// and whose half-sweep is within `angle_tolerance`, become segments
    /// (thesis 2.2.5.1: nearly collinear arcs are numerically unstable and
    /// indistinguishable from their chord). The sweep condition keeps the
    /// class of every joint: short arcs of a smooth biarc curve stay arcs.
    /// Default: the same as the touching tolerance.
    pub flatten_sagitta: Option<f64>,
    /// Arcs whose radius exceeds this multiple of the bounding-box diagonal
    /// become segments (thesis 2.2.5.1: "a bound flag for the arc's radii").
    /// Such arcs deviate from their chord by at most diagonal / (8 × ratio),
    /// 1.25e-7 × diagonal at the default 1e6, while their centres lie so far
    /// away that distances computed from them lose more digits than the
    /// touching tolerance allows.
    pub max_radius_ratio: f64,
    /// Loose elements (DXF LINE/ARC, explicit elements) whose ends are at most
    /// this far apart are joined into one loop, the gap closed by moving the
    /// end onto the start. Default: `1e-6 × diagonal`, enough for files
    /// written with 6–7 significant digits.
    pub chain_tolerance: Option<f64>,
}

impl Default for ShapeOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}

// The annotation below keeps cbindgen from exporting `DEFAULT` (a Rust-only
// constant) into the C header.
/// cbindgen:ignore
impl ShapeOptions {
    /// The defaults, as a constant (the C ABI builds its defaults from it).
    pub const DEFAULT: ShapeOptions = ShapeOptions {
        tolerance: None,
        relative_tolerance: 1e-9,
        angle_tolerance: 1e-6,
        flatten_sagitta: None,
        max_radius_ratio: 1e6,
        chain_tolerance: None,
    };

    /// The absolute touching tolerance for a shape whose bounding-box diagonal is `diagonal`.
    pub fn tolerance_for(&self, diagonal: f64) -> f64 {
        self.tolerance.unwrap_or(self.relative_tolerance * diagonal)
    }

    /// The absolute chaining tolerance for a shape whose bounding-box diagonal is `diagonal`.
    pub fn chain_tolerance_for(&self, diagonal: f64) -> f64 {
        self.chain_tolerance.unwrap_or(1e-6 * diagonal).max(self.tolerance_for(diagonal))
    }

    /// Checks that every tolerance is finite and non-negative and the angle below π/2.
    pub fn check(&self) -> Result<(), crate::shape::model::error::ShapeError> {
        let bad = |name: &str, v: f64| crate::shape::model::error::ShapeError::InvalidArgument {
            what: format!("option {name} = {v} must be finite and >= 0"),
        };
        for (name, v) in [
            ("tolerance", self.tolerance),
            ("relative_tolerance", Some(self.relative_tolerance)),
            ("flatten_sagitta", self.flatten_sagitta),
            ("chain_tolerance", self.chain_tolerance),
        ] {
            if let Some(v) = v {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(bad(name, v));
                }
            }
        }
        if self.max_radius_ratio.is_nan() || self.max_radius_ratio < 1.0 {
            return Err(crate::shape::model::error::ShapeError::InvalidArgument {
                what: format!("option max_radius_ratio = {} must be >= 1", self.max_radius_ratio),
            });
        }
        if !(self.angle_tolerance.is_finite()
            && self.angle_tolerance >= 0.0
            && self.angle_tolerance < std::f64::consts::FRAC_PI_2)
        {
            return Err(crate::shape::model::error::ShapeError::InvalidArgument {
                what: format!("option angle_tolerance = {} must be in [0, π/2)", self.angle_tolerance),
            });
        }
        Ok(())
    }
}
