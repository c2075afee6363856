//! Instructor tools: LaTeX that is well formed (that it compiles:
//! tests/render/latex_compiles.rs), SVG that parses, `check` exit codes, and exercises
//! that are deterministic, valid lessons, and practise what they say.

use crate::common;

use std::path::Path;

use assert_cmd::Command;
use contact_lab::exercise::{self, Kind};
use contact_lab::format::Fmt;
use contact_lab::lesson::validate;
use contact_lab::render::{self, svg::Plane};
use predicates::str::contains;

fn cli() -> Command {
    Command::cargo_bin("contact-lab").unwrap()
}

/// Runs the CLI with `args`, asserts success, returns stdout as text.
fn stdout(args: &[&str]) -> String {
    String::from_utf8(
        cli()
            .args(args)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone(),
    )
    .unwrap()
}

/// Every LaTeX document the tool writes: each lesson's worked solution and
/// exercise sheets of every kind.
fn latex_documents() -> Vec<(String, String)> {
    let fmt = Fmt::default();
    let mut docs: Vec<(String, String)> = common::all_lessons()
        .iter()
        .map(|l| {
            let traces: Vec<_> = (0..l.contacts.len())
                .map(|k| contact_lab::worked_solution(l, k))
                .collect();
            (
                l.id.clone(),
                render::contact::latex::document(&traces, &fmt, false),
            )
        })
        .collect();
    for kind in [None, Some(Kind::Frictionless), Some(Kind::Penetration)] {
        let e = exercise::generate(3, kind, 4).unwrap();
        let r = exercise::sheet::Request {
            seed: 3,
            kind: "mixed",
            count: 4,
        };
        docs.push((
            format!("exercises {kind:?}"),
            exercise::sheet::latex(&e, &r, true, &fmt),
        ));
    }
    docs
}

/// Checks braces (outside `\{`, `\}`), `\begin`/`\end` pairs, and inline `$`
/// pairs per paragraph; returns the first problem.
fn latex_structure(doc: &str) -> Result<(), String> {
    let mut envs: Vec<String> = Vec::new();
    let mut depth: i64 = 0;
    let chars: Vec<char> = doc.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '\\' => {
                let rest: String = chars[i..].iter().take(200).collect();
                for (cmd, open) in [("\\begin{", true), ("\\end{", false)] {
                    if let Some(after) = rest.strip_prefix(cmd) {
                        let name = after.split('}').next().unwrap().to_string();
                        if open {
                            envs.push(name);
                        } else if envs.pop().as_deref() != Some(name.as_str()) {
                            return Err(format!(
                                "\\end{{{name}}} does not close the open environment"
                            ));
                        }
                    }
                }
                i += 2; // skip the escaped character or the command's first letter
                continue;
            }
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth < 0 {
                    return Err("a } closes nothing".into());
                }
            }
            '%' => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            _ => {}
        }
        i += 1;
    }
    if depth != 0 {
        return Err(format!("{depth} unclosed brace(s)"));
    }
    if !envs.is_empty() {
        return Err(format!("unclosed environments {envs:?}"));
    }
    for para in doc.split("\n\n") {
        let dollars = para.replace("\\$", "").matches('$').count();
        if dollars % 2 != 0 {
            return Err(format!("odd number of $ in paragraph: {para}"));
        }
    }
    // Nothing pdflatex cannot read: non-ASCII only as Latin letters.
    if let Some(c) = doc
        .chars()
        .find(|c| !(c.is_ascii() || (c.is_alphabetic() && (*c as u32) < 0x250)))
    {
        return Err(format!(
            "character {c:?} (U+{:04X}) left unconverted",
            c as u32
        ));
    }
    Ok(())
}

#[test]
fn latex_is_structurally_valid() {
    for (name, doc) in latex_documents() {
        assert!(doc.starts_with("\\documentclass"), "{name}");
        assert!(doc.contains("\\usepackage{amsmath}"), "{name}");
        if let Err(e) = latex_structure(&doc) {
            panic!("{name}: {e}");
        }
    }
    assert!(latex_structure("\\begin{a}\\end{b}").is_err());
    assert!(latex_structure("\\begin{a}{\\end{a}").is_err());
    assert!(latex_structure("\\{").is_ok());
    assert!(latex_structure("$x").is_err());
    assert!(latex_structure("μ").is_err());
}

#[test]
fn latex_fragment_is_the_body_only() {
    let text = stdout(&["solve", "lecture-2", "--format", "latex", "--fragment"]);
    assert!(!text.contains("\\documentclass") && !text.contains("\\begin{document}"));
    assert!(text.contains("\\begin{align*}"));
    latex_structure(&text).unwrap();
}

fn svg_ok(svg: &str, what: &str) {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("{what}: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg", "{what}");
    assert_eq!(
        root.tag_name().namespace(),
        Some("http://www.w3.org/2000/svg")
    );
    let texts: Vec<String> = root
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(str::to_string))
        .collect();
    for label in ["q", "d̂", "Legend"] {
        assert!(texts.iter().any(|t| t == label), "{what}: no label {label}");
    }
    assert!(
        root.descendants().any(|n| n.has_tag_name("title")),
        "{what}"
    );
}

