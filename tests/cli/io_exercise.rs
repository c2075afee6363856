//! `exercise --grade` reads its answer file by the lesson loader's rules
//! (issue 23, item 6): a regular file only (never a device or a FIFO), a
//! size limit, control characters escaped wherever the file is echoed,
//! extra `[[exercise]]` tables and nested arrays refused; and `exercise -o`
//! onto a directory or a symbolic link writes no figure beside it (item 8).

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("io-exercise-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs contact-lab and kills it after 20 s: a read that blocks must fail
/// the test, not hang it.
fn run(args: &[&std::ffi::OsStr]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(20) {
            child.kill().unwrap();
            panic!("contact-lab {args:?} hung");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

fn grade(path: &Path) -> (Option<i32>, String, String) {
    let out = run(&["exercise".as_ref(), "--grade".as_ref(), path.as_os_str()]);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn has_control(s: &str) -> bool {
    s.chars()
        .any(|c| (c.is_control() && c != '\n') || ('\u{202a}'..='\u{202e}').contains(&c))
}

#[test]
fn a_device_is_refused_at_once() {
    let (code, out, err) = grade(Path::new("/dev/zero"));
    assert_eq!(code, Some(1), "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("/dev/zero: it is a character device, not an answer file"),
        "{err}"
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_blocking() {
    let d = scratch("fifo");
    let fifo = d.join("answers.toml");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let (code, _, err) = grade(&fifo);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("it is a FIFO (named pipe), not an answer file"),
        "{err}"
    );
}

#[test]
fn a_file_over_the_size_limit_is_refused_and_nothing_is_echoed() {
    let d = scratch("big");
    let path = d.join("answers.toml");
    let answer = "1".repeat(2 << 20);
    std::fs::write(
        &path,
        format!("seed = 1\ncount = 1\n[[exercise]]\ndv = \"{answer}\"\n"),
    )
    .unwrap();
    let (code, out, err) = grade(&path);
    assert_eq!(code, Some(1), "{err}");
    assert!(out.is_empty(), "nothing graded");
    assert!(err.contains("larger than 1024 KiB"), "{err}");
    assert!(
        err.len() < 500,
        "the answer is not echoed: {} bytes",
        err.len()
    );
}

#[test]
fn a_long_answer_is_echoed_once_and_cut() {
    let d = scratch("long");
    let path = d.join("answers.toml");
    let answer = "7".repeat(100_000);
    std::fs::write(
        &path,
        format!("seed = 1\nkind = \"frictionless\"\ncount = 1\n[[exercise]]\ndv = \"{answer}\"\n"),
    )
    .unwrap();
    let (code, out, err) = grade(&path);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.len() < 2_000,
        "the answer cut in the report: {} bytes",
        out.len()
    );
    // Echoed once, cut at 80 characters; the problem quotes 16 of them.
    let sevens = out.matches('7').count();
    assert!(sevens < 80 + 16 + 5, "echoed once: {sevens} sevens\n{out}");
    assert!(out.contains("7…"), "{out}");
}

#[test]
fn control_characters_in_answers_keys_kind_and_path_are_escaped() {
    let d = scratch("control");
    let path = d.join("answers.toml");
    std::fs::write(
        &path,
        "seed = 1\nkind = \"frictionless\"\ncount = 1\n[[exercise]]\ndv = \"\\u001b]0;PWNED\\u0007\\u001b[2J \\u202e1\"\n\"\\u001b[31mkey\" = \"1\"\n",
    )
    .unwrap();
    let (code, out, err) = grade(&path);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        !has_control(&out),
        "raw control characters echoed:\n{out:?}"
    );
    assert!(
        out.contains("Δv = \\u{1b}]0;PWNED\\u{7}\\u{1b}[2J \\u{202e}1"),
        "{out}"
    );
    assert!(out.contains("? `\\u{1b}[31mkey` is not an answer"), "{out}");

    let kind = d.join("kind.toml");
    std::fs::write(&kind, "seed = 1\ncount = 1\nkind = \"\\u001b[2Jx\"\n").unwrap();
    let (code, _, err) = grade(&kind);
    assert_eq!(code, Some(2), "{err}");
    assert!(!has_control(&err), "{err:?}");
    assert!(
        err.contains("unknown exercise kind \"\\u{1b}[2Jx\""),
        "{err}"
    );

    let odd = d.join("a\u{1b}[2Jb.toml");
    let (code, _, err) = grade(&odd);
    assert_eq!(code, Some(1), "{err}");
    assert!(!has_control(&err), "the path escaped: {err:?}");
    assert!(err.contains("a\\u{1b}[2Jb.toml"), "{err}");
}

#[test]
fn extra_exercise_tables_and_nested_arrays_are_refused() {
    let d = scratch("shape");
    let extra = d.join("extra.toml");
    std::fs::write(&extra, "seed = 1\ncount = 1\n[[exercise]]\n[[exercise]]\n").unwrap();
    let (code, _, err) = grade(&extra);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("2 [[exercise]] tables for a sheet of 1 exercise(s)"),
        "{err}"
    );
    let nested = d.join("nested.toml");
    std::fs::write(
        &nested,
        "seed = 1\ncount = 1\n[[exercise]]\ndv = [[1, 2], [3]]\n",
    )
    .unwrap();
    let (code, _, err) = grade(&nested);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("`dv` holds a nested array or table"), "{err}");
}

fn entries(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn sheet_to(target: &Path) -> Output {
    run(&[
        "exercise".as_ref(),
        "--seed".as_ref(),
        "1".as_ref(),
        "--count".as_ref(),
        "2".as_ref(),
        "--format".as_ref(),
        "md".as_ref(),
        "-o".as_ref(),
        target.as_os_str(),
    ])
}

#[test]
fn a_sheet_onto_a_directory_writes_no_figures() {
    let d = scratch("onto-dir");
    std::fs::create_dir(d.join("sheet.md")).unwrap();
    let out = sheet_to(&d.join("sheet.md"));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("it is a directory, not a regular file"),
        "{err}"
    );
    assert_eq!(entries(&d), ["sheet.md"], "no figure left beside it");
}

#[cfg(unix)]
#[test]
fn a_sheet_onto_a_symbolic_link_writes_no_figures() {
    let d = scratch("onto-link");
    std::fs::write(d.join("elsewhere.md"), "kept").unwrap();
    std::os::unix::fs::symlink(d.join("elsewhere.md"), d.join("sheet.md")).unwrap();
    let out = sheet_to(&d.join("sheet.md"));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("it is a symbolic link"), "{err}");
    assert_eq!(
        entries(&d),
        ["elsewhere.md", "sheet.md"],
        "no figure left beside it"
    );
    assert_eq!(
        std::fs::read_to_string(d.join("elsewhere.md")).unwrap(),
        "kept"
    );
}
