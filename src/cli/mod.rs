//! Command-line interface: argument parsing and dispatch. Each subcommand
//! lives in its own file and only calls the library's public API.

/// `println!` that never panics: a closed stdout (`medax axis … | head`)
/// loses the rest of the report, not the run.
macro_rules! out {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($t)*);
    }};
}

/// Writes `text` to stdout as it is, ignoring a closed stdout (see `out!`).
fn put(text: &str) {
    use std::io::Write as _;
    let _ = std::io::stdout().write_all(text.as_bytes());
}

mod axis;
mod axis3d;
mod ball;
mod demo;
mod info;
mod mesh;
mod offset;
mod query3d;
mod voronoi;

use clap::{Parser, Subcommand};
use medax::shape::{Drawing2d, DrawingOptions, Shape2d, ShapeError, ShapeOptions};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// medax: medial axes, Voronoi diagrams and offsets of shapes bounded by arcs and segments.
#[derive(Parser)]
#[command(version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

/// Options shared by commands that read a shape.
#[derive(clap::Args)]
struct ShapeArgs {
    /// Shape file: .json (medax loops), .dxf (ASCII) or .svg (`medax info` also reads solids: .obj, .off, .stl, .ply).
    shape: PathBuf,
    /// Absolute touching tolerance in model units (default: 1e-9 × bounding-box diagonal).
    #[arg(long)]
    tolerance: Option<f64>,
    /// Joint angle tolerance in radians (smooth vs corner).
    #[arg(long, default_value_t = 1e-6)]
    angle_tolerance: f64,
    /// Gap closed when chaining DXF/SVG pieces into loops (default: 1e-6 × diagonal).
    #[arg(long)]
    chain_tolerance: Option<f64>,
    /// Which shape of a drawing with several: K (0 = the largest; `medax info` lists them), or
    /// `all` (axis, offset: one run per shape, output files NAME.K.EXT).
    #[arg(long = "shape", value_name = "K|all", value_parser = pick)]
    pick: Option<Pick>,
    /// Refuse a DXF/SVG drawing with anything but closed loops of one shape (no profile extraction).
    #[arg(long)]
    strict: bool,
    /// Take the curves of this DXF layer only (repeatable; default: every layer).
    #[arg(long = "layer", value_name = "NAME")]
    layers: Vec<String>,
    /// Take the curves of this DXF colour only: an AutoCAD colour index 1-255, by layer and by
    /// block resolved (repeatable; default: every colour).
    #[arg(long = "colour", visible_alias = "color", value_name = "ACI", value_parser = clap::value_parser!(i16).range(1..=255))]
    colours: Vec<i16>,
    /// Keep both copies of a loop drawn twice (default: merge them into one, reported).
    #[arg(long)]
    keep_duplicates: bool,
}

/// `--shape`: one shape of a drawing, or every one.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Pick {
    One(usize),
    All,
}

fn pick(s: &str) -> Result<Pick, String> {
    match s.trim() {
        "all" => Ok(Pick::All),
        k => k.parse().map(Pick::One).map_err(|_| format!("{s:?} is neither a shape number nor `all`")),
    }
}

/// `path` with the shape number before its extension (`out.json` →
/// `out.2.json`) when a run writes one file per shape (`k` given).
fn per_shape(path: &Path, k: Option<usize>) -> PathBuf {
    let Some(k) = k else { return path.to_path_buf() };
    let stem = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let name = match path.extension() {
        Some(ext) => format!("{stem}.{k}.{}", ext.to_string_lossy()),
        None => format!("{stem}.{k}"),
    };
    path.with_file_name(name)
}

impl ShapeArgs {
    fn options(&self) -> ShapeOptions {
        ShapeOptions {
            tolerance: self.tolerance,
            angle_tolerance: self.angle_tolerance,
            chain_tolerance: self.chain_tolerance,
            ..ShapeOptions::default()
        }
    }

    /// The drawing's profiles (one shape, nothing ignored, under `--strict`).
    fn load_drawing(&self) -> Result<Drawing2d, ShapeError> {
        if self.strict {
            return Ok(Drawing2d::of(Shape2d::from_file(&self.shape, &self.options())?));
        }
        let select = DrawingOptions {
            layers: self.layers.clone(),
            colours: self.colours.clone(),
            keep_duplicates: self.keep_duplicates,
        };
        Drawing2d::from_file(&self.shape, &self.options(), &select)
    }

    /// The shape to work on: the one `--shape` picks (the largest by
    /// default), with a note on stderr of what else the drawing held.
    fn load(&self) -> Result<Shape2d, ShapeError> {
        if self.pick == Some(Pick::All) {
            return Err(ShapeError::InvalidArgument { what: "--shape all: this command takes one shape".into() });
        }
        Ok(self.load_each()?.swap_remove(0).1)
    }

