//! Files the binary writes (`figure -o`, `solve --figures`, `exercise --dir`):
//! a target that is not a regular file (FIFO, device, directory, symbolic
//! link) is refused with exit 1 and left as it was; a regular file is
//! replaced atomically and no temporary file is left behind.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("output-files-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn entries(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Runs contact-lab and kills it after 20 s: a write that blocks on a FIFO
/// must fail the test, not hang it.
fn run(args: &[&std::ffi::OsStr]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
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

fn os(s: &str) -> &std::ffi::OsStr {
    s.as_ref()
}

fn assert_refused(out: &Output, what: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(
        stderr.contains(&format!("it is {what}, not a regular file")),
        "{stderr}"
    );
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().expect("mkfifo");
    assert!(status.success());
}

#[cfg(unix)]
#[test]
fn figure_onto_a_fifo_is_refused_and_the_fifo_kept() {
    use std::os::unix::fs::FileTypeExt;
    let d = scratch("fifo");
    let fifo = d.join("figure.svg");
    mkfifo(&fifo);
    let out = run(&[os("figure"), os("lecture-2"), os("-o"), fifo.as_os_str()]);
    assert_refused(&out, "a FIFO (named pipe)");
    let t = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    assert!(t.is_fifo(), "the FIFO is still a FIFO");
    assert_eq!(entries(&d), ["figure.svg"], "no temporary file left");
}

#[cfg(unix)]
#[test]
fn figure_onto_a_device_is_refused() {
    use std::os::unix::fs::FileTypeExt;
    // A private copy of /dev/null (major 1, minor 3) in a scratch directory,
    // never /dev/null itself: a regression would replace that device, which
    // as root destroys it for the whole machine.
    let d = scratch("device");
    let node = d.join("null");
    let made = Command::new("mknod")
        .arg(&node)
        .args(["c", "1", "3"])
        .stderr(Stdio::null())
        .status();
    if !made.is_ok_and(|s| s.success()) {
        println!("skipped: mknod needs root; the FIFO test covers the same refusal");
        return;
    }
    let out = run(&[os("figure"), os("lecture-2"), os("-o"), node.as_os_str()]);
    assert_refused(&out, "a character device");
    let t = std::fs::symlink_metadata(&node).unwrap().file_type();
    assert!(t.is_char_device(), "the device node is still a device");
    assert_eq!(entries(&d), ["null"]);
}

#[test]
fn figure_onto_a_directory_is_refused() {
    let d = scratch("dir");
    let target = d.join("figure.svg");
    std::fs::create_dir(&target).unwrap();
    let out = run(&[os("figure"), os("lecture-2"), os("-o"), target.as_os_str()]);
    assert_refused(&out, "a directory");
    assert!(target.is_dir());
}

#[cfg(unix)]
#[test]
fn a_planted_symbolic_link_is_refused_and_its_target_untouched() {
    let d = scratch("link");
    let victim = d.join("victim.txt");
    std::fs::write(&victim, "precious").unwrap();
    let target = d.join("figure.svg");
    std::os::unix::fs::symlink(&victim, &target).unwrap();
    let out = run(&[os("figure"), os("lecture-2"), os("-o"), target.as_os_str()]);
    assert_refused(&out, "a symbolic link");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");

    // The same for the figures `solve --figures` writes.
    let figs = d.join("figs");
    std::fs::create_dir(&figs).unwrap();
    std::os::unix::fs::symlink(&victim, figs.join("lecture-2-contact-0.svg")).unwrap();
    let out = run(&[
        os("solve"),
        os("lecture-2"),
        os("--format"),
        os("md"),
        os("--figures"),
        figs.as_os_str(),
    ]);
    assert_refused(&out, "a symbolic link");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
}

#[cfg(unix)]
#[test]
fn the_exercise_writer_refuses_a_fifo_and_writes_the_rest_of_a_clean_directory() {
    let d = scratch("exercise");
    mkfifo(&d.join("exercise-7-1.toml"));
    let args = [
        os("exercise"),
        os("--seed"),
        os("7"),
        os("--count"),
        os("2"),
        os("--format"),
        os("toml"),
        os("--dir"),
    ];
    let out = run(&[&args[..], &[d.as_os_str()]].concat());
    assert_refused(&out, "a FIFO (named pipe)");

    let clean = scratch("exercise-clean");
    let out = run(&[&args[..], &[clean.as_os_str()]].concat());
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(entries(&clean), ["exercise-7-1.toml", "exercise-7-2.toml"]);
}

#[test]
fn a_regular_file_is_replaced_and_no_temporary_file_is_left() {
    let d = scratch("regular");
    let target = d.join("figure.svg");
    std::fs::write(&target, "old").unwrap();
    let out = run(&[os("figure"), os("lecture-2"), os("-o"), target.as_os_str()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&target).unwrap().contains("<svg "));
    assert_eq!(entries(&d), ["figure.svg"]);
}
