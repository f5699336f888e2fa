//! `medax voronoi`: the Voronoi diagram of sites as JSON and/or SVG.

use super::{write_file, write_streamed, RunArgs};
use medax::io::Format;
use medax::kernel::{BBox, FilteredKernel};
use medax::plane::read_sites;
use medax::plane::AxisOptions;
use medax::plane::Sites;
use medax::plane::{voronoi, VoronoiOptions};
use medax::polymetric::{voronoi_with_ball, BallVoronoiOptions};
use medax::shape::{Ball2, BoxTree, Drawing2d, DrawingOptions, Shape2d, ShapeOptions, SiteId, Vertex};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `medax voronoi`.
#[derive(clap::Args)]
pub struct VoronoiArgs {
    /// Sites file (JSON): {"points": [[x,y],..], "curves": [[[x,y,bulge],..],..],
    /// "regions": [[[x,y,bulge],..],..], "boundary": [[x,y,bulge],..]}, every key optional; or a
    /// drawing (DXF, SVG, shape or drawing JSON), whose parts (outer loops) are the region sites.
    pub sites: PathBuf,
    /// Of a drawing, take the curves of this DXF layer only (repeatable).
    #[arg(long = "layer", value_name = "NAME")]
    pub layers: Vec<String>,
    /// Of a drawing, take the curves of this DXF colour only (repeatable; 1-255).
    #[arg(long = "colour", visible_alias = "color", value_name = "ACI", value_parser = clap::value_parser!(i16).range(1..=255))]
    pub colours: Vec<i16>,
    /// Write the diagram as JSON (nodes, edges with the sites they separate, regions).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a picture of the sites and the diagram.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Leave out self-edges (points with two nearest points on one site).
    #[arg(long)]
    pub no_self_edges: bool,
    /// The unit ball of the metric (points, segments and polygons only): square, diamond, triangle,
    /// ngon:K[:DEGREES], ball JSON text, or a file of ball JSON. Default: the Euclidean disk.
    #[arg(long)]
    pub ball: Option<String>,
    /// Absolute touching tolerance in model units (default: 1e-9 × the sites' bounding-box diagonal;
    /// the sample tolerance's default is relative to that diagonal too).
    #[arg(long)]
    pub tolerance: Option<f64>,
    #[command(flatten)]
    pub run: RunArgs,
}

/// The sites of a sites file, or the parts of a drawing as region sites.
fn load(args: &VoronoiArgs) -> Result<(Sites, Option<Vec<Vertex>>), ExitCode> {
    let name = args.sites.display();
    let fail = |e: &dyn std::fmt::Display| {
        eprintln!("medax: {name}: {e}");
        ExitCode::from(1)
    };
    let format = Format::from_path(&args.sites);
    let mut sites_error = None;
    if matches!(format, None | Some(Format::Json)) {
        let text = std::fs::read_to_string(&args.sites).map_err(|e| {
            eprintln!("medax: cannot read {name}: {e}");
            ExitCode::from(3)
        })?;
        match read_sites(&text) {
            Ok(_) if !args.layers.is_empty() || !args.colours.is_empty() => {
                return Err(fail(&"--layer and --colour select the curves of a drawing, not sites"));
            }
            Ok(read) => return Ok(read),
            // Not a sites file: perhaps a shape or drawing.
            Err(e) if text.contains("\"loops\"") || text.contains("\"shapes\"") => sites_error = Some(e),
            Err(e) => return Err(fail(&e)),
        }
    }
    let select = DrawingOptions { layers: args.layers.clone(), colours: args.colours.clone(), ..Default::default() };
    let opts = ShapeOptions { tolerance: args.tolerance, ..ShapeOptions::default() };
    let d = Drawing2d::from_file(&args.sites, &opts, &select).map_err(|e| match &sites_error {
        Some(s) => fail(&format!("{s}; nor is it a drawing: {e}")),
        None => fail(&e),
    })?;
    let parts = parts(&d.shapes);
    if parts.is_empty() {
        return Err(fail(&"the drawing has no closed profile (`medax info` says what it holds)"));
    }
    let islands = d.shapes.len() - parts.len();
    eprintln!(
        "medax: {name}: the outer loops of {} part(s) as region sites{}",
        parts.len(),
        if islands > 0 { format!(" ({islands} island(s) inside other parts left out)") } else { String::new() }
    );
    let regions = parts.iter().map(|s| s.outer().vertices().to_vec()).collect();
    Ok((Sites { regions, ..Sites::default() }, None))
}

