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

/// Whether `needle` occurs in `hay` as a whole number: not inside a longer
/// one (`0.5` is not in `10.52`).
fn has_number(hay: &str, needle: &str) -> bool {
    let part = |c: Option<char>| c.is_some_and(|c| c.is_ascii_digit() || c == '.');
    hay.match_indices(needle).any(|(i, _)| {
        let before = hay[..i].chars().next_back();
        let after = hay[i + needle.len()..].chars().next();
        // `-0.5` does not hold the answer 0.5.
        let negated = before == Some('-') && !needle.starts_with('-');
        !part(before) && !negated && !part(after)
    })
}

/// Every number a set-up gives (the lesson's inputs and the arms r = q - p
/// the figure draws): an answer made only of these is not given away.
fn givens(l: &contact_lab::lesson::Lesson) -> Vec<f64> {
    let mut out = vec![0.0];
    let c = &l.contacts[0];
    out.extend(c.point.iter().chain(c.normal.iter()));
    out.extend([
        c.penetration,
        c.restitution,
        c.static_friction,
        c.dynamic_friction,
    ]);
    for b in &l.bodies {
        out.push(b.mass);
        out.extend(b.position.iter().chain(b.velocity.iter()));
        out.extend(b.angular_velocity.iter());
        out.extend(b.orientation.coords.iter());
        out.extend((c.point - b.position).iter());
        if let Some(m) = b.inertia {
            out.extend(m.iter());
        }
    }
    out
}

/// The LaTeX set-up pictures of a sheet: every line inside the picture's
/// box (the floor's ticks once printed over the caption), and a caption
/// that names only what a set-up draws (no velocity after, no impulse, no
/// outline after the projection).
fn set_up_picture(tex: &str, seed: u64) {
    let mut size = [0.0f64; 2];
    for line in tex.lines() {
        let numbers = |s: &str| -> Vec<f64> {
            s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                .filter_map(|t| t.parse().ok())
                .collect()
        };
        if let Some(rest) = line.strip_prefix("\\begin{picture}") {
            let n = numbers(rest);
            size = [n[0], n[1]];
        } else if let Some(rest) = line.strip_prefix("\\qbezier") {
            for p in numbers(rest).chunks(2) {
                assert!(
                    (-0.5..=size[0] + 0.5).contains(&p[0])
                        && (-0.5..=size[1] + 0.5).contains(&p[1]),
                    "seed {seed}: {line} outside the picture {size:?}"
                );
            }
        } else if line.starts_with("{\\footnotesize") {
            for word in ["after", "impulse", "$v'$", "$g$"] {
                assert!(
                    !line.contains(word),
                    "seed {seed}: {word} in the caption {line}"
                );
            }
        }
    }
}

