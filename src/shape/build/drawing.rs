//! A drawing's profiles read from files and written as JSON.

use crate::io::{dxf, json, svg_path, Format};
use crate::kernel::Point;
use crate::shape::build::import::{decode, looks_json, read_bytes, svg_drawing};
use crate::shape::build::profiles::{profiles, Drawing2d, DrawingOptions, Ignored, IgnoredKind};
use crate::shape::model::error::ShapeError;
use crate::shape::model::options::ShapeOptions;
use crate::shape::shape2d::Shape2d;

impl Drawing2d {
    /// A drawing of one shape and nothing else.
    pub fn of(shape: Shape2d) -> Drawing2d {
        Drawing2d::of_shapes(vec![shape])
    }

    /// A drawing of these shapes and nothing else.
    pub fn of_shapes(shapes: Vec<Shape2d>) -> Drawing2d {
        Drawing2d { shapes, ignored: Vec::new(), gaps: Vec::new(), touching: Vec::new(), units: None }
    }

    /// Reads a drawing file: DXF and SVG through [`profiles`]; medax shape
    /// JSON (`{"loops": ...}`) is one shape, read as
    /// [`Shape2d::from_file`] does; drawing JSON (`{"shapes": [{"loops":
    /// ...}, ...]}`, what [`to_json`](Self::to_json) writes) its shapes,
    /// those that do not validate reported as
    /// [`IgnoredKind::InvalidShape`] with their index as the source. The
    /// format comes from the extension or, failing that, from the content.
    ///
    /// # Errors
    ///
    /// The file cannot be read or parsed, or (shape JSON only) its shape
    /// does not validate; an SVG elliptical arc; a selection by layer or
    /// colour for JSON or SVG, which have neither.
    pub fn from_file(
        path: impl AsRef<std::path::Path>,
        opts: &ShapeOptions,
        select: &DrawingOptions,
    ) -> Result<Drawing2d, ShapeError> {
        let path = path.as_ref();
        Drawing2d::from_bytes(&read_bytes(path)?, Format::from_path(path), opts, select)
    }

    /// Reads a drawing from a file's bytes (as [`from_file`](Self::from_file)
    /// does), in `format` or, when `None`, the format the content shows.
    /// Bytes that are not UTF-8 are replaced (DXF comments in other code
    /// pages).
    ///
    /// # Errors
    ///
    /// As [`from_file`](Self::from_file), without the I/O.
    pub fn from_bytes(
        bytes: &[u8],
        format: Option<Format>,
        opts: &ShapeOptions,
        select: &DrawingOptions,
    ) -> Result<Drawing2d, ShapeError> {
        if format == Some(Format::Json) || (format.is_none() && looks_json(bytes)) {
            no_selection(Format::Json, select)?;
            if let Some(raw) = json::read_loops_fast(bytes) {
                return Ok(Drawing2d::of(Shape2d::from_raw_json(raw, opts)?));
            }
        }
        let (text, format) = decode(bytes, format);
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
        no_selection(format, select)?;
        let raw = match format {
            Format::Json => return json_drawing(text, opts),
            Format::Dxf => dxf::read_dxf(text)?,
            Format::Svg => svg_drawing(&svg_path::read_svg(text)?)?,
        };
        Ok(profiles(&raw, opts, select))
    }

    /// The drawing as JSON: `{"units": NAME or null, "shapes": [SHAPE,
    /// ...], "ignored": [...], "warnings": [...]}`, each shape in medax
    /// shape JSON (`{"loops": ...}`, what [`Shape2d::from_json_str`]
    /// reads), each ignored thing as `{"kind", "source", "layer",
    /// "position": [x, y], "handles": [HEX, ...], "reason"}` (kind in snake
    /// case: `open_chain`, `entity`, `other_layer`, `flat_loop`,
    /// `duplicate_loop`, `touching_loop`, `invalid_shape`), each warning as
    /// `{"kind": "gap_closed", "position", "gap"}` or `{"kind":
    /// "touching_shapes", "shapes": [i, j], "position", "sources": [a, b],
    /// "handles": [HEX, HEX]}` (model units; handles as DXF writes them,
    /// upper-case hexadecimal, "" where the file gives none).
    pub fn to_json(&self) -> String {
        let hex = |h: u64| if h == 0 { String::new() } else { format!("{h:X}") };
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
                    "handles": i.handles.iter().map(|&h| hex(h)).collect::<Vec<_>>(),
                    "reason": i.reason,
                })
            })
            .collect();
        let gaps =
            self.gaps.iter().map(|(p, d)| serde_json::json!({"kind": "gap_closed", "position": [p.x, p.y], "gap": d}));
        let touching = self.touching.iter().map(|t| {
            serde_json::json!({
                "kind": "touching_shapes",
                "shapes": t.shapes,
                "position": [t.position.x, t.position.y],
                "sources": t.sources,
                "handles": [hex(t.handles[0]), hex(t.handles[1])],
            })
        });
        let warnings: Vec<serde_json::Value> = gaps.chain(touching).collect();
        format!(
            "{{\"units\": {}, \"shapes\": [{}], \"ignored\": {}, \"warnings\": {}}}\n",
            serde_json::Value::from(self.units),
            shapes.join(", "),
            serde_json::Value::from(ignored),
            serde_json::Value::from(warnings)
        )
    }
}

/// Refuses a selection by layer or colour for a format without them
/// (medax JSON, SVG), which would otherwise leave nothing, unreported.
fn no_selection(format: Format, select: &DrawingOptions) -> Result<(), ShapeError> {
    if format == Format::Dxf || (select.layers.is_empty() && select.colours.is_empty()) {
        return Ok(());
    }
    Err(ShapeError::InvalidArgument {
        what: format!("{} has no layers or colours to select: select by layer or colour in DXF only", format.name()),
    })
}

/// Shape JSON as one shape (errors as for [`Shape2d::from_json_str`]), or
/// drawing JSON as its shapes.
fn json_drawing(text: &str, opts: &ShapeOptions) -> Result<Drawing2d, ShapeError> {
    let shapes = match json::read_doc(text)? {
        json::JsonDoc::Shape(loops) => return Ok(Drawing2d::of(Shape2d::from_raw_json(loops, opts)?)),
        json::JsonDoc::Drawing(shapes) => shapes,
    };
    let mut d = Drawing2d::of_shapes(Vec::new());
    for (k, raw) in shapes.into_iter().enumerate() {
        let position =
            raw.first().and_then(|p| p.vertices.first()).map_or(Default::default(), |v| Point::new(v.x, v.y));
        match Shape2d::from_raw_json(raw, opts) {
            Ok(s) => d.shapes.push(s),
            Err(e) => d.ignored.push(Ignored {
                kind: IgnoredKind::InvalidShape,
                source: k,
                layer: String::new(),
                position,
                reason: format!("shape {k}: {e}"),
                cause: Some(e),
                handles: Vec::new(),
            }),
        }
    }
    Ok(d)
}
