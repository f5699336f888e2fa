//! A drawing's profiles read from files and written as JSON.

use crate::io::{dxf, svg_path, Format};
use crate::shape::build::import::{decode, looks_json, read_bytes, svg_drawing};
use crate::shape::build::profiles::{profiles, Drawing2d, DrawingOptions};
use crate::shape::model::error::ShapeError;
use crate::shape::model::options::ShapeOptions;
use crate::shape::shape2d::Shape2d;

impl Drawing2d {
    /// A drawing of one shape and nothing else.
    pub fn of(shape: Shape2d) -> Drawing2d {
        Drawing2d { shapes: vec![shape], ignored: Vec::new(), gaps: Vec::new(), units: None }
    }

    /// Reads a drawing file: DXF and SVG through [`profiles`]; a medax JSON
    /// file is one shape, read as [`Shape2d::from_file`] does. The format
    /// comes from the extension or, failing that, from the content.
    ///
    /// # Errors
    ///
    /// The file cannot be read or parsed, or (JSON only) its shape does not
    /// validate; an SVG elliptical arc.
    pub fn from_file(
        path: impl AsRef<std::path::Path>,
        opts: &ShapeOptions,
        select: &DrawingOptions,
    ) -> Result<Drawing2d, ShapeError> {
        let path = path.as_ref();
        let bytes = read_bytes(path)?;
        let hint = Format::from_path(path);
        if hint == Some(Format::Json) || (hint.is_none() && looks_json(&bytes)) {
            return Ok(Drawing2d::of(Shape2d::from_file(path, opts)?));
        }
        let (text, format) = decode(&bytes, hint);
        Drawing2d::from_str_as(&text, format, opts, select)
    }

    /// Reads drawing text in the given format (see
    /// [`from_file`](Self::from_file)).
    pub fn from_str_as(
        text: &str,
        format: Format,
        opts: &ShapeOptions,
        select: &DrawingOptions,
    ) -> Result<Drawing2d, ShapeError> {
        opts.check()?;
        let raw = match format {
            Format::Json => {
                return Ok(Drawing2d::of(Shape2d::from_json_str(text, opts)?));
            }
            Format::Dxf => dxf::read_dxf(text)?,
            Format::Svg => svg_drawing(&svg_path::read_svg(text)?)?,
        };
        Ok(profiles(&raw, opts, select))
    }

    /// The drawing as JSON: `{"units": NAME or null, "shapes": [SHAPE,
    /// ...], "ignored": [...], "gaps": [...]}`, each shape in medax shape JSON (`{"loops": ...}`,
    /// what [`Shape2d::from_json_str`] reads), each ignored thing as
    /// `{"kind", "source", "layer", "position": [x, y], "reason"}` (kind
    /// in snake case: `open_chain`, `entity`, `other_layer`, `flat_loop`,
    /// `duplicate_loop`, `touching_loop`, `invalid_shape`), each gap closed
    /// as `{"position": [x, y], "gap"}` (model units).
    pub fn to_json(&self) -> String {
        let shapes: Vec<String> = self.shapes.iter().map(|s| s.to_json()).collect();
        let ignored: Vec<serde_json::Value> = self
            .ignored
            .iter()
            .map(|i| {
                serde_json::json!({
                    "kind": i.kind.name().replace(' ', "_"),
                    "source": i.source,
                    "layer": i.layer,
                    "position": [i.position.x, i.position.y],
                    "reason": i.reason,
                })
            })
            .collect();
        let gaps: Vec<serde_json::Value> =
            self.gaps.iter().map(|(p, d)| serde_json::json!({"position": [p.x, p.y], "gap": d})).collect();
        format!(
            "{{\"units\": {}, \"shapes\": [{}], \"ignored\": {}, \"gaps\": {}}}\n",
            serde_json::Value::from(self.units),
            shapes.join(", "),
            serde_json::Value::from(ignored),
            serde_json::Value::from(gaps)
        )
    }
}
