//! The knob table is the one declaration of every tunable: each knob is read
//! from its lesson-file tables, offered on the command line, in the TUI's
//! edit form and by the study (or says why not), documented in
//! docs/knobs.md, and spelled as a string nowhere else in src/.

use assert_cmd::Command;
use contact_lab::knobs::{Cli, Kind, Knob, Level, Offered, Range, Table, Value, KNOBS};
use contact_lab::lesson::{edit, knob_value, validate, Lesson};
use contact_lab::study::{self, grid};

/// A value the knob accepts that differs from its default.
fn sample(knob: &Knob) -> Value {
    let default = (knob.get)(&Default::default());
    let candidates = match knob.kind {
        Kind::Number {
            range: Range::Share | Range::Damping,
            ..
        } => {
            vec![Value::Number(0.5), Value::Number(0.25)]
        }
        Kind::Number {
            range: Range::Duration,
            ..
        } => vec![Value::Number(0.02), Value::Number(0.03)],
        Kind::Number { .. } => vec![Value::Number(0.125), Value::Number(0.375)],
        Kind::Count { .. } => vec![Value::Count(3), Value::Count(5)],
        Kind::Flag => vec![Value::Flag(true), Value::Flag(false)],
        Kind::Choice { choices } => choices.iter().map(|c| Value::Choice(c.name)).collect(),
        Kind::Vector => vec![Value::Vector([0.0, -1.0, 0.0])],
    };
    candidates
        .into_iter()
        .find(|v| *v != default)
        .expect("a value other than the default")
}

fn toml_text(v: Value) -> String {
    match v {
        Value::Number(x) => format!("{x:?}"),
        Value::Count(n) => n.to_string(),
        Value::Flag(b) => b.to_string(),
        Value::Choice(c) => format!("\"{c}\""),
        Value::Vector([x, y, z]) => format!("[{x:?}, {y:?}, {z:?}]"),
        Value::Unset => unreachable!(),
    }
}

const SCENE: &str = r#"
id = "knob-probe"
title = "A ball on a floor"
[[body]]
name = "ball"
mass = 1.0
shape = { sphere = 0.5 }
position = [0, 0.5, 0]
[[body]]
name = "floor"
mass = inf
shape = "half_space"
normal = [0, 1, 0]
position = [0, 0, 0]
"#;

/// The scene with `key = value` in `table` (a contact's tables get a contact).
fn lesson_with(table: Table, key: &str, value: &str) -> String {
    let contact = "[[contact]]\nbodies = [\"ball\", \"floor\"]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nrestitution = 0.5\n";
    match table {
        Table::Contact => format!("{SCENE}[step]\n{contact}{key} = {value}\n"),
        Table::ContactSettings => {
            format!("{SCENE}[step]\n{contact}[contact.settings]\n{key} = {value}\n")
        }
        Table::Settings => format!("{SCENE}[step]\n[settings]\n{key} = {value}\n"),
        Table::World => format!("{SCENE}[world]\n{key} = {value}\n"),
        Table::Step => format!("{SCENE}[step]\n{key} = {value}\n"),
        Table::Sleep => format!("{SCENE}[sleep]\n{key} = {value}\n"),
    }
}

#[test]
fn every_knob_is_read_from_each_of_its_tables() {
    for knob in KNOBS {
        let v = sample(knob);
        for &table in knob.tables {
            let text = lesson_with(table, knob.name, &toml_text(v));
            let l = validate::parse("probe.toml", &text)
                .unwrap_or_else(|e| panic!("{} in {}: {e:?}", knob.name, table.name()));
            let mut all = l.knobs();
            if matches!(table, Table::Contact | Table::ContactSettings) {
                all.contact = l.contacts[0].settings;
            }
            assert_eq!((knob.get)(&all), v, "{} in {}", knob.name, table.name());
        }
        for old in knob.old_names {
            let text = lesson_with(knob.tables[0], old, &toml_text(v));
            let l = validate::parse("probe.toml", &text).unwrap();
            assert_eq!((knob.get)(&l.knobs()), v, "{} as {old}", knob.name);
        }
    }
}

#[test]
fn a_refused_value_is_refused_in_a_file_and_on_the_command_line_alike() {
    // The same rule everywhere: a value the command line refuses, a file refuses.
    let cases = [
        ("dt", "2e6"),
        ("island_time", "0"),
        ("relaxation", "0"),
        ("duration", "0"),
    ];
    for (name, text) in cases {
        let knob = contact_lab::knobs::find(name).unwrap();
        let cli = knob_value::from_text(knob, text).unwrap_err();
        let file = validate::parse("probe.toml", &lesson_with(knob.tables[0], name, text))
            .map(|_| ())
            .unwrap_err();
        let file = format!("{file:?}");
        assert!(
            file.contains(&cli),
            "{name}: file says {file}, CLI says {cli}"
        );
    }
}

