//! The entities read from the pairs: LWPOLYLINE, POLYLINE with its
//! VERTEX records, LINE, ARC and CIRCLE, mirrored where the extrusion
//! direction says so, each with its layer; INSERT records and BLOCK
//! definitions kept for `blocks.rs`; other entities kept as skipped;
//! sections other than HEADER, BLOCKS and ENTITIES skipped.

use crate::io::dxf::blocks::{expand, Block, Colours, Insert, DEFAULT_COLOUR};
use crate::io::dxf::pairs::{error, integer, number, Pair};
use crate::io::{ParseError, RawArc, RawCircle, RawDrawing, RawLine, RawPolyline, RawSkipped, RawVertex};
use std::collections::HashMap;

/// POLYLINE flag bits of 3D polylines, polygon meshes and polyface meshes,
/// which have no place in a 2D shape and are skipped.
const POLYLINE_NOT_2D: i64 = 8 | 16 | 64;
/// VERTEX flag bit of spline frame control points: they are not on the curve.
const VERTEX_SPLINE_FRAME: i64 = 16;

/// The groups of a simple entity that this reader uses. DXF assigns codes
/// 10-59 to reals and 70-79 to integers in every entity, so parsing them all
/// cannot reject a valid file.
#[derive(Default)]
struct Fields {
    x: Option<f64>,
    y: Option<f64>,
    x2: Option<f64>,
    y2: Option<f64>,
    radius: Option<f64>,
    bulge: Option<f64>,
    start_deg: Option<f64>,
    end_deg: Option<f64>,
    flags: Option<i64>,
    extrusion_z: Option<f64>,
    /// Group 62 as written (0 by block, 256 by layer, negative: layer off).
    colour: Option<i16>,
    handle: u64,
}

impl Fields {
    fn read(entity: &str, at: usize, groups: &[Pair]) -> Result<Fields, ParseError> {
        let mut f = Fields::default();
        for g in groups {
            let slot = match g.code {
                10 => &mut f.x,
                20 => &mut f.y,
                11 => &mut f.x2,
                21 => &mut f.y2,
                40 => &mut f.radius,
                42 => &mut f.bulge,
                50 => &mut f.start_deg,
                51 => &mut f.end_deg,
                230 => &mut f.extrusion_z,
                70 => {
                    f.flags = Some(integer(entity, at, g)?);
                    continue;
                }
                62 => {
                    f.colour = colour(g);
                    continue;
                }
                5 => {
                    f.handle = handle(g);
                    continue;
                }
                _ => continue,
            };
            *slot = Some(number(entity, at, g)?);
        }
        Ok(f)
    }

    fn mirrored(&self) -> bool {
        self.extrusion_z.is_some_and(|z| z < 0.0)
    }
}

/// A handle (group 5, hexadecimal); 0 when it does not parse, as handles
/// only name things in reports.
pub(crate) fn handle(g: &Pair) -> u64 {
    u64::from_str_radix(g.value.trim(), 16).unwrap_or(0)
}

/// A colour (group 62) as written; `None` when it does not parse, as
/// colours only select.
pub(crate) fn colour(g: &Pair) -> Option<i16> {
    g.value.trim().parse::<i64>().ok().map(|c| c.clamp(-32768, 32767) as i16)
}

/// Colour 62 as written: by layer (256) where the entity does not say.
const BY_LAYER: i16 = 256;

/// Unwraps a required group or says which one is missing.
fn required(entity: &str, at: usize, value: Option<f64>, code: i32, what: &str) -> Result<f64, ParseError> {
    value.ok_or_else(|| error(at, format!("{entity} at line {at} has no {what} (group {code})")))
}

/// A POLYLINE whose VERTEX entities are still being read.
struct OpenPolyline {
    polyline: RawPolyline,
    /// 3D polyline or mesh: read past its vertices without keeping them.
    skip: bool,
    mirror: bool,
}

#[derive(Default, PartialEq)]
enum Section {
    /// Outside any SECTION: a bare entity list is read.
    #[default]
    None,
    Entities,
    /// Block definitions: the entities of each BLOCK are kept for the
    /// INSERTs that place them.
    Blocks,
    /// The tables: the LAYER records give the layers' colours.
    Tables,
    /// Any other section: skipped.
    Other,
}

