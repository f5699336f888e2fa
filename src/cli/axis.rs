//! `medax axis`: the medial axis of a shape as JSON and/or SVG.

use super::{fail, per_shape, write_file, write_streamed, RunArgs, ShapeArgs};
use medax::plane::{medial_axis, AxisOptions, AxisPicture, NodeKind};
use medax::polymetric::medial_axis_with_ball;
use medax::shape::{Ball2, Shape2d};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `medax axis`.
#[derive(clap::Args)]
pub struct AxisArgs {
    #[command(flatten)]
    pub shape: ShapeArgs,
    /// Write the axis as JSON (nodes, edges with sites and samples).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a picture of the shape and its axis.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    #[command(flatten)]
    pub run: RunArgs,
    /// Draw the maximal disks at branch points in the picture.
    #[arg(long)]
    pub disks: bool,
    /// The unit ball of the metric (polygons only): square, diamond, triangle, ngon:K[:DEGREES],
    /// ball JSON text, or a file of ball JSON ({"vertices": [[x, y], ...]}). Default: the
    /// Euclidean disk.
    #[arg(long)]
    pub ball: Option<String>,
}

pub fn run(args: &AxisArgs) -> Result<(), ExitCode> {
    let t = Instant::now();
    let shapes = args.shape.load_each().map_err(|e| fail(&args.shape.shape, &e))?;
    let read = t.elapsed().as_secs_f64();
    let pool = args.run.pool()?;
    let ball = args.ball.as_deref().map(super::ball::load_ball).transpose()?;
    for (k, shape) in &shapes {
        if let Some(k) = k {
            out!("shape {k}:");
        }
        match &ball {
            Some(ball) => run_ball(args, shape, ball, *k, read)?,
            None => run_one(args, shape, *k, read, &pool)?,
        }
    }
    Ok(())
}

/// The axis of one shape (`k`: its number, when the run has several).
fn run_one(
    args: &AxisArgs,
    shape: &Shape2d,
    k: Option<usize>,
    read: f64,
    pool: &rayon::ThreadPool,
) -> Result<(), ExitCode> {
    let opts = AxisOptions { seed: args.run.seed, ..AxisOptions::default() };
    let t = Instant::now();
    let axis = pool.install(|| medial_axis(shape, &opts)).map_err(|e| {
        let which = k.map_or_else(String::new, |k| format!(" shape {k}"));
        eprintln!("medax: {}{which}: {e}", args.shape.shape.display());
        ExitCode::from(1)
    })?;
    let took = t.elapsed().as_secs_f64();
    let count = |k: NodeKind| axis.nodes.iter().filter(|n| n.kind == k).count();
    out!(
        "medial axis: {} nodes ({} branch, {} corner, {} leaf, {} joint), {} edges",
        axis.nodes.len(),
        count(NodeKind::Branch),
        count(NodeKind::Corner),
        count(NodeKind::Leaf),
        count(NodeKind::Joint),
        axis.edges.len()
    );
    out!("read in {read:.3} s, axis in {took:.3} s ({} elements)", shape.element_count());
    let tol = args.run.sample_tolerance.unwrap_or(1e-4 * shape.bbox().diagonal());
    if let Some(path) = &args.json {
        let path = per_shape(path, k);
        write_streamed(&path, |w| axis.write_json(shape, tol, w))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.svg {
        let path = per_shape(path, k);
        let pic = AxisPicture { width_px: 900.0, tolerance: tol, disks: args.disks };
        write_file(&path, &axis.to_svg(shape, &pic))?;
        out!("wrote {}", path.display());
    }
    Ok(())
}

/// The axis of one shape under a polygon ball (thesis chapter 3).
fn run_ball(args: &AxisArgs, shape: &Shape2d, ball: &Ball2, k: Option<usize>, read: f64) -> Result<(), ExitCode> {
    let t = Instant::now();
    let axis = medial_axis_with_ball(shape, ball).map_err(|e| {
        let which = k.map_or_else(String::new, |k| format!(" shape {k}"));
        eprintln!("medax: {}{which}: {e}", args.shape.shape.display());
        ExitCode::from(1)
    })?;
    let took = t.elapsed().as_secs_f64();
    let [branch, pseudo, corner, joint, leaf] = axis.kind_counts();
    out!(
        "medial axis under a {}-gon ball: {} nodes ({branch} branch, {pseudo} pseudo-branch, {corner} corner, {joint} joint, {leaf} leaf), {} edges ({} jump)",
        ball.len(),
        axis.nodes.len(),
        axis.edges.len(),
        axis.jump_count()
    );
    out!("read in {read:.3} s, axis in {took:.3} s ({} elements)", shape.element_count());
    if let Some(path) = &args.json {
        let path = per_shape(path, k);
        write_streamed(&path, |w| axis.write_json(shape, w))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.svg {
        let path = per_shape(path, k);
        write_file(&path, &axis.to_svg(shape, 900.0))?;
        out!("wrote {}", path.display());
    }
    Ok(())
}