#[test]
fn every_knob_is_on_the_command_line_or_says_why_not() {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["simulate", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    for knob in KNOBS {
        let flag = format!("--{}", knob.name.replace('_', "-"));
        match knob.cli {
            Cli::Option | Cli::Negated(_) => {
                assert!(help.contains(&flag), "{flag} missing from simulate --help")
            }
            Cli::No(why) => assert!(!why.is_empty() && !help.contains(&flag), "{}", knob.name),
        }
        if let Cli::Negated(alias) = knob.cli {
            assert!(help.contains(&format!("--{alias}")), "--{alias}");
        }
    }
    // A contact's knobs on solve; the resolver's on resolve.
    for (command, levels) in [
        ("solve", &[Level::Contact][..]),
        ("resolve", &[Level::Contact, Level::Resolver][..]),
    ] {
        let out = Command::cargo_bin("contact-lab")
            .unwrap()
            .args([command, "--help"])
            .output()
            .unwrap();
        let help = String::from_utf8(out.stdout).unwrap();
        for knob in KNOBS.iter().filter(|k| levels.contains(&k.level)) {
            let flag = format!("--{}", knob.name.replace('_', "-"));
            assert!(help.contains(&flag), "{flag} missing from {command} --help");
        }
    }
}

#[test]
fn the_command_line_sets_each_knob() {
    // One flag per knob, through the binary: the run's JSON shows no error.
    for knob in KNOBS.iter().filter(|k| k.cli == Cli::Option) {
        let v = knob_value::text(sample(knob));
        let flag = format!("--{}={v}", knob.name.replace('_', "-"));
        let steps_given = knob.level == Level::Step && matches!(knob.kind, Kind::Count { .. });
        let mut args = vec!["simulate", "ball-drop", "--format", "json", &flag];
        if !steps_given {
            args.extend(["--steps", "2"]);
        }
        let out = Command::cargo_bin("contact-lab")
            .unwrap()
            .args(&args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{flag}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let n = json["steps"].as_array().unwrap().len();
        assert!(steps_given || n == 3, "{flag}: {n} frames");
    }
}

#[test]
fn every_knob_is_in_the_tui_edit_form_or_says_why_not() {
    let lesson = Lesson::load("lecture-2").unwrap();
    let stack = Lesson::load("stack-5").unwrap();
    let mut player = contact_lab::session::Player::new(&stack).unwrap();
    assert!(player.reach(5));
    let scene = player.record(5).unwrap().lesson_at(&stack, 0);
    assert!(scene.simulation.is_some() && !scene.contacts.is_empty());
    for knob in KNOBS {
        let in_form = |l: &Lesson| {
            edit::fields(l, 0)
                .iter()
                .any(|f| f.key == edit::Key::Knob(knob))
        };
        match knob.edit {
            Offered::Yes => {
                assert!(in_form(&scene), "{} missing from a scene's form", knob.name);
                assert_eq!(
                    in_form(&lesson),
                    knob.level == Level::Contact,
                    "{}",
                    knob.name
                );
                // Its text reads back as the same value.
                let f = edit::fields(&scene, 0)
                    .into_iter()
                    .find(|f| f.key == edit::Key::Knob(knob))
                    .unwrap();
                let mut m = scene.clone();
                let text = knob_value::text(sample(knob));
                edit::set(&mut m, 0, &f, &text).unwrap_or_else(|e| panic!("{}: {e}", knob.name));
                assert_eq!(edit::get(&m, 0, &f), text, "{}", knob.name);
            }
            Offered::No(why) => {
                assert!(!why.is_empty());
                assert!(!in_form(&scene), "{}", knob.name);
            }
        }
    }
}

#[test]
fn every_knob_is_in_the_study_or_says_why_not() {
    let lesson = Lesson::load("resting-box").unwrap();
    let default = grid::default_config(&lesson).unwrap();
    let names = grid::knob_names();
    for knob in KNOBS {
        match knob.study {
            Offered::Yes => {
                assert!(names.contains(&knob.name), "{}", knob.name);
                let v = sample(knob);
                let mut c = default;
                grid::set(&mut c, knob.name, &knob_value::text(v))
                    .unwrap_or_else(|e| panic!("{e}"));
                assert_eq!(c.get(knob), v, "{}", knob.name);
                assert!(
                    study::Config::knobs(&c)
                        .iter()
                        .any(|(n, _)| *n == knob.name),
                    "{} not shown in a row",
                    knob.name
                );
            }
            Offered::No(why) => {
                assert!(!why.is_empty());
                assert!(!names.contains(&knob.name), "{}", knob.name);
            }
        }
    }
}

#[test]
fn docs_knobs_md_is_the_table() {
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/knobs.md"))
        .unwrap()
        .replace("\r\n", "\n");
    assert_eq!(
        page,
        contact_lab::render::knobs::markdown(),
        "docs/knobs.md is stale: run `cargo run -- knobs > docs/knobs.md`"
    );
    for knob in KNOBS {
        assert!(
            page.contains(&format!("### `{}`", knob.name)),
            "{}",
            knob.name
        );
    }
}

#[test]
fn a_knob_name_is_spelled_once() {
    // Outside knobs/ (its declaration) and physics/ (its physics), a knob's
    // name is not written as a string: lesson/, cli/, commands/, study/,
    // tui/ read the table. `relaxation` is the example of the issue that asked for it.
    let mut offenders = Vec::new();
    for entry in walk(concat!(env!("CARGO_MANIFEST_DIR"), "/src")) {
        let rel = entry
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .unwrap()
            .to_string_lossy()
            .to_string();
        let skip = ["src/knobs/", "src/physics/", "src/trace/", "src/render/"];
        if skip.iter().any(|s| rel.starts_with(s)) {
            continue;
        }
        let text = std::fs::read_to_string(&entry).unwrap();
        // The code, not its unit tests or comments.
        let text = text.split("#[cfg(test)]").next().unwrap_or("");
        let text: String = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        for knob in KNOBS
            .iter()
            .filter(|k| matches!(k.level, Level::Contact | Level::Resolver))
        {
            let quoted = format!("\"{}\"", knob.name);
            if text.contains(&quoted)
                && !(knob.name == "friction_model" && rel.ends_with("validate.rs"))
            {
                offenders.push(format!("{rel}: {quoted}"));
            }
        }
    }
    assert!(
        offenders.is_empty(),
        "knob names spelled outside the table: {offenders:#?}"
    );
}

fn walk(dir: &str) -> Vec<std::path::PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(walk(p.to_str().unwrap()));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    out
}

#[test]
fn world_static_friction_alone_sets_dynamic_friction_too() {
    let l = validate::parse(
        "probe.toml",
        &format!("{SCENE}[world]\nstatic_friction = 0.5\n"),
    )
    .unwrap();
    let sim = l.simulation.unwrap();
    assert_eq!(sim.material.static_friction, 0.5);
    assert_eq!(
        sim.material.dynamic_friction, 0.5,
        "μ_d falls back to μ_s, as on a contact"
    );
    for m in &sim.materials {
        assert_eq!(m.dynamic_friction, 0.5);
    }
    // A body's μ_s alone over [world]'s: its μ_d follows its μ_s.
    let text = format!("{SCENE}[world]\nfriction = 0.2\n").replace(
        "shape = { sphere = 0.5 }",
        "shape = { sphere = 0.5 }\nstatic_friction = 0.8",
    );
    let l = validate::parse("probe.toml", &text).unwrap();
    let sim = l.simulation.unwrap();
    assert_eq!(sim.materials[0].static_friction, 0.8);
    assert_eq!(sim.materials[0].dynamic_friction, 0.8);
    assert_eq!(sim.materials[1].dynamic_friction, 0.2);
}

#[test]
fn old_spellings_stay_accepted() {
    for (table, key, value) in [
        (Table::Settings, "solver", "\"deepest_first\""),
        (Table::Settings, "solver", "\"sequential_impulse\""),
        (Table::Sleep, "enabled", "false"),
        (Table::Sleep, "epsilon", "0.2"),
        (Table::Sleep, "mode", "\"island\""),
    ] {
        validate::parse("probe.toml", &lesson_with(table, key, value))
            .unwrap_or_else(|e| panic!("{key} = {value}: {e:?}"));
    }
}

#[test]
fn relaxation_is_named_only_by_its_declaration_physics_trace_and_renderer() {
    // The issue's example: outside knobs/ (the table), physics/ (what
    // computes with it), trace/ (its stage) and render/ (its docs page) no
    // file names the knob at all, not even in a comment.
    let mut named = Vec::new();
    for entry in walk(concat!(env!("CARGO_MANIFEST_DIR"), "/src")) {
        let rel = entry
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .unwrap()
            .to_string_lossy()
            .to_string();
        let text = std::fs::read_to_string(&entry).unwrap();
        let word = text
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .any(|w| w == "relaxation");
        if word {
            named.push(rel);
        }
    }
    for rel in &named {
        assert!(
            ["src/knobs/", "src/physics/", "src/trace/", "src/render/"]
                .iter()
                .any(|p| rel.starts_with(p)),
            "{rel} names relaxation: {named:#?}"
        );
    }
}

#[test]
fn each_choice_is_spelled_in_one_list_that_set_and_get_agree_with() {
    // A choice type's values and spellings are one list (knobs::choices!):
    // setting a knob to each spelling, or to an old one, reads back the
    // canonical spelling, and every spelling is a different value.
    for knob in KNOBS {
        let Kind::Choice { choices } = knob.kind else {
            continue;
        };
        for c in choices {
            for typed in std::iter::once(&c.name).chain(c.aliases) {
                let mut s = contact_lab::physics::Settings::default();
                (knob.set)(&mut s, Value::Choice(knob.choice(typed).unwrap()));
                assert_eq!(
                    (knob.get)(&s),
                    Value::Choice(c.name),
                    "{} = {typed}",
                    knob.name
                );
            }
        }
    }
}

#[test]
fn the_ccd_choices_are_spelled_in_one_source_file() {
    let mut files = Vec::new();
    for entry in walk(concat!(env!("CARGO_MANIFEST_DIR"), "/src")) {
        let text = std::fs::read_to_string(&entry).unwrap();
        if text.contains("\"bisection\"") || text.contains("\"conservative\"") {
            files.push(entry);
        }
    }
    assert_eq!(files.len(), 1, "{files:#?}");
}

/// A number or count knob's boundary values (accepted), and a value just
/// past each (refused), as typed.
fn boundaries(knob: &Knob) -> (Vec<String>, Vec<String>) {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    match knob.kind {
        Kind::Number { range, .. } => match range {
            Range::Duration => (s(&["1e6", "1000000", "1e-60"]), s(&["1.0000001e6", "0"])),
            Range::Share | Range::Damping => (s(&["1", "1e-60"]), s(&["1.0000001", "0"])),
            Range::NonNegative => (s(&["0", "1e60"]), s(&["-1e-60", "1.0000001e60"])),
            Range::NonNegativeOrInf => (s(&["0", "inf", "1e60"]), s(&["-1e-60"])),
        },
        // A substep count starts at 1 (0 would be no step).
        Kind::Count { max, .. } if knob.name == "substeps" => (
            vec!["1".into(), max.to_string()],
            vec!["0".into(), (max + 1).to_string()],
        ),
        Kind::Count { max, .. } => (
            vec!["0".into(), max.to_string()],
            vec![(max + 1).to_string()],
        ),
        _ => (vec![], vec![]),
    }
}

#[test]
fn every_range_accepts_its_boundary_in_a_file_on_the_command_line_and_in_the_grid() {
    for knob in KNOBS {
        let (inside, past) = boundaries(knob);
        let grid_offered = matches!(knob.study, Offered::Yes);
        for text in &inside {
            knob_value::from_text(knob, text)
                .unwrap_or_else(|e| panic!("{} = {text} on the command line: {e}", knob.name));
            for &table in knob.tables {
                validate::parse("probe.toml", &lesson_with(table, knob.name, text)).unwrap_or_else(
                    |e| panic!("{} = {text} in {}: {e:?}", knob.name, table.name()),
                );
            }
            if grid_offered {
                grid::parse_grid(&format!("{}={text}", knob.name))
                    .unwrap_or_else(|e| panic!("--grid {}={text}: {e}", knob.name));
            }
        }
        for text in &past {
            let cli = knob_value::from_text(knob, text)
                .expect_err(&format!("{} = {text} on the command line", knob.name));
            let file = validate::parse("probe.toml", &lesson_with(knob.tables[0], knob.name, text))
                .map(|_| ())
                .expect_err(&format!("{} = {text} in a file", knob.name));
            assert!(
                format!("{file:?}").contains(&cli),
                "{}: {file:?} vs {cli}",
                knob.name
            );
            if grid_offered {
                let grid = grid::parse_grid(&format!("{}={text}", knob.name))
                    .expect_err(&format!("--grid {}={text}", knob.name));
                assert!(grid.ends_with(&cli), "{}: grid {grid} vs {cli}", knob.name);
            }
        }
    }
}
