//! `simulate` streams its output (issue 23, item 5): the first steps are
//! written while the run goes on, with memory flat in the number of steps,
//! and the JSON stays one document.

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Peak resident memory of process `pid` in KiB (`VmHWM`).
fn peak_kib(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

#[test]
fn a_ten_million_step_run_writes_its_first_steps_at_once_in_little_memory() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "simulate",
            "ball-drop",
            "--steps",
            "10000000",
            "--format",
            "json",
        ])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("contact-lab runs");
    let mut stdout = child.stdout.take().unwrap();
    let start = Instant::now();
    let mut seen = Vec::new();
    let mut buf = [0u8; 1 << 16];
    // Step 3000 written means the run is streamed (all of it kept first
    // would write nothing for 10 million steps).
    let reached = loop {
        if start.elapsed() > Duration::from_secs(120) {
            break false;
        }
        let n = stdout.read(&mut buf).unwrap();
        if n == 0 {
            break false;
        }
        seen.extend_from_slice(&buf[..n]);
        let tail =
            String::from_utf8_lossy(&seen[seen.len().saturating_sub(200_000)..]).into_owned();
        if tail.contains("\"step\": 3000,") {
            break true;
        }
        if seen.len() > 50_000_000 {
            seen.drain(..seen.len() - 200_000);
        }
    };
    let peak = peak_kib(child.id());
    let _ = child.kill();
    let _ = child.wait();
    assert!(reached, "step 3000 was written while the run went on");
    let text = String::from_utf8_lossy(&seen[..200.min(seen.len())]).into_owned();
    assert!(
        text.starts_with("{\n  \"lesson\": \"ball-drop\",\n  \"dt\": 0.001,\n  \"steps\": [\n    {\n      \"step\": 0,"),
        "{text}"
    );
    if let Some(kib) = peak {
        assert!(
            kib < 200_000,
            "peak memory {kib} KiB after 3000 of 10 million steps"
        );
    }
}

#[test]
fn streamed_json_is_one_document_with_every_step() {
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "simulate",
            "ball-drop",
            "--steps",
            "1200",
            "--every",
            "100",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    let steps: Vec<u64> = doc["steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["step"].as_u64().unwrap())
        .collect();
    assert_eq!(steps, (0..=12).map(|k| k * 100).collect::<Vec<_>>());
    assert!(!doc["events"].as_array().unwrap().is_empty(), "the bounces");
}
