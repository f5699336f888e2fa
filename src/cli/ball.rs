//! `medax ball`: what a unit ball is (vertices, symmetry, how far its
//! distance strays from the Euclidean one) and a picture of it.

use super::write_file;
use medax::kernel::Point;
use medax::shape::Ball2;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `medax ball`.
#[derive(clap::Args)]
pub struct BallArgs {
    /// The ball: square, diamond, triangle, ngon:K[:DEGREES], ball JSON text, or a file of ball
    /// JSON ({"vertices": [[x, y], ...]}).
    pub ball: String,
    /// Draw the ball (the unit circle dashed, the origin marked, vertices numbered, the mirrored
    /// ball faint when it differs).
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

/// The ball `spec` names: a preset, ball JSON text, or a file holding
/// ball JSON. Errors are printed; exit code 3 for an unreadable file, 1
/// for a bad ball.
pub fn load_ball(spec: &str) -> Result<Ball2, ExitCode> {
    let path = PathBuf::from(spec);
    let text = if path.is_file() {
        std::fs::read_to_string(&path).map_err(|e| {
            eprintln!("medax: cannot read {}: {e}", path.display());
            ExitCode::from(3)
        })?
    } else {
        spec.to_string()
    };
    Ball2::parse(&text).map_err(|e| {
        eprintln!("medax: {spec}: {e}");
        ExitCode::from(1)
    })
}

pub fn run(args: &BallArgs) -> Result<(), ExitCode> {
    let ball = load_ball(&args.ball)?;
    let v = ball.vertices();
    let n = v.len();
    // The largest circle inside and the smallest around, centred at the
    // origin: δ_B lies between |x|/outer and |x|/inner.
    let outer = v.iter().map(|p| p.norm()).fold(0.0, f64::max);
    let inner = (0..n)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % n]);
            (b - a).cross(Point::new(0.0, 0.0) - a).abs() / (b - a).norm()
        })
        .fold(f64::INFINITY, f64::min);
    out!(
        "unit ball: {n} vertices (counter-clockwise), {}",
        if ball.is_symmetric() {
            "symmetric: a metric"
        } else {
            "not symmetric: a quasi-metric (δ(p, q) ≠ δ(q, p))"
        }
    );
    for (i, p) in v.iter().enumerate().take(12) {
        out!("  vertex {i}: ({}, {})", p.x, p.y);
    }
    if n > 12 {
        out!("  … and {} more", n - 12);
    }
    out!("origin-centred circles: inside radius {inner}, around radius {outer}; δ_B(p, q) lies between |q − p| / {outer} and |q − p| / {inner}");
    if let Some(svg) = &args.svg {
        write_file(svg, &picture(&ball, outer.max(1.0)))?;
        out!("wrote {}", svg.display());
    }
    Ok(())
}

/// The ball in a square picture spanning ±1.15 `extent`.
fn picture(ball: &Ball2, extent: f64) -> String {
    let size = 480.0;
    let scale = size / (2.3 * extent);
    let at = |p: Point| ((p.x * scale + size / 2.0), (size / 2.0 - p.y * scale));
    let path = |b: &Ball2| {
        let mut d = String::new();
        for (i, p) in b.vertices().iter().enumerate() {
            let (x, y) = at(*p);
            d += &format!("{}{x:.3},{y:.3} ", if i == 0 { "M" } else { "L" });
        }
        d + "Z"
    };
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{size}\" height=\"{size}\" viewBox=\"0 0 {size} {size}\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
         <circle cx=\"{c}\" cy=\"{c}\" r=\"{r:.3}\" fill=\"none\" stroke=\"#999\" stroke-dasharray=\"4 4\"/>\n",
        c = size / 2.0,
        r = scale
    );
    if !ball.is_symmetric() {
        s +=
            &format!("<path d=\"{}\" fill=\"none\" stroke=\"#c66\" stroke-opacity=\"0.5\"/>\n", path(&ball.mirrored()));
    }
    s += &format!(
        "<path d=\"{}\" fill=\"#36c\" fill-opacity=\"0.15\" stroke=\"#36c\" stroke-width=\"2\"/>\n",
        path(ball)
    );
    s += &format!("<circle cx=\"{c}\" cy=\"{c}\" r=\"3\" fill=\"black\"/>\n", c = size / 2.0);
    if ball.len() <= 24 {
        for (i, p) in ball.vertices().iter().enumerate() {
            let (x, y) = at(*p * 1.08);
            s += &format!("<text x=\"{x:.1}\" y=\"{y:.1}\" font-family=\"DejaVu Sans\" font-size=\"12\" text-anchor=\"middle\">{i}</text>\n");
        }
    }
    s + "</svg>\n"
}
