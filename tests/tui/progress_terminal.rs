//! Progress on a real (pseudo-)terminal: `advise` draws its bar of stages
//! and finishes. The bar's ticking thread draws on standard error; with the
//! error stream locked for the whole command it waited for the lock while
//! holding the bar, and the command's next update waited for the bar: a
//! deadlock at the first tick, on a terminal only (a pipe hides the bar).
//! `timeout` turns a hang into a failure rather than a stuck test.

use std::process::Command;

#[test]
fn advise_shows_its_progress_on_a_terminal_and_finishes() {
    if Command::new("script").arg("--version").output().is_err() {
        println!("skipped: `script` (util-linux) is not installed");
        return;
    }
    let bin = env!("CARGO_BIN_EXE_contact-lab");
    let shell = format!(
        "stty cols 100 rows 30; timeout 300 {bin} advise ball-drop --error 0.01 --seconds 0.5 > /dev/null; echo \"status=$?\""
    );
    let out = Command::new("script")
        .args(["-q", "-e", "-c", &shell, "/dev/null"])
        .env("TERM", "xterm-256color")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("stages ·"),
        "the bar of stages was drawn:\n{text}"
    );
    assert!(
        text.contains("status=0"),
        "advise finished (124: it hung until the timeout):\n{text}"
    );
}
