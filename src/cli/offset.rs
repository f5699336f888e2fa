//! `medax offset`: trimmed offsets at given distances, pocketing rings or
//! V-carve paths of a shape, as JSON, DXF and/or SVG.

use super::{fail, per_shape, write_file, write_streamed, RunArgs, ShapeArgs};
use medax::cam::{pocket, vcarve, CamError, Pocket, PocketOptions, PocketOrder, VCarve, VCarveOptions};
use medax::plane::offsets_to_dxf;
use medax::plane::offsets_to_svg;
use medax::plane::write_offsets_json;
use medax::plane::{
    medial_axis, AxisOptions, MedialAxis2d, OffsetLayer, OffsetLoop, OffsetOptions, OffsetRegion, Offsets,
};
use medax::polymetric::{medial_axis_with_ball, outer_offset, BallOffsetLayer};
use medax::shape::{Ball2, Shape2d, Vertex};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `medax offset`.
#[derive(clap::Args)]
#[command(group(clap::ArgGroup::new("mode").required(true).args(["distance", "pocket", "vcarve"])))]
pub struct OffsetArgs {
    #[command(flatten)]
    pub shape: ShapeArgs,
    /// Offset distances, model units, comma-separated: positive inwards, negative outwards
    /// (e.g. --distance=-2,1,3.5).
    #[arg(long, value_name = "D1,D2,...", value_delimiter = ',', allow_hyphen_values = true, value_parser = finite)]
    pub distance: Option<Vec<f64>>,
    /// Pocketing rings at TOOL_RADIUS + k × STEPOVER (model units) until nothing is left.
    #[arg(long, value_name = "TOOL_RADIUS,STEPOVER", value_parser = pocket_values)]
    pub pocket: Option<(f64, f64)>,
    /// V-carve paths for a V-bit of included angle ANGLE_DEG (degrees) cut at most MAX_DEPTH deep
    /// (model units; `inf` for no cap).
    #[arg(long, value_name = "ANGLE_DEG,MAX_DEPTH", value_parser = vcarve_values)]
    pub vcarve: Option<(f64, f64)>,
    /// Machine pocket rings from the wall inwards (default: inside out, the wall last); with --pocket.
    #[arg(long)]
    pub outside_in: bool,
    /// Write the result as JSON (offsets, pocket or v-carve format; see README).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write the result as DXF (closed LWPOLYLINEs with bulges; v-carve paths as 3D POLYLINEs).
    #[arg(long)]
    pub dxf: Option<PathBuf>,
    /// Write a picture of the shape, its axis and the loops, rings or paths.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// The unit ball of the metric (polygons, --distance only): square, diamond, triangle,
    /// ngon:K[:DEGREES], ball JSON text, or a file of ball JSON. The offset at d > 0 is then the
    /// path of the centre of the tool d·BALL kept inside the shape, at d < 0 kept outside it.
    /// Default: the Euclidean disk.
    #[arg(long)]
    pub ball: Option<String>,
    #[command(flatten)]
    pub run: RunArgs,
}

fn finite(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|_| format!("{s:?} is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{s:?} is not a finite number"))
    }
}

/// Two comma-separated numbers (`what` names them for the message).
fn pair(s: &str, what: &str) -> Result<(f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let [a, b] = parts[..] else { return Err(format!("expected {what}, two numbers separated by a comma")) };
    let num = |t: &str| t.trim().parse::<f64>().map_err(|_| format!("{t:?} is not a number (expected {what})"));
    Ok((num(a)?, num(b)?))
}

/// A CAM option's range error in the words of the command line.
fn option_error(e: CamError) -> String {
    match e {
        CamError::BadOption { name, value, expected } => {
            let words = match name {
                "tool_radius" => "tool radius",
                "angle_deg" => "angle",
                "max_depth" => "maximum depth",
                other => other,
            };
            format!("{words} {value} must be {expected}")
        }
        other => other.to_string(),
    }
}

fn pocket_values(s: &str) -> Result<(f64, f64), String> {
    let (r, step) = pair(s, "TOOL_RADIUS,STEPOVER")?;
    PocketOptions::new(r, step).check().map_err(option_error)?;
    Ok((r, step))
}

fn vcarve_values(s: &str) -> Result<(f64, f64), String> {
    let (angle_deg, max_depth) = pair(s, "ANGLE_DEG,MAX_DEPTH")?;
    VCarveOptions { angle_deg, max_depth, tolerance: 0.0 }.check().map_err(option_error)?;
    Ok((angle_deg, max_depth))
}

/// What was computed, written only in the formats asked for.
enum Computed {
    Offsets(Vec<OffsetLayer>),
    Pocket(Pocket),
    VCarve(VCarve),
}

