//! The `medax` binary: the axis of a shape with a hole and a Voronoi diagram through the CLI
//! (JSON contract: one cycle per hole), and a closed stdout is not a crash.

use std::process::{Command, Stdio};

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
