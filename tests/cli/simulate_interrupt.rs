//! A long `simulate` can be cancelled: Ctrl-C (SIGINT) stops the run after
//! the step it is in, the output written so far stays one document (the
//! JSON closed, `stopped` saying so), and the exit code is 1. On a pipe
//! nothing but the error is written to stderr (no progress bar).

#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_long_run_cleanly() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let dir = crate::common::scratch("simulate-interrupt");
    let out_path = dir.join("run.json");
    let out = std::fs::File::create(&out_path).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["simulate", "ball-drop", "--steps", "10000000"])
        .args(["--format", "json", "--every", "100000"])
        .stdout(out)
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    // Ten million steps take minutes: it is well inside the run by now.
    std::thread::sleep(Duration::from_millis(1500));
    // SAFETY: sending a signal to a child process this test started.
    let sent = unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) };
    assert_eq!(sent, 0);
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "still running 10 s after Ctrl-C"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    assert_eq!(status.code(), Some(1), "{stderr}");
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
