//! The knobs of a run: the time step (`[step]`), the world (`[world]`) and
//! sleep (`[sleep]`), and their choices.

use super::choice::{choices, Choice};
use super::knob::{choice, count, flag, number, vector};
use super::knob::{Cli, Kind, Knob, Level, Needs, Offered, Range, Table, Value, MAX_STEPS};
use crate::physics::detect::ToiMethod;
use crate::physics::params::{
    BoxBoxMode, BroadPhaseMethod, Ccd, InternalEdges, NarrowPhase, NormalFrom, Rollback, SleepMode,
};

const RUN_ONLY: &str = "a run's setting: change it on the run (simulate), not on one contact";

choices!(Ccd {
    Ccd::None => "none":
        "detect at the step's poses only: a body that crosses another inside one step is missed (tunnelling)";
    Ccd::Bisection => "bisection":
        "the lecture's: the step sampled, then [t₀, t₁] halved until it is shorter than the tolerance";
    Ccd::Conservative => "conservative":
        "conservative advancement: advance by GJK distance / bound on the closing speed";
});

/// A time-of-collision search's name: the `ccd` choice that runs it.
pub fn toi_method_name(m: ToiMethod) -> &'static str {
    Ccd::VALUES
        .iter()
        .find(|c| c.method() == Some(m))
        .map_or("", |c| c.name())
}

choices!(Rollback {
    Rollback::Projection => "projection":
        "the lecture's: the position phase projects the pair apart";
    Rollback::Rollback => "rollback":
        "the pair is moved back along its motion to its time of collision, the rest of the world is not";
});

choices!(NormalFrom {
    NormalFrom::Current => "current":
        "the least penetration at t (EPA's or the analytic routine's)";
    NormalFrom::Previous => "previous":
        "from the closest points at t − Δt, the depth along it";
});

choices!(BoxBoxMode {
    BoxBoxMode::Manifold => "manifold":
        "the reference face clipped against the incident face, up to 4 points";
    BoxBoxMode::Single => "single": "the reference engine's one point-face or edge-edge contact";
});

choices!(NarrowPhase {
    NarrowPhase::Analytic => "analytic":
        "the analytic routine where one exists, GJK/EPA for every other convex pair";
    NarrowPhase::Gjk => "gjk":
        "GJK/EPA and the clipped manifold for every pair but a half-space's";
});

choices!(BroadPhaseMethod {
    BroadPhaseMethod::Sweep => "sweep":
        "sort and sweep: boxes sorted along the axis of largest spread, each met by the later ones that start before it ends";
    BroadPhaseMethod::Grid => "grid":
        "a uniform grid (cell: the median box's largest side): each box hashed into the cells it overlaps, each pair tested once in the first cell both share";
    BroadPhaseMethod::Bvh => "bvh":
        "a dynamic bounding-volume tree of fat boxes (refitted as bodies move), each body's box queried down it";
});

choices!(InternalEdges {
    InternalEdges::Corrected => "fix" ["corrected"]:
        "a mesh's normal on an edge or corner shared with another triangle turned to what the neighbouring faces allow: no bump at a seam";
    InternalEdges::Raw => "raw":
        "each triangle's own normal, as if it were alone: a body sliding across a seam may bump (a ghost collision)";
});

choices!(SleepMode {
    SleepMode::Body => "body": "each body on its own (the lecture)";
    SleepMode::Island => "island":
        "an island of touching bodies sleeps together (Box2D, Bullet, PhysX)";
});

// ---- the time step -----------------------------------------------

/// `dt`.
pub const DT: Knob = Knob {
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
    grid: &["1/30", "1/60", "1/120", "1/240", "1/480"],
    needs: Needs::Always,
    get: |s| Value::Number(s.scene.dt),
    set: |s, v| s.scene.dt = number(v),
};

/// `steps`.
pub const STEPS: Knob = Knob {
    name: "steps",
    old_names: &[],
    level: Level::Step,
    tables: &[Table::Step],
    doc: "How many steps a run takes.",
    default: "600",
    kind: Kind::Count {
        max: MAX_STEPS,
        optional: false,
    },
    cli: Cli::Option,
    edit: Offered::No("the run screen computes steps as it plays"),
    study: Offered::No("the study runs each scene for its own time (--seconds)"),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Count(s.scene.steps),
    set: |s, v| s.scene.steps = count(v).unwrap_or(0) as u64,
};

