//! A long `simulate` can be cancelled: Ctrl-C (SIGINT) stops the run after
//! the step it is in, the output written so far stays one document (the
//! JSON closed, `stopped` saying so), and the exit code is 1. On a pipe
//! nothing but the error is written to stderr (no progress bar).

#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_long_run_cleanly() {
    use std::process::{Command, Stdio};
    use std::time::Duration;
    let dir = crate::common::scratch("simulate-interrupt");
    let out_path = dir.join("run.json");
    let out = std::fs::File::create(&out_path).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["simulate", "ball-drop", "--steps", "10000000"])
        .args(["--format", "json", "--every", "100000"])
        .stdout(out)
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    // Ten million steps take minutes: it is well inside the run by then.
    let (code, stderr) = crate::common::cli::interrupt(child, Duration::from_millis(1500));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.starts_with("error: ball-drop: interrupted (Ctrl-C) after step "),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    let text = std::fs::read_to_string(&out_path).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).expect("one JSON document");
    let stopped = json["stopped"].as_str().expect("stopped");
    assert!(stopped.contains("interrupted (Ctrl-C)"), "{stopped}");
    assert!(json["steps"].as_array().is_some_and(|s| !s.is_empty()));
}

/// One step of 100 coincident spheres takes a second in a release build and
/// far longer in a debug one (1,000 took over 15 minutes a step): Ctrl-C
/// inside the step ends the resolution there (it polls every 1,024
/// iterations), the cut step is not written, and the run stops as above.
#[cfg(unix)]
#[test]
fn ctrl_c_inside_a_long_step_ends_it() {
    use std::process::{Command, Stdio};
    use std::time::Duration;
    let pile = crate::common::pile::coincident("simulate-interrupt", 100);
    let dir = crate::common::scratch("simulate-interrupt-step");
    let out_path = dir.join("run.json");
    let out = std::fs::File::create(&out_path).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .arg("simulate")
        .arg(&pile)
        .args(["--steps", "1", "--format", "json"])
        .stdout(out)
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    // The helper fails if it is still running 10 s after Ctrl-C.
    let (code, stderr) = crate::common::cli::interrupt(child, Duration::from_millis(1500));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.starts_with("error: pile-100: interrupted (Ctrl-C) after step 0 of 1"),
        "{stderr}"
    );
    let text = std::fs::read_to_string(&out_path).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).expect("one JSON document");
    // Only the state before the first step: the cut step is not written.
    assert_eq!(json["steps"].as_array().map(Vec::len), Some(1), "{text}");
}