    /// The shapes to work on, each with its number when there are several
    /// (`--shape all` on a drawing of more than one), else the one picked.
    fn load_each(&self) -> Result<Vec<(Option<usize>, Shape2d)>, ShapeError> {
        let mut d = self.load_drawing()?;
        let picked = match self.pick {
            Some(Pick::All) => format!("all {}", d.shapes.len()),
            Some(Pick::One(k)) => format!("shape {k}"),
            None => "shape 0".into(),
        };
        if d.shapes.len() > 1 || !d.ignored.is_empty() {
            eprintln!(
                "medax: {}: {} shape(s), {} thing(s) ignored; using {picked} (`medax info` lists them)",
                self.shape.display(),
                d.shapes.len(),
                d.ignored.len()
            );
        }
        match self.pick {
            Some(Pick::All) if d.shapes.len() > 1 => {
                Ok(d.shapes.into_iter().enumerate().map(|(k, s)| (Some(k), s)).collect())
            }
            pick => {
                let k = match pick {
                    Some(Pick::One(k)) => k,
                    _ => 0,
                };
                if k >= d.shapes.len() {
                    return Err(no_shape(&d, k));
                }
                Ok(vec![(None, d.shapes.swap_remove(k))])
            }
        }
    }
}

/// The error of a drawing without shape `k`: its first invalid shape's
/// validation error, or that it holds no closed profile.
fn no_shape(d: &Drawing2d, k: usize) -> ShapeError {
    if !d.shapes.is_empty() {
        return ShapeError::InvalidArgument {
            what: format!("--shape {k}: the drawing has {} shape(s)", d.shapes.len()),
        };
    }
    if let Some(cause) = d.ignored.iter().find_map(|i| i.cause.clone()) {
        return cause;
    }
    match d.ignored.first() {
        Some(i) => ShapeError::NoProfile {
            ignored: d.ignored.len(),
            first: format!(
                "{} at line/byte {} near ({}, {}): {}",
                i.kind.name(),
                i.source,
                i.position.x,
                i.position.y,
                i.reason
            ),
        },
        None => ShapeError::Empty,
    }
}

/// Options shared by commands that compute an axis.
#[derive(clap::Args)]
struct RunArgs {
    /// Chordal tolerance of the samples, model units (default: 1e-4 × bounding-box diagonal).
    #[arg(long)]
    sample_tolerance: Option<f64>,
    /// Seed of the divide step's random choices.
    #[arg(long, default_value_t = medax::plane::AxisOptions::default().seed)]
    seed: u64,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
}

impl RunArgs {
    /// A thread pool of the requested size.
    fn pool(&self) -> Result<rayon::ThreadPool, ExitCode> {
        rayon::ThreadPoolBuilder::new().num_threads(self.threads.unwrap_or(0)).build().map_err(|e| {
            eprintln!("medax: cannot start threads: {e}");
            ExitCode::from(3)
        })
    }
}

