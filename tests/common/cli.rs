//! The binary run as a user runs it: from the repository's root, its exit
//! code and both streams as text.

use assert_cmd::Command;

/// `contact-lab`, started in the repository's root.
pub fn contact_lab() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_contact-lab"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

/// What one run gave.
pub struct Run {
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `contact-lab ARGS`.
pub fn run(args: &[&str]) -> Run {
    let out = contact_lab().args(args).output().expect("contact-lab runs");
    Run {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Sends SIGINT to `child` after `after`, waits at most 10 s for it to end,
/// and returns its exit code and stderr (which must be piped). `child` must
/// still be running when the signal goes.
#[cfg(unix)]
pub fn interrupt(
    mut child: std::process::Child,
    after: std::time::Duration,
) -> (Option<i32>, String) {
    use std::time::{Duration, Instant};
    std::thread::sleep(after);
    assert!(child.try_wait().unwrap().is_none(), "still running");
    // SAFETY: sending a signal to a child process the test started.
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
    (status.code(), stderr)
}
