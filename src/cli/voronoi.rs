//! `medax voronoi`: the Voronoi diagram of sites as JSON and/or SVG.

use super::{write_file, write_streamed, RunArgs};
use medax::plane::read_sites;
use medax::plane::AxisOptions;
use medax::plane::{voronoi, VoronoiOptions};
use medax::shape::ShapeOptions;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `medax voronoi`.
#[derive(clap::Args)]
pub struct VoronoiArgs {
    /// Sites file (JSON): {"points": [[x,y],..], "curves": [[[x,y,bulge],..],..],
    /// "regions": [[[x,y,bulge],..],..], "boundary": [[x,y,bulge],..]}, every key optional.
    pub sites: PathBuf,
    /// Write the diagram as JSON (nodes, edges with the sites they separate, regions).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a picture of the sites and the diagram.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Leave out self-edges (points with two nearest points on one site).
    #[arg(long)]
    pub no_self_edges: bool,
    /// Absolute touching tolerance in model units (default: 1e-9 × the sites' bounding-box diagonal;
    /// the sample tolerance's default is relative to that diagonal too).
    #[arg(long)]
    pub tolerance: Option<f64>,
    #[command(flatten)]
    pub run: RunArgs,
}

pub fn run(args: &VoronoiArgs) -> Result<(), ExitCode> {
    let name = args.sites.display();
    let text = std::fs::read_to_string(&args.sites).map_err(|e| {
        eprintln!("medax: cannot read {name}: {e}");
        ExitCode::from(3)
    })?;
    let (sites, boundary) = read_sites(&text).map_err(|e| {
        eprintln!("medax: {name}: {e}");
        ExitCode::from(1)
    })?;
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
