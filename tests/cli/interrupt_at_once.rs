//! `detect` and `resolve` write their output only at the end, so Ctrl-C
//! (SIGINT) ends them at once with exit code 130 (a killed process has no
//! exit code: the handler makes it 130, as a shell reports it). On a pipe
//! they draw no progress: stderr stays empty.

/// Runs `args` from the repository root, sends SIGINT after 1.5 s, and
/// returns the exit code and stderr.
#[cfg(unix)]
fn interrupted(args: &[&std::ffi::OsStr]) -> (Option<i32>, String) {
    use std::process::{Command, Stdio};
    let child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    // Each run takes far longer (minutes in a debug build): it is well
    // inside its work by then.
    crate::common::cli::interrupt(child, std::time::Duration::from_millis(1500))
}

#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_long_detect_with_130() {
    // 300 coincident spheres: 45,150 pairs through GJK and EPA.
    let pile = crate::common::pile::coincident("interrupt", 300);
    let (code, stderr) = interrupted(&["detect".as_ref(), pile.as_os_str()]);
    assert_eq!(code, Some(130), "{stderr}");
    assert_eq!(stderr, "", "no progress on a pipe");
}

/// A lesson of `n` contacts between a box and a floor, each 5 cm deep.
fn many_contacts(n: usize) -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join(format!("interrupt-contacts-{n}.toml"));
    let mut s = String::from(
        "id = \"many-contacts\"\ntitle = \"many contacts\"\n\n[[body]]\nname = \"b\"\nmass = 1.0\nshape = { box = [2, 1, 2] }\nposition = [0, 0.45, 0]\nvelocity = [0, -1, 0]\n\n[[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nposition = [0, 0, 0]\n",
    );
    for k in 0..n {
        let (x, z) = (
            (k % 100) as f64 / 50.0 - 1.0,
            (k / 100) as f64 / 100.0 - 1.0,
        );
        s.push_str(&format!(
            "\n[[contact]]\nbodies = [\"b\", \"floor\"]\npoint = [{x}, -0.05, {z}]\nnormal = [0.0, 1.0, 0.0]\npenetration = 0.05\nrestitution = 0.5\nfriction = 0.5\n"
        ));
    }
    std::fs::write(&path, s).unwrap();
    path
}

#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_long_resolve_with_130() {
    let lesson = many_contacts(20_000);
    let (code, stderr) = interrupted(&["resolve".as_ref(), lesson.as_os_str()]);
    assert_eq!(code, Some(130), "{stderr}");
    // The table's note may be said; never a progress line.
    assert!(
        stderr
            .lines()
            .all(|l| l.starts_with("note: ") || l.starts_with("warning: ")),
        "{stderr}"
    );
}