/// A set-up shows only the set-up (issue 40): over 20 seeds of five mixed
/// exercises, every short answer of the key (full values, as the JSON of
/// the worked solution holds them), formatted as the figure's legend, the
/// text and the answer key format numbers, is found in no set-up SVG and
/// nowhere in the Markdown or LaTeX question sheet. An answer made only of
/// numbers the set-up gives (ω′ = ω when the impulse has no arm) is skipped.
#[test]
fn no_answer_shows_in_a_set_up_figure_or_the_question_sheet() {
    use contact_lab::exercise::sheet::short_answers;
    use contact_lab::format::Fmt;
    use contact_lab::trace::Value;
    let formats = [Fmt::new(4), Fmt::default(), Fmt::new(10)];
    let dir = common::scratch("exercise-set-up");
    let (mut searched, mut moved) = (0, 0);
    for seed in 1..=20u64 {
        let s = seed.to_string();
        let md = dir.join(format!("sheet-{seed}.md"));
        cli()
            .args(["exercise", "--seed", &s, "--count", "5", "-o"])
            .arg(&md)
            .assert()
            .success();
        let exercises = contact_lab::exercise::generate(seed, None, 5).unwrap();
        // The LaTeX sheet as `--format latex` prints it (one process fewer).
        let request = contact_lab::exercise::sheet::Request {
            seed,
            kind: "mixed",
            count: 5,
        };
        let tex = contact_lab::exercise::sheet::latex(&exercises, &request, false, &Fmt::default());
        set_up_picture(&tex, seed);
        let md = std::fs::read_to_string(&md).unwrap();
        // Each exercise's part of each sheet (another's inputs may be this
        // one's answers), the picture's coordinates left out.
        let md_parts: Vec<&str> = md.split("\n## ").skip(1).collect();
        let tex: String = tex
            .lines()
            .filter(|l| !l.starts_with("\\qbezier") && !l.starts_with("\\begin{picture}"))
            .map(|l| match l.strip_prefix("\\put(") {
                Some(rest) => rest.split_once(')').map_or(rest, |(_, text)| text),
                None => l,
            })
            .collect::<Vec<_>>()
            .join("\n");
        let tex_parts: Vec<&str> = tex.split("\\subsection*{").skip(1).collect();
        assert_eq!((md_parts.len(), tex_parts.len()), (5, 5));
        for (i, e) in exercises.iter().enumerate() {
            moved += usize::from(same_set_up_whatever_the_answers(e, seed));
            let sheet = format!("{}\n{}", md_parts[i], tex_parts[i]);
            let file = dir.join(format!("sheet-{seed}-{}.svg", i + 1));
            let svg = std::fs::read_to_string(&file).unwrap();
            // The projection's move (p to p′, the outline after) is an answer too.
            assert!(
                !svg.contains("stroke=\"#E69F00\""),
                "seed {seed}, exercise {}: the set-up figure draws the projection's move",
                i + 1
            );
            let doc = roxmltree::Document::parse(&svg).unwrap();
            let figure: String = doc
                .descendants()
                .filter_map(|n| n.text())
                .collect::<Vec<_>>()
                .join("\n");
            let hay = format!("{figure}\n{sheet}");
            let given = givens(&e.lesson);
            for a in short_answers(e.kind, &e.trace) {
                // Words (static, dynamic) are the sheet's own vocabulary.
                let rows: Vec<Vec<f64>> = match a.value {
                    Value::Matrix(m) => m.iter().map(|r| r.to_vec()).collect(),
                    Value::Text(_) | Value::List(_) => continue,
                    v => vec![v.numbers()],
                };
                for row in rows {
                    let (open, close) = match a.value {
                        Value::Quaternion(_) => ("[", "]"),
                        _ => ("(", ")"),
                    };
                    let mut needles = vec![];
                    // As the figure and the text format numbers, and to four
                    // decimals as the answer key does.
                    let shows: [&dyn Fn(f64) -> String; 4] = [
                        &|x| formats[0].num(x),
                        &|x| formats[1].num(x),
                        &|x| formats[2].num(x),
                        &|x| formats[0].fixed(x, 4),
                    ];
                    // A vector's round-off components show as 0, as `Fmt::list` shows them.
                    let row = contact_lab::format::snap_zeros(&row);
                    for show in shows {
                        let shown: Vec<String> = row.iter().map(|x| show(*x)).collect();
                        if shown.iter().all(|x| given.iter().any(|g| show(*g) == *x)) {
                            continue;
                        }
                        // A small whole number alone is a label's too
                        // (body 2, question 3, sphere2).
                        if let [x] = row.as_slice() {
                            if x.fract() == 0.0 && x.abs() <= 10.0 {
                                continue;
                            }
                        }
                        needles.push(match shown.as_slice() {
                            [x] => x.clone(),
                            xs => format!("{open}{}{close}", xs.join(", ")),
                        });
                    }
                    for needle in &needles {
                        searched += 1;
                        assert!(
                            !has_number(&hay, needle),
                            "seed {seed}, exercise {} ({:?}): the answer {} = {needle} is in its set-up figure or the question sheet",
                            i + 1,
                            e.kind,
                            a.label
                        );
                    }
                }
            }
        }
    }
    assert!(searched > 2000, "{searched}");
    assert!(
        moved > 50,
        "{moved} of 100 exercises' answers moved with restitution"
    );
}