/// The shapes not inside another shape's outer loop: islands in holes
/// would overlap the part around them as region sites. Candidates by a box
/// tree: a drawing may hold thousands of parts.
fn parts(shapes: &[Shape2d]) -> Vec<&Shape2d> {
    let k = FilteredKernel;
    let tree = BoxTree::new(shapes.iter().map(|s| s.bbox()).collect());
    let inside = |i: usize| {
        let p = shapes[i].outer().vertices()[0].p;
        let mut found = false;
        tree.visit_overlapping(&BBox::of_points(p, p), |j| {
            found = j != i && shapes[j].outer().winding_number(&k, p) != 0;
            if found {
                std::ops::ControlFlow::Break(())
            } else {
                std::ops::ControlFlow::Continue(())
            }
        });
        found
    };
    (0..shapes.len()).filter(|&i| !inside(i)).map(|i| &shapes[i]).collect()
}

pub fn run(args: &VoronoiArgs) -> Result<(), ExitCode> {
    let name = args.sites.display();
    let (sites, boundary) = load(args)?;
    if let Some(spec) = &args.ball {
        let ball = super::ball::load_ball(spec)?;
        return run_ball(args, &sites, boundary, &ball);
    }
    let opts = VoronoiOptions {
        axis: AxisOptions { seed: args.run.seed, ..AxisOptions::default() },
        shape: ShapeOptions { tolerance: args.tolerance, ..ShapeOptions::default() },
        boundary,
    };
    let pool = args.run.pool()?;
    let t = Instant::now();
    let vd = pool.install(|| voronoi(&sites, &opts)).map_err(|e| {
        eprintln!("medax: {name}: {e}");
        ExitCode::from(1)
    })?;
    let took = t.elapsed().as_secs_f64();
    let kept = vd.diagram_edges(!args.no_self_edges);
    let selfs = kept.iter().filter(|&&i| vd.edges[i].self_edge).count();
    let unbounded = vd.regions.iter().filter(|r| r.unbounded).count();
    out!(
        "voronoi diagram: {} sites, {} edges ({selfs} self-edges), {unbounded} unbounded regions{}",
        sites.len(),
        kept.len(),
        if vd.complete {
            ""
        } else {
            "; the frame reached its limit: far vertices of nearly collinear sites are missing"
        }
    );
    out!("computed in {took:.3} s ({} elements)", vd.shape().element_count());
    let site_diag = vd.shape().loops()[usize::from(vd.auto_frame)..]
        .iter()
        .fold(medax::kernel::BBox::EMPTY, |b, l| b.union(&l.bbox()))
        .diagonal();
    let tol = args.run.sample_tolerance.unwrap_or(1e-4 * site_diag);
    if let Some(path) = &args.json {
        write_streamed(path, |w| vd.write_json(tol, !args.no_self_edges, w))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.svg {
        write_file(path, &vd.to_svg(900.0, tol, !args.no_self_edges))?;
        out!("wrote {}", path.display());
    }
    Ok(())
}

/// The diagram under a polygon ball (thesis chapter 3's distance).
fn run_ball(args: &VoronoiArgs, sites: &Sites, boundary: Option<Vec<Vertex>>, ball: &Ball2) -> Result<(), ExitCode> {
    let name = args.sites.display();
    let opts =
        BallVoronoiOptions { shape: ShapeOptions { tolerance: args.tolerance, ..ShapeOptions::default() }, boundary };
    let t = Instant::now();
    let vd = voronoi_with_ball(sites, ball, &opts).map_err(|e| {
        eprintln!("medax: {name}: {e}");
        ExitCode::from(1)
    })?;
    let took = t.elapsed().as_secs_f64();
    let between = vd.site_edges().count();
    // The library's frame has an axis of its own (its corners): not the sites'.
    let selfs = vd.edges.iter().filter(|e| e.self_edge && !(vd.auto_frame && e.sides[0] == SiteId::Frame)).count();
    let unbounded = vd.frontier.iter().filter(|&&f| f).count();
    out!(
        "voronoi diagram under a {}-gon ball: {} sites, {between} edges between sites, {selfs} self-edges, {unbounded} running to infinity",
        ball.len(),
        sites.len()
    );
    out!("computed in {took:.3} s ({} elements)", vd.shape().element_count());
    if let Some(path) = &args.json {
        write_streamed(path, |w| vd.write_json(!args.no_self_edges, w))?;
        out!("wrote {}", path.display());
    }
    if let Some(path) = &args.svg {
        write_file(path, &vd.to_svg(900.0, !args.no_self_edges))?;
        out!("wrote {}", path.display());
    }
    Ok(())
}
