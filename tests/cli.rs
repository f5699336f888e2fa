//! The `medax` binary: the axis of a shape with a hole through the CLI
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
