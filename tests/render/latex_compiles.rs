//! The LaTeX the tool writes compiles (issue 28, item 7): every lesson's
//! worked solution, exercise sheets of every kind with their answers, and
//! the glossary, run through the installed TeX engine (pdflatex, else
//! lualatex, else tectonic). Without an engine the test skips and says why;
//! in CI (`CI` set) it fails instead, since `.ci/run` installs one.

use crate::common;

use contact_lab::exercise::{self, Kind};
use contact_lab::format::Fmt;
use contact_lab::render;

/// The engine to compile with, and the arguments before the file name.
fn tex_engine() -> Option<(std::path::PathBuf, &'static [&'static str])> {
    let path = std::env::var_os("PATH")?;
    let dirs: Vec<_> = std::env::split_paths(&path).collect();
    let find = |name: &str| dirs.iter().map(|d| d.join(name)).find(|p| p.is_file());
    const LATEX: &[&str] = &["-interaction=nonstopmode", "-halt-on-error"];
    find("pdflatex")
        .map(|p| (p, LATEX))
        .or_else(|| find("lualatex").map(|p| (p, LATEX)))
        .or_else(|| find("tectonic").map(|p| (p, &["--chatter", "minimal"][..])))
}

/// Every LaTeX document: (name, text).
fn documents() -> Vec<(String, String)> {
    let fmt = Fmt::default();
    let mut docs: Vec<(String, String)> = common::all_lessons()
        .iter()
        .map(|l| {
            let traces: Vec<_> = (0..l.contacts.len())
                .map(|k| contact_lab::worked_solution(l, k))
                .collect();
            (
                format!("worked solution of {}", l.id),
                render::contact::latex::document(&traces, &fmt, false),
            )
        })
        .collect();
    let kinds = [
        (None, "mixed"),
        (Some(Kind::Frictionless), "frictionless"),
        (Some(Kind::StaticFriction), "static-friction"),
        (Some(Kind::DynamicFriction), "dynamic-friction"),
        (Some(Kind::Penetration), "penetration"),
    ];
    for (kind, name) in kinds {
        let e = exercise::generate(3, kind, 4).unwrap();
        let r = exercise::sheet::Request {
            seed: 3,
            kind: name,
            count: 4,
        };
        for answers in [false, true] {
            docs.push((
                format!("exercise sheet {name} (answers: {answers})"),
                exercise::sheet::latex(&e, &r, answers, &fmt),
            ));
        }
    }
    docs.push(("glossary".into(), render::glossary::latex()));
    docs
}

#[test]
fn the_glossary_subscripts_the_whole_c_to_w() {
    let tex = render::glossary::latex();
    assert!(
        tex.contains("$M_{C\\to W}$"),
        "no M_{{C→W}} in the glossary"
    );
    assert!(!tex.contains("M_C\\to W"));
}

#[test]
fn worked_solutions_exercise_sheets_and_the_glossary_compile() {
    let Some((engine, args)) = tex_engine() else {
        let why = "no TeX engine on PATH (pdflatex, lualatex or tectonic; apt-get install texlive-latex-base)";
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must compile the LaTeX, but there is {why}: .ci/run installs one"
        );
        println!("skipping: {why}");
        return;
    };
    let dir = common::scratch("latex-compiles");
    let docs = documents();
    assert!(docs.len() > 20, "{} documents", docs.len());
    for (i, (name, doc)) in docs.into_iter().enumerate() {
        let file = format!("doc{i}.tex");
        std::fs::write(dir.join(&file), &doc).unwrap();
        let out = std::process::Command::new(&engine)
            .args(args)
            .arg(&file)
            .current_dir(&dir)
            .output()
            .unwrap();
        let log = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{name} does not compile with {}:\n{log}",
            engine.display()
        );
        assert!(!log.contains("\n! "), "{name}: TeX error:\n{log}");
        assert!(dir.join(format!("doc{i}.pdf")).is_file(), "{name}: no PDF");
    }
}