impl Computed {
    fn write_json(&self, w: &mut impl std::io::Write) -> std::io::Result<()> {
        match self {
            Computed::Offsets(layers) => write_offsets_json(layers, w),
            Computed::Pocket(p) => p.write_json(w),
            Computed::VCarve(v) => v.write_json(w),
        }
    }

    fn dxf(&self) -> String {
        match self {
            Computed::Offsets(layers) => offsets_to_dxf(layers),
            Computed::Pocket(p) => p.to_dxf(),
            Computed::VCarve(v) => v.to_dxf(),
        }
    }

    fn svg(&self, ctx: &Context) -> String {
        let (shape, axis) = (ctx.shape, ctx.axis);
        match self {
            Computed::Offsets(layers) => offsets_to_svg(shape, axis, layers, 900.0, ctx.tol),
            Computed::Pocket(p) => p.to_svg(shape, axis, 900.0, ctx.tol),
            Computed::VCarve(v) => v.to_svg(shape, axis, 900.0, ctx.tol),
        }
    }
}

pub fn run(args: &OffsetArgs) -> Result<(), ExitCode> {
    // Checked here: clap's `requires` is not enforced on a member of the
    // satisfied mode group.
    if args.outside_in && args.pocket.is_none() {
        eprintln!("medax offset: --outside-in orders pocket rings; use it with --pocket");
        return Err(ExitCode::from(2));
    }
    let ball = args.ball.as_deref().map(super::ball::load_ball).transpose()?;
    if ball.is_some() && args.distance.as_ref().is_none_or(|ds| ds.contains(&0.0)) {
        eprintln!(
            "medax offset: under --ball give --distance with non-zero distances (pockets and V-carve are Euclidean)"
        );
        return Err(ExitCode::from(2));
    }
    let shapes = args.shape.load_each().map_err(|e| fail(&args.shape.shape, &e))?;
    let pool = args.run.pool()?;
    for (k, shape) in &shapes {
        if let Some(k) = k {
            out!("shape {k}:");
        }
        match (&ball, &args.distance) {
            (Some(ball), Some(ds)) => run_ball(args, shape, ball, ds, *k)?,
            _ => run_one(args, shape, *k, &pool)?,
        }
    }
    Ok(())
}