/// The set-up figures (SVG and LaTeX) of exercise `e` are byte for byte
/// those of the same set-up with another restitution, which changes only
/// the answers: nothing in them (an arrow's scale, which spins are worth
/// drawing) is measured on the speeds after the impulse. Whether the
/// velocities after moved (a penetration exercise's may not).
fn same_set_up_whatever_the_answers(e: &contact_lab::exercise::Exercise, seed: u64) -> bool {
    use contact_lab::exercise::sheet::figure_svg;
    use contact_lab::physics::StageId;
    use contact_lab::render::contact::latex_figure::picture;
    let mut lesson = e.lesson.clone();
    let r = lesson.contacts[0].restitution;
    lesson.contacts[0].restitution = if r < 0.5 { r + 0.45 } else { r - 0.45 };
    let solution = contact_lab::physics::solve(&lesson.problem::<f64>(0));
    let trace = contact_lab::trace::build(&lesson, 0, &solution);
    let what = format!("seed {seed}, exercise {} ({:?})", e.number, e.kind);
    let other = contact_lab::exercise::Exercise {
        lesson,
        solution,
        trace,
        ..e.clone()
    };
    let velocity = |t: &contact_lab::trace::Trace| {
        t.scene
            .bodies
            .iter()
            .map(|b| b.velocity_after)
            .collect::<Vec<_>>()
    };
    let moved = velocity(&e.trace) != velocity(&other.trace);
    assert_eq!(figure_svg(e), figure_svg(&other), "{what}: the set-up SVG");
    let stage = Some(StageId::ContactFrame);
    assert_eq!(
        picture(&e.trace.scene, stage),
        picture(&other.trace.scene, stage),
        "{what}: the set-up LaTeX picture"
    );
    moved
}

/// Every quantity a sheet shows carries its unit (issue 40): the scene
/// table and the contact line in Markdown and LaTeX (units upright in
/// maths), and the set-up figure's legend, which gives ω but not ω′.
#[test]
fn a_sheet_and_its_set_up_figure_give_units() {
    let md = stdout(&["exercise", "--seed", "1", "--count", "2"]);
    for row in [
        "| mass m | 8 kg | ∞ (immovable) |",
        "| shape | cube, sides 12 m | half-space |",
        "| inertia tensor I | diag(192, 192, 192) kg·m² | – |",
        "| position p | (3, 13.44, 0) m | (-1.08, 6, 0) m |",
        "| velocity v | (-2.21, -1.68, 0) m/s | – |",
        "| angular velocity ω | (0, 0, 0) rad/s | – |",
    ] {
        assert!(md.contains(row), "{row}");
    }
    assert!(md.contains("Contact point q = (-1.08, 6, 0) m; normal d̂ = (0, 1, 0)"));
    let tex = stdout(&[
        "exercise", "--seed", "1", "--count", "1", "--format", "latex",
    ]);
    assert!(
        tex.contains("diag(192, 192, 192)$\\,\\mathrm{kg\\cdot m^2}$"),
        "{tex}"
    );
    assert!(tex.contains("-{}-seed 1"), "a flag is not an en dash");
    let dir = common::scratch("exercise-units");
    cli()
        .args(["exercise", "--seed", "1", "--count", "2", "-o"])
        .arg(dir.join("week3.md"))
        .assert()
        .success();
    let svg = std::fs::read_to_string(dir.join("week3-2.svg")).unwrap();
    for line in [
        "q contact point (14.72, 10, 0) m",
        "v₁ before (0.91, -1.07, 0) m/s",
        "ω₁ (0, 0, 0.66) rad/s",
        "Velocities to scale;",
    ] {
        assert!(svg.contains(&format!(">{line}<")), "{line}\n{svg}");
    }
}
