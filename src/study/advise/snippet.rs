//! The advice as lesson tables, ready to paste.

use super::Advice;
use crate::knobs::Table;
use crate::lesson::knob_value;
use crate::study::grid;

/// The tables a scene's knobs are read from, in the order the lesson reads
/// them (lesson/validate/simulation.rs): a knob set in a later table
/// overrides one set in an earlier (`friction_model` in `[world]` over
/// `[settings]`).
const SCENE_TABLES: [Table; 4] = [Table::Settings, Table::World, Table::Step, Table::Sleep];

/// The choice as lesson tables, ready to paste: each searched knob in its
/// table (`visits_per_contact` for the budget; a knob with several homes
/// in the one the scene reads last), spelled as the scene spells it there
/// (an old name the scene uses: `[sleep] enabled`), the float type as a
/// comment (a lesson runs in f64; the study and advise can run f32).
pub fn settings_snippet(a: &Advice) -> String {
    let names: Vec<&str> = a.values.iter().map(|(n, _)| *n).collect();
    snippet(&a.choice.config, &names, &a.spellings)
}

/// [`settings_snippet`] of `c`: the knobs `names` (the searched
/// dimensions), each spelled as `spellings` (the scene's) says.
pub fn snippet(
    c: &crate::study::Config,
    names: &[&str],
    spellings: &[(Table, &'static str, String)],
) -> String {
    let mut tables: Vec<(Table, Vec<String>)> = Vec::new();
    let mut push = |t: Table, line: String| match tables.iter_mut().find(|(x, _)| *x == t) {
        Some((_, lines)) => lines.push(line),
        None => tables.push((t, vec![line])),
    };
    push(
        Table::Settings,
        format!("visits_per_contact = {}", c.budget.per_contact()),
    );
    for name in names {
        let Some(k) = crate::knobs::find(name) else {
            continue;
        };
        // The table the scene reads last among the knob's homes, so that
        // the snippet overrides the scene wherever the scene spells it.
        let Some(table) = SCENE_TABLES
            .into_iter()
            .rev()
            .find(|t| k.tables.contains(t))
            .or(k.tables.first().copied())
        else {
            continue;
        };
        let v = c.get(k);
        let toml = match v {
            crate::knobs::Value::Choice(s) => format!("\"{s}\""),
            _ => knob_value::text(v),
        };
        // The scene's own spelling where it sets the knob in that table
        // (`[sleep] enabled`): the same key, so the merge replaces it.
        let key = spellings
            .iter()
            .find(|(t, knob, _)| *t == table && *knob == k.name)
            .map_or(k.name, |(_, _, key)| key.as_str());
        // The time step as a decimal the loader reads, named as a fraction.
        let note = match k.name {
            "dt" if grid::dt_label(c.params.dt).starts_with("1/") => {
                format!("  # {} s", grid::dt_label(c.params.dt))
            }
            _ => String::new(),
        };
        push(table, format!("{key} = {toml}{note}"));
    }
    let mut out = String::new();
    for (t, lines) in &tables {
        out.push_str(t.name());
        out.push('\n');
        for l in lines {
            out.push_str(l);
            out.push('\n');
        }
        out.push('\n');
    }
    out.push_str(&format!(
        "# precision: {} (the float type: a lesson runs in f64; study --grid precision={0} runs this one)\n",
        c.precision.name()
    ));
    out
}
