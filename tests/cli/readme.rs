//! The README and the docs/ pages tell the truth about the program (issue
//! 28, item 1; issue 40, item 9): every excerpt that starts with
//! `$ contact-lab …` is what that command prints (a `…` line stands for
//! lines left out), every command the README shows runs, every command a
//! docs/ page shows parses, and the errata table's "right" column
//! (docs/errata.md) is what `contact-lab check` computes, to the digits it
//! shows.

use std::path::Path;

use assert_cmd::Command;

use crate::common;

const README: &str = include_str!("../../README.md");
const ERRATA: &str = include_str!("../../docs/errata.md");

fn stdout(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "contact-lab {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The README, then every page of docs/: (name, text).
fn pages() -> Vec<(String, String)> {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let mut names: Vec<_> = std::fs::read_dir(&docs)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".md"))
        .collect();
    names.sort();
    let mut out = vec![("README.md".to_string(), README.to_string())];
    for n in names {
        let text = std::fs::read_to_string(docs.join(&n)).unwrap();
        out.push((format!("docs/{n}"), text));
    }
    out
}

/// The fenced blocks of `text`: (the opening fence's info string, the lines).
fn blocks(text: &str) -> Vec<(String, Vec<&str>)> {
    let mut out = Vec::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        let Some(info) = line.trim_start().strip_prefix("```") else {
            continue;
        };
        let block = lines
            .by_ref()
            .take_while(|l| !l.trim_start().starts_with("```"))
            .collect();
        out.push((info.trim().to_string(), block));
    }
    out
}

/// The fenced blocks whose first line is `$ contact-lab ARGS  # comment`:
/// (args, the lines shown after it).
fn excerpts(text: &str) -> Vec<(Vec<String>, Vec<String>)> {
    let mut out = Vec::new();
    for (_, block) in blocks(text) {
        let Some(command) = block.first().and_then(|l| l.strip_prefix("$ contact-lab ")) else {
            continue;
        };
        let command = command.split('#').next().unwrap();
        let args = command.split_whitespace().map(String::from).collect();
        let shown = block[1..]
            .iter()
            .map(|l| l.trim_end().to_string())
            .collect();
        out.push((args, shown));
    }
    out
}

#[test]
fn every_excerpt_is_what_its_command_prints() {
    assert!(
        !excerpts(README).is_empty(),
        "the README shows no `$ contact-lab` excerpt"
    );
    for (page, text) in pages() {
        check_excerpts(&page, &text);
    }
}

fn check_excerpts(page: &str, text: &str) {
    for (args, shown) in excerpts(text) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let printed = stdout(&args);
        let mut rest = printed.lines().map(str::trim_end);
        for line in shown.iter().filter(|l| l.trim() != "…") {
            assert!(
                rest.any(|p| p == line),
                "`contact-lab {}`: {page} shows\n{line}\nwhich is not in the output (in this order):\n{printed}",
                args.join(" ")
            );
        }
    }
}

/// The decimal numbers in a table cell (`−` read as a minus sign).
fn numbers(cell: &str) -> Vec<(f64, usize)> {
    let cell = cell.replace('−', "-");
    let mut out = Vec::new();
    let mut token = String::new();
    for c in cell.chars().chain([' ']) {
        if c.is_ascii_digit() || c == '.' || (c == '-' && token.is_empty()) {
            token.push(c);
        } else {
            if let Ok(x) = token.parse::<f64>() {
                let decimals = token.split('.').nth(1).map_or(0, str::len);
                out.push((x, decimals));
            }
            token.clear();
        }
    }
    out
}

#[test]
fn the_errata_table_gives_what_check_computes() {
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&["check", "--format", "json"])).unwrap();
    let errata: Vec<(Vec<f64>, Vec<f64>)> = json["items"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|i| !i["erratum"].is_null())
        .map(|i| (flat_one(&i["printed"]), flat_one(&i["computed"])))
        .collect();
    let mut compared = 0;
    for row in ERRATA.lines().filter(|l| l.starts_with("| ex.")) {
        let cells: Vec<&str> = row.split(" | ").collect();
        let printed: Vec<f64> = numbers(cells[1]).into_iter().map(|(x, _)| x).collect();
        let right = numbers(cells[2]);
        let Some((_, computed)) = errata.iter().find(|(p, _)| *p == printed) else {
            continue;
        };
        assert_eq!(right.len(), computed.len(), "{row}");
        for ((x, decimals), c) in right.iter().zip(computed) {
            let half_unit = 0.5 * 10f64.powi(-(*decimals as i32));
            assert!(
                (x - c).abs() <= half_unit * (1.0 + 1e-9),
                "{row}: {x} is not {c} to {decimals} decimals"
            );
        }
        compared += 1;
    }
    assert!(
        compared >= 7,
        "only {compared} errata rows matched a check item"
    );
}

fn flat_one(v: &serde_json::Value) -> Vec<f64> {
    match v {
        serde_json::Value::Array(a) => a.iter().flat_map(flat_one).collect(),
        x => x.as_f64().into_iter().collect(),
    }
}

/// The ball-drop scene says how its energy behaves in flight, with the
/// numbers `simulate` prints (it is not flat: the integrator loses energy).
#[test]
fn ball_drop_states_its_energy_loss_in_flight() {
    let out = stdout(&["simulate", "ball-drop", "--seconds", "0.4", "--table"]);
    let energy = |line: &str| line.split_whitespace().nth(7).unwrap().to_string();
    let first = out
        .lines()
        .find(|l| l.trim_start().starts_with("0 "))
        .unwrap();
    let last = out.lines().rev().find(|l| l.contains(" 0.4 ")).unwrap();
    let (e0, e1) = (energy(first), energy(last));
    assert_ne!(e0, e1, "{out}");
    let lesson = include_str!("../../lessons/scenes/ball-drop.toml");
    assert!(!lesson.contains("flat in flight"));
    let said = format!("from {e0} J to {e1} J in the first 0.4 s");
    assert!(lesson.replace('\n', " ").contains(&said), "{said}");
}