#[derive(Subcommand)]
enum Command {
    /// Read and validate a solid, write it in another format (.obj, .off or .ply, by extension): triangulated,
    /// welded, facing outward.
    Convert {
        /// The solid: .obj, .off, .stl or .ply.
        input: PathBuf,
        /// The output file: .obj, .off or .ply (binary).
        output: PathBuf,
    },
    /// For each point of a JSON file (`{"points": [[x, y, z], ...]}`): inside a solid or not (exact), the
    /// Euclidean distance and closest surface point, and with `--ball` the largest ball at inside points.
    Query3d {
        /// The solid: .obj, .off, .stl or .ply.
        mesh: PathBuf,
        /// A space ball: tetra, cube, octa, icosa, geodesic:N, or a mesh file (the hull of its vertices).
        #[arg(long)]
        ball: Option<String>,
        /// The points file.
        #[arg(long)]
        points: PathBuf,
        /// With --ball: decide the largest ball's radius and contacts exactly and list every contact
        /// (`contacts`: ball and surface features, VF/EE/FV/VE/EV/VV); about five times slower.
        #[arg(long, requires = "ball")]
        exact: bool,
        /// Write `{"results": [...]}` here (default: print it).
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// The medial axis of a solid under a space ball: JSON (vertices with radii, triangles, sheets with
    /// their contact classes), OBJ, or PLY coloured by radius; progress on stderr.
    Axis3d {
        /// The solid: .obj, .off, .stl or .ply.
        mesh: PathBuf,
        /// The space ball: tetra, cube, octa, icosa, geodesic:N, or a mesh file (the hull of its vertices);
        /// NAME@RX,RY,RZ turns it by a rotation vector (radians).
        #[arg(long)]
        ball: String,
        /// Worker threads (default: all cores).
        #[arg(long)]
        threads: Option<usize>,
        /// Write the axis JSON here (default: print it, unless --obj or --ply is given).
        #[arg(long)]
        json: Option<PathBuf>,
        /// Write the axis triangles as OBJ.
        #[arg(long)]
        obj: Option<PathBuf>,
        /// Write the axis as PLY with a radius and a colour by radius per vertex.
        #[arg(long)]
        ply: Option<PathBuf>,
        /// Write a picture: the axis coloured by radius over the solid's outline, an oblique view.
        #[arg(long)]
        svg: Option<PathBuf>,
    },
    /// Validate a shape, or the shapes of a drawing, and report loops, elements, joints, area, extent and what was ignored;
    /// or validate a solid (.obj, .off, .stl, .ply) and report its components, volume, area and genus.
    Info {
        #[command(flatten)]
        shape: ShapeArgs,
        /// Write the drawing's shapes, ignored things and closed gaps as JSON.
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Draw a shape as SVG (arcs stay exact arcs).
    Draw {
        #[command(flatten)]
        shape: ShapeArgs,
        /// Output SVG file.
        #[arg(short, long)]
        output: PathBuf,
        /// Picture width in pixels.
        #[arg(long, default_value_t = 900.0)]
        width: f64,
    },
    /// Compute the medial axis: nodes, conic edges with their boundary sites, samples.
    Axis(axis::AxisArgs),
    /// Compute the Voronoi diagram of sites: points, open curves and closed regions.
    Voronoi(voronoi::VoronoiArgs),
    /// Trimmed offsets at distances, pocketing rings or V-carve paths (arcs stay arcs).
    Offset(offset::OffsetArgs),
    /// Describe and draw a unit ball of a polygonal distance (thesis chapter 3).
    Ball(ball::BallArgs),
    /// Run the demo: validate and draw the embedded demo shape (the default).
    Demo {
        /// Output SVG file.
        #[arg(short, long, default_value = "medax-demo.svg")]
        output: PathBuf,
    },
}

/// Prints an error the way every subcommand does and picks the exit code:
/// 1 for invalid input, 3 for I/O problems.
fn fail(context: &Path, e: &ShapeError) -> ExitCode {
    eprintln!("medax: {}: {e}", context.display());
    match e {
        ShapeError::Io { .. } => ExitCode::from(3),
        _ => ExitCode::from(1),
    }
}

fn write_file(path: &Path, text: &str) -> Result<(), ExitCode> {
    std::fs::write(path, text).map_err(|e| {
        eprintln!("medax: cannot write {}: {e}", path.display());
        ExitCode::from(3)
    })
}

/// Writes a file through `write` (buffered), streaming instead of building
/// the whole text first: an axis of 10^6 arcs is about 0.75 GB of JSON.
fn write_streamed(
    path: &Path,
    write: impl FnOnce(&mut std::io::BufWriter<std::fs::File>) -> std::io::Result<()>,
) -> Result<(), ExitCode> {
    std::fs::File::create(path)
        .and_then(|f| {
            let mut w = std::io::BufWriter::with_capacity(1 << 20, f);
            write(&mut w)
        })
        .map_err(|e| {
            eprintln!("medax: cannot write {}: {e}", path.display());
            ExitCode::from(3)
        })
}

/// Entry point of the binary.
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command.unwrap_or(Command::Demo { output: "medax-demo.svg".into() }) {
        Command::Info { shape, json } => info::run(&shape, json.as_deref()),
        Command::Convert { input, output } => mesh::run_convert(&input, &output),
        Command::Query3d { mesh, ball, points, exact, json } => {
            query3d::run(&mesh, ball.as_deref(), &points, exact, json.as_deref())
        }
        Command::Axis3d { mesh, ball, threads, json, obj, ply, svg } => {
            axis3d::run(&mesh, &ball, threads, json.as_deref(), obj.as_deref(), ply.as_deref(), svg.as_deref())
        }
        Command::Axis(args) => axis::run(&args),
        Command::Voronoi(args) => voronoi::run(&args),
        Command::Offset(args) => offset::run(&args),
        Command::Ball(args) => ball::run(&args),
        Command::Draw { shape, output, width } => match shape.load() {
            Ok(s) => write_file(&output, &s.to_svg(width)).map(|_| out!("wrote {}", output.display())),
            Err(e) => Err(fail(&shape.shape, &e)),
        },
        Command::Demo { output } => demo::run(&output),
    };
    result.err().unwrap_or(ExitCode::SUCCESS)
}
