//! The knob table as a reference page (`docs/knobs.md`, and
//! `contact-lab knobs`): every tunable, where it lives, what it trades, its
//! default, its values, and where it can be set.

use crate::knobs::{Choice, Cli, Kind, Knob, Level, Offered, KNOBS, RELAXATION};
use crate::lesson::knob_value::expected;
use crate::physics::Solver;

fn surfaces(k: &Knob) -> String {
    let flag = k.name.replace('_', "-");
    let cli = match k.cli {
        Cli::Option => format!("`--{flag}`"),
        Cli::Negated(alias) => format!("`--{flag}`, `--{alias}`"),
        Cli::No(why) => format!("not on the command line ({why})"),
    };
    let offered = |o: Offered, what: &str| match o {
        Offered::Yes => format!("{what}: yes"),
        Offered::No(why) => format!("{what}: no ({why})"),
    };
    format!(
        "{cli}; {}; {}",
        offered(k.edit, "TUI edit"),
        offered(k.study, "study")
    )
}

fn values(k: &Knob) -> String {
    match k.kind {
        Kind::Choice { choices } => {
            let mut s: Vec<String> = choices
                .iter()
                .map(|c| format!("`{}` ({})", c.name, c.doc))
                .collect();
            let aliases: Vec<&str> = choices.iter().flat_map(|c| c.aliases).copied().collect();
            if !aliases.is_empty() {
                s.push(format!(
                    "old spellings still read: {}",
                    aliases
                        .iter()
                        .map(|a| format!("`{a}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
            }
            s.join("; ")
        }
        _ => expected(k),
    }
}

/// The page, in Markdown.
pub fn markdown() -> String {
    // The examples are a knob and a choice by their handles.
    let mut out = format!(
        "# Knobs\n\n\
         Every tunable of contact-lab, declared once in `src/knobs/`; this page is\n\
         generated from that table (`contact-lab knobs`; a test keeps it current).\n\n\
         A knob has one name: the key in a lesson file's table, the key in JSON and in the\n\
         study's `--grid`, and, with `-` for `_`, the command-line flag (`{knob}`,\n\
         `--{knob}`). Choices are spelled in kebab-case (`{choice}`); the old\n\
         spellings stay accepted. Material coefficients (`restitution`, `friction`,\n\
         `static_friction`, `dynamic_friction`) are data of a contact, a body or `[world]`, not\n\
         knobs: `friction` sets both μ_s and μ_d, and μ_d defaults to μ_s wherever they are written.\n",
        knob = RELAXATION.name,
        choice = Solver::DeepestFirst.name(),
    );
    for level in Level::ALL {
        out.push_str(&format!("\n## {} knobs\n\n", level.name()));
        for k in KNOBS.iter().filter(|k| k.level == level) {
            let tables: Vec<&str> = k.tables.iter().map(|t| t.name()).collect();
            out.push_str(&format!("### `{}`\n\n{}\n\n", k.name, k.doc));
            out.push_str(&format!("- default: {}\n", k.default));
            out.push_str(&format!("- values: {}\n", values(k)));
            out.push_str(&format!("- lesson file: {}", tables.join(", ")));
            if !k.old_names.is_empty() {
                let old: Vec<String> = k.old_names.iter().map(|n| format!("`{n}`")).collect();
                out.push_str(&format!(" (also read as {})", old.join(", ")));
            }
            out.push('\n');
            out.push_str(&format!("- set from: {}\n\n", surfaces(k)));
        }
    }
    out
}
