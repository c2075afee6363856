//! The README tells the truth about the program (issue 28, item 1): every
//! excerpt that starts with `$ contact-lab …` is what that command prints
//! (a `…` line stands for lines left out), and the errata table's "right"
//! column is what `contact-lab check` computes, to the digits it shows.

use assert_cmd::Command;

const README: &str = include_str!("../../README.md");

fn stdout(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "contact-lab {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The fenced blocks whose first line is `$ contact-lab ARGS  # comment`:
/// (args, the lines shown after it).
fn excerpts() -> Vec<(Vec<String>, Vec<String>)> {
    let mut out = Vec::new();
    let mut lines = README.lines();
    while let Some(line) = lines.next() {
        if !line.starts_with("```") {
            continue;
        }
        let block: Vec<&str> = lines
            .by_ref()
            .take_while(|l| !l.starts_with("```"))
            .collect();
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
fn every_readme_excerpt_is_what_its_command_prints() {
    let all = excerpts();
    assert!(
        !all.is_empty(),
        "the README shows no `$ contact-lab` excerpt"
    );
    for (args, shown) in all {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let printed = stdout(&args);
        let mut rest = printed.lines().map(str::trim_end);
        for line in shown.iter().filter(|l| l.trim() != "…") {
            assert!(
                rest.any(|p| p == line),
                "`contact-lab {}`: the README shows\n{line}\nwhich is not in the output (in this order):\n{printed}",
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
    let section = README
        .split("## What the lecture gets wrong")
        .nth(1)
        .unwrap()
        .split("\n## ")
        .next()
        .unwrap();
    let mut compared = 0;
    for row in section.lines().filter(|l| l.starts_with("| ex.")) {
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