/// `ccd`.
pub const CCD: Knob = Knob {
    name: "ccd",
    old_names: &[],
    level: Level::Step,
    tables: &[Table::Step],
    doc: "Continuous detection: pairs whose swept bounds meet get their time of collision; the step advances to the earliest, resolves it there (velocity phase) and spends the rest of the step (at most 8 sub-steps; docs/ccd.md): trades a GJK search per close pair for collisions a fast small body would otherwise tunnel through.",
    default: "none",
    kind: Kind::Choice { choices: Ccd::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: Ccd::NAMES,
    needs: Needs::Always,
    get: |s| Value::Choice(s.scene.ccd.name()),
    set: |s, v| {
        if let Some(m) = Ccd::from_name(choice(v)) {
            s.scene.ccd = m;
        }
    },
};

/// `rollback`: its grid sets the lecture's projection against rolling
/// back to the time of collision, in the scenes where a pair can be found
/// deep and closing.
pub const ROLLBACK: Knob = Knob {
    name: "rollback",
    old_names: &[],
    level: Level::Step,
    tables: &[Table::Step],
    doc: "What is done with a pair found interpenetrating deeper than position_epsilon and closing: project it apart (the lecture) or roll its bodies back along their motion to the time of collision, τ = penetration / closing speed (the lecture's question): trades projection's energy and rotation errors for the time the pair loses (and potential energy when it rolls back up). A choice, not a flag: docs/ccd.md says why.",
    default: "projection",
    kind: Kind::Choice { choices: Rollback::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: Rollback::NAMES,
    needs: Needs::Penetration,
    get: |s| Value::Choice(s.scene.rollback.name()),
    set: |s, v| {
        if let Some(m) = Rollback::from_name(choice(v)) {
            s.scene.rollback = m;
        }
    },
};

/// `normal_from`.
pub const NORMAL_FROM: Knob = Knob {
    name: "normal_from",
    old_names: &[],
    level: Level::Step,
    tables: &[Table::Step],
    doc: "Which normal a penetrating contact between two convex bodies takes in a step: the least penetration where the bodies are now (current: EPA's or the analytic routine's), or the direction from their closest points one frame earlier, when the pair was still apart, with the depth of the overlap along it (previous: Lecture IV Collisions' proposal for fast motion): trades a sideways normal when a fast body strikes an edge for a stale one when a body has slid into contact.",
    default: "current",
    kind: Kind::Choice { choices: NormalFrom::SPELLINGS },
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
};

// ---- the world ---------------------------------------------------

/// `gravity`.
pub const GRAVITY: Knob = Knob {
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
};

/// `linear_damping`.
pub const LINEAR_DAMPING: Knob = Knob {
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
};

/// `angular_damping`.
pub const ANGULAR_DAMPING: Knob = Knob {
    name: "angular_damping",
    old_names: &[],
    level: Level::World,
    tables: &[Table::World],
    doc: "Fraction of angular velocity kept per second, (0, 1] (1 = no damping).",
    default: "0.99",
    kind: Kind::Number {
        range: Range::Damping,
        optional: false,
    },
    cli: Cli::Option,
    edit: Offered::No(RUN_ONLY),
    study: Offered::Yes,
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.scene.world.angular_damping),
    set: |s, v| s.scene.world.angular_damping = number(v),
};

/// `acceleration_compensation`.
pub const ACCELERATION_COMPENSATION: Knob = Knob {
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
};

/// `box_box`.
pub const BOX_BOX: Knob = Knob {
    name: "box_box",
    old_names: &[],
    level: Level::World,
    tables: &[Table::World],
    doc: "Which contacts a pair of boxes generates: trades the reference engine's one cheap point (a box on a box rocks) for a clipped manifold (stacks stand).",
    default: "manifold",
    kind: Kind::Choice { choices: BoxBoxMode::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: &["single", "manifold"],
    needs: Needs::BoxPairs,
    get: |s| Value::Choice(s.scene.box_box.name()),
    set: |s, v| {
        if let Some(m) = BoxBoxMode::from_name(choice(v)) {
            s.scene.box_box = m;
        }
    },
};

/// `narrow_phase`.
pub const NARROW_PHASE: Knob = Knob {
    name: "narrow_phase",
    old_names: &[],
    level: Level::World,
    tables: &[Table::World],
    doc: "Which routine finds a convex pair's contacts: trades the analytic routines (exact, cheap) for GJK/EPA and the clipped manifold on every pair (one general method, to compare cost and depth/normal error); pairs without an analytic routine (cylinder with a box, sphere or cylinder) run GJK/EPA either way, a half-space pair keeps its routine.",
    default: "analytic",
    kind: Kind::Choice { choices: NarrowPhase::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: NarrowPhase::NAMES,
    needs: Needs::Always,
    get: |s| Value::Choice(s.scene.narrow_phase.name()),
    set: |s, v| {
        if let Some(m) = NarrowPhase::from_name(choice(v)) {
            s.scene.narrow_phase = m;
        }
    },
};

/// `contact_margin`.
pub const CONTACT_MARGIN: Knob = Knob {
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
};

/// `speculative`.
pub const SPECULATIVE: Knob = Knob {
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
};

// ---- sleep -------------------------------------------------------

/// `sleep`.
pub const SLEEP: Knob = Knob {
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
    grid: &["true", "false"],
    needs: Needs::Always,
    get: |s| Value::Flag(s.scene.sleep.enabled),
    set: |s, v| s.scene.sleep.enabled = flag(v),
};

/// `sleep_epsilon`.
pub const SLEEP_EPSILON: Knob = Knob {
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
};

/// `sleep_mode`.
pub const SLEEP_MODE: Knob = Knob {
    name: "sleep_mode",
    old_names: &["mode"],
    level: Level::Sleep,
    tables: &[Table::Sleep],
    doc: "Sleep per body (the lecture) or per island of touching bodies.",
    default: "body",
    kind: Kind::Choice {
        choices: SleepMode::SPELLINGS,
    },
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
};

/// `island_time`.
pub const ISLAND_TIME: Knob = Knob {
    name: "island_time",
    old_names: &[],
    level: Level::Sleep,
    tables: &[Table::Sleep],
    doc: "Island sleep: how long (s) every body of an island must have been slow before it sleeps.",
    default: "0.5",
    kind: Kind::Number {
        range: Range::Duration,
        optional: false,
    },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Number(s.scene.sleep.island_time),
    set: |s, v| s.scene.sleep.island_time = number(v),
};

/// `internal_edges`.
pub const INTERNAL_EDGES: Knob = Knob {
    name: "internal_edges",
    old_names: &[],
    level: Level::World,
    tables: &[Table::World],
    doc: "A mesh's contact normal on an edge or corner two triangles share: corrected from the neighbouring triangles (a body slides across the seam of a flat triangulated floor without a bump) or raw, each triangle alone (the ghost collision engines correct).",
    default: "fix",
    kind: Kind::Choice { choices: InternalEdges::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Choice(s.scene.internal_edges.name()),
    set: |s, v| {
        if let Some(m) = InternalEdges::from_name(choice(v)) {
            s.scene.internal_edges = m;
        }
    },
};

/// `broad_phase`.
pub const BROAD_PHASE: Knob = Knob {
    name: "broad_phase",
    old_names: &[],
    level: Level::World,
    tables: &[Table::World],
    doc: "How the broad phase finds the pairs whose boxes overlap: trades sort and sweep (cheap when bodies spread along one axis) for a uniform grid (cheap at an even density, poor when bodies cluster or differ much in size) or a dynamic tree (robust to clusters and sizes); every method finds the same pairs in the same order, so a run is the same state for state, only its cost differs (study --broad-phase).",
    default: "sweep",
    kind: Kind::Choice { choices: BroadPhaseMethod::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No("the broad phase never changes a run, only what finding its pairs costs: study --broad-phase measures that"),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Choice(s.scene.broad_phase.name()),
    set: |s, v| {
        if let Some(m) = BroadPhaseMethod::from_name(choice(v)) {
            s.scene.broad_phase = m;
        }
    },
};
