//! Slide-ready text (issue 28, item 2): plain text folds to a width (100
//! columns when stdout is not a terminal, `--width N`, `--width 0` never),
//! Markdown tables are never folded, `simulate` prints a summary unless
//! asked for `--table`, and the film strip explains its outlines.

use assert_cmd::Command;

fn stdout(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "contact-lab {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

fn widest(text: &str) -> usize {
    text.lines().map(|l| l.chars().count()).max().unwrap_or(0)
}

#[test]
fn resolve_text_folds_to_100_columns_when_piped_and_to_width() {
    let folded = stdout(&["resolve", "box-stack"]);
    assert!(widest(&folded) <= 100, "{} columns", widest(&folded));
    let narrow = stdout(&["resolve", "box-stack", "--width", "60"]);
    assert!(widest(&narrow) <= 60, "{} columns", widest(&narrow));
    let whole = stdout(&["resolve", "box-stack", "--width", "0"]);
    assert!(widest(&whole) > 500, "{} columns", widest(&whole));
    // Folding moves line breaks only.
    let words = |t: &str| t.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(words(&folded), words(&whole));
    assert_eq!(words(&narrow), words(&whole));
    // A continuation hangs under the iteration's text, not at the margin.
    let p0 = folded
        .lines()
        .position(|l| l.starts_with("   p0 "))
        .unwrap();
    let next = folded.lines().nth(p0 + 1).unwrap();
    assert!(
        next.starts_with("         ") && !next.starts_with("          "),
        "{next:?}"
    );
}

#[test]
fn markdown_tables_are_never_folded() {
    let md = stdout(&["resolve", "box-stack", "--format", "md"]);
    assert_eq!(
        md,
        stdout(&["resolve", "box-stack", "--format", "md", "--width", "40"])
    );
    assert!(md
        .lines()
        .any(|l| l.starts_with('|') && l.chars().count() > 40));
}

#[test]
fn simulate_prints_a_summary_and_the_table_on_request() {
    let summary = stdout(&["simulate", "stack-5"]);
    assert!(summary.lines().count() < 80, "{summary}");
    for part in [
        "600 steps of dt = 0.0166667 s (10 s), 6 bodies (5 movable)",
        "energy (J)           122.625 at t = 0 s → ",
        "deepest penetration  ",
        "events: ",
        "final state (t = 10 s):",
        "   box5: position (",
        "--table",
    ] {
        assert!(summary.contains(part), "no {part:?} in:\n{summary}");
    }
    assert!(widest(&summary) <= 100);
    // The summary reads every step: `--every` thins the table only.
    assert_eq!(summary, stdout(&["simulate", "stack-5", "--every", "100"]));
    let table = stdout(&["simulate", "stack-5", "--table"]);
    let rows = table
        .lines()
        .filter(|l| {
            l.split_whitespace()
                .next()
                .is_some_and(|w| w.parse::<u64>().is_ok())
        })
        .count();
    assert_eq!(rows, 601, "a row for step 0 and each of 600 steps");
    let json = |extra: &[&str]| {
        let mut args = vec![
            "simulate",
            "ball-drop",
            "--format",
            "json",
            "--every",
            "500",
        ];
        args.extend_from_slice(extra);
        stdout(&args)
    };
    assert_eq!(json(&[]), json(&["--table", "--width", "20"]));
}

#[test]
fn the_film_strip_has_a_legend_for_its_dashed_boxes() {
    let svg = stdout(&["simulate", "stack-5", "--format", "svg"]);
    let legend = svg.split(r#"<g class="legend""#).nth(1).expect("a legend");
    let legend = legend.split("</g>").next().unwrap();
    for label in ["awake", "asleep (dashed)", "immovable", "contact point"] {
        assert!(legend.contains(label), "no {label:?} in the legend");
    }
    assert!(legend.contains(r#"stroke-dasharray="4 3""#));
}

/// `contact-lab ARGS` run to success, its stdout.
fn text_of(args: &[String]) -> String {
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    stdout(&refs)
}

/// Every line of `text` no wider than `width`, else the lines that are.
fn fits(what: &str, text: &str, width: usize) {
    let wide: Vec<&str> = text.lines().filter(|l| l.chars().count() > width).collect();
    assert!(
        wide.is_empty(),
        "{what} --width {width}: {} line(s) wider, first {:?}",
        wide.len(),
        wide[0]
    );
}

#[test]
fn solve_check_detect_and_study_fold_every_lesson_and_scene_to_the_width() {
    use contact_lab::lesson::embedded;
    let lessons = embedded::ids();
    let scenes = embedded::scene_ids();
    for width in [60usize, 80, 100] {
        let w = width.to_string();
        let with = |args: &[&str]| -> Vec<String> {
            args.iter()
                .map(|a| a.to_string())
                .chain(["--width".to_string(), w.clone()])
                .collect()
        };
        for id in &lessons {
            for args in [
                with(&["solve", id, "--all-contacts"]),
                with(&["solve", id, "--compare-friction"]),
                with(&["detect", id]),
            ] {
                fits(&args.join(" "), &text_of(&args), width);
            }
        }
        for id in &scenes {
            for args in [with(&["detect", id]), with(&["detect", id, "--toi"])] {
                fits(&args.join(" "), &text_of(&args), width);
            }
        }
        // `check` exits 0: every printed number agrees or is a known erratum.
        fits("check", &text_of(&with(&["check"])), width);
        let study = with(&[
            "study",
            "ramp-stick",
            "--quick",
            "--no-timing",
            "--seconds",
            "0.2",
        ]);
        fits("study", &text_of(&study), width);
    }
}

#[test]
fn solve_and_check_fold_by_moving_line_breaks_only() {
    let words = |t: &str| t.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    for args in [&["solve", "rod-reverses"][..], &["check", "lecture-1"][..]] {
        let whole = stdout(&[args, &["--width", "0"]].concat());
        let narrow = stdout(&[args, &["--width", "60"]].concat());
        assert!(widest(&whole) > 200, "{args:?}: {} columns", widest(&whole));
        assert_eq!(words(&narrow), words(&whole), "{args:?}");
    }
}

#[test]
fn a_wide_table_folds_into_blocks_that_keep_each_row_named() {
    // The study's table: knob and value start every block's rows.
    let args = [
        "study",
        "ramp-stick",
        "--quick",
        "--no-timing",
        "--seconds",
        "0.2",
    ];
    let whole = stdout(&[&args[..], &["--width", "0"]].concat());
    let narrow = stdout(&[&args[..], &["--width", "60"]].concat());
    assert!(widest(&whole) > 120);
    let heads: Vec<&str> = narrow
        .lines()
        .filter(|l| l.starts_with("  knob       value "))
        .collect();
    assert!(heads.len() >= 3, "{narrow}");
    for column in ["visits/step", "pen. left", "energy gain", "error", "front"] {
        assert!(
            heads.iter().any(|h| h.contains(column)),
            "no block holds {column}: {heads:?}"
        );
    }
    let f32_rows = narrow
        .lines()
        .filter(|l| l.starts_with("  precision  f32"))
        .count();
    assert_eq!(f32_rows, heads.len(), "the f32 row in each block");
    // detect's GJK table: one block unfolded, the iteration k heading each
    // block at 60 columns.
    let whole = stdout(&["detect", "epa-edge-edge", "--width", "0"]);
    assert!(whole.contains("\nk  v_k  "), "{whole}");
    let narrow = stdout(&["detect", "epa-edge-edge", "--width", "60"]);
    for head in ["k  v_k\n", "k  simplex + w_k (✗ dropped)\n", "k  faces\n"] {
        assert!(narrow.contains(head), "no block {head:?} in:\n{narrow}");
    }
}

/// `list` folds as a table: every line within the width, each lesson's id
/// and contact count at the start of its row, the title folded under its
/// own column, and the same words as the unfolded list.
#[test]
fn list_folds_its_title_column_under_itself() {
    let whole = stdout(&["list", "--width", "0"]);
    assert!(widest(&whole) > 150, "{} columns", widest(&whole));
    let folded = stdout(&["list", "--width", "80"]);
    assert!(widest(&folded) <= 80, "{} columns", widest(&folded));
    let words = |t: &str| t.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(words(&folded), words(&whole));
    let title_column = folded.lines().next().unwrap().find("title").unwrap();
    let lecture_3 = folded
        .lines()
        .position(|l| l.starts_with("lecture-3 "))
        .expect("lecture-3's row");
    let next = folded.lines().nth(lecture_3 + 1).unwrap();
    assert_eq!(
        next.len() - next.trim_start().len(),
        title_column,
        "{next:?}"
    );
    // Piped with no --width: 100 columns.
    assert!(widest(&stdout(&["list"])) <= 100);
}
