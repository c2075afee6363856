//! Bad lesson files through the binary (as bottom tests its invalid configs): every
//! file in `tests/invalid_lessons/` exits 65, names `FILE:LINE:COLUMN` and a
//! specific message, writes nothing to stdout and does not panic. Also very
//! long files (generated), a missing file (66), paths that are not regular
//! files or cannot be read (1), non-UTF-8 file names, a closed stdout and
//! command-line misuse (2).

use std::path::{Path, PathBuf};

const DIR: &str = "tests/invalid_lessons";

/// File → line, column and a fragment of the message of its one error.
/// A file in the folder without a row here fails the test, and so does a row
/// without its file.
#[rustfmt::skip]
const CASES: &[(&str, usize, usize, &str)] = &[
    ("bad-shape-size", 8, 9, "shape sizes must be finite and > 0"),
    ("binary-junk", 1, 9, "the file is not UTF-8 text"),
    ("box-with-four-sides", 8, 9, "expected an array of 3 numbers, got 4"),
    ("comments-only", 1, 1, "missing field `id`"),
    ("control-character-in-name", 6, 8, "body name must not contain control characters (found U+001B)"),
    ("crlf-unknown-field", 17, 1, "unknown field `friciton`"),
    ("decimal-comma-in-velocity", 10, 12, "expected an array of 3 numbers, got 4"),
    ("duplicate-body-names", 13, 8, "body name 'ball' is used twice"),
    ("duplicate-id", 4, 1, "duplicate key `id`"),
    ("duplicate-key", 8, 1, "duplicate key `mass`"),
    ("duplicate-settings-table", 21, 2, "table [settings] is defined twice"),
    ("duration-zero", 19, 12, "in [settings]: duration must be a finite number > 0, got 0"),
    ("empty-body-name", 6, 8, "body name must not be empty"),
    ("empty-file", 1, 1, "the lesson file is empty"),
    ("empty-id", 2, 6, "id must not be empty"),
    ("exact-unknown-law", 19, 9, "in [settings]: exact must be one of \"none\", \"newton\", \"poisson\", \"stronge\", got \"hooke\""),
    ("float-past-f64", 7, 8, "the number 1e400 is too large for a 64-bit float"),
    ("half-space-with-finite-mass", 8, 9, "a half-space must be immovable (mass = inf)"),
    ("hull-collinear-points", 8, 9, "body 'tetra': the convex hull is degenerate: all points lie on one line"),
    ("hull-coplanar-points", 8, 9, "body 'tetra': the convex hull is degenerate: all points lie in one plane"),
    ("hull-duplicate-points", 8, 9, "body 'tetra': the convex hull is degenerate: points 1 and 3 are the same point"),
    ("hull-three-points", 8, 9, "body 'tetra': the convex hull is degenerate: a convex hull needs at least 4 points, got 3"),
    ("immovable-with-velocity", 17, 12, "body 'floor' is immovable (mass = inf): its velocity must be zero"),
    ("inf-penetration", 17, 15, "penetration: must be a finite number, got inf"),
    ("inf-position", 9, 12, "position: every component must be a finite number within ±1e60, got inf in y"),
    ("integer-past-i64", 7, 8, "the integer 99999999999999999999 does not fit in 64 bits"),
    ("mesh-against-mesh", 11, 9, "body 'block': a movable mesh beside another mesh ('ground'): contacts between two meshes"),
    ("mesh-degenerate-triangle", 8, 9, "body 'ground': the mesh is refused: triangle 0 is degenerate"),
    ("mesh-inconsistent-winding", 8, 9, "triangles 0 and 1 wind their shared edge (2, 1) the same way"),
    ("mesh-obj-missing", 8, 9, "the mesh file 'tests/invalid_lessons/no-such-mesh.obj' cannot be read"),
    ("mesh-open-movable", 8, 9, "a movable mesh must be closed: the edge (0, 2) of triangle 0 has no neighbour"),
    ("mesh-vertex-out-of-range", 8, 9, "triangle 0 names vertex 3, but there are 3 vertices"),
    ("mass-too-small-to-invert", 7, 8, "mass 1e-310 is too small: its inverse 1/m overflows"),
    ("missing-field-id", 1, 1, "missing field `id`"),
    ("missing-field-mass", 5, 1, "missing field `mass`"),
    ("missing-field-restitution", 12, 1, "missing field `restitution`"),
    ("movable-without-inertia", 6, 8, "body 'ball' needs an `inertia` tensor or a `shape`"),
    ("nan-in-tensor", 8, 11, "every inertia component must be a finite number within ±1e60, got NaN in row 2, column 2"),
    ("nan-in-velocity", 10, 12, "velocity: every component must be a finite number within ±1e60, got NaN in y"),
    ("nan-mass", 7, 8, "mass must be > 0 (or inf for an immovable body), got NaN"),
    ("negative-angular-limit", 19, 17, "in [settings]: angular_limit must be ≥ 0"),
    ("negative-friction", 17, 12, "friction coefficient must be a finite number ≥ 0, got -0.3"),
    ("negative-mass", 7, 8, "mass must be > 0 (or inf for an immovable body), got -1"),
    ("negative-velocity-limit", 19, 18, "in [settings]: velocity_limit must be a finite number ≥ 0, got -0.25"),
    ("no-bodies-in-contact", 13, 10, "a contact names one or two bodies, got 0"),
    ("no-contact", 1, 1, "the lesson has no [[contact]]"),
    ("non-positive-definite-tensor", 8, 11, "inertia tensor must be positive-definite"),
    ("non-symmetric-tensor", 8, 11, "inertia tensor must be symmetric"),
    ("printed-contact-out-of-range", 19, 11, "printed entry names contact 3 but the lesson has 1"),
    ("printed-unknown-stage", 19, 9, "unknown stage \"impulses\""),
    ("printed-where-with-escape", 22, 9, "where must not contain control characters (found U+001B)"),
    ("raw-escape-in-comment", 1, 77, "invalid comment character"),
    ("relaxation-above-one", 19, 14, "in [contact.settings]: relaxation must be in (0, 1], got 1.5"),
    ("relaxation-zero", 19, 14, "in [settings]: relaxation must be in (0, 1], got 0"),
    ("restitution-above-one", 16, 15, "restitution must be in [0, 1], got 1.5"),
    ("same-body-twice", 13, 19, "a contact needs two different bodies, got 'ball' twice"),
    ("shape-too-small-to-invert", 8, 9, "shape sizes must be finite and > 0 (within 1e-60 to 1e60)"),
    ("syntax-bad-array", 10, 1, "missing comma between array elements"),
    ("syntax-missing-equals", 7, 6, "key with no value, expected `=`"),
    ("syntax-unterminated-string", 3, 20, "invalid basic string, expected `\"`"),
    ("tensor-row-too-long", 8, 11, "a 3×3 tensor row: expected an array of 3 numbers, got 4"),
    ("tensor-too-small-to-invert", 8, 11, "inertia component in row 1, column 1: 1e-120 is below contact-lab's smallest non-zero magnitude, 1e-60"),
    ("tensor-with-tiny-principal-moment", 8, 11, "its smallest principal moment is 1e-61, below contact-lab's 1e-60: its inverse I⁻¹ would reach 1e61"),
    ("tensor-ill-conditioned", 8, 11, "the inertia tensor [[1, 0, 0], [0, 1, 0], [0, 0, 1e-20]]: its condition number (largest / smallest principal moment) is 1e20"),
    ("shape-inertia-past-range", 8, 9, "(from the shape): its largest principal moment is 4e79, above contact-lab's 1e60"),
    ("velocity-below-range", 10, 12, "body 'ball' velocity: 1e-170 is below contact-lab's smallest non-zero magnitude, 1e-60"),
    ("product-overflows", 13, 10, "contact 0: its numbers overflow a 64-bit float: `energy_after` reaches 6.409905439180083e304"),
    ("product-overflows-under-another-model", 13, 10, "contact 0: its numbers overflow a 64-bit float under the kinetic-direction friction model"),
    ("friction-below-range", 17, 12, "friction coefficient 1e-300 is below contact-lab's smallest non-zero magnitude"),
    ("three-bodies-in-contact", 19, 10, "a contact names one or two bodies, got 3"),
    ("two-immovable-bodies", 18, 10, "a contact needs at least one movable body"),
    ("unknown-body", 13, 11, "unknown body 'bal' (bodies: ball)"),
    ("unknown-body-after-non-ascii", 18, 19, "unknown body 'ballé' (bodies: bäll, ball)"),
    ("unknown-body-with-escape", 13, 11, r"unknown body '\u{1b}]0;pwned\u{7}' (bodies: ball)"),
    ("unknown-field-typo", 16, 1, "unknown field `restitutoin`"),
    ("unknown-friction-model", 18, 18, "in [[contact]]: friction_model must be one of \"millington\", \"kinetic-direction\", \"velocity-scaling\", got \"coulomb\""),
    ("unknown-projection", 19, 14, "in [settings]: projection must be one of \"nonlinear\", \"linear\", got \"quadratic\""),
    ("unknown-settings-field", 19, 1, "unknown field `relaxtion`"),
    ("unknown-shape", 8, 11, "unknown variant `cone`"),
    ("utf16-file", 1, 1, "the file is not UTF-8 text"),
    ("wrong-length-normal", 15, 10, "expected an array of 3 numbers, got 2"),
    ("wrong-table-kind-body", 5, 1, "[body] must be an array of tables: write [[body]]"),
    ("wrong-type-mass-string", 7, 8, "invalid type: string \"heavy\", expected a number"),
    ("wrong-type-position-scalar", 9, 12, "invalid type: floating point `0.5`, expected an array"),
    ("mass-past-range", 7, 8, "mass 1e61 is outside contact-lab's range of 1e-60 to 1e60"),
    ("velocity-past-range", 10, 12, "velocity: every component must be a finite number within ±1e60, -1e200 is outside ±1e60 in y"),
    ("friction-past-range", 17, 12, "friction coefficient 1e308 is outside contact-lab's range of 0 to 1e60"),
    ("zero-mass", 7, 8, "mass must be > 0 (or inf for an immovable body), got 0"),
    ("zero-normal", 15, 10, "contact normal must be non-zero (its length is 0)"),
    ("zero-quaternion", 11, 15, "orientation must be a non-zero quaternion"),
    ("carriage-return-in-body-name", 6, 8, "body name must not contain control characters (found U+000D), a carriage return"),
    ("line-feed-in-id", 2, 6, "id must not contain control characters (found U+000A), a line feed"),
    ("line-feed-in-title", 3, 9, "title must not contain control characters (found U+000A)"),
    ("escape-in-contact-name", 13, 8, "contact name must not contain control characters (found U+001B), an escape"),
    ("bidi-override-in-body-name", 6, 8, "body name must not contain control characters (found U+202E), a bidirectional-text control"),
    ("lone-carriage-return-in-summary", 4, 11, "summary must not contain control characters (found U+000D), a carriage return"),
    ("immovable-with-acceleration", 17, 16, "body 'floor' is immovable (mass = inf): its acceleration must be zero or absent"),
    ("immovable-with-inertia", 17, 11, "body 'floor' is immovable (mass = inf): it takes no `inertia` tensor"),
    ("printed-empty-array", 21, 11, "the printed value is empty"),
    ("printed-jagged-matrix", 21, 11, "a printed matrix is 3 rows of 3 numbers: row 2 has 1"),
    ("printed-empty-row", 21, 11, "a printed matrix is 3 rows of 3 numbers: row 1 has 0"),
    ("printed-two-numbers", 21, 11, "a printed vector has 3 numbers (4 for a quaternion), got 2"),
    ("printed-component-of-a-vector", 21, 13, "`component` picks one number of a vector, so `printed` must be one number"),
    ("printed-component-out-of-range", 21, 13, "component must be 0, 1 or 2 (3 for a quaternion's z), got 9"),
    ("scene-gravity-below-range", 6, 11, "in [world]: gravity y: -1e-70 is below contact-lab's smallest non-zero magnitude, 1e-60"),
    ("scene-damping-below-range", 6, 18, "in [world]: linear_damping 1e-300 is below contact-lab's smallest magnitude, 1e-60"),
    ("scene-dt-below-range", 9, 6, "in [step]: dt 1e-70 is below contact-lab's smallest magnitude, 1e-60"),
    ("scene-escape-in-box-box", 6, 11, r#"in [world]: box_box must be one of "manifold", "single", got "single\u{1b}[31m""#),
    ("scene-half-space-normal-past-range", 22, 10, "body 'floor' normal: every component must be a finite number within ±1e60, 1e200 is outside ±1e60 in y"),
    ("scene-dt-zero", 9, 6, "in [step]: dt must be a finite number > 0, got 0"),
    ("scene-dt-negative", 9, 6, "in [step]: dt must be a finite number > 0, got -0.01"),
    ("scene-dt-nan", 9, 6, "in [step]: dt must be a finite number > 0, got NaN"),
    ("scene-steps-past-limit", 10, 9, "in [step]: steps must be a whole number from 0 to 10000000, got 10000001"),
    ("scene-half-space-zero-normal", 23, 10, "body 'floor': a half-space's normal must be non-zero"),
    ("scene-damping-zero", 7, 18, "in [world]: linear_damping is the fraction of velocity kept per second and must be in (0, 1], got 0"),
    ("scene-damping-above-one", 7, 19, "in [world]: angular_damping is the fraction of velocity kept per second and must be in (0, 1], got 1.5"),
    ("scene-sleep-epsilon-negative", 14, 11, "in [sleep]: epsilon must be a finite number ≥ 0, got -0.3 (the knob sleep_epsilon)"),
    ("scene-sleep-unknown-mode", 13, 8, "in [sleep]: mode must be one of \"body\", \"island\", got \"stack\" (the knob sleep_mode)"),
    ("scene-box-box-unknown", 7, 11, "in [world]: box_box must be one of \"manifold\", \"single\", got \"double\""),
    ("figure-unknown-body", 22, 8, "[[figure.body]] names 'bal', which is not a body of the lesson"),
    ("figure-half-space-drawn", 23, 9, "[[figure.body]] 'ball': the shape drawn must be finite"),
    ("scene-movable-without-shape", 13, 8, "body 'ball' moves in a scene (the lesson has [world], [step] or [sleep]) and needs a `shape` to collide"),
];

/// Extra help lines some cases must carry.
const HELP: &[(&str, &str)] = &[
    ("crlf-unknown-field", "did you mean `friction`?"),
    ("unknown-field-typo", "did you mean `restitution`?"),
    ("unknown-settings-field", "did you mean `relaxation`?"),
    ("utf16-file", "it starts like UTF-16 text"),
    ("float-past-f64", "write `inf` where infinity is meant"),
];

use crate::common::cli::{contact_lab, run};

/// Runs `solve PATH` and checks everything a bad lesson must give; returns stderr.
fn assert_invalid(path: &str, line: usize, column: usize, fragment: &str) -> String {
    let r = run(&["solve", path]);
    let context = format!("{path}\n--- stderr ---\n{}", r.stderr);
    assert_eq!(r.code, Some(65), "exit code, {context}");
    assert!(r.stdout.is_empty(), "stdout must be empty, {context}");
    assert!(!r.stderr.contains("panicked"), "panic, {context}");
    assert!(
        !r.stderr.contains('\u{1b}'),
        "raw escape on stderr, {context}"
    );
    let first = r.stderr.lines().next().unwrap_or("");
    let at = format!("error: {path}:{line}:{column}: ");
    assert!(first.starts_with(&at), "expected `{at}…`, {context}");
    assert!(first.contains(fragment), "expected «{fragment}», {context}");
    let header = format!("[{path}:{line}:{column}]");
    assert!(
        r.stderr.contains(&header),
        "snippet header {header}, {context}"
    );
    r.stderr
}

fn corpus() -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(DIR);
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("tests/invalid_lessons exists")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn every_bad_lesson_fails_with_its_line_column_and_message() {
    let files = corpus();
    assert!(files.len() >= 30, "the corpus has {} files", files.len());
    for file in &files {
        let stem = file.strip_suffix(".toml").unwrap_or_else(|| {
            panic!("{DIR}/{file}: lesson files end in .toml");
        });
        let Some(&(_, line, column, fragment)) = CASES.iter().find(|c| c.0 == stem) else {
            panic!("{DIR}/{file} has no row in CASES: add its line, column and message");
        };
        let stderr = assert_invalid(&format!("{DIR}/{file}"), line, column, fragment);
        let errors = stderr.lines().filter(|l| l.starts_with("error: ")).count();
        assert_eq!(errors, 1, "{file} has one defect, so one error:\n{stderr}");
        if let Some((_, help)) = HELP.iter().find(|h| h.0 == stem) {
            assert!(
                stderr.contains(help),
                "{file}: expected help «{help}»:\n{stderr}"
            );
        }
    }
    for (stem, ..) in CASES {
        assert!(
            files.contains(&format!("{stem}.toml")),
            "CASES names {stem}, which is not in {DIR}"
        );
    }
}

/// A scratch file for generated lessons too big to commit.
fn scratch(name: &str, text: &str) -> String {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn valid_lesson() -> String {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(DIR)
            .join("negative-mass.toml"),
    );
    text.unwrap().replace("mass = -1.0", "mass = 1.0")
}

#[test]
fn a_very_long_file_reports_the_right_line() {
    let mut text = valid_lesson();
    let lines = text.lines().count();
    for i in 0..200_000 {
        text.push_str(&format!("# filler comment {i}\n"));
    }
    text.push_str("restitutoin = 0.5\n");
    let path = scratch("very-long.toml", &text);
    let stderr = assert_invalid(&path, lines + 200_001, 1, "unknown field `restitutoin`");
    assert!(stderr.len() < 4_000, "{} bytes of stderr", stderr.len());
}

#[test]
fn a_very_long_line_is_shown_as_an_excerpt() {
    let long = format!("title = \"{}\", restitution = 2\n", "é".repeat(2_000_000));
    let text = valid_lesson().replace("title = \"One defect\"\n", &long);
    let path = scratch("very-long-line.toml", &text);
    let stderr = assert_invalid(&path, 3, 2_000_011, "expected newline");
    assert!(stderr.len() < 4_000, "{} bytes of stderr", stderr.len());
    assert!(
        stderr.contains("…éééé"),
        "an excerpt of the line:\n{stderr}"
    );
}

#[test]
fn thousands_of_errors_are_counted_not_all_printed() {
    let mut text = valid_lesson();
    for i in 0..5_000 {
        text.push_str(&format!(
            "\n[[body]]\nname = \"b{i}\"\nmass = -1.0\nshape = {{ sphere = 1.0 }}\nposition = [0.0, 0.0, 0.0]\n"
        ));
    }
    let path = scratch("many-errors.toml", &text);
    let stderr = assert_invalid(&path, 20, 8, "body 'b0': mass must be > 0");
    let errors = stderr.lines().filter(|l| l.starts_with("error: ")).count();
    assert_eq!(errors, 21, "20 errors and a count of the rest:\n{stderr}");
    assert!(stderr.contains("4980 more error(s) not shown"), "{stderr}");
}

#[test]
fn deep_nesting_is_refused_without_overflowing_the_stack() {
    let text = format!("a = {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
    let path = scratch("deep-nesting.toml", &text);
    assert_invalid(&path, 1, 85, "recursion");
}

#[test]
fn a_missing_file_exits_66() {
    for path in [
        "tests/no/such/lesson.toml",
        "not-a-lesson-id",
        "tests/invalid_lessons/zero-mass.toml/below-a-file",
    ] {
        let r = run(&["solve", path]);
        assert_eq!(r.code, Some(66), "{path}: {}", r.stderr);
        assert!(r.stdout.is_empty());
        assert!(
            r.stderr
                .starts_with(&format!("error: lesson file missing: {path}: ")),
            "{}",
            r.stderr
        );
    }
}

/// A path that exists but is not a regular file is refused at once (exit 1),
/// never read: a FIFO would block forever, a device never ends.
#[test]
fn a_lesson_path_that_is_not_a_regular_file_is_refused_at_once() {
    let mut cases = vec![(DIR.to_string(), "it is a directory, not a lesson file")];
    #[cfg(unix)]
    {
        let fifo = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("lesson-fifo.toml");
        let _ = std::fs::remove_file(&fifo);
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        assert!(made.unwrap().success(), "mkfifo");
        cases.push((
            fifo.display().to_string(),
            "it is a FIFO (named pipe), not a lesson file",
        ));
        cases.push((
            "/dev/zero".into(),
            "it is a character device, not a lesson file",
        ));
    }
    for (path, why) in &cases {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_contact-lab"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["solve", path])
            .stdin(std::process::Stdio::null())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > std::time::Duration::from_secs(20) {
                child.kill().unwrap();
                panic!("solve {path} blocked");
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{path}: {stderr}");
        assert!(out.stdout.is_empty());
        assert_eq!(
            stderr.trim_end(),
            format!("error: cannot read lesson file {path}: {why} (a lesson is a TOML file)")
        );
    }
}

/// `resolve` and `simulate` read lessons through the same loader as
/// `solve`: a bad scene (the corpus's `scene-*` files), a directory, a
/// device and a missing path are refused by each exactly as `solve` refuses
/// them (65, 1, 1, 66), with the same first line and nothing on stdout.
#[test]
fn resolve_and_simulate_refuse_what_solve_refuses() {
    let mut paths: Vec<String> = corpus()
        .into_iter()
        .filter(|f| f.starts_with("scene-"))
        .map(|f| format!("{DIR}/{f}"))
        .collect();
    assert!(paths.len() >= 5, "{paths:?}");
    paths.push(DIR.into());
    paths.push("tests/no/such/lesson.toml".into());
    #[cfg(unix)]
    paths.push("/dev/zero".into());
    for path in &paths {
        let solve = run(&["solve", path]);
        assert!(
            matches!(solve.code, Some(1 | 65 | 66)),
            "{path}: {}",
            solve.stderr
        );
        for command in ["resolve", "simulate"] {
            let r = run(&[command, path]);
            assert_eq!(r.code, solve.code, "{command} {path}: {}", r.stderr);
            assert!(r.stdout.is_empty(), "{command} {path}");
            assert_eq!(
                r.stderr.lines().next(),
                solve.stderr.lines().next(),
                "{command} {path}"
            );
        }
    }
}

/// Permission denied is not "missing" (66) but a failure to read (exit 1).
/// Root reads any file, so the check runs only for other users.
#[cfg(unix)]
#[test]
fn an_unreadable_lesson_is_not_called_missing() {
    use std::os::unix::fs::PermissionsExt;
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("unreadable.toml");
    std::fs::write(&path, valid_lesson()).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o000)).unwrap();
    if std::fs::read(&path).is_ok() {
        println!("skipped: this user (root?) reads files without read permission");
        return;
    }
    let r = run(&["solve", &path.display().to_string()]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert!(!r.stderr.contains("missing"), "{}", r.stderr);
    assert!(r.stderr.contains("permission denied"), "{}", r.stderr);
}

/// A file name that is not UTF-8 (and holds an escape) opens, and the name is
/// shown escaped.
#[cfg(unix)]
#[test]
fn a_non_utf8_file_name_opens() {
    use std::os::unix::ffi::OsStrExt;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let name = std::ffi::OsStr::from_bytes(b"caf\xe9-\x1b[31m.toml");
    let path = dir.join(name);
    std::fs::write(&path, valid_lesson()).unwrap();
    let out = contact_lab()
        .arg("solve")
        .arg(&path)
        .arg("--format")
        .arg("json")
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("\"lesson\": \"bad\""));
    std::fs::write(&path, "id = 3\n").unwrap();
    let out = contact_lab().arg("solve").arg(&path).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(65), "{stderr}");
    assert!(
        stderr.contains("caf\u{fffd}-\\u{1b}[31m.toml:1:"),
        "{stderr}"
    );
    assert!(!stderr.contains('\u{1b}'), "{stderr}");
}