#[derive(Default)]
pub(crate) struct Reader {
    /// What is being read: the drawing, or the BLOCK being defined.
    out: RawDrawing,
    /// The INSERTs of `out`.
    inserts: Vec<Insert>,
    section: Section,
    polyline: Option<OpenPolyline>,
    /// Layer names seen so far (in the drawing and in blocks alike), and
    /// their indices.
    layers: Vec<String>,
    layer_ids: HashMap<String, u32>,
    /// The colour of each layer (LAYER table), 1–255.
    layer_colours: Vec<i16>,
    /// The BLOCK being defined: its name, base point, and the drawing's
    /// own entities and INSERTs while it is read.
    block: Option<(String, [f64; 2], RawDrawing, Vec<Insert>)>,
    blocks: HashMap<String, Block>,
}

/// Records that only structure the file or belong to a POLYLINE: never
/// reported as skipped entities.
const STRUCTURE: [&str; 4] = ["SEQEND", "EOF", "ENDTAB", "ENDBLK"];

impl Reader {
    /// Interprets one complete record: its `0` pair and the groups after it.
    pub(crate) fn record(&mut self, head: &Pair, groups: &[Pair]) -> Result<(), ParseError> {
        let name = head.value.trim().to_ascii_uppercase();
        match name.as_str() {
            "SECTION" => {
                self.flush_polyline();
                let named = |n: &str| groups.iter().any(|g| g.code == 2 && g.value.trim().eq_ignore_ascii_case(n));
                if named("HEADER") {
                    // Header variables are `9 $NAME` pairs, each followed by its value.
                    let at =
                        groups.iter().position(|g| g.code == 9 && g.value.trim().eq_ignore_ascii_case("$INSUNITS"));
                    self.out.units = at.and_then(|k| groups.get(k + 1)).and_then(|g| g.value.trim().parse().ok());
                }
                self.section = if named("ENTITIES") {
                    Section::Entities
                } else if named("BLOCKS") {
                    Section::Blocks
                } else if named("TABLES") {
                    Section::Tables
                } else {
                    Section::Other
                };
                return Ok(());
            }
            "ENDSEC" => {
                self.flush_polyline();
                self.end_block();
                self.section = Section::None;
                return Ok(());
            }
            _ => {}
        }
        match (&self.section, name.as_str()) {
            (Section::Other, _) => return Ok(()),
            (Section::Tables, "LAYER") => {
                let name = groups.iter().find(|g| g.code == 2).map_or("0", |g| g.value.trim());
                let id = self.layer_id(name) as usize;
                // A negative colour marks the layer off; it keeps its colour.
                let c = groups.iter().find(|g| g.code == 62).and_then(colour).map(i16::unsigned_abs);
                self.layer_colours[id] = c.filter(|c| (1..=255).contains(c)).map_or(DEFAULT_COLOUR, |c| c as i16);
                return Ok(());
            }
            (Section::Tables, _) => return Ok(()),
            (Section::Blocks, "BLOCK") => {
                self.flush_polyline();
                self.end_block();
                let text = |code: i32| groups.iter().find(|g| g.code == code).map(|g| g.value.trim());
                let coord = |code: i32| text(code).and_then(|v| v.parse::<f64>().ok()).unwrap_or(0.0);
                let main = std::mem::take(&mut self.out);
                let main_inserts = std::mem::take(&mut self.inserts);
                self.block = Some((text(2).unwrap_or("").to_string(), [coord(10), coord(20)], main, main_inserts));
                return Ok(());
            }
            (Section::Blocks, "ENDBLK") => {
                self.flush_polyline();
                self.end_block();
                return Ok(());
            }
            // Entities between blocks belong to none.
            (Section::Blocks, _) if self.block.is_none() => return Ok(()),
            _ => {}
        }
        let at = head.line;
        if name == "VERTEX" {
            return self.vertex(at, groups);
        }
        // Any other entity ends a POLYLINE, also when its SEQEND is missing.
        self.flush_polyline();
        let layer = self.layer(groups);
        match name.as_str() {
            "INSERT" | "MINSERT" => {
                let f = Fields::read(&name, at, groups)?;
                let mut extra = [None; 6];
                for g in groups {
                    if let Some(k) = [41, 42, 44, 45, 71, 43].iter().position(|&c| c == g.code) {
                        extra[k] = Some(number(&name, at, g)?);
                    }
                }
                let count = |v: Option<f64>| v.map_or(1, |n| n.clamp(1.0, u32::MAX as f64) as u32);
                self.inserts.push(Insert {
                    name: groups.iter().find(|g| g.code == 2).map_or("", |g| g.value.trim()).to_string(),
                    at: [f.x.unwrap_or(0.0), f.y.unwrap_or(0.0)],
                    scale: [extra[0].unwrap_or(1.0), f.bulge.unwrap_or(1.0)],
                    rotation_deg: f.start_deg.unwrap_or(0.0),
                    columns: f.flags.map_or(1, |n| n.clamp(1, u32::MAX as i64) as u32),
                    rows: count(extra[4]),
                    spacing: [extra[2].unwrap_or(0.0), extra[3].unwrap_or(0.0)],
                    mirror: f.mirrored(),
                    source: at,
                    layer,
                    colour: f.colour.unwrap_or(BY_LAYER),
                    handle: f.handle,
                });
                Ok(())
            }
            "LWPOLYLINE" => self.lwpolyline(at, layer, groups),
            "POLYLINE" => {
                let f = Fields::read("POLYLINE", at, groups)?;
                let flags = f.flags.unwrap_or(0);
                self.polyline = Some(OpenPolyline {
                    polyline: RawPolyline {
                        vertices: Vec::new(),
                        closed: flags & 1 != 0,
                        source: at,
                        layer,
                        colour: f.colour.unwrap_or(BY_LAYER),
                        handle: f.handle,
                    },
                    skip: flags & POLYLINE_NOT_2D != 0,
                    mirror: f.mirrored(),
                });
                Ok(())
            }
            "LINE" => {
                let f = Fields::read("LINE", at, groups)?;
                // LINE endpoints are world coordinates: no mirroring.
                let line = RawLine {
                    a: [required("LINE", at, f.x, 10, "start x")?, required("LINE", at, f.y, 20, "start y")?],
                    b: [required("LINE", at, f.x2, 11, "end x")?, required("LINE", at, f.y2, 21, "end y")?],
                    source: at,
                    layer,
                    colour: f.colour.unwrap_or(BY_LAYER),
                    handle: f.handle,
                };
                self.out.lines.push(line);
                Ok(())
            }
            "ARC" => {
                let f = Fields::read("ARC", at, groups)?;
                let mut arc = RawArc {
                    center: [required("ARC", at, f.x, 10, "centre x")?, required("ARC", at, f.y, 20, "centre y")?],
                    radius: required("ARC", at, f.radius, 40, "radius")?,
                    start_deg: required("ARC", at, f.start_deg, 50, "start angle")?,
                    end_deg: required("ARC", at, f.end_deg, 51, "end angle")?,
                    source: at,
                    layer,
                    colour: f.colour.unwrap_or(BY_LAYER),
                    handle: f.handle,
                };
                if f.mirrored() {
                    // Mirroring reverses the direction: the old end becomes the start.
                    arc.center[0] = -arc.center[0];
                    let (s, e) = (arc.start_deg, arc.end_deg);
                    arc.start_deg = 180.0 - e;
                    arc.end_deg = 180.0 - s;
                }
                self.out.arcs.push(arc);
                Ok(())
            }
            "CIRCLE" => {
                let f = Fields::read("CIRCLE", at, groups)?;
                let mut circle = RawCircle {
                    center: [
                        required("CIRCLE", at, f.x, 10, "centre x")?,
                        required("CIRCLE", at, f.y, 20, "centre y")?,
                    ],
                    radius: required("CIRCLE", at, f.radius, 40, "radius")?,
                    source: at,
                    layer,
                    colour: f.colour.unwrap_or(BY_LAYER),
                    handle: f.handle,
                };
                if f.mirrored() {
                    circle.center[0] = -circle.center[0];
                }
                self.out.circles.push(circle);
                Ok(())
            }
            // SEQEND only ends the POLYLINE, done above.
            _ if STRUCTURE.contains(&name.as_str()) => Ok(()),
            _ => {
                // Not geometry we read: kept to be reported. Its point is
                // only a hint, so a value that does not parse is no error.
                let coord = |code: i32| groups.iter().find(|g| g.code == code)?.value.trim().parse::<f64>().ok();
                let position = coord(10).zip(coord(20)).map(|(x, y)| [x, y]);
                let handle = groups.iter().find(|g| g.code == 5).map_or(0, handle);
                let colour = groups.iter().find(|g| g.code == 62).and_then(colour).unwrap_or(BY_LAYER);
                self.out.skipped.push(RawSkipped { entity: name, layer, colour, handle, position, source: at });
                Ok(())
            }
        }
    }

