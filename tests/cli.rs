//! The `medax` binary: the axis of a shape with a hole and a Voronoi diagram through the CLI
//! (JSON contract: one cycle per hole), and a closed stdout is not a crash.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

#[path = "common/solids.rs"]
mod solids;

fn medax() -> Command {
    Command::new(env!("CARGO_BIN_EXE_medax"))
}

fn holed_square(dir: &std::path::Path) -> std::path::PathBuf {
    let p = dir.join("holed.json");
    std::fs::write(&p, r#"{"loops": [[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [1, 3], [3, 3], [3, 1]]]}"#).unwrap();
    p
}

#[test]
fn axis_of_a_shape_with_a_hole() {
    let dir = std::env::temp_dir().join(format!("medax-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let shape = holed_square(&dir);
    let json = dir.join("axis.json");
    let out = medax().arg("axis").arg(&shape).arg("--json").arg(&json).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&json).unwrap();
    // One cycle: as many edges as nodes; the hole's loop among the sites.
    let nodes = text.matches("\"x\":").count();
    let edges = text.matches("\"sites\":").count();
    assert!(nodes > 8, "{text}");
    assert_eq!(nodes, edges, "{text}");
    assert!(text.contains("\"loop\":1"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_closed_stdout_is_not_a_crash() {
    let dir = std::env::temp_dir().join(format!("medax-cli-pipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let shape = holed_square(&dir);
    for args in [vec!["axis"], vec!["info"]] {
        let mut child = medax().args(&args).arg(&shape).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success(), "{args:?}: {:?} {}", out.status, String::from_utf8_lossy(&out.stderr));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn voronoi_of_region_sites_and_bad_sites() {
    let dir = std::env::temp_dir().join(format!("medax-cli-vd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let sites = dir.join("sites.json");
    // Two squares and a U whose mouth faces up: a self-edge in the mouth.
    std::fs::write(
        &sites,
        r#"{"regions": [[[0, 0], [1, 0], [1, 1], [0, 1]], [[3, 0], [4, 0], [4, 1], [3, 1]],
            [[0, 3], [3, 3], [3, 6], [2, 6], [2, 4], [1, 4], [1, 6], [0, 6]]]}"#,
    )
    .unwrap();
    let (json, svg) = (dir.join("vd.json"), dir.join("vd.svg"));
    let out = medax().arg("voronoi").arg(&sites).arg("--json").arg(&json).arg("--svg").arg(&svg).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(doc["frame"], "auto");
    assert_eq!(doc["complete"], true);
    let edges = doc["edges"].as_array().unwrap();
    let selfs = edges.iter().filter(|e| e["self"] == true).count();
    assert!(selfs > 0 && selfs < edges.len());
    assert!(edges.iter().all(|e| e["separates"].as_array().unwrap().iter().all(|s| s != "boundary")));
    assert_eq!(doc["regions"].as_array().unwrap().len(), 3);
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    let without = medax().arg("voronoi").arg(&sites).arg("--no-self-edges").arg("--json").arg(&json).output().unwrap();
    assert!(without.status.success());
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert!(doc["edges"].as_array().unwrap().iter().all(|e| e["self"] == false));
    // Overlapping sites: exit 1 and the site named.
    std::fs::write(&sites, r#"{"regions": [[[0, 0], [2, 0], [2, 2], [0, 2]], [[1, 1], [3, 1], [3, 3], [1, 3]]]}"#)
        .unwrap();
    let bad = medax().arg("voronoi").arg(&sites).output().unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("region site"), "{}", String::from_utf8_lossy(&bad.stderr));
    std::fs::write(&sites, r#"{"regoins": []}"#).unwrap();
    let typo = medax().arg("voronoi").arg(&sites).output().unwrap();
    assert_eq!(typo.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&typo.stderr).contains("regoins"));
    std::fs::remove_dir_all(&dir).ok();
}

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("medax-cli-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `medax offset SHAPE MODE... --json DIR/NAME.json --dxf DIR/NAME.dxf
/// --svg DIR/NAME.svg`, which must succeed: its stdout and the three paths.
fn run_offset(shape: &Path, mode: &[&str], dir: &Path, name: &str) -> (String, [PathBuf; 3]) {
    let paths = ["json", "dxf", "svg"].map(|ext| dir.join(format!("{name}.{ext}")));
    let mut cmd = medax();
    cmd.arg("offset").arg(shape).args(mode);
    for (flag, path) in ["--json", "--dxf", "--svg"].iter().zip(&paths) {
        cmd.arg(flag).arg(path);
    }
    let out = cmd.output().unwrap();
    assert!(out.status.success(), "{mode:?}: {}", String::from_utf8_lossy(&out.stderr));
    (String::from_utf8_lossy(&out.stdout).into_owned(), paths)
}

fn json_file(path: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Closed bulge loops `[[[x, y, bulge], ..], ..]` from JSON.
fn loops_of(v: &serde_json::Value) -> Vec<Vec<medax::shape::Vertex>> {
    let num = |x: &serde_json::Value| x.as_f64().unwrap();
    v.as_array()
        .unwrap()
        .iter()
        .map(|l| {
            let l = l.as_array().unwrap();
            l.iter()
                .map(|v| medax::shape::Vertex {
                    p: medax::kernel::Point::new(num(&v[0]), num(&v[1])),
                    bulge: num(&v[2]),
                })
                .collect()
        })
        .collect()
}

fn signed_area(l: &[medax::shape::Vertex]) -> f64 {
    medax::shape::Loop::new(l.to_vec()).signed_area()
}

#[test]
fn offset_distances_as_json_dxf_and_svg() {
    use std::f64::consts::PI;
    let dir = scratch("offset");
    let shape = holed_square(&dir);
    let (stdout, [json, dxf, svg]) = run_offset(&shape, &["--distance", "0.25,-0.5"], &dir, "o");
    assert!(stdout.contains("distance 0.25: 2 loop(s), 1 region(s)"), "{stdout}");
    assert!(stdout.contains("distance -0.5: 2 loop(s), 1 region(s)"), "{stdout}");
    let doc = json_file(&json);
    let layers = doc["offsets"].as_array().unwrap();
    assert_eq!(layers.len(), 2);
    // Inside: the outer square shrinks to 3.5 × 3.5, the 2 × 2 hole grows
    // by 0.25 with round corners. Outside: the square grows by 0.5 with
    // round corners, the hole shrinks to 1 × 1.
    let expected = [(0.25, 12.25 - (4.0 + 2.0 + PI * 0.0625)), (-0.5, 16.0 + 8.0 + PI * 0.25 - 1.0)];
    let mut dxf_loops = 0;
    for (layer, (d, area)) in layers.iter().zip(expected) {
        assert_eq!(layer["distance"].as_f64(), Some(d));
        let loops = loops_of(&layer["loops"]);
        assert_eq!(loops.len(), 2);
        dxf_loops += loops.len();
        let from_loops: f64 = loops.iter().map(|l| signed_area(l)).sum();
        assert!((from_loops - area).abs() < 1e-9, "distance {d}: {from_loops} vs {area}");
        assert!((layer["area"].as_f64().unwrap() - area).abs() < 1e-9);
        let regions = layer["regions"].as_array().unwrap();
        assert_eq!(regions.len(), 1);
        let outer = regions[0]["outer"].as_u64().unwrap() as usize;
        let holes = regions[0]["holes"].as_array().unwrap();
        assert_eq!(holes.len(), 1);
        assert!(signed_area(&loops[outer]) > 0.0);
        assert!(signed_area(&loops[holes[0].as_u64().unwrap() as usize]) < 0.0);
    }
    // The DXF holds one closed polyline with bulges per loop, and reads back.
    let drawing = medax::io::dxf::read_dxf(&std::fs::read_to_string(&dxf).unwrap()).unwrap();
    assert_eq!(drawing.polylines.len(), dxf_loops);
    assert!(drawing.polylines.iter().all(|p| p.closed));
    assert!(drawing.polylines.iter().any(|p| p.vertices.iter().any(|v| v.bulge != 0.0)), "arcs stay arcs");
    // Rounded corners are SVG arcs.
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.starts_with("<svg") && picture.contains("A0.25 0.25"), "{picture}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn offset_pocket_rings_in_both_orders() {
    let dir = scratch("pocket");
    let shape = holed_square(&dir);
    for outside_in in [false, true] {
        let mode: &[&str] =
            if outside_in { &["--pocket", "0.1,0.15", "--outside-in"] } else { &["--pocket", "0.1,0.15"] };
        let (stdout, [json, dxf, svg]) = run_offset(&shape, mode, &dir, "p");
        assert!(stdout.contains("pocket: ") && stdout.contains("level 0 (distance 0.1): 1 ring(s)"), "{stdout}");
        let doc = json_file(&json);
        let rings = doc["rings"].as_array().unwrap();
        // Levels at 0.1, 0.25 and 0.4 are one ring round the hole each; at
        // 0.55 only the four corners are left (their largest disks have
        // radius sqrt(2) / (1 + sqrt(2)) = 0.586), children of the third.
        assert_eq!(rings.len(), 7, "{doc}");
        for (i, r) in rings.iter().enumerate() {
            let level = r["level"].as_u64().unwrap();
            assert_eq!(level, (i as u64).min(3));
            assert!((r["distance"].as_f64().unwrap() - (0.1 + 0.15 * level as f64)).abs() < 1e-12);
            assert_eq!(loops_of(&r["loops"]).len(), if level < 3 { 2 } else { 1 }, "ring {i}");
            for c in r["children"].as_array().unwrap() {
                assert_eq!(rings[c.as_u64().unwrap() as usize]["parent"].as_u64(), Some(i as u64));
            }
        }
        let order: Vec<usize> = doc["order"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap() as usize).collect();
        let mut position = vec![usize::MAX; rings.len()];
        for (k, &i) in order.iter().enumerate() {
            position[i] = k;
        }
        assert!(position.iter().all(|&k| k != usize::MAX), "{order:?}");
        // Inside-out: every ring after the rings inside it, the wall last;
        // outside-in: the wall first.
        for (i, r) in rings.iter().enumerate() {
            for c in r["children"].as_array().unwrap() {
                let child_first = position[c.as_u64().unwrap() as usize] < position[i];
                assert_eq!(child_first, !outside_in, "{order:?}");
            }
        }
        assert_eq!(if outside_in { order[0] } else { order[6] }, 0, "{order:?}");
        assert!(doc["uncut"].is_array() && doc["truncated"] == false);
        let drawing = medax::io::dxf::read_dxf(&std::fs::read_to_string(&dxf).unwrap()).unwrap();
        assert!(drawing.polylines.len() >= 10);
        assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn offset_vcarve_paths_and_flat_bottom() {
    let dir = scratch("vcarve");
    let shape = holed_square(&dir);
    let (stdout, [json, dxf, svg]) = run_offset(&shape, &["--vcarve", "90,0.3"], &dir, "v");
    assert!(stdout.contains("v-carve: ") && stdout.contains("flat bottom: 2 ring(s)"), "{stdout}");
    let doc = json_file(&json);
    assert_eq!(doc["angle_deg"].as_f64(), Some(90.0));
    // A 90° bit: depth = radius, capped at 0.3, where the corridor's
    // half-width 0.5 would go deeper.
    assert!((doc["flat_radius"].as_f64().unwrap() - 0.3).abs() < 1e-12);
    let paths = doc["paths"].as_array().unwrap();
    assert!(!paths.is_empty());
    for p in paths {
        for q in p.as_array().unwrap() {
            let depth = q[2].as_f64().unwrap();
            assert!((-1e-12..=0.3 + 1e-9).contains(&depth), "{q}");
        }
    }
    assert_eq!(loops_of(&doc["flat"]["loops"]).len(), 2);
    let text = std::fs::read_to_string(&dxf).unwrap();
    assert!(text.contains("POLYLINE\n  8\nVCARVE"), "3D tool paths");
    // Our 2D reader skips the 3D paths and reads the flat rings.
    assert_eq!(medax::io::dxf::read_dxf(&text).unwrap().polylines.len(), 2);
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn offset_bad_arguments_name_the_option() {
    let dir = scratch("offset-bad");
    let shape = holed_square(&dir);
    let cases: [(&[&str], &str); 9] = [
        (&[], "--distance"),
        (&["--distance", "1,abc"], "--distance"),
        (&["--distance=nan"], "--distance"),
        (&["--pocket", "1"], "--pocket"),
        (&["--pocket", "0,0.5"], "tool radius"),
        (&["--pocket", "1,-2"], "stepover"),
        (&["--vcarve", "180,1"], "--vcarve"),
        (&["--vcarve", "60,0"], "maximum depth"),
        (&["--distance", "1", "--outside-in"], "--outside-in"),
    ];
    for (args, named) in cases {
        let out = medax().arg("offset").arg(&shape).args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(named), "{args:?}: {err}");
    }
    let both = medax().arg("offset").arg(&shape).args(["--distance", "1", "--pocket", "1,1"]).output().unwrap();
    assert_eq!(both.status.code(), Some(2));
    // An invalid shape: exit 1 with the validation error.
    let bad = dir.join("bad.json");
    std::fs::write(&bad, r#"{"loops": [[[0, 0], [1, 1], [1, 0], [0, 1]]]}"#).unwrap();
    let out = medax().arg("offset").arg(&bad).args(["--distance", "0.1"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("intersect"));
    std::fs::remove_dir_all(&dir).ok();
}

/// Two parts side by side and a centre line, drawn as DXF LINEs.
fn two_part_drawing(dir: &Path) -> PathBuf {
    let line = |a: [f64; 2], b: [f64; 2]| {
        format!("0\nLINE\n8\nPART\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n", a[0], a[1], b[0], b[1])
    };
    let square = |x: f64, s: f64| {
        [[x, 0.0], [x + s, 0.0], [x + s, s], [x, s]]
            .iter()
            .zip([[x + s, 0.0], [x + s, s], [x, s], [x, 0.0]])
            .map(|(a, b)| line(*a, b))
            .collect::<String>()
    };
    let text = format!(
        "0\nSECTION\n2\nENTITIES\n{}{}{}0\nENDSEC\n0\nEOF\n",
        square(0.0, 4.0),
        square(10.0, 2.0),
        line([-1.0, 2.0], [5.0, 2.0])
    );
    let p = dir.join("parts.dxf");
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn a_drawing_of_two_parts_gives_two_shapes_and_says_what_it_ignored() {
    let dir = std::env::temp_dir().join(format!("medax-cli-parts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let drawing = two_part_drawing(&dir);
    let json = dir.join("parts.json");
    let out = medax().arg("info").arg(&drawing).arg("--json").arg(&json).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("2 shapes") && stdout.contains("ignored: 1 open chain"), "{stdout}");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(doc["shapes"].as_array().unwrap().len(), 2);
    assert_eq!(doc["ignored"][0]["kind"], "open_chain");
    assert_eq!(doc["ignored"][0]["layer"], "PART");
    // The other commands take one shape: the second with --shape 1.
    let axis = dir.join("axis.json");
    let out = medax().arg("axis").arg(&drawing).args(["--shape", "1", "--json"]).arg(&axis).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("2 shape(s)"));
    let out = medax().arg("axis").arg(&drawing).args(["--shape", "2"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    // Every shape in one run: a file per shape.
    let all = dir.join("all.json");
    let out = medax().arg("axis").arg(&drawing).args(["--shape", "all", "--json"]).arg(&all).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for k in 0..2 {
        let text = std::fs::read_to_string(dir.join(format!("all.{k}.json"))).unwrap();
        assert!(text.contains("\"edges\""), "{text}");
    }
    let rings = dir.join("rings.dxf");
    let out = medax()
        .arg("offset")
        .arg(&drawing)
        .args(["--shape", "all", "--pocket", "0.2,0.3", "--dxf"])
        .arg(&rings)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("rings.0.dxf").exists() && dir.join("rings.1.dxf").exists());
    let out = medax().arg("draw").arg(&drawing).args(["--shape", "all", "-o"]).arg(dir.join("x.svg")).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    // The drawing JSON that info wrote reads back as the same two shapes.
    let again = dir.join("again.json");
    let out = medax().arg("axis").arg(&json).args(["--shape", "1", "--json"]).arg(&again).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(&again).unwrap(), std::fs::read_to_string(&axis).unwrap());
    // The Voronoi diagram of the parts: each part a region site.
    let vd = dir.join("vd.json");
    let out = medax().arg("voronoi").arg(&drawing).arg("--json").arg(&vd).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("2 part(s) as region sites"));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&vd).unwrap()).unwrap();
    let between = doc["edges"].as_array().unwrap().iter().any(|e| {
        e["separates"] == serde_json::json!([{"region": 0}, {"region": 1}])
            || e["separates"] == serde_json::json!([{"region": 1}, {"region": 0}])
    });
    assert!(between, "no edge between the two parts");
    // Under --strict the drawing is refused whole, as before.
    let out = medax().arg("info").arg(&drawing).arg("--strict").output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn ball_describes_and_draws_a_unit_ball() {
    let dir = scratch("ball");
    let svg = dir.join("tri.svg");
    let out = medax().args(["ball", "triangle", "--svg"]).arg(&svg).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("3 vertices") && stdout.contains("not symmetric"), "{stdout}");
    assert!(std::fs::read_to_string(&svg).unwrap().matches("<path").count() == 2, "the ball and its mirror");
    let file = dir.join("square.json");
    std::fs::write(&file, r#"{"vertices": [[1, 1], [-1, 1], [-1, -1], [1, -1]]}"#).unwrap();
    let out = medax().arg("ball").arg(&file).output().unwrap();
    assert!(out.status.success() && String::from_utf8_lossy(&out.stdout).contains("symmetric: a metric"));
    let out = medax().args(["ball", r#"{"vertices": [[2, 0], [0, 2], [0.5, 0], [0, -2]]}"#]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("vertex 2"));
}

#[test]
fn axis_and_offsets_under_a_ball() {
    let dir = scratch("ball_axis");
    let shape = dir.join("l.json");
    // An L: under the square its axis is straight, under the triangle its
    // corners are pruned (pseudo-branchings).
    std::fs::write(&shape, r#"{"loops": [[[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 4, 0], [0, 4, 0]]]}"#)
        .unwrap();
    let (json, svg) = (dir.join("axis.json"), dir.join("axis.svg"));
    let out = medax()
        .arg("axis")
        .arg(&shape)
        .args(["--ball", "triangle", "--json"])
        .arg(&json)
        .arg("--svg")
        .arg(&svg)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("3-gon ball") && stdout.contains("pseudo-branch"), "{stdout}");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(doc["ball"]["vertices"].as_array().unwrap().len(), 3);
    let edges = doc["edges"].as_array().unwrap();
    assert!(!edges.is_empty());
    for e in edges {
        assert_eq!(e["kind"], "line");
        assert!(e["jump"].is_boolean());
        assert_eq!(e["samples"].as_array().unwrap().len(), 2);
        for s in e["sites"].as_array().unwrap() {
            assert!(["VE", "EV", "EE"].contains(&s["class"].as_str().unwrap()), "{s}");
        }
    }
    let kinds: Vec<&str> = doc["nodes"].as_array().unwrap().iter().map(|n| n["kind"].as_str().unwrap()).collect();
    assert!(kinds.contains(&"pseudo_branch"), "{kinds:?}");
    assert!(std::fs::read_to_string(&svg).unwrap().contains("jump edges"));
    let (oj, os) = (dir.join("off.json"), dir.join("off.svg"));
    let out = medax()
        .arg("offset")
        .arg(&shape)
        .args(["--ball", "square", "--distance", "0.25,0.45", "--json"])
        .arg(&oj)
        .arg("--svg")
        .arg(&os)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&oj).unwrap()).unwrap();
    // Under the square the tool is the square [−d, d]²: at 0.25 the L's
    // arms become 3.5 × 0.5 each, overlapping in 0.5 × 0.5: area 3.25.
    let area = doc["offsets"][0]["area"].as_f64().unwrap();
    assert!((area - 3.25).abs() < 1e-12, "area {area}");
    assert!(os.exists());
    // Outer offsets: the L grown by a diamond tool.
    let out = medax()
        .arg("offset")
        .arg(&shape)
        .args(["--ball", "diamond", "--distance=-0.2", "--json"])
        .arg(&oj)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&oj).unwrap()).unwrap();
    assert_eq!(doc["offsets"][0]["distance"].as_f64(), Some(-0.2));
    assert!(doc["offsets"][0]["area"].as_f64().unwrap() > 7.0);
    // Pockets, a bad ball and arcs are refused with a message.
    let out = medax().arg("offset").arg(&shape).args(["--ball", "square", "--pocket", "0.1,0.1"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = medax().arg("axis").arg(&shape).args(["--ball", r#"{"vertices": [[1, 0], [0, 1]]}"#]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let arc = dir.join("arc.json");
    std::fs::write(&arc, r#"{"loops": [[[0, 0, 0], [4, 0, 1], [4, 4, 0], [0, 4, 0]]]}"#).unwrap();
    let out = medax().arg("axis").arg(&arc).args(["--ball", "square"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is an arc"));
}

#[test]
fn voronoi_under_a_ball() {
    let dir = scratch("ball_voronoi");
    let sites = dir.join("sites.json");
    // Two points under the square: split by x = 1 (one edge or a few on
    // that line, the region beyond |y| = 1 where they tie given to one).
    std::fs::write(&sites, r#"{"points": [[0, 0], [2, 0]], "curves": [[[0, 3, 0], [2, 3, 0]]]}"#).unwrap();
    let (json, svg) = (dir.join("vd.json"), dir.join("vd.svg"));
    let out = medax()
        .arg("voronoi")
        .arg(&sites)
        .args(["--ball", "square", "--json"])
        .arg(&json)
        .arg("--svg")
        .arg(&svg)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("4-gon ball") && stdout.contains("3 sites"), "{stdout}");
    // The picture: the sites, a ball at the vertex, the edges between sites.
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.contains("under a 4-gon ball: 3 sites"), "{picture}");
    assert!(picture.matches("<path").count() >= 4, "{picture}");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let edges = doc["edges"].as_array().unwrap();
    let nodes = doc["nodes"].as_array().unwrap();
    let between: Vec<&serde_json::Value> = edges
        .iter()
        .filter(|e| e["sides"].as_array().unwrap().iter().all(|s| s == "point 0" || s == "point 1"))
        .collect();
    assert!(!between.is_empty(), "{doc}");
    for e in &between {
        for s in e["samples"].as_array().unwrap() {
            let (x, y, r) = (s[0].as_f64().unwrap(), s[1].as_f64().unwrap(), s[2].as_f64().unwrap());
            // Both points at the radius (L∞); on the line x = 1 where |y| < 1.
            assert!((x.abs().max(y.abs()) - r).abs() < 1e-12 && ((x - 2.0).abs().max(y.abs()) - r).abs() < 1e-12);
            assert!(y.abs() >= 1.0 || (x - 1.0).abs() < 1e-12, "{e}");
        }
        assert!(e["from"].as_u64().unwrap() < nodes.len() as u64);
    }
    assert!(nodes.iter().any(|n| n["frontier"] == true));
    // Arcs are refused, naming the site.
    std::fs::write(&sites, r#"{"points": [[0, 0]], "curves": [[[0, 3, 0.5], [2, 3, 0]]]}"#).unwrap();
    let out = medax().arg("voronoi").arg(&sites).args(["--ball", "square"]).output().unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("curve site 0: element 0 is an arc"));
}

/// `medax info` on solids: the report of a box with a cavity written as
/// OFF (triangles) and a binary STL, and the typed error of an open box
/// with exit code 1.
#[test]
fn info_reports_solids_and_their_errors() {
    use medax::shape::mesh_samples::{cuboid, union};
    let dir = scratch("info_mesh");
    let (v, t) = union(&[cuboid([0.0; 3], [4.0; 3]), cuboid([1.0; 3], [2.0; 3])]);
    let off = dir.join("cavity.off");
    std::fs::write(&off, medax::io::mesh::write_off(&v, &t)).unwrap();
    let out = medax().arg("info").arg(&off).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("valid solid: 2 component(s) (1 cavity)"), "{text}");
    assert!(text.contains("volume: 63"), "{text}");
    assert!(text.contains("components reversed to face out of the material: 1"), "{text}");
    // Binary STL: 50 bytes per facet, corners unshared: welded.
    let mut stl = vec![0u8; 80];
    stl.extend((t.len() as u32).to_le_bytes());
    for tri in &t {
        stl.extend([0u8; 12]);
        for &i in tri {
            for c in v[i as usize] {
                stl.extend((c as f32).to_le_bytes());
            }
        }
        stl.extend([0u8; 2]);
    }
    let stl_path = dir.join("cavity.stl");
    std::fs::write(&stl_path, &stl).unwrap();
    let out = medax().arg("info").arg(&stl_path).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("vertices welded onto an equal one: 56"), "{text}");
    // Converted to PLY and back: the same report.
    let ply = dir.join("cavity.ply");
    let out = medax().arg("convert").arg(&stl_path).arg(&ply).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let back = medax().arg("info").arg(&ply).output().unwrap();
    let back = String::from_utf8_lossy(&back.stdout);
    assert!(back.contains("valid solid: 2 component(s) (1 cavity)") && back.contains("volume: 63"), "{back}");
    // Open: the last face dropped.
    let open = dir.join("open.off");
    std::fs::write(&open, medax::io::mesh::write_off(&v, &t[..t.len() - 1])).unwrap();
    let out = medax().arg("info").arg(&open).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("open there") && err.contains("line"), "{err}");
}

/// `medax query3d`: sides, distances and the largest octahedron ball in a
/// box, as JSON; a bad ball name exits 2.
#[test]
fn query3d_answers_points_as_json() {
    use medax::shape::mesh_samples::cuboid;
    let dir = scratch("query3d");
    let (v, t) = cuboid([0.0; 3], [4.0, 4.0, 2.0]);
    let off = dir.join("box.off");
    std::fs::write(&off, medax::io::mesh::write_off(&v, &t)).unwrap();
    let pts = dir.join("points.json");
    std::fs::write(&pts, r#"{"points": [[1, 1, 1], [5, 1, 1], [2, 2, 0.5]]}"#).unwrap();
    let out_json = dir.join("out.json");
    let query = |extra: &[&str]| {
        let out = medax()
            .args(["query3d"])
            .arg(&off)
            .args(["--ball", "octa"])
            .args(extra)
            .arg("--points")
            .arg(&pts)
            .arg("--json")
            .arg(&out_json)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&out_json).unwrap()).unwrap()
    };
    let doc = query(&[]);
    let r = doc["results"].as_array().unwrap();
    assert_eq!(r.len(), 3);
    assert_eq!(
        (r[0]["inside"].as_bool(), r[0]["distance"].as_f64(), r[0]["ball_radius"].as_f64()),
        (Some(true), Some(1.0), Some(1.0))
    );
    assert_eq!((r[1]["inside"].as_bool(), r[1]["distance"].as_f64()), (Some(false), Some(1.0)));
    assert!(r[1].get("ball_radius").is_none());
    assert_eq!(r[2]["ball_radius"].as_f64(), Some(0.5));
    let bad = medax().args(["query3d"]).arg(&off).args(["--ball", "dodeca", "--points"]).arg(&pts).output().unwrap();
    assert_eq!(bad.status.code(), Some(2));
    // --exact lists every contact: at (1, 1, 1) the octahedron touches the
    // floor z = 0, the ceiling z = 2 and the walls x = 0 and y = 0, each
    // with a vertex; floor and ceiling where their triangles' diagonals
    // run (VE), the walls inside a triangle (VF).
    let doc = query(&["--exact"]);
    let first = &doc["results"][0];
    assert_eq!(first["ball_radius"].as_f64(), Some(1.0));
    let contacts = first["contacts"].as_array().unwrap();
    assert_eq!(contacts.len(), 4, "{contacts:?}");
    let kinds: Vec<&str> = contacts.iter().map(|c| c["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds.iter().filter(|&&k| k == "VE").count(), 2, "{contacts:?}");
    assert!(contacts.iter().all(|c| c["ball"]["vertex"].is_u64() && c["flat"] == serde_json::json!(false)));
    let on_walls: Vec<[f64; 3]> = contacts
        .iter()
        .map(|c| {
            let p = c["point"].as_array().unwrap();
            [0, 1, 2].map(|k| p[k].as_f64().unwrap())
        })
        .collect();
    for want in [[0.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 0.0], [1.0, 1.0, 2.0]] {
        assert!(on_walls.contains(&want), "{on_walls:?}");
    }
    // --exact without --ball is a usage error.
    let lone = medax().args(["query3d"]).arg(&off).args(["--exact", "--points"]).arg(&pts).output().unwrap();
    assert_eq!(lone.status.code(), Some(2));
}

/// `medax axis3d`: the axis of a perturbed octahedron under the
/// tetrahedron as JSON (every triangle in one sheet, radii positive),
/// OBJ and PLY with radii; a sheared L prism's EE sheets and picture; a box with a
/// cavity's FV sheets; a turned cube on the prism exits 1 naming a facet.
#[test]
fn axis3d_writes_the_axis_of_a_convex_solid() {
    let dir = scratch("axis3d");
    let v = [
        [3.05, 0.02, -0.04],
        [-2.97, 0.05, 0.03],
        [0.04, 3.02, 0.01],
        [-0.03, -2.96, 0.05],
        [0.02, -0.05, 3.04],
        [0.01, 0.03, -2.98],
    ];
    let t = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]];
    let off = dir.join("octahedron.off");
    std::fs::write(&off, medax::io::mesh::write_off(&v, &t)).unwrap();
    let (json, obj, ply) = (dir.join("axis.json"), dir.join("axis.obj"), dir.join("axis.ply"));
    let out = medax()
        .arg("axis3d")
        .arg(&off)
        .args(["--ball", "tetra", "--json"])
        .arg(&json)
        .arg("--obj")
        .arg(&obj)
        .arg("--ply")
        .arg(&ply)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let vertices = doc["vertices"].as_array().unwrap();
    let triangles = doc["triangles"].as_array().unwrap();
    assert!(!triangles.is_empty());
    assert!(vertices.iter().all(|q| q.as_array().unwrap().len() == 4 && q[3].as_f64().unwrap() > 0.0));
    let mut seen = vec![0; triangles.len()];
    for s in doc["sheets"].as_array().unwrap() {
        assert_eq!(s["kind"], "sheet");
        assert_eq!(s["classes"].as_array().unwrap().len(), 2);
        for t in s["triangles"].as_array().unwrap() {
            seen[t.as_u64().unwrap() as usize] += 1;
        }
    }
    assert!(seen.iter().all(|&n| n == 1), "every triangle in exactly one sheet");
    let obj_text = std::fs::read_to_string(&obj).unwrap();
    assert_eq!(obj_text.lines().filter(|l| l.starts_with("v ")).count(), vertices.len());
    let ply_text = std::fs::read_to_string(&ply).unwrap();
    assert!(
        ply_text.contains("property double radius") && ply_text.contains(&format!("element face {}", triangles.len()))
    );
    // A sheared L-shaped prism has a reflex edge: sheets of EE classes
    // (a ball edge sliding along it) appear.
    let l = dir.join("l.off");
    let (pv, pt) = solids::l_prism(1.3, 1.0);
    std::fs::write(&l, medax::io::mesh::write_off(&pv, &pt)).unwrap();
    let svg = dir.join("l.svg");
    let out = medax()
        .arg("axis3d")
        .arg(&l)
        .args(["--ball", "tetra", "--json"])
        .arg(&json)
        .arg("--svg")
        .arg(&svg)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // The picture: one filled path per axis triangle, over the outline.
    let picture = std::fs::read_to_string(&svg).unwrap();
    let filled = picture.matches("<path").count();
    let n_tri = serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&json).unwrap()).unwrap()
        ["triangles"]
        .as_array()
        .unwrap()
        .len();
    assert!(picture.contains("<svg"), "not an SVG");
    assert!(filled > n_tri && picture.contains("medial axis:"), "{filled} paths for {n_tri} triangles");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let ee = doc["sheets"].as_array().unwrap().iter().flat_map(|s| s["classes"].as_array().unwrap().clone());
    let ee: Vec<_> = ee.filter(|c| c["kind"] == "EE").collect();
    assert!(!ee.is_empty() && ee.iter().all(|c| c["ball"]["edge"].is_u64() && c["surface"]["edge"].is_array()));
    // A box with a box-shaped cavity: a ball facet rests on the cavity's
    // corners (FV classes).
    let outer = medax::shape::mesh_samples::cuboid([-6.0, -6.0, -6.0], [6.0, 6.0, 6.0]);
    let inner = medax::shape::mesh_samples::cuboid([-2.0, -2.5, -3.0], [3.0, 2.0, 1.5]);
    let inner = (inner.0, inner.1.iter().map(|t| [t[0], t[2], t[1]]).collect::<Vec<_>>());
    let (cv, ct) = medax::shape::mesh_samples::union(&[outer, inner]);
    let cavity = dir.join("cavity.off");
    std::fs::write(&cavity, medax::io::mesh::write_off(&cv, &ct)).unwrap();
    let out = medax()
        .arg("axis3d")
        .arg(&cavity)
        .args(["--ball", "tetra@0.2,0.4,-0.3", "--json"])
        .arg(&json)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let fv = doc["sheets"].as_array().unwrap().iter().flat_map(|s| s["classes"].as_array().unwrap().clone());
    let fv: Vec<_> = fv.filter(|c| c["kind"] == "FV").collect();
    assert!(!fv.is_empty() && fv.iter().all(|c| c["ball"]["facet"].is_u64() && c["surface"]["vertex"].is_u64()));
    // A turned cube's squares are not exactly planar: refused with the
    // L prism's reflex edge, exit 1 naming the facet.
    let out = medax().arg("axis3d").arg(&l).args(["--ball", "cube@0.3,-0.5,0.2"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("facet") && err.contains("planar"), "{err}");
}