/// Inner offsets of one shape under a polygon ball, from its axis under
/// that ball (thesis 3.2, Observation 13).
fn run_ball(args: &OffsetArgs, shape: &Shape2d, ball: &Ball2, ds: &[f64], k: Option<usize>) -> Result<(), ExitCode> {
    let which = k.map_or_else(String::new, |k| format!(" shape {k}"));
    let failed = |e: &dyn std::fmt::Display| {
        eprintln!("medax: {}{which}: {e}", args.shape.shape.display());
        ExitCode::from(1)
    };
    let t = Instant::now();
    let axis = medial_axis_with_ball(shape, ball).map_err(|e| failed(&e))?;
    // Negative distances: the shape grown, from the complement's axis.
    let layers: Vec<BallOffsetLayer> = ds
        .iter()
        .map(|&d| if d > 0.0 { axis.offset(shape, d) } else { outer_offset(shape, ball, -d) })
        .collect::<Result<_, _>>()
        .map_err(|e| failed(&e))?;
    out!("computed in {:.3} s ({} elements)", t.elapsed().as_secs_f64(), shape.element_count());
    out!("offsets under a {}-gon ball: {} distance(s)", ball.len(), layers.len());
    for l in &layers {
        out!("  distance {}: {} loop(s), {} region(s), area {}", l.distance, l.loops.len(), l.regions.len(), l.area());
    }
    // As the Euclidean layers (straight elements), for the same writers.
    let plain: Vec<OffsetLayer> = layers.iter().map(plain_layer).collect();
    if let Some(path) = &args.json {
        let path = per_shape(path, k);
        write_streamed(&path, |w| write_offsets_json(&plain, w))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.dxf {
        let path = per_shape(path, k);
        write_file(&path, &offsets_to_dxf(&plain))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.svg {
        let path = per_shape(path, k);
        write_file(&path, &axis.offsets_svg(shape, &layers, 900.0))?;
        out!("wrote {}", path.display());
    }
    Ok(())
}

/// The offsets, pocket or v-carve of one shape (`k`: its number, when the
/// run has several).
fn run_one(args: &OffsetArgs, shape: &Shape2d, k: Option<usize>, pool: &rayon::ThreadPool) -> Result<(), ExitCode> {
    let which = k.map_or_else(String::new, |k| format!(" shape {k}"));
    let name = format!("{}{which}", args.shape.shape.display());
    let failed = |e: &dyn std::fmt::Display| {
        eprintln!("medax: {name}: {e}");
        ExitCode::from(1)
    };
    let axis_opts = AxisOptions { seed: args.run.seed, ..AxisOptions::default() };
    let t = Instant::now();
    let axis = pool.install(|| medial_axis(shape, &axis_opts)).map_err(|e| failed(&e))?;
    let tol = args.run.sample_tolerance.unwrap_or(1e-4 * shape.bbox().diagonal());
    let ctx = Context { shape, axis: &axis, axis_opts, tol };
    let computed = pool.install(|| {
        if let Some(ds) = &args.distance {
            offsets(&ctx, ds)
        } else if let Some((r, s)) = args.pocket {
            pocket_rings(&ctx, r, s, args.outside_in)
        } else if let Some((angle, depth)) = args.vcarve {
            vcarve_paths(&ctx, angle, depth)
        } else {
            unreachable!("clap requires one mode")
        }
    });
    let computed = computed.map_err(|e| failed(&e))?;
    out!("computed in {:.3} s ({} elements)", t.elapsed().as_secs_f64(), shape.element_count());
    if let Some(path) = &args.json {
        let path = per_shape(path, k);
        write_streamed(&path, |w| computed.write_json(w))?;
        out!("wrote {}", path.display());
    }
    let writers: [(&Option<PathBuf>, &dyn Fn() -> String); 2] =
        [(&args.dxf, &|| computed.dxf()), (&args.svg, &|| computed.svg(&ctx))];
    for (path, text) in writers {
        if let Some(path) = path {
            let path = per_shape(path, k);
            write_file(&path, &text())?;
            out!("wrote {}", path.display());
        }
    }
    Ok(())
}

/// The shape, its axis and how it was computed.
struct Context<'a> {
    shape: &'a Shape2d,
    axis: &'a MedialAxis2d,
    axis_opts: AxisOptions,
    /// Chordal tolerance of drawn axis curves and v-carve paths, model units.
    tol: f64,
}

fn offsets(ctx: &Context, distances: &[f64]) -> Result<Computed, String> {
    let reach = distances.iter().map(|d| -d).fold(0.0, f64::max);
    // Outer offsets need the complement's axes too; the shape's is reused.
    let offsets = Offsets::from_axis(ctx.shape, ctx.axis)
        .and_then(|o| o.with_outer(ctx.shape, &OffsetOptions { axis: ctx.axis_opts, outer_reach: reach }))
        .map_err(|e| e.to_string())?;
    let layers = offsets.layers(distances).map_err(|e| e.to_string())?;
    out!("offsets: {} distance(s)", layers.len());
    for l in &layers {
        out!("  distance {}: {} loop(s), {} region(s), area {}", l.distance, l.loops.len(), l.regions.len(), l.area());
    }
    Ok(Computed::Offsets(layers))
}

fn pocket_rings(ctx: &Context, tool_radius: f64, stepover: f64, outside_in: bool) -> Result<Computed, String> {
    let offsets = Offsets::from_axis(ctx.shape, ctx.axis).map_err(|e| e.to_string())?;
    let order = if outside_in { PocketOrder::OutsideIn } else { PocketOrder::InsideOut };
    let opts = PocketOptions { order, ..PocketOptions::new(tool_radius, stepover) };
    let p = pocket(&offsets, &opts).map_err(|e| e.to_string())?;
    let levels = p.level_count();
    let uncut = p.uncut_area();
    out!(
        "pocket: {} ring(s) in {levels} level(s), {} order{}",
        p.rings.len(),
        if outside_in { "outside-in" } else { "inside-out" },
        if p.truncated { "; cut short at the level limit" } else { "" }
    );
    // Rings are stored level by level: one run per level.
    for run in p.rings.chunk_by(|a, b| a.level == b.level) {
        out!("  level {} (distance {}): {} ring(s)", run[0].level, run[0].distance, run.len());
    }
    out!("uncut: {} region(s), area {uncut}", p.uncut.len());
    Ok(Computed::Pocket(p))
}

fn vcarve_paths(ctx: &Context, angle_deg: f64, max_depth: f64) -> Result<Computed, String> {
    let opts = VCarveOptions { angle_deg, max_depth, tolerance: ctx.tol };
    let v = vcarve(ctx.shape, ctx.axis, &opts).map_err(|e| e.to_string())?;
    out!("v-carve: {} path(s), deepest {}", v.paths.len(), v.deepest());
    out!("flat bottom: {} ring(s) at radius {}", v.flat.loops.len(), v.flat_radius());
    Ok(Computed::VCarve(v))
}

/// A layer under a ball as the Euclidean layers' type (straight elements),
/// for the same writers.
fn plain_layer(l: &BallOffsetLayer) -> OffsetLayer {
    let loops = l
        .loops
        .iter()
        .map(|lp| OffsetLoop {
            vertices: lp.points.iter().map(|&p| Vertex { p, bulge: 0.0 }).collect(),
            area: lp.area,
            region: lp.region,
        })
        .collect();
    let regions = l.regions.iter().map(|r| OffsetRegion { outer: r.outer, holes: r.holes.clone() }).collect();
    OffsetLayer::from_loops(l.distance, loops, regions)
}
