//! In a real (pseudo-)terminal: a panic inside the app restores the terminal.
//! A test build panics after its first frame when CONTACT_LAB_TEST_PANIC is
//! set; `script` gives the app a terminal, and `stty -a` run afterwards in
//! the same terminal shows whether raw mode was undone.

use std::process::Command;

#[test]
fn a_panic_inside_the_app_restores_the_terminal() {
    if Command::new("script").arg("--version").output().is_err() {
        println!(
            "skipped: `script` (util-linux) is not installed, so no pseudo-terminal can be made"
        );
        return;
    }
    let bin = env!("CARGO_BIN_EXE_contact-lab");
    let out = Command::new("script")
        .args([
            "-q",
            "-e",
            "-c",
            &format!("{bin} tui lecture-2; stty -a"),
            "/dev/null",
        ])
        .env("CONTACT_LAB_TEST_PANIC", "1")
        .env("TERM", "xterm-256color")
        .env("COLUMNS", "100")
        .env("LINES", "30")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script runs");
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    let entered = text
        .find("\x1b[?1049h")
        .expect("the app entered the alternate screen");
    let left = text
        .rfind("\x1b[?1049l")
        .expect("the alternate screen was left");
    assert!(
        left > entered,
        "left the alternate screen after entering it"
    );
    let panicked = text
        .find("CONTACT_LAB_TEST_PANIC")
        .expect("the deliberate panic happened");
    assert!(panicked > entered);
    // stty ran after the app: the terminal is back in cooked mode with echo.
    let stty = &text[text.rfind("speed").expect("stty -a printed the settings")..];
    assert!(
        stty.contains(" icanon") && !stty.contains("-icanon"),
        "canonical mode restored:\n{stty}"
    );
    assert!(
        stty.contains(" echo ") && !stty.contains("-echo "),
        "echo restored:\n{stty}"
    );
}