    /// The index of the entity's layer (group 8; "0", DXF's default
    /// layer, when it has none), adding the name on first sight.
    fn layer(&mut self, groups: &[Pair]) -> u32 {
        self.layer_id(groups.iter().find(|g| g.code == 8).map_or("0", |g| g.value.trim()))
    }

    fn layer_id(&mut self, name: &str) -> u32 {
        if let Some(&id) = self.layer_ids.get(name) {
            return id;
        }
        let id = self.layers.len() as u32;
        self.layers.push(name.to_string());
        self.layer_colours.push(DEFAULT_COLOUR);
        self.layer_ids.insert(name.to_string(), id);
        id
    }

    /// Ends the BLOCK being defined, if any: kept by name, and the
    /// drawing read on.
    fn end_block(&mut self) {
        if let Some((name, base, main, main_inserts)) = self.block.take() {
            let drawing = std::mem::replace(&mut self.out, main);
            let inserts = std::mem::replace(&mut self.inserts, main_inserts);
            self.blocks.insert(name, Block { base, drawing, inserts });
        }
    }

    /// The drawing, with its block references expanded.
    pub(crate) fn finish(mut self) -> RawDrawing {
        self.flush_polyline();
        self.end_block();
        self.out.layers = std::mem::take(&mut self.layers);
        let colours = Colours { layers: &self.layer_colours, by_block: DEFAULT_COLOUR };
        colours.resolve_all(&mut self.out);
        for ins in &mut self.inserts {
            ins.colour = colours.of(ins.colour, ins.layer);
        }
        expand(&mut self.out, &self.inserts, &self.blocks, &self.layer_colours);
        self.out
    }