#[test]
fn every_figure_parses_as_svg() {
    for lesson in common::all_lessons() {
        for k in 0..lesson.contacts.len() {
            let t = contact_lab::worked_solution(&lesson, k);
            for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
                svg_ok(
                    &render::svg::render(&t, plane),
                    &format!("{} {k} {plane:?}", lesson.id),
                );
            }
            if t.scene.impulse.is_some() {
                let svg = render::svg::render(&t, Plane::Xy);
                assert!(svg.contains(">g</text>"), "{}: impulse label", lesson.id);
            }
        }
    }
    for e in exercise::generate(11, None, 8).unwrap() {
        svg_ok(&render::svg::render(&e.trace, Plane::Xy), &e.lesson.id);
    }
}

#[test]
fn figure_writes_a_file_with_o_and_stdout_without() {
    let dir = common::scratch("figure");
    let file = dir.join("f.svg");
    cli()
        .args(["figure", "lecture-2", "-o"])
        .arg(&file)
        .assert()
        .success()
        .stdout("");
    let written = std::fs::read_to_string(&file).unwrap();
    svg_ok(&written, "figure -o");
    let leftovers: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(leftovers.len(), 1, "only the figure, no temporary file");
    assert_eq!(stdout(&["figure", "lecture-2"]), written);
    cli()
        .args(["figure", "lecture-2", "--plane", "yz"])
        .assert()
        .success();
    cli()
        .args(["figure", "lecture-2", "--contact", "3"])
        .assert()
        .code(2);
    cli().args(["figure", "no-such-lesson"]).assert().code(66);
    cli()
        .args(["figure", "lecture-2", "-o", "/nonexistent-dir/f.svg"])
        .assert()
        .code(1);
}

#[test]
fn markdown_with_figures_writes_and_links_them() {
    let dir = common::scratch("md-figures");
    let figs = dir.join("figs");
    let out = cli()
        .args([
            "solve",
            "friction-cube",
            "--all-contacts",
            "--format",
            "md",
            "--figures",
        ])
        .arg(&figs)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let md = String::from_utf8(out).unwrap();
    for k in 0..2 {
        let name = format!("friction-cube-contact-{k}.svg");
        svg_ok(&std::fs::read_to_string(figs.join(&name)).unwrap(), &name);
        assert!(
            md.contains(&format!("]({}/{name})", figs.display())),
            "link to {name}"
        );
    }
    assert!(md.contains("## Contact 0: sticks") && md.contains("## Contact 1: slides"));
}

#[test]
fn solve_format_combinations() {
    cli()
        .args(["solve", "lecture-2", "--format", "md"])
        .assert()
        .success()
        .stdout(contains("### 4. Impulse").and(contains("$$\n\\begin{aligned}")))
        .stdout(contains("### 5. Friction clamp — skipped"));
    cli()
        .args(["solve", "lecture-2", "--fragment"])
        .assert()
        .code(2)
        .stderr(contains("--fragment applies to --format latex"));
    cli()
        .args(["solve", "lecture-2", "--figures", "x"])
        .assert()
        .code(2);
    cli()
        .args([
            "solve",
            "friction-cube",
            "--format",
            "latex",
            "--compare-friction",
        ])
        .assert()
        .code(2);
    cli()
        .args(["solve", "friction-cube", "--all-contacts", "--contact", "1"])
        .assert()
        .code(2);
    let out = stdout(&[
        "solve",
        "friction-cube",
        "--all-contacts",
        "--format",
        "json",
    ])
    .into_bytes();
    let all: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(all.as_array().map(Vec::len), Some(2));
}

use predicates::prelude::PredicateBooleanExt;

fn lesson_with_printed(dir: &Path, name: &str, printed: &str) -> std::path::PathBuf {
    let base = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/lessons/lecture-2.toml"
    ))
    .unwrap();
    let start = base.find("[[printed]]").unwrap();
    let path = dir.join(name);
    std::fs::write(&path, format!("{}{printed}", &base[..start])).unwrap();
    path
}

#[test]
fn check_exit_codes() {
    cli()
        .arg("check")
        .assert()
        .code(0)
        .stdout(contains("Every disagreement is a known erratum."));
    cli().args(["check", "no-such-lesson"]).assert().code(66);
    let dir = common::scratch("check");
    let new = lesson_with_printed(
        &dir,
        "new.toml",
        "[[printed]]\nstage = \"impulse\"\nvalue = \"impulse_world\"\nprinted = [0, 19.5, 0]\nwhere = \"a slide\"\n",
    );
    cli()
        .arg("check")
        .arg(&new)
        .assert()
        .code(1)
        .stdout(contains("NEW DISAGREEMENT"))
        .stderr(contains("1 new disagreement"));
    let stale = lesson_with_printed(
        &dir,
        "stale.toml",
        "[[printed]]\nstage = \"impulse\"\nvalue = \"impulse_world\"\nprinted = [0, 18.7337, 0]\nwhere = \"a slide\"\nerratum = \"was wrong once\"\n",
    );
    cli()
        .arg("check")
        .arg(&stale)
        .assert()
        .code(1)
        .stdout(contains("STALE ERRATUM"));
    let missing = lesson_with_printed(
        &dir,
        "missing.toml",
        "[[printed]]\nstage = \"impulse\"\nvalue = \"impulse_wrold\"\nprinted = 1\nwhere = \"a typo\"\n",
    );
    let out = cli()
        .args(["check", "--format", "json"])
        .arg(&missing)
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let json: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let item = &json["items"][0];
    assert_eq!(item["computed"], serde_json::Value::Null);
    assert_eq!(item["agrees"], false);
    assert_eq!(item["status"], "not_computed");
}

