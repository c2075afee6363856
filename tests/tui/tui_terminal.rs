//! In a real (pseudo-)terminal: a panic inside the app, and the signals that
//! end a program (SIGTERM, SIGHUP), restore the terminal. A test build
//! panics after its first frame when CONTACT_LAB_TEST_PANIC is set; the
//! signals are sent by the shell; `script` gives the app a terminal, and
//! `stty -a` run afterwards in the same terminal shows whether raw mode was
//! undone, and the escape codes whether mouse reports were switched off.

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
    assert_mouse_off(&text, "panic");
    assert_cursor_shown(&text, "panic");
}

/// Mouse reports (`?1000h`) were switched on, and off (`?1000l`) after.
fn assert_mouse_off(text: &str, case: &str) {
    let on = text
        .find("\x1b[?1000h")
        .unwrap_or_else(|| panic!("{case}: mouse reports switched on"));
    let off = text
        .rfind("\x1b[?1000l")
        .unwrap_or_else(|| panic!("{case}: mouse reports switched off"));
    assert!(off > on, "{case}: switched off after on");
}

/// The app in a pseudo-terminal, sent `signal` a second after it starts;
/// returns everything the terminal showed (the app's output, the exit
/// status the shell saw, then `stty -a`).
fn run_and_signal(signal: &str, lesson: &str) -> Option<String> {
    if Command::new("script").arg("--version").output().is_err() {
        println!("skipped: `script` (util-linux) is not installed");
        return None;
    }
    let bin = env!("CARGO_BIN_EXE_contact-lab");
    // In `sh -c` a background job's stdin is /dev/null unless redirected.
    let shell = format!(
        "stty cols 100 rows 30; {bin} tui {lesson} </dev/tty & pid=$!; sleep 1; kill -{signal} $pid; wait $pid; echo \"status=$?\"; stty -a"
    );
    let out = Command::new("script")
        .args(["-q", "-e", "-c", &shell, "/dev/null"])
        .env("TERM", "xterm-256color")
        .env("COLUMNS", "100")
        .env("LINES", "30")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script runs");
    Some(String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr))
}

fn assert_restored(text: &str, signal: &str, number: i32) {
    let entered = text
        .find("\x1b[?1049h")
        .unwrap_or_else(|| panic!("{signal}: the app entered the alternate screen:\n{text}"));
    let left = text
        .rfind("\x1b[?1049l")
        .unwrap_or_else(|| panic!("{signal}: the alternate screen was left:\n{text}"));
    assert!(left > entered, "{signal}: left after entering");
    // The app died of the signal itself, as its parent expects: 128 + n.
    assert!(
        text.contains(&format!("status={}", 128 + number)),
        "{signal}: exit status 128 + {number}:\n{text}"
    );
    let stty = &text[text.rfind("speed").expect("stty -a printed the settings")..];
    assert!(
        stty.contains(" icanon") && !stty.contains("-icanon"),
        "{signal}: canonical mode restored:\n{stty}"
    );
    assert!(
        stty.contains(" echo ") && !stty.contains("-echo "),
        "{signal}: echo restored:\n{stty}"
    );
    assert_mouse_off(text, signal);
    assert_cursor_shown(text, signal);
}

/// The frames hid the cursor (`?25l`); it was shown again (`?25h`) after.
fn assert_cursor_shown(text: &str, case: &str) {
    let hidden = text
        .rfind("\x1b[?25l")
        .unwrap_or_else(|| panic!("{case}: the frames hid the cursor"));
    let shown = text
        .rfind("\x1b[?25h")
        .unwrap_or_else(|| panic!("{case}: the cursor was never shown again"));
    assert!(
        shown > hidden,
        "{case}: the cursor shown after it was last hidden"
    );
}

#[test]
fn sigint_restores_the_terminal_and_shows_the_cursor() {
    if let Some(text) = run_and_signal("INT", "lecture-2") {
        assert_restored(&text, "SIGINT", 2);
    }
}

#[test]
fn sigquit_restores_the_terminal_and_shows_the_cursor() {
    if let Some(text) = run_and_signal("QUIT", "stack-5") {
        assert_restored(&text, "SIGQUIT", 3);
    }
}

#[test]
fn sigterm_restores_the_terminal() {
    if let Some(text) = run_and_signal("TERM", "lecture-2") {
        assert_restored(&text, "SIGTERM", 15);
    }
}

#[test]
fn sigterm_on_a_scenes_run_restores_the_terminal() {
    if let Some(text) = run_and_signal("TERM", "stack-5") {
        assert!(
            text.contains("stack-5") && text.contains("paused"),
            "the run screen showed"
        );
        assert_restored(&text, "SIGTERM", 15);
    }
}

#[test]
fn sighup_restores_the_terminal() {
    if let Some(text) = run_and_signal("HUP", "lecture-2") {
        assert_restored(&text, "SIGHUP", 1);
    }
}

/// The state letter of process `pid` (`None` once it is gone; `Z` a zombie
/// nobody has reaped yet, which has ended too).
fn state(pid: &str) -> Option<char> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    stat.rsplit(')').next()?.trim().chars().next()
}

#[test]
fn a_terminal_that_hangs_up_ends_the_app() {
    if Command::new("script").arg("--version").output().is_err() {
        println!("skipped: `script` (util-linux) is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let pidfile = dir.path().join("app.pid");
    let bin = env!("CARGO_BIN_EXE_contact-lab");
    // The app is the terminal's session leader; killing `script` closes the
    // terminal under it (the kernel sends SIGHUP), as closing a window does.
    let mut script = Command::new("script")
        .args([
            "-q",
            "-e",
            "-c",
            &format!(
                "stty cols 100 rows 30; echo $$ > {}; exec {bin} tui stack-5",
                pidfile.display()
            ),
            "/dev/null",
        ])
        .env("TERM", "xterm-256color")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("script runs");
    let mut pid = String::new();
    for _ in 0..100 {
        pid = std::fs::read_to_string(&pidfile)
            .unwrap_or_default()
            .trim()
            .to_string();
        if !pid.is_empty() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    assert!(!pid.is_empty(), "the app started");
    std::thread::sleep(std::time::Duration::from_secs(1));
    script.kill().unwrap();
    let _ = script.wait();
    // The app must end (a stuck terminal read once kept it spinning forever).
    let mut ended = false;
    for _ in 0..200 {
        if matches!(state(&pid), None | Some('Z') | Some('X')) {
            ended = true;
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    if !ended {
        let _ = Command::new("kill").args(["-KILL", &pid]).status();
    }
    assert!(ended, "the app ended after its terminal hung up");
}
