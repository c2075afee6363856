//! The knobs of a lesson file's tables (`[settings]`, a contact's
//! `settings`, `[world]`, `[step]`, `[sleep]`), read against the knob table:
//! a key is a knob of that table, a field the caller reads itself (the
//! coefficients in `[world]`), or refused with the closest known name.

use super::super::knob_value;
use super::super::raw::{KnobTable, S};
use super::super::source::Note;
use super::Validator;
use crate::knobs::{self, Table, KNOBS};
use crate::physics::Settings;

impl Validator {
    /// Sets each knob of `raw` (a `table`) on `into`; the keys in `fields`
    /// are the caller's and are skipped.
    pub(super) fn knob_table(
        &mut self,
        table: Table,
        raw: &KnobTable,
        into: &mut Settings,
        fields: &[&str],
    ) {
        let mut entries: Vec<(&S<String>, &S<toml::Value>)> = raw.iter().collect();
        entries.sort_by_key(|(k, _)| k.span().start);
        // The knobs this table sets, as the file spells each.
        let mut here: Vec<(&'static str, &str)> = Vec::new();
        for (key, value) in entries {
            let name = key.get_ref().as_str();
            if fields.contains(&name) {
                continue;
            }
            let knob = knobs::in_table(table, name);
            if let Some(knob) = knob {
                if let Some((_, first)) = here.iter().find(|(k, _)| *k == knob.name) {
                    // A knob and its old name in one table: one would be lost.
                    self.err(
                        key.span(),
                        format!(
                            "in {}: {name} sets the knob {} again (`{first}` sets it above): keep one",
                            table.name(),
                            knob.name
                        ),
                    );
                    continue;
                }
                here.push((knob.name, name));
                self.twice_in_scene(table, knob.name, key);
            }
            match knob {
                Some(knob) => match knob_value::from_toml(knob, value.get_ref()) {
                    Ok(v) => (knob.set)(into, v),
                    Err(e) => {
                        // Named as the file writes it (an old spelling, too).
                        let e = if name == knob.name {
                            e
                        } else {
                            format!(
                                "{} (the knob {})",
                                e.replacen(knob.name, name, 1),
                                knob.name
                            )
                        };
                        self.err(value.span(), format!("in {}: {e}", table.name()))
                    }
                },
                None => self.misplaced(table, key, fields),
            }
        }
    }

    /// A scene-wide knob set in a second table: a warning, since the table
    /// read last wins without a word ([settings], then [world], [step], [sleep]).
    fn twice_in_scene(&mut self, table: Table, knob: &'static str, key: &S<String>) {
        if matches!(table, Table::Contact | Table::ContactSettings) {
            return;
        }
        if let Some((_, first, _)) = self.scene_knobs.iter().find(|(k, _, _)| *k == knob) {
            let message = format!(
                "{knob} is set in {} and again in {}: {} is read later, so its value is the one used",
                first.name(),
                table.name(),
                table.name()
            );
            self.warnings.push(Note::new(message, key.span()));
        }
        self.scene_knobs.push((knob, table, key.get_ref().clone()));
    }

    /// A key that is no knob of `table`: a knob of another table, or unknown.
    fn misplaced(&mut self, table: Table, key: &S<String>, fields: &[&str]) {
        let name = key.get_ref().as_str();
        let elsewhere = KNOBS
            .iter()
            .find(|k| k.name == name || k.old_names.contains(&name));
        if let Some(knob) = elsewhere {
            let message = if table == Table::ContactSettings
                && knob.tables.contains(&Table::Settings)
            {
                format!("{name} is a setting of the whole scene: put it in the lesson's [settings], not in a contact's settings")
            } else {
                let homes: Vec<&str> = knob.tables.iter().map(|t| t.name()).collect();
                format!(
                    "{name} belongs in {}, not in {}",
                    homes.join(" or "),
                    table.name()
                )
            };
            self.err(key.span(), message);
            return;
        }
        let known: Vec<String> = KNOBS
            .iter()
            .filter(|k| k.tables.contains(&table))
            .map(|k| k.name)
            .chain(fields.iter().copied())
            .map(|n| format!("`{n}`"))
            .collect();
        let message = format!(
            "unknown field `{name}`, expected one of {}",
            known.join(", ")
        );
        let help = super::super::syntax::did_you_mean(&message)
            .unwrap_or_else(|| "see lessons/README.md and docs/knobs.md for every field".into());
        self.errors.push(Note::new(message, key.span()).help(help));
    }
}