#[test]
fn the_same_seed_gives_the_same_bytes() {
    let run = |args: &[&str]| {
        cli()
            .args(args)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone()
    };
    for format in ["md", "latex", "toml"] {
        let count = if format == "toml" { "1" } else { "5" };
        let args = [
            "exercise",
            "--seed",
            "1",
            "--count",
            count,
            "--answers",
            "--format",
            format,
        ];
        let a = run(&args);
        assert_eq!(a, run(&args), "{format}");
        let mut other = args;
        other[2] = "2";
        assert_ne!(a, run(&other), "{format}: seeds 1 and 2 differ");
    }
    // A longer sheet starts with the shorter one's exercises.
    let three = exercise::generate(9, None, 3).unwrap();
    let five = exercise::generate(9, None, 5).unwrap();
    for (a, b) in three.iter().zip(&five) {
        assert_eq!(a.toml, b.toml);
    }
}

/// Every generated scene is a valid lesson file, solves with every check
/// passing, and practises its kind.
#[test]
fn every_generated_scene_is_a_valid_lesson_that_solves_cleanly() {
    let mut regimes = std::collections::BTreeMap::new();
    for seed in 0..25 {
        for kind in Kind::ALL {
            for e in exercise::generate(seed, Some(kind), 2).unwrap() {
                let lesson = validate::parse("generated.toml", &e.toml)
                    .unwrap_or_else(|err| panic!("{err}\n{}", e.toml));
                assert!(
                    lesson.warnings.is_empty(),
                    "{:?}\n{}",
                    lesson.warnings,
                    e.toml
                );
                let t = contact_lab::worked_solution(&lesson, 0);
                assert_eq!(t, e.trace, "the TOML round-trips to the same solution");
                for v in &t.verdicts {
                    assert_ne!(
                        v.passed,
                        Some(false),
                        "{}: {} ({})\n{}",
                        lesson.id,
                        v.label,
                        v.detail,
                        e.toml
                    );
                }
                assert!(exercise::suits(kind, &lesson, &t));
                let regime = match t.value("friction_clamp", "regime") {
                    Some(contact_lab::trace::Value::Text(r)) => Some(r.clone()),
                    _ => None,
                };
                match kind {
                    Kind::StaticFriction => assert_eq!(regime.as_deref(), Some("static")),
                    Kind::DynamicFriction => assert_eq!(regime.as_deref(), Some("dynamic")),
                    Kind::Frictionless => assert!(regime.is_none()),
                    Kind::Penetration => {
                        assert!(t.stage("nonlinear_projection").unwrap().skipped.is_none())
                    }
                }
                *regimes.entry(format!("{kind:?}")).or_insert(0) += 1;
                // Numbers in the lecture's style: at most four decimals.
                for line in e
                    .toml
                    .lines()
                    .filter(|l| l.contains('[') || l.contains(" = "))
                {
                    for word in line.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                    {
                        if let Some((_, frac)) = word.split_once('.') {
                            assert!(frac.len() <= 4, "{word} in {line}");
                        }
                    }
                }
            }
        }
    }
    assert_eq!(regimes.len(), 4);
}

#[test]
fn exercise_usage_errors() {
    cli()
        .args([
            "exercise", "--seed", "1", "--count", "3", "--format", "toml",
        ])
        .assert()
        .code(2)
        .stderr(contains("--dir"));
    cli()
        .args(["exercise", "--seed", "1", "--count", "0"])
        .assert()
        .code(2);
    cli().args(["exercise"]).assert().code(2);
    let dir = common::scratch("exercise-dir");
    let out = cli()
        .args([
            "exercise", "--seed", "4", "--count", "3", "--format", "toml", "--dir",
        ])
        .arg(&dir)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert_eq!(String::from_utf8(out).unwrap().lines().count(), 3);
    for n in 1..=3 {
        let path = dir.join(format!("exercise-4-{n}.toml"));
        cli().arg("solve").arg(&path).assert().success();
    }
}

#[test]
fn exercise_sheet_has_questions_and_answers() {
    let md = stdout(&[
        "exercise",
        "--seed",
        "1",
        "--count",
        "5",
        "--answers",
        "--format",
        "md",
    ]);

    assert_eq!(
        md.matches("\n## Exercise ").count(),
        10,
        "5 questions + 5 answers"
    );
    assert!(md.contains("# Answers"));
    assert!(md.contains("#### 1. Contact frame"));
    assert!(!stdout(&["exercise", "--seed", "1", "--count", "5"]).contains("# Answers"));
}
