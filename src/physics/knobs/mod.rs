//! Every tunable, declared once: its name (the same in TOML, JSON, the
//! study's `--grid`, and on the command line with `-` for `_`), where it lives,
//! what it trades, its default, its range rule or its choices, which TOML
//! tables take it, and how it is read and written on
//! [`Settings`](super::params::Settings).
//!
//! Lesson validation, the command line, overrides, the TUI's edit form and
//! scene edits, the study and `docs/knobs.md` all read [`KNOBS`]; none of
//! them names a knob. The words a refusal is made of live in
//! `lesson::knob_value`: physics only declares the rule.

use super::exact::RestitutionLaw;
use super::params::{BoxBoxMode, NarrowPhase};
use super::step::ccd_mode::{Ccd, NormalFrom, Rollback};
use super::step::SleepMode;
use super::{FrictionModel, ProjectionMethod, RestitutionFrom, Solver};

pub mod grid;
mod knob;

pub use grid::Needs;
pub use knob::*;

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

fn number(v: Value) -> f64 {
    match v {
        Value::Number(x) => x,
        Value::Count(n) => n as f64,
        _ => f64::NAN,
    }
}

fn count(v: Value) -> Option<usize> {
    match v {
        Value::Count(n) => Some(usize::try_from(n).unwrap_or(usize::MAX)),
        _ => None,
    }
}

fn flag(v: Value) -> bool {
    matches!(v, Value::Flag(true))
}

fn choice(v: Value) -> &'static str {
    match v {
        Value::Choice(c) => c,
        _ => "",
    }
}

fn vector(v: Value) -> [f64; 3] {
    match v {
        Value::Vector(x) => x,
        _ => [f64::NAN; 3],
    }
}

const CONTACT_TABLES: &[Table] = &[Table::Settings, Table::ContactSettings];
const RESOLVER_TABLES: &[Table] = &[Table::Settings];

const FRICTION_MODELS: &[(&str, &str)] = &[
    (
        "millington",
        "the lecture's: solve for no sliding, then clamp to the Coulomb cone",
    ),
    (
        "kinetic-direction",
        "the collisions lectures' (Lecture IV Collisions; Pronost): j(n + μ_d t), t against the sliding direction",
    ),
    (
        "velocity-scaling",
        "the friction lecture's (PSE Friction): remove the planar velocity below v_c μ_s, else scale it by μ_d",
    ),
];
const PROJECTIONS: &[(&str, &str)] = &[
    (
        "nonlinear",
        "the lecture's: linear and angular inertia share the move",
    ),
    ("linear", "inverse-mass weighting only: no rotation"),
];
const EXACT_LAWS: &[(&str, &str)] = &[
    ("none", "skip the exact_impact stage"),
    ("newton", "kinematic: u_n' = -e u_n0"),
    (
        "poisson",
        "kinetic: P_n = (1 + e) P_n at maximum compression",
    ),
    (
        "stronge",
        "energetic: restitution work = -e² × compression work",
    ),
];
const SOLVERS: &[(&str, &str)] = &[
    (
        "deepest-first",
        "the lecture's: the deepest penetration, the largest desired Δv first",
    ),
    (
        "sequential-impulse",
        "projected Gauss–Seidel with accumulated, clamped impulses",
    ),
];
const RESTITUTION_FROM: &[(&str, &str)] = &[
    (
        "current",
        "the contact velocity when the contact is taken (the reference engine)",
    ),
    (
        "initial",
        "the contact velocity before the velocity phase began (Box2D v3)",
    ),
];
const BOX_BOX: &[(&str, &str)] = &[
    (
        "manifold",
        "the reference face clipped against the incident face, up to 4 points",
    ),
    (
        "single",
        "the reference engine's one point-face or edge-edge contact",
    ),
];
const NARROW_PHASE: &[(&str, &str)] = &[
    (
        "analytic",
        "the analytic routine where one exists, GJK/EPA for every other convex pair",
    ),
    (
        "gjk",
        "GJK/EPA and the clipped manifold for every pair but a half-space's",
    ),
];
const SLEEP_MODES: &[(&str, &str)] = &[
    ("body", "each body on its own (the lecture)"),
    (
        "island",
        "an island of touching bodies sleeps together (Box2D, Bullet, PhysX)",
    ),
];

