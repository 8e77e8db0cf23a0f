//! `shoal-lab` from the outside (issue 16): the same CSV bytes on one thread and
//! on two, shards that merge to them, and bad input refused in one line naming
//! the field, with exit code 2.

#![cfg(not(target_arch = "wasm32"))]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_shoal-lab");

/// Two levels of alignment × two seeds, ten fish, one simulated second.
const TINY: &str = r#"{
  "name": "cli-tiny",
  "settings": {"scene": "boids", "left": {"preset": "group", "fish_count": 10}},
  "factors": [{"key": "left.alignment", "levels": [10, 90]}],
  "replicates": {"count": 2, "first_seed": 3},
  "warmup_secs": 0.25,
  "measure_secs": 0.75,
  "measures": [{"measure": "polarization"}, {"measure": "groups", "summary": "series"}]
}"#;

/// A fresh folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("shoal-lab-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    dir
}

fn shoal_lab(args: &[&Path]) -> Output {
    Command::new(BIN)
        .args(args)
        .output()
        .expect("shoal-lab starts")
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).expect("the CSV was written")
}

#[test]
fn one_thread_two_threads_and_merged_shards_write_the_same_bytes() {
    let dir = folder("same");
    let design = dir.join("tiny.json");
    std::fs::write(&design, TINY).unwrap();
    let run = |extra: &[&str], out: &str| {
        let out = dir.join(out);
        let mut args: Vec<&Path> = vec![design.as_path()];
        args.extend(extra.iter().map(Path::new));
        args.push(Path::new("--out"));
        args.push(&out);
        let output = shoal_lab(&args);
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        out
    };
    let one = text(&run(&["--threads", "1"], "one.csv"));
    let two = text(&run(&["--threads", "2"], "two.csv"));
    assert_eq!(one, two, "the thread count does not change the file");
    assert!(one.starts_with("# Shoal experiment: cli-tiny\n"));
    assert!(one.contains("\n3,4,90.0,polarization,mean,,"), "{one}");
    let a = run(&["--shard", "0/2", "--threads", "1"], "a.csv");
    let b = run(&["--shard", "1/2", "--threads", "2"], "b.csv");
    let all = dir.join("all.csv");
    let output = shoal_lab(&[
        Path::new("merge"),
        &b,
        &a,
        Path::new("--out"),
        all.as_path(),
    ]);
    assert!(output.status.success());
    assert_eq!(text(&all), one, "merged shards give the same file");
    // A missing shard: exit code 2, the missing runs named.
    let output = shoal_lab(&[Path::new("merge"), &a]);
    assert_eq!(output.status.code(), Some(2));
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(err.contains("run(s) 1, 3 are in no file"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_bad_file_is_refused_in_one_line_naming_the_field_with_exit_code_2() {
    let dir = folder("bad");
    for (from, to, field) in [
        ("left.alignment", "left.alignmnt", "factors[0].key"),
        ("[10, 90]", "[10, 190]", "factors[0].levels[1]"),
        ("\"count\": 2", "\"count\": 0", "replicates.count"),
        ("\"groups\"", "\"spawnings\"", "measures[1].measure"),
        (
            "\"measure_secs\": 0.75",
            "\"measure_secs\": 0",
            "measure_secs",
        ),
    ] {
        let design = dir.join("bad.json");
        std::fs::write(&design, TINY.replace(from, to)).unwrap();
        let output = shoal_lab(&[design.as_path()]);
        assert_eq!(output.status.code(), Some(2), "{to}");
        let err = String::from_utf8_lossy(&output.stderr);
        assert_eq!(err.lines().count(), 1, "one line: {err}");
        assert!(err.contains(&format!("{field}: ")), "{to}: {err}");
        assert!(output.stdout.is_empty(), "no CSV for a bad design");
    }
    let output = shoal_lab(&[Path::new("no-such-file.json")]);
    assert_eq!(output.status.code(), Some(2));
    let output = shoal_lab(&[Path::new("--shard"), Path::new("2/2")]);
    assert_eq!(output.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}
