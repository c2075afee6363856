//! Graded answers (issue 16, item 6): `exercise --answer-template` gives a
//! file to fill in, `exercise --grade FILE` grades it against the worked
//! solution with the lecture check's tolerance; `--answers` gives the key to
//! four decimals, as the sheet asks.

use assert_cmd::Command;
use contact_lab::render::fill::Fill;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn the_answer_key_is_given_to_four_decimals() {
    let (code, sheet, _) = run(&["exercise", "--seed", "1", "--count", "1", "--answers"]);
    assert_eq!(code, 0);
    assert!(sheet.contains("Work to four decimals"));
    let key = &sheet[sheet.find("# Answers").unwrap()..];
    let line = key.lines().find(|l| l.starts_with("- Δv = ")).unwrap();
    assert_eq!(line, "- Δv = 2.0160 m/s");
    let g = key.lines().find(|l| l.starts_with("- g_world = ")).unwrap();
    assert_eq!(g, "- g_world = (0.0000, 9.5229, 0.0000) N·s");
}

#[test]
fn a_filled_answer_file_is_graded_with_the_right_answers_and_a_score() {
    let (code, template, _) = run(&[
        "exercise",
        "--seed",
        "1",
        "--count",
        "1",
        "--answer-template",
    ]);
    assert_eq!(code, 0);
    assert!(template.contains("seed = 1\n"), "{template}");
    // One right (from the key, four decimals), one a little off, one wrong.
    let filled = template
        .replace("dv = \"\"", "dv = \"2.0160\"")
        .replace("v_s = \"\"", "v_s = \"−1.6801 m/s\"")
        .replace("dq_t = \"\"", "dq_t = 0.5");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("answers.toml");
    std::fs::write(&path, filled).unwrap();
    let (code, report, err) = run(&["exercise", "--grade", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(report.contains("✓ Δv = 2.0160"), "{report}");
    assert!(report.contains("✓ v_s = −1.6801 m/s"), "{report}");
    assert!(
        report.contains("✗ Δq̇_t = 0.5   right: 0.2117 (m/s)/(N·s), difference -0.2883"),
        "{report}"
    );
    assert!(
        report.contains("· g_world: no answer (right: (0.0000, 9.5229, 0.0000) N·s)"),
        "{report}"
    );
    let asked = template.matches(" = \"\"").count();
    assert!(
        report.contains(&format!(
            "\nScore: 2/{asked} ({} %): 2 right, 1 wrong, {} blank\n",
            (200.0 / asked as f64).round(),
            asked - 3
        )),
        "{report}"
    );
    assert!(
        report.contains("Wrong (1):\n   exercise 1: Δq̇_t\n"),
        "{report}"
    );
}

/// A partly filled sheet scores right / asked, not right / answered (issue
/// 40): the template of five exercises with only v_s filled in scores one
/// of every answer the sheet asks, the blanks counted and listed.
#[test]
fn a_partly_filled_sheet_counts_every_question_asked() {
    let (code, template, _) = run(&[
        "exercise",
        "--seed",
        "1",
        "--count",
        "5",
        "--answer-template",
    ]);
    assert_eq!(code, 0);
    let asked = template.matches(" = \"\"").count();
    assert!(asked > 50, "{asked}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("answers.toml");
    // The first exercise's v_s, right to four decimals.
    let filled = template.replacen("v_s = \"\"", "v_s = \"-1.6800\"", 1);
    std::fs::write(&path, &filled).unwrap();
    let (code, report, err) = run(&["exercise", "--grade", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(report.contains("✓ v_s = -1.6800"), "{report}");
    assert!(
        report.contains(&format!(
            "\nScore: 1/{asked} (2 %): 1 right, 0 wrong, {} blank\n",
            asked - 1
        )),
        "{report}"
    );
    assert!(
        report.contains(&format!(
            "Blank: {} of the {asked} answers the sheet asks",
            asked - 1
        )),
        "{report}"
    );
    assert!(report.contains("\n   exercise 5: "), "{report}");
    assert!(!report.contains("Wrong ("), "{report}");
    // The template as printed: nothing answered, 0 %.
    std::fs::write(&path, &template).unwrap();
    let (code, report, _) = run(&["exercise", "--grade", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        report.contains(&format!(
            "\nScore: 0/{asked} (0 %): 0 right, 0 wrong, {asked} blank\n"
        )),
        "{report}"
    );
    assert!(
        report.contains(&format!("Blank: all {asked} answers")),
        "{report}"
    );
}

#[test]
fn a_broken_answer_file_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("answers.toml");
    std::fs::write(&path, "count = 1\n").unwrap();
    let (code, out, err) = run(&["exercise", "--grade", path.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.contains("seed"), "{err}");
}

/// Predict mode grades what a stage reveals: every result of every stage of
/// every lesson, typed back as the text shows it, is right; the same
/// answer 10 % off is wrong.
#[test]
fn every_revealed_result_typed_as_shown_is_right_and_ten_percent_off_is_wrong() {
    use contact_lab::exercise::answer::{grade, Score};
    use contact_lab::format::Fmt;
    use contact_lab::lesson::Lesson;
    use contact_lab::trace::Value;
    let fmt = Fmt::default();
    let mut score = Score::default();
    for id in contact_lab::lesson::embedded::ids() {
        let l = Lesson::load(id).unwrap();
        for k in 0..l.contacts.len() {
            let t = contact_lab::worked_solution(&l, k);
            for step in t.stages.iter().filter(|s| s.skipped.is_none()) {
                for f in &step.formulas {
                    let Some(v) = f.result.as_ref().and_then(|r| step.lookup(r)) else {
                        continue;
                    };
                    let shown = fmt.value(v);
                    let g = grade(&shown, v);
                    assert!(
                        g.correct,
                        "{id} #{k} {}: {shown} graded wrong: {g:?}",
                        f.lhs
                    );
                    score.record(&g);
                    let off: Vec<f64> = v.numbers().iter().map(|x| x * 1.1 + 1.0).collect();
                    if !off.is_empty() {
                        let wrong = format!("({})", fmt.list(&off));
                        let expected = match v {
                            Value::Scalar(_) => fmt.list(&off),
                            _ => wrong,
                        };
                        assert!(!grade(&expected, v).correct, "{id} {}: {expected}", f.lhs);
                    }
                }
            }
        }
    }
    assert_eq!(score.correct, score.graded);
    assert!(score.graded > 500, "{}", score.summary());
}
