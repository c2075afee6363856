//! Slide-ready numbers (issue 28, item 2): a value that is zero up to
//! round-off against the scale of its quantity prints as 0, whatever
//! `--digits` says (`resolve box-stack --digits 3` printed `-6.93889e-18`).

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

/// Every number of `text` that is below 1e-14 in size but not 0.
fn round_off(text: &str) -> Vec<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-'))
        .filter(|w| w.contains('e'))
        .filter_map(|w| w.parse::<f64>().ok().map(|x| (w, x)))
        .filter(|(_, x)| *x != 0.0 && x.abs() < 1e-14)
        .map(|(w, _)| w.to_string())
        .collect()
}

#[test]
fn resolve_box_stack_prints_no_round_off() {
    for digits in ["3", "6"] {
        let out = stdout(&["resolve", "box-stack", "--digits", digits]);
        assert!(
            out.contains("penetration 0.0467 → 0;") || digits != "3",
            "{out}"
        );
        assert_eq!(round_off(&out), Vec::<String>::new(), "--digits {digits}");
    }
}

#[test]
fn solve_box_stack_prints_no_round_off_in_vectors() {
    let out = stdout(&["solve", "box-stack", "--digits", "3"]);
    assert!(out.contains("(0.0739, 0, -0.0892)"), "{out}");
    // A check's error is a size of its own (1.11e-16 is the round-off), so
    // only the vectors are read here.
    let vectors: String = out
        .split('(')
        .skip(1)
        .filter_map(|s| s.split(')').next())
        .collect::<Vec<_>>()
        .join(" ");
    assert_eq!(round_off(&vectors), Vec::<String>::new());
}