    fn vertex(&mut self, at: usize, groups: &[Pair]) -> Result<(), ParseError> {
        // A VERTEX outside a POLYLINE is stray; a 3D one is skipped unread.
        let Some(open) = self.polyline.as_mut() else {
            return Ok(());
        };
        if open.skip {
            return Ok(());
        }
        let f = Fields::read("VERTEX", at, groups)?;
        if f.flags.unwrap_or(0) & VERTEX_SPLINE_FRAME != 0 {
            return Ok(());
        }
        let mut v = RawVertex {
            x: required("VERTEX", at, f.x, 10, "x")?,
            y: required("VERTEX", at, f.y, 20, "y")?,
            bulge: f.bulge.unwrap_or(0.0),
        };
        if open.mirror {
            v.x = -v.x;
            v.bulge = -v.bulge;
        }
        open.polyline.vertices.push(v);
        Ok(())
    }

    fn lwpolyline(&mut self, at: usize, layer: u32, groups: &[Pair]) -> Result<(), ParseError> {
        const E: &str = "LWPOLYLINE";
        // Group 90 (vertex count) is not trusted: the 10 groups are the vertices.
        let mut vertices: Vec<RawVertex> = Vec::new();
        // Line of the latest 10 group while its 20 has not been seen.
        let mut missing_y: Option<usize> = None;
        let (mut closed, mut mirror) = (false, false);
        let (mut colour_62, mut handle_5) = (BY_LAYER, 0);
        for g in groups {
            match g.code {
                5 => handle_5 = handle(g),
                62 => colour_62 = colour(g).unwrap_or(BY_LAYER),
                10 => {
                    if let Some(l) = missing_y {
                        return Err(error(l, format!("{E} at line {at}: vertex x (group 10) has no y (group 20)")));
                    }
                    vertices.push(RawVertex { x: number(E, at, g)?, y: 0.0, bulge: 0.0 });
                    missing_y = Some(g.line);
                }
                20 | 42 => {
                    let value = number(E, at, g)?;
                    let Some(v) = vertices.last_mut() else {
                        let msg =
                            format!("{E} at line {at}: group {} comes before the first vertex x (group 10)", g.code);
                        return Err(error(g.line, msg));
                    };
                    if g.code == 20 {
                        v.y = value;
                        missing_y = None;
                    } else {
                        v.bulge = value;
                    }
                }
                70 => closed = integer(E, at, g)? & 1 != 0,
                230 => mirror = number(E, at, g)? < 0.0,
                _ => {}
            }
        }
        if let Some(l) = missing_y {
            return Err(error(l, format!("{E} at line {at}: vertex x (group 10) has no y (group 20)")));
        }
        if mirror {
            for v in &mut vertices {
                v.x = -v.x;
                v.bulge = -v.bulge;
            }
        }
        self.out.polylines.push(RawPolyline {
            vertices,
            closed,
            source: at,
            layer,
            colour: colour_62,
            handle: handle_5,
        });
        Ok(())
    }

    /// Ends the open POLYLINE, if any, keeping it unless it is 3D.
    pub(crate) fn flush_polyline(&mut self) {
        if let Some(open) = self.polyline.take() {
            if !open.skip {
                self.out.polylines.push(open.polyline);
            }
        }
    }
}
