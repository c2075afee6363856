//! What a knob is: its value, where it lives, which tables take it, how it
//! is written, which surfaces offer it, and the [`Knob`] entry itself (the
//! table of every knob is `KNOBS` in `knobs/mod.rs`).

use super::choice::Spelling;
use crate::physics::params::Settings;

/// What a scene must have for a knob to matter in it (the study's default
/// grid tries a knob's `grid` values only where it does).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    Always,
    /// A friction coefficient above 0.
    Friction,
    /// Two boxes or more.
    BoxPairs,
    /// Bodies that can end deep in one another: a mass ratio above 10
    /// between two movable bodies (the light one's contacts give way under
    /// the heavy one), or a body that crosses half the thinnest other body
    /// in one step (a tunnelling scene). Only the study's default grid reads
    /// it: `advise` searches such a knob in every scene.
    Penetration,
}

/// A knob's value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    Number(f64),
    Count(u64),
    Flag(bool),
    /// One of the knob's choices, by its canonical name.
    Choice(&'static str),
    Vector([f64; 3]),
    /// An optional knob left to its default rule (e.g. `8 × contacts`).
    Unset,
}

/// Where a knob lives: which part of the physics reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    /// How one contact is resolved (`[settings]`, a contact's `settings`).
    Contact,
    /// How a set of contacts is resolved together (`[settings]`).
    Resolver,
    /// The time step (`[step]`).
    Step,
    /// Forces and contact generation (`[world]`).
    World,
    /// When bodies stop being simulated (`[sleep]`).
    Sleep,
}

impl Level {
    pub const ALL: [Level; 5] = [
        Level::Contact,
        Level::Resolver,
        Level::Step,
        Level::World,
        Level::Sleep,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Level::Contact => "contact",
            Level::Resolver => "resolver",
            Level::Step => "step",
            Level::World => "world",
            Level::Sleep => "sleep",
        }
    }
}

/// A TOML table of a lesson file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Table {
    /// `[settings]`.
    Settings,
    /// A `[[contact]]`'s own `settings` table.
    ContactSettings,
    /// A `[[contact]]` itself.
    Contact,
    World,
    Step,
    Sleep,
}

impl Table {
    /// The table as a lesson file writes it.
    pub fn name(self) -> &'static str {
        match self {
            Table::Settings => "[settings]",
            Table::ContactSettings => "[contact.settings]",
            Table::Contact => "[[contact]]",
            Table::World => "[world]",
            Table::Step => "[step]",
            Table::Sleep => "[sleep]",
        }
    }
}

/// The values a number knob accepts (checked and worded in `lesson::knob_value`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Range {
    /// A finite number ≥ 0.
    NonNegative,
    /// A number ≥ 0, `inf` allowed (no limit).
    NonNegativeOrInf,
    /// In (0, 1]: a share.
    Share,
    /// In (0, 1]: the fraction of velocity kept per second.
    Damping,
    /// A finite duration > 0, at most [`MAX_DT`] seconds.
    Duration,
}

/// The longest time step or frame duration accepted, in seconds (the same
/// in a file, on the command line and in the study).
pub const MAX_DT: f64 = 1e6;
/// The most iterations a resolver phase may be given.
pub const MAX_ITERATIONS: u64 = 1_000_000_000;
/// The most steps a run may ask for (a longer run is a loop, not a lesson).
pub const MAX_STEPS: u64 = 10_000_000;

/// How a knob's value is written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A number under its range rule; `optional` when it may be left unset
    /// (unset follows another rule, which the knob's doc names).
    Number {
        range: Range,
        optional: bool,
    },
    /// A whole number from 0 to `max`; `optional` when it may be left unset.
    Count {
        max: u64,
        optional: bool,
    },
    Flag,
    /// One name of a list (a [`Choice`](super::Choice) type's spellings,
    /// each with the old spellings still accepted).
    Choice {
        choices: &'static [Spelling],
    },
    Vector,
}

impl Kind {
    /// A number's range rule; `None` for every other kind.
    pub fn range(&self) -> Option<Range> {
        match self {
            Kind::Number { range, .. } => Some(*range),
            _ => None,
        }
    }
}

/// How a knob is set on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cli {
    /// `--NAME VALUE` (for a flag knob: `--NAME` alone means true, and
    /// `--NAME=false` turns it off).
    Option,
    /// As `Option`, and `--ALIAS` alone sets the flag knob to false.
    Negated(&'static str),
    /// Not on the command line, and why.
    No(&'static str),
}

/// Which surfaces offer a knob besides the lesson file; a `No` says why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Offered {
    Yes,
    No(&'static str),
}

/// One tunable.
pub struct Knob {
    /// The one spelling: a TOML key, a JSON key, a study knob, and a
    /// command-line flag with `-` for `_`.
    pub name: &'static str,
    /// Old TOML keys still read as this knob.
    pub old_names: &'static [&'static str],
    pub level: Level,
    /// The tables of a lesson file that take it.
    pub tables: &'static [Table],
    /// What it does and what it trades.
    pub doc: &'static str,
    /// The default, as the docs show it.
    pub default: &'static str,
    pub kind: Kind,
    pub cli: Cli,
    /// The TUI's edit form (scene knobs: when the contact was opened from a run).
    pub edit: Offered,
    /// The study's `--grid`.
    pub study: Offered,
    /// The values the study's default grid tries, one at a time around a
    /// scene's own configuration (empty: not in the default grid; a choice
    /// knob that tries every choice names its type's `NAMES`).
    pub grid: &'static [&'static str],
    /// What a scene must have for the default grid to try the knob.
    pub needs: Needs,
    pub get: fn(&Settings) -> Value,
    pub set: fn(&mut Settings, Value),
}

impl std::fmt::Debug for Knob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

impl PartialEq for Knob {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

impl Knob {
    /// The canonical choice `name` stands for (an alias or the name itself).
    pub fn choice(&self, name: &str) -> Option<&'static str> {
        let Kind::Choice { choices } = self.kind else {
            return None;
        };
        choices
            .iter()
            .find(|c| c.name == name)
            .or_else(|| choices.iter().find(|c| c.aliases.contains(&name)))
            .map(|c| c.name)
    }

    /// True when a TOML key `key` in `table` is this knob.
    pub fn read_as(&self, table: Table, key: &str) -> bool {
        self.tables.contains(&table) && (self.name == key || self.old_names.contains(&key))
    }
}

// The values a knob's `get` and `set` convert (a wrong kind reads as NaN,
// none, false or "").

pub(super) fn number(v: Value) -> f64 {
    match v {
        Value::Number(x) => x,
        Value::Count(n) => n as f64,
        _ => f64::NAN,
    }
}

pub(super) fn count(v: Value) -> Option<usize> {
    match v {
        Value::Count(n) => Some(usize::try_from(n).unwrap_or(usize::MAX)),
        _ => None,
    }
}

pub(super) fn flag(v: Value) -> bool {
    matches!(v, Value::Flag(true))
}

pub(super) fn choice(v: Value) -> &'static str {
    match v {
        Value::Choice(c) => c,
        _ => "",
    }
}

pub(super) fn vector(v: Value) -> [f64; 3] {
    match v {
        Value::Vector(x) => x,
        _ => [f64::NAN; 3],
    }
}
