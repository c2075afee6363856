//! The soft step's knobs (`solver = "soft-step"`, Box2D v3's solver; the
//! substep count it shares with XPBD is `contact.rs`'s `substeps`).
//! Defaults are Box2D v3's, with one difference: Box2D doubles the contact
//! hertz against a static body; contact-lab keeps one frequency for every
//! contact, so that a contact's coefficients are the three numbers the
//! trace prints from f, ζ and h alone (docs/knobs.md says so).

use super::knob::{count, number};
use super::knob::{Cli, Kind, Knob, Level, Needs, Offered, Range, Table, Value};

const RESOLVER_TABLES: &[Table] = &[Table::Settings];

/// Why the study and `advise` leave the soft knobs at their defaults: only
/// the soft step reads them, and searching them in every scene would cost
/// every other solver's runs for nothing (the study tries the soft step
/// itself, through the solver knob, at these defaults).
const SOFT_ONLY: &str = "only the soft step reads it: the study tries that solver at its defaults";

/// `contact_hertz`.
pub const CONTACT_HERTZ: Knob = Knob {
    name: "contact_hertz",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step: the contact spring's frequency f (Hz): trades a stiffer contact (less overlap left) for one that stays stable with a long substep; 0 = rigid, no push-out. Box2D doubles it against a static body; here one frequency holds for every contact.",
    default: "30",
    kind: Kind::Number { range: Range::NonNegative, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(SOFT_ONLY),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.soft.contact_hertz),
    set: |s, v| s.resolver.soft.contact_hertz = number(v),
};

/// `contact_damping_ratio`.
pub const CONTACT_DAMPING_RATIO: Knob = Knob {
    name: "contact_damping_ratio",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step: the contact spring's damping ratio ζ: trades a push-out without bounce for a slower one.",
    default: "10",
    kind: Kind::Number { range: Range::NonNegative, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(SOFT_ONLY),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.soft.contact_damping_ratio),
    set: |s, v| s.resolver.soft.contact_damping_ratio = number(v),
};

/// `push_out_speed`.
pub const PUSH_OUT_SPEED: Knob = Knob {
    name: "push_out_speed",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step: the fastest an overlap is pushed out (m/s): trades recovery time for bodies that do not fly apart (inf = no cap).",
    default: "3",
    kind: Kind::Number { range: Range::NonNegativeOrInf, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(SOFT_ONLY),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.soft.push_out_speed),
    set: |s, v| s.resolver.soft.push_out_speed = number(v),
};

/// `relax_iterations`.
pub const RELAX_ITERATIONS: Knob = Knob {
    name: "relax_iterations",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step: relax sweeps per substep (solve without bias): trades time for the push-out's velocity removed (0 = bodies keep it).",
    default: "1",
    kind: Kind::Count { max: 64, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(SOFT_ONLY),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Count(s.resolver.soft.relax_iterations as u64),
    set: |s, v| s.resolver.soft.relax_iterations = count(v).unwrap_or(1),
};

/// `restitution_threshold`.
pub const RESTITUTION_THRESHOLD: Knob = Knob {
    name: "restitution_threshold",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step: closing speeds at or below this (m/s) do not bounce: trades bounce fidelity at low speed for resting contacts that do not vibrate.",
    default: "1",
    kind: Kind::Number { range: Range::NonNegative, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(SOFT_ONLY),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.soft.restitution_threshold),
    set: |s, v| s.resolver.soft.restitution_threshold = number(v),
};
