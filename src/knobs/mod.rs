//! Every tunable, declared once: its name (the same in TOML, JSON, the
//! study's `--grid`, and on the command line with `-` for `_`), where it lives,
//! what it trades, its default, its range rule or its choices, which TOML
//! tables take it, and how it is read and written on
//! [`Settings`](crate::physics::params::Settings).
//!
//! Lesson validation, the command line, overrides, the TUI's edit form and
//! scene edits, the study and `docs/knobs.md` all read [`KNOBS`]; none of
//! them names a knob (a command that needs one takes its handle, e.g.
//! [`STEPS`]). The words a refusal is made of live in
//! `lesson::knob_value`: this table only declares the rule. Physics holds
//! the typed parameters the knobs are read into (`physics::params`); the
//! spelling of each choice is here ([`Choice`], one list per type).
//!
//! - `knob.rs`: what a knob is; `choice.rs`: a choice type's spellings;
//! - `contact.rs`: one contact's and a set of contacts' knobs;
//! - `scene.rs`: a run's (the step, the world, sleep);
//! - `soft.rs`: the soft step's (Box2D v3's solver).

mod choice;
mod contact;
mod knob;
mod scene;
mod soft;

pub use choice::{Choice, Spelling};
pub use contact::*;
pub use knob::*;
pub use scene::*;
pub use soft::*;

/// The knob named `name` (the canonical spelling, `-` or `_` alike).
pub fn find(name: &str) -> Option<&'static Knob> {
    let name = name.replace('-', "_");
    KNOBS.iter().find(|k| k.name == name)
}

/// The knob a TOML key `key` of `table` stands for.
pub fn in_table(table: Table, key: &str) -> Option<&'static Knob> {
    KNOBS.iter().find(|k| k.read_as(table, key))
}

/// The knobs of these levels, in table order.
pub fn of_levels(levels: &[Level]) -> impl Iterator<Item = &'static Knob> + '_ {
    KNOBS.iter().filter(move |k| levels.contains(&k.level))
}

/// Every knob. A new knob is one entry here and its `const` beside its
/// level's (and its physics); everything else reads this table.
pub static KNOBS: &[Knob] = &[
    FRICTION_MODEL,
    VELOCITY_LIMIT,
    ANGULAR_LIMIT,
    RELAXATION,
    DURATION,
    PROJECTION,
    EXACT,
    SOLVER,
    WARM_START,
    POSITION_ITERATIONS,
    VELOCITY_ITERATIONS,
    VISITS_PER_CONTACT,
    POSITION_EPSILON,
    VELOCITY_EPSILON,
    SLIP_SPEED,
    RESTITUTION_FROM,
    SUBSTEPS,
    CONTACT_HERTZ,
    CONTACT_DAMPING_RATIO,
    PUSH_OUT_SPEED,
    RELAX_ITERATIONS,
    RESTITUTION_THRESHOLD,
    LCP_RESTITUTION,
    DT,
    STEPS,
    CCD,
    ROLLBACK,
    NORMAL_FROM,
    GRAVITY,
    LINEAR_DAMPING,
    ANGULAR_DAMPING,
    ACCELERATION_COMPENSATION,
    BOX_BOX,
    NARROW_PHASE,
    CONTACT_MARGIN,
    SPECULATIVE,
    SLEEP,
    SLEEP_EPSILON,
    SLEEP_MODE,
    ISLAND_TIME,
    BROAD_PHASE,
    INTERNAL_EDGES,
];