/// The commands a page's shell blocks show, as `contact-lab` arguments:
/// each line of a fenced block that starts with `contact-lab`, `$
/// contact-lab` or `cargo run --release`, its comment cut off, with the
/// file a `> FILE` sends its output to (a synopsis with `[--…]` is left
/// out; a command of another crate is shown after a `cd`).
fn commands(text: &str) -> Vec<(String, Vec<String>, Option<String>)> {
    let mut out = Vec::new();
    for (_, block) in blocks(text) {
        for line in block {
            let line = line.trim();
            let line = line.strip_prefix("$ ").unwrap_or(line);
            let rest = if line == "contact-lab" || line == "cargo run --release" {
                ""
            } else if let Some(r) = line.strip_prefix("contact-lab ") {
                r
            } else if let Some(r) = line.strip_prefix("cargo run --release -- ") {
                r
            } else if let Some(r) = line.strip_prefix("cargo run --release ") {
                // `cargo run --release  # …`: the app, with a comment.
                assert!(r.trim_start().starts_with('#'), "{line}");
                ""
            } else {
                continue;
            };
            let rest = rest.split(" #").next().unwrap();
            if rest.contains("[--") {
                // A synopsis (`detect SCENE [--pair A,B] …`), not a command.
                continue;
            }
            assert!(
                !rest.contains(['"', '\'', '|', '<', '`', '$']),
                "`{line}`: quotes, pipes and substitutions are not read here; show a plain command"
            );
            let (args, into) = match rest.split_once('>') {
                Some((a, f)) => (a, Some(f.trim().to_string())),
                None => (rest, None),
            };
            let args = args.split_whitespace().map(String::from).collect();
            out.push((line.to_string(), args, into));
        }
    }
    out
}

/// Every command the README shows runs and exits 0, in a scratch
/// directory (the files it writes land there, and a later command can
/// read them); the app, which needs a terminal, loads its lesson and
/// stops at the terminal check.
#[test]
fn every_command_the_readme_shows_runs() {
    let dir = common::scratch("readme-commands");
    let all = commands(README);
    assert!(all.len() >= 10, "{all:?}");
    for (line, args, into) in all {
        let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
            .current_dir(&dir)
            .args(&args)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        if args.first().map(String::as_str) == Some("tui") {
            assert_eq!(out.status.code(), Some(2), "`{line}`: {stderr}");
            assert!(
                stderr.contains("the TUI needs a terminal"),
                "`{line}` did not reach the terminal check: {stderr}"
            );
            continue;
        }
        assert_eq!(out.status.code(), Some(0), "`{line}`: {stderr}");
        // What it made: the file `-o` names, or its output.
        let made = match args.iter().position(|a| a == "-o") {
            Some(i) => std::fs::metadata(dir.join(&args[i + 1])).map_or(0, |m| m.len()),
            None => out.stdout.len() as u64,
        };
        assert!(made > 0, "`{line}` made nothing");
        if let Some(file) = into {
            std::fs::write(dir.join(file), &out.stdout).unwrap();
        }
    }
}

/// Every command a docs/ page shows parses: its subcommand and flags are
/// ones the program has (clap stops at the `--help` put after them).
#[test]
fn every_command_a_docs_page_shows_parses() {
    let mut checked = 0;
    for (page, text) in pages().into_iter().skip(1) {
        for (line, mut args, _) in commands(&text) {
            args.push("--help".into());
            let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
                .args(&args)
                .output()
                .unwrap();
            assert_eq!(
                out.status.code(),
                Some(0),
                "{page}: `{line}` does not parse: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            checked += 1;
        }
    }
    assert!(checked >= 40, "only {checked} commands in docs/");
}

/// A heading's anchor as GitHub makes it: lower case, spaces to `-`,
/// punctuation other than `-` and `_` dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// Every link of the README and of a docs/ page to a file of the
/// repository leads to one that exists, and a `#heading` to a heading of
/// that page (the content moved from the README is found where it says).
#[test]
fn every_link_between_the_pages_leads_somewhere() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut followed = 0;
    for (page, text) in pages() {
        let dir = root.join(&page).parent().unwrap().to_path_buf();
        for link in text.split("](").skip(1) {
            let target = link.split(')').next().unwrap();
            if target.contains("://") || target.is_empty() {
                continue;
            }
            let (file, heading) = target.split_once('#').unwrap_or((target, ""));
            let path = if file.is_empty() {
                root.join(&page)
            } else {
                dir.join(file)
            };
            assert!(path.exists(), "{page}: the link to {target} leads nowhere");
            if !heading.is_empty() {
                let linked = std::fs::read_to_string(&path).unwrap();
                let anchors: Vec<String> = linked
                    .lines()
                    .filter_map(|l| l.strip_prefix('#'))
                    .map(|h| anchor(h.trim_start_matches('#')))
                    .collect();
                assert!(
                    anchors.iter().any(|a| a == heading),
                    "{page}: {target}: no such heading in {file} ({anchors:?})"
                );
            }
            followed += 1;
        }
    }
    assert!(followed >= 40, "only {followed} links followed");
}