/// `contact-lab … >&-`: output that cannot be delivered is a failure, not
/// success (the closed pipe of `… | head` stays quiet, tested above).
#[cfg(unix)]
#[test]
fn a_closed_stdout_is_reported() {
    let bin = env!("CARGO_BIN_EXE_contact-lab");
    let out = std::process::Command::new("sh")
        .args(["-c", &format!("'{bin}' solve lecture-2 >&-")])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(
        stderr,
        "error: cannot write output: standard output is closed\n"
    );
    // The same for the commands that stepped in later.
    for command in [
        "resolve sphere-row",
        "simulate lessons/scenes/ball-drop.toml --steps 10",
    ] {
        let out = std::process::Command::new("sh")
            .args(["-c", &format!("'{bin}' {command} >&-")])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{command}: {stderr}");
        assert_eq!(
            stderr, "error: cannot write output: standard output is closed\n",
            "{command}"
        );
    }
    // A command that writes nothing to stdout is not affected.
    let svg = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("closed-stdout.svg");
    let out = std::process::Command::new("sh")
        .args([
            "-c",
            &format!("'{bin}' figure lecture-2 -o '{}' >&-", svg.display()),
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn command_line_misuse_exits_2_with_a_message() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["solve", "lecture-2", "--bogus"],
            "unexpected argument '--bogus'",
        ),
        (
            &["solve", "lecture-2", "--contact", "99"],
            "--contact 99: lesson 'lecture-2' has 1 contact(s)",
        ),
        (&["solve", "lecture-2", "--contact", "-1"], "'-1'"),
        (
            &["solve", "lecture-2", "--digits", "0"],
            "0 is not in 1..=17",
        ),
        (
            &["solve", "lecture-2", "--digits", "18"],
            "18 is not in 1..=17",
        ),
        (
            &["solve", "lecture-2", "--relaxation", "2"],
            "--relaxation: relaxation must be in (0, 1], got 2",
        ),
        (
            &["solve", "lecture-2", "--relaxation", "nan"],
            "--relaxation: relaxation must be in (0, 1], got NaN",
        ),
        (
            &["solve", "lecture-2", "--relaxation", "-0.5"],
            "--relaxation: relaxation must be in (0, 1], got -0.5",
        ),
        (
            &["solve", "lecture-2", "--angular-limit", "-1"],
            "--angular-limit: angular_limit must be ≥ 0",
        ),
        (
            &["solve", "lecture-2", "--format", "yaml"],
            "invalid value 'yaml' for '--format <FORMAT>'",
        ),
        (
            &["solve", "lecture-2", "--friction-model", "coulomb"],
            "--friction-model: friction_model must be one of \"millington\", \"kinetic-direction\", \"velocity-scaling\", got 'coulomb'",
        ),
        (
            &["solve"],
            "the following required arguments were not provided",
        ),
        (
            &["solve", "lecture-2", "extra"],
            "unexpected argument 'extra'",
        ),
        (&["frobnicate"], "unrecognized subcommand 'frobnicate'"),
        // `simulate`'s options follow the lesson file's range rules.
        (
            &["simulate", "ball-drop", "--dt", "1e-70"],
            "--dt: dt 1e-70 is below contact-lab's smallest magnitude, 1e-60",
        ),
        (
            &["simulate", "ball-drop", "--gravity", "0,1e-70,0"],
            "--gravity: gravity y: 1e-70 is below contact-lab's smallest non-zero magnitude, 1e-60",
        ),
        (
            &["simulate", "ball-drop", "--damping", "1e-300"],
            "--damping: linear_damping 1e-300 is below contact-lab's smallest magnitude, 1e-60",
        ),
        (
            &["simulate", "ball-drop", "--velocity-limit", "1e-70"],
            "--velocity-limit: velocity_limit 1e-70 is below contact-lab's smallest non-zero magnitude",
        ),
        (
            &["resolve", "sphere-row", "--velocity-epsilon", "1e-70"],
            "--velocity-epsilon: velocity_epsilon 1e-70 is below contact-lab's smallest non-zero magnitude",
        ),
    ];
    for (args, fragment) in cases {
        let r = run(args);
        assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
        assert!(r.stdout.is_empty(), "{args:?} wrote {}", r.stdout);
        assert!(
            r.stderr.contains(fragment),
            "{args:?}: expected «{fragment}» in {}",
            r.stderr
        );
        assert!(!r.stderr.contains("panicked"), "{args:?}: {}", r.stderr);
    }
}

#[test]
fn a_reader_that_goes_away_ends_the_output_quietly() {
    // 100 KB of JSON, more than a pipe holds: the write after the reader
    // has gone fails with a broken pipe, as `contact-lab … | head` does.
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "solve",
            "extreme-normals",
            "--all-contacts",
            "--format",
            "json",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("contact-lab runs");
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
}

#[cfg(target_os = "linux")]
#[test]
fn an_unwritable_stderr_still_gives_the_exit_code() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let path = format!("{DIR}/negative-mass.toml");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["solve", &path])
        .stderr(full)
        .status()
        .unwrap();
    assert_eq!(
        status.code(),
        Some(65),
        "eprint! panics (101) on a full stderr"
    );
}

#[test]
fn a_file_over_16_mib_is_refused_unread() {
    // Sparse: 17 MiB of length, no blocks written.
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("huge.toml");
    let f = std::fs::File::create(&path).unwrap();
    f.set_len(17 << 20).unwrap();
    drop(f);
    let stderr = assert_invalid(
        &path.display().to_string(),
        1,
        1,
        "the file is larger than 16 MiB",
    );
    assert!(stderr.len() < 1_000, "{stderr}");
}
