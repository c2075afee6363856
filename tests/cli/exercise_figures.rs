//! Exercise sheets include the figure of each exercise (issue 16, item 9):
//! Markdown on stdout embeds it as a `data:` URI image, Markdown written
//! with `--output FILE` writes `FILE-N.svg` beside the sheet and links it,
//! and the LaTeX sheet draws it in the question and in the worked solution.

use crate::common;

use assert_cmd::Command;
use base64::Engine;

fn cli() -> Command {
    Command::cargo_bin("contact-lab").unwrap()
}

fn stdout(args: &[&str]) -> String {
    let out = cli()
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    String::from_utf8(out).unwrap()
}

/// The SVG parses, is an SVG, and shows the set-up: q labelled, no impulse.
fn set_up_svg(svg: &str, what: &str) {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(doc.root_element().tag_name().name(), "svg", "{what}");
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect();
    assert!(texts.contains(&"q"), "{what}: q");
    assert!(
        !texts.contains(&"g"),
        "{what}: the question's figure shows no impulse"
    );
}

#[test]
fn a_markdown_sheet_on_stdout_embeds_each_figure() {
    let md = stdout(&["exercise", "--seed", "3", "--count", "3", "--format", "md"]);
    let images: Vec<&str> = md
        .lines()
        .filter(|l| l.starts_with("<img alt=\"Exercise "))
        .collect();
    assert_eq!(images.len(), 3, "one figure per exercise");
    for (i, line) in images.iter().enumerate() {
        assert!(
            line.starts_with(&format!("<img alt=\"Exercise {}:", i + 1)),
            "{line}"
        );
        let data = line
            .split("src=\"data:image/svg+xml;base64,")
            .nth(1)
            .and_then(|s| s.strip_suffix("\">"))
            .expect("a base64 data URI");
        let svg = base64::engine::general_purpose::STANDARD
            .decode(data)
            .unwrap();
        set_up_svg(
            &String::from_utf8(svg).unwrap(),
            &format!("exercise {}", i + 1),
        );
    }
    // Each figure sits under its exercise's heading, before the questions.
    let first = md.find("## ").unwrap();
    let image = md.find("<img ").unwrap();
    let question = md.find("\n1. ").unwrap();
    assert!(first < image && image < question);
}

#[test]
fn a_markdown_sheet_written_to_a_file_links_svgs_beside_it() {
    let dir = common::scratch("exercise-md");
    let sheet = dir.join("week 3.md");
    cli()
        .args([
            "exercise",
            "--seed",
            "3",
            "--count",
            "2",
            "--answers",
            "--output",
        ])
        .arg(&sheet)
        .assert()
        .success()
        .stdout("");
    let md = std::fs::read_to_string(&sheet).unwrap();
    assert!(!md.contains("data:image"), "files are linked, not embedded");
    for n in 1..=2 {
        let name = format!("week 3-{n}.svg");
        let svg = std::fs::read_to_string(dir.join(&name)).unwrap();
        set_up_svg(&svg, &name);
        assert!(
            md.contains(&format!("](week%203-{n}.svg)")),
            "link to {name}"
        );
    }
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(
        files,
        ["week 3-1.svg", "week 3-2.svg", "week 3.md"],
        "no temporary files"
    );
    // The rest of the sheet is the stdout sheet's, but for the figures.
    let on_stdout = stdout(&["exercise", "--seed", "3", "--count", "2", "--answers"]);
    let strip = |s: &str| -> Vec<String> {
        s.lines()
            .filter(|l| !l.starts_with("<img ") && !l.starts_with("![Exercise "))
            .map(str::to_string)
            .collect()
    };
    assert_eq!(strip(&md), strip(&on_stdout));
}

#[test]
fn the_latex_sheet_draws_each_exercise_in_the_question_and_the_answer() {
    let tex = stdout(&[
        "exercise", "--seed", "5", "--count", "3", "--format", "latex",
    ]);
    assert_eq!(tex.matches("\\begin{picture}").count(), 3);
    let tex = stdout(&[
        "exercise",
        "--seed",
        "5",
        "--count",
        "3",
        "--format",
        "latex",
        "--answers",
    ]);
    assert_eq!(tex.matches("\\begin{picture}").count(), 6);
    // --output writes the same document to a file.
    let dir = common::scratch("exercise-tex");
    let file = dir.join("sheet.tex");
    cli()
        .args([
            "exercise",
            "--seed",
            "5",
            "--count",
            "3",
            "--format",
            "latex",
            "--answers",
            "-o",
        ])
        .arg(&file)
        .assert()
        .success()
        .stdout("");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), tex);
    cli()
        .args([
            "exercise", "--seed", "5", "--format", "toml", "--count", "2", "--dir",
        ])
        .arg(&dir)
        .arg("-o")
        .arg(dir.join("x.toml"))
        .assert()
        .code(2);
}