const CCD_MODES: &[(&str, &str)] = &[
    ("none", "detect at the step's poses only: a body that crosses another inside one step is missed (tunnelling)"),
    ("bisection", "the lecture's: the step sampled, then [t₀, t₁] halved until it is shorter than the tolerance"),
    ("conservative", "conservative advancement: advance by GJK distance / bound on the closing speed"),
];
const ROLLBACK_MODES: &[(&str, &str)] = &[
    ("projection", "the lecture's: the position phase projects the pair apart"),
    ("rollback", "the pair is moved back along its motion to its time of collision, the rest of the world is not"),
];

const RUN_ONLY: &str = "a run's setting: change it on the run (simulate), not on one contact";

/// Every knob. A new knob is one entry here (and its physics); everything
/// else reads this table.
pub static KNOBS: &[Knob] = &[
    // ---- one contact -------------------------------------------------
    Knob {
        name: "friction_model",
        old_names: &[],
        level: Level::Contact,
        tables: &[Table::Settings, Table::ContactSettings, Table::Contact, Table::World],
        doc: "How friction is modelled: trades the lecture's exact sticking impulse for the companion lectures' cheaper rules (which can gain energy).",
        default: "millington",
        kind: Kind::Choice { choices: FRICTION_MODELS, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::FRICTION_MODEL,
        needs: Needs::Friction,
        get: |s| Value::Choice(s.contact.friction_model.name()),
        set: |s, v| {
            if let Some(m) = FrictionModel::from_name(choice(v)) {
                s.contact.friction_model = m;
            }
        },
    },
    Knob {
        name: "velocity_limit",
        old_names: &[],
        level: Level::Contact,
        tables: &[Table::Settings, Table::ContactSettings, Table::World],
        doc: "Restitution is 0 below this closing speed (m/s): trades bounce fidelity at low speed for resting contacts that do not vibrate.",
        default: "0 (the lecture); 0.25 in a scene (the reference engine)",
        kind: Kind::Number { range: Range::NonNegative, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::VELOCITY_LIMIT,
        needs: Needs::Always,
        get: |s| Value::Number(s.contact.velocity_limit),
        set: |s, v| s.contact.velocity_limit = number(v),
    },
    Knob {
        name: "angular_limit",
        old_names: &[],
        level: Level::Contact,
        tables: CONTACT_TABLES,
        doc: "Largest angular move in projection, as a multiple of |r⊥|: trades believable rotation for robustness against over-rotation (inf = no limit).",
        default: "0.2",
        kind: Kind::Number { range: Range::NonNegativeOrInf, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.contact.angular_limit),
        set: |s, v| s.contact.angular_limit = number(v),
    },
    Knob {
        name: "relaxation",
        old_names: &[],
        level: Level::Contact,
        tables: CONTACT_TABLES,
        doc: "Share of the penetration resolved in one projection, (0, 1]: trades speed of separation for stability when many contacts touch one body.",
        default: "1",
        kind: Kind::Number { range: Range::Share, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::RELAXATION,
        needs: Needs::Always,
        get: |s| Value::Number(s.contact.relaxation),
        set: |s, v| s.contact.relaxation = number(v),
    },
    Knob {
        name: "duration",
        old_names: &[],
        level: Level::Contact,
        tables: CONTACT_TABLES,
        doc: "Last frame's duration (s), for acceleration compensation: the velocity a·duration that one frame of acceleration builds up is not bounced back.",
        default: "0.01",
        kind: Kind::Number { range: Range::Duration, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::No("in a run every contact lasts the time step: vary dt"),
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.contact.duration),
        set: |s, v| s.contact.duration = number(v),
    },
    Knob {
        name: "projection",
        old_names: &[],
        level: Level::Contact,
        tables: CONTACT_TABLES,
        doc: "How penetration is resolved: trades the lecture's believable rotation for a cheaper move without rotation.",
        default: "nonlinear",
        kind: Kind::Choice { choices: PROJECTIONS, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::PROJECTION,
        needs: Needs::Always,
        get: |s| Value::Choice(s.contact.projection.name()),
        set: |s, v| {
            if let Some(p) = ProjectionMethod::from_name(choice(v)) {
                s.contact.projection = p;
            }
        },
    },
    Knob {
        name: "exact",
        old_names: &[],
        level: Level::Contact,
        tables: CONTACT_TABLES,
        doc: "Integrate the impact exactly under this restitution law beside the one-shot impulse (the exact_impact stage): trades an integration's cost for the accuracy reference; applies nothing.",
        default: "none",
        kind: Kind::Choice { choices: EXACT_LAWS, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::No("it describes a contact and applies nothing: a run is the same with it"),
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Choice(s.contact.exact.map_or("none", RestitutionLaw::name)),
        set: |s, v| s.contact.exact = RestitutionLaw::from_name(choice(v)),
    },
    // ---- a set of contacts -------------------------------------------
    Knob {
        name: "solver",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Which algorithm resolves a set of contacts: trades the lecture's one-shot impulses, exact for one contact, for accumulated impulses that settle coupled contacts.",
        default: "deepest-first",
        kind: Kind::Choice {
            choices: SOLVERS,
            aliases: &[("deepest_first", "deepest-first"), ("sequential_impulse", "sequential-impulse")],
        },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Choice(s.resolver.solver.name()),
        set: |s, v| {
            if let Some(x) = Solver::from_name(choice(v)) {
                s.resolver.solver = x;
            }
        },
    },
    Knob {
        name: "warm_start",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Sequential impulses only: start from the previous step's accumulated impulses (matched by body pair and contact point): trades a little bookkeeping for fewer sweeps on resting contacts.",
        default: "false",
        kind: Kind::Flag,
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Flag(s.resolver.warm_start),
        set: |s, v| s.resolver.warm_start = flag(v),
    },
    Knob {
        name: "position_iterations",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Most position-phase iterations (contact visits): trades time for penetration left.",
        default: "visits_per_contact × contacts",
        kind: Kind::Count { max: MAX_ITERATIONS, optional: true },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::No("a run's contacts change in number: vary visits_per_contact (the study's budget)"),
        grid: &[],
        needs: Needs::Always,
        get: |s| s.resolver.position_iterations.map_or(Value::Unset, |n| Value::Count(n as u64)),
        set: |s, v| s.resolver.position_iterations = count(v),
    },
    Knob {
        name: "velocity_iterations",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Most velocity-phase iterations (contact visits): trades time for closing velocity left.",
        default: "visits_per_contact × contacts",
        kind: Kind::Count { max: MAX_ITERATIONS, optional: true },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::No("a run's contacts change in number: vary visits_per_contact (the study's budget)"),
        grid: &[],
        needs: Needs::Always,
        get: |s| s.resolver.velocity_iterations.map_or(Value::Unset, |n| Value::Count(n as u64)),
        set: |s, v| s.resolver.velocity_iterations = count(v),
    },
    Knob {
        name: "visits_per_contact",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Each phase's limit when no explicit count is given, in visits per contact: trades time for what is left (the study's budget).",
        default: "8 (the lecture's 8 × contacts)",
        kind: Kind::Count { max: MAX_ITERATIONS, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::No("the study's budget is this knob, with converged for 1000"),
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Count(s.resolver.visits_per_contact as u64),
        set: |s, v| s.resolver.visits_per_contact = count(v).unwrap_or(8),
    },
    Knob {
        name: "position_epsilon",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Penetrations at or below this (m) are left alone: trades resting jitter for penetration left.",
        default: "0.01",
        kind: Kind::Number { range: Range::NonNegative, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::POSITION_EPSILON,
        needs: Needs::Always,
        get: |s| Value::Number(s.resolver.position_epsilon),
        set: |s, v| s.resolver.position_epsilon = number(v),
    },
    Knob {
        name: "velocity_epsilon",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "A desired Δv at or below this (m/s) is left alone: trades time for closing velocity left.",
        default: "0.01",
        kind: Kind::Number { range: Range::NonNegative, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::VELOCITY_EPSILON,
        needs: Needs::Always,
        get: |s| Value::Number(s.resolver.velocity_epsilon),
        set: |s, v| s.resolver.velocity_epsilon = number(v),
    },
    Knob {
        name: "slip_speed",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Sequential impulses: a contact whose slip (before this step's accelerations) is at or below this speed (m/s) sticks under μ_s, above it slides under μ_d: trades sticking that holds for slides that start late.",
        default: "velocity_epsilon",
        kind: Kind::Number { range: Range::NonNegative, optional: true },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| s.resolver.slip_speed.map_or(Value::Unset, Value::Number),
        set: |s, v| {
            s.resolver.slip_speed = match v {
                Value::Unset => None,
                v => Some(number(v)),
            }
        },
    },
    Knob {
        name: "restitution_from",
        old_names: &[],
        level: Level::Resolver,
        tables: RESOLVER_TABLES,
        doc: "Which contact velocity restitution is applied to in the velocity phase (sequential impulses always take the initial one).",
        default: "current",
        kind: Kind::Choice { choices: RESTITUTION_FROM, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::RESTITUTION_FROM,
        needs: Needs::Always,
        get: |s| Value::Choice(s.resolver.restitution_from.name()),
        set: |s, v| {
            if let Some(r) = RestitutionFrom::from_name(choice(v)) {
                s.resolver.restitution_from = r;
            }
        },
    },
    // ---- the time step -----------------------------------------------
    Knob {
        name: "dt",
        old_names: &[],
        level: Level::Step,
        tables: &[Table::Step],
        doc: "The time step (s): trades cost per simulated second for accuracy (penetration, energy, tunnelling).",
        default: "1/60",
        kind: Kind::Number { range: Range::Duration, optional: false },
        cli: Cli::Option,
        edit: Offered::No("a run's time step is its frames: change it with simulate --dt"),
        study: Offered::Yes,
        grid: grid::DT,
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.dt),
        set: |s, v| s.scene.dt = number(v),
    },
    Knob {
        name: "steps",
        old_names: &[],
        level: Level::Step,
        tables: &[Table::Step],
        doc: "How many steps a run takes.",
        default: "600",
        kind: Kind::Count { max: MAX_STEPS, optional: false },
        cli: Cli::Option,
        edit: Offered::No("the run screen computes steps as it plays"),
        study: Offered::No("the study runs each scene for its own time (--seconds)"),
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Count(s.scene.steps),
        set: |s, v| s.scene.steps = count(v).unwrap_or(0) as u64,
    },
    Knob {
        name: "ccd",
        old_names: &[],
        level: Level::Step,
        tables: &[Table::Step],
        doc: "Continuous detection: pairs whose swept bounds meet get their time of collision; the step advances to the earliest, resolves it there (velocity phase) and spends the rest of the step (at most 8 sub-steps; docs/ccd.md): trades a GJK search per close pair for collisions a fast small body would otherwise tunnel through.",
        default: "none",
        kind: Kind::Choice { choices: CCD_MODES, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::CCD,
        needs: Needs::Always,
        get: |s| Value::Choice(s.scene.ccd.name()),
        set: |s, v| {
            if let Some(m) = Ccd::from_name(choice(v)) {
                s.scene.ccd = m;
            }
        },
    },
    Knob {
        name: "rollback",
        old_names: &[],
        level: Level::Step,
        tables: &[Table::Step],
        doc: "What is done with a pair found interpenetrating deeper than position_epsilon and closing: project it apart (the lecture) or roll its bodies back along their motion to the time of collision, τ = penetration / closing speed (the lecture's question): trades projection's energy and rotation errors for the time the pair loses (and potential energy when it rolls back up). A choice, not a flag: docs/ccd.md says why.",
        default: "projection",
        kind: Kind::Choice { choices: ROLLBACK_MODES, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::ROLLBACK,
        needs: Needs::Penetration,
        get: |s| Value::Choice(s.scene.rollback.name()),
        set: |s, v| {
            if let Some(m) = Rollback::from_name(choice(v)) {
                s.scene.rollback = m;
            }
        },
    },
    Knob {
        name: "normal_from",
        old_names: &[],
        level: Level::Step,
        tables: &[Table::Step],
        doc: "Which normal a penetrating contact between two convex bodies takes in a step: the least penetration where the bodies are now (current: EPA's or the analytic routine's), or the direction from their closest points one frame earlier, when the pair was still apart, with the depth of the overlap along it (previous: Lecture IV Collisions' proposal for fast motion): trades a sideways normal when a fast body strikes an edge for a stale one when a body has slid into contact.",
        default: "current",
        kind: Kind::Choice {
            choices: &[
                ("current", "the least penetration at t (EPA's or the analytic routine's)"),
                ("previous", "from the closest points at t − Δt, the depth along it"),
            ],
            aliases: &[],
        },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Choice(s.scene.normal_from.name()),
        set: |s, v| {
            if let Some(m) = NormalFrom::from_name(choice(v)) {
                s.scene.normal_from = m;
            }
        },
    },
    // ---- the world ---------------------------------------------------
    Knob {
        name: "gravity",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Uniform acceleration of every movable body (m/s², x, y, z).",
        default: "0, -9.81, 0",
        kind: Kind::Vector,
        cli: Cli::Option,
        edit: Offered::No(RUN_ONLY),
        study: Offered::No("it changes the scene, not the model"),
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Vector(s.scene.world.gravity.into()),
        set: |s, v| s.scene.world.gravity = vector(v).into(),
    },
    Knob {
        name: "linear_damping",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Fraction of linear velocity kept per second, (0, 1]: trades energy lost for stability (1 = no damping).",
        default: "0.99",
        kind: Kind::Number { range: Range::Damping, optional: false },
        cli: Cli::Option,
        edit: Offered::No(RUN_ONLY),
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.world.linear_damping),
        set: |s, v| s.scene.world.linear_damping = number(v),
    },
    Knob {
        name: "angular_damping",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Fraction of angular velocity kept per second, (0, 1] (1 = no damping).",
        default: "0.99",
        kind: Kind::Number { range: Range::Damping, optional: false },
        cli: Cli::Option,
        edit: Offered::No(RUN_ONLY),
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.world.angular_damping),
        set: |s, v| s.scene.world.angular_damping = number(v),
    },
    Knob {
        name: "acceleration_compensation",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "The lecture's micro-collisions: the velocity one step of acceleration builds up is not bounced back. Off, a resting box vibrates.",
        default: "true",
        kind: Kind::Flag,
        cli: Cli::Negated("no-compensation"),
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Flag(s.scene.acceleration_compensation),
        set: |s, v| s.scene.acceleration_compensation = flag(v),
    },
    Knob {
        name: "box_box",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Which contacts a pair of boxes generates: trades the reference engine's one cheap point (a box on a box rocks) for a clipped manifold (stacks stand).",
        default: "manifold",
        kind: Kind::Choice { choices: BOX_BOX, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::BOX_BOX,
        needs: Needs::BoxPairs,
        get: |s| Value::Choice(s.scene.box_box.name()),
        set: |s, v| {
            if let Some(m) = BoxBoxMode::from_name(choice(v)) {
                s.scene.box_box = m;
            }
        },
    },
    Knob {
        name: "narrow_phase",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Which routine finds a convex pair's contacts: trades the analytic routines (exact, cheap) for GJK/EPA and the clipped manifold on every pair (one general method, to compare cost and depth/normal error); pairs without an analytic routine (cylinder with a box, sphere or cylinder) run GJK/EPA either way, a half-space pair keeps its routine.",
        default: "analytic",
        kind: Kind::Choice { choices: NARROW_PHASE, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::NARROW_PHASE,
        needs: Needs::Always,
        get: |s| Value::Choice(s.scene.narrow_phase.name()),
        set: |s, v| {
            if let Some(m) = NarrowPhase::from_name(choice(v)) {
                s.scene.narrow_phase = m;
            }
        },
    },
    Knob {
        name: "contact_margin",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "Contacts are generated for gaps up to this distance (m), with a negative penetration: a resting body keeps its contact after the position phase resolved it, instead of falling freely for a step; too large and bodies stop short of touching.",
        default: "0.005",
        kind: Kind::Number { range: Range::NonNegative, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.contact_margin),
        set: |s, v| s.scene.contact_margin = number(v),
    },
    Knob {
        name: "speculative",
        old_names: &[],
        level: Level::World,
        tables: &[Table::World],
        doc: "A contact in the contact margin's gap g that does not bounce removes only the closing velocity beyond g/Δt (a speculative contact): trades a closing velocity left within the gap for a body that lands instead of hovering (resolved as touching, a gap contact stops a body up to the margin above the face, and one kicked up each step climbs there). Deepest-first only; the lecture has no margin.",
        default: "false",
        kind: Kind::Flag,
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Flag(s.scene.speculative),
        set: |s, v| s.scene.speculative = flag(v),
    },
    // ---- sleep -------------------------------------------------------
    Knob {
        name: "sleep",
        old_names: &["enabled"],
        level: Level::Sleep,
        tables: &[Table::Sleep],
        doc: "Whether bodies may sleep: trades the cost of simulating resting bodies for the risk of freezing one that should still move.",
        default: "true",
        kind: Kind::Flag,
        cli: Cli::Negated("no-sleep"),
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: grid::SLEEP,
        needs: Needs::Always,
        get: |s| Value::Flag(s.scene.sleep.enabled),
        set: |s, v| s.scene.sleep.enabled = flag(v),
    },
    Knob {
        name: "sleep_epsilon",
        old_names: &["epsilon"],
        level: Level::Sleep,
        tables: &[Table::Sleep],
        doc: "Motion (recency-weighted v·v + ω·ω, m²/s²) below which a body sleeps (the reference engine's 0.3).",
        default: "0.3",
        kind: Kind::Number { range: Range::NonNegative, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.sleep.epsilon),
        set: |s, v| s.scene.sleep.epsilon = number(v),
    },
    Knob {
        name: "sleep_mode",
        old_names: &["mode"],
        level: Level::Sleep,
        tables: &[Table::Sleep],
        doc: "Sleep per body (the lecture) or per island of touching bodies.",
        default: "body",
        kind: Kind::Choice { choices: SLEEP_MODES, aliases: &[] },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Choice(s.scene.sleep.mode.name()),
        set: |s, v| {
            if let Some(m) = SleepMode::from_name(choice(v)) {
                s.scene.sleep.mode = m;
            }
        },
    },
    Knob {
        name: "island_time",
        old_names: &[],
        level: Level::Sleep,
        tables: &[Table::Sleep],
        doc: "Island sleep: how long (s) every body of an island must have been slow before it sleeps.",
        default: "0.5",
        kind: Kind::Number { range: Range::Duration, optional: false },
        cli: Cli::Option,
        edit: Offered::Yes,
        study: Offered::Yes,
        grid: &[],
        needs: Needs::Always,
        get: |s| Value::Number(s.scene.sleep.island_time),
        set: |s, v| s.scene.sleep.island_time = number(v),
    },
];
