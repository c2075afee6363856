//! The knobs of one contact and of a set of contacts (`[settings]`, a
//! contact's `settings`), and their choices.

use super::choice::{choices, Choice};
use super::knob::{choice, count, flag, number};
use super::knob::{Cli, Kind, Knob, Level, Needs, Offered, Range, Table, Value, MAX_ITERATIONS};
use crate::physics::exact::RestitutionLaw;
use crate::physics::{FrictionModel, LcpRestitution, ProjectionMethod, RestitutionFrom, Solver};

const CONTACT_TABLES: &[Table] = &[Table::Settings, Table::ContactSettings];
const RESOLVER_TABLES: &[Table] = &[Table::Settings];

choices!(FrictionModel {
    FrictionModel::Millington => "millington":
        "the lecture's: solve for no sliding, then clamp to the Coulomb cone";
    FrictionModel::KineticDirection => "kinetic-direction":
        "the collisions lectures' (Lecture IV Collisions; Pronost): j(n + μ_d t), t against the sliding direction";
    FrictionModel::VelocityScaling => "velocity-scaling":
        "the friction lecture's (PSE Friction): remove the planar velocity below v_c μ_s, else scale it by μ_d";
});

choices!(ProjectionMethod {
    ProjectionMethod::Nonlinear => "nonlinear":
        "the lecture's: linear and angular inertia share the move";
    ProjectionMethod::Linear => "linear": "inverse-mass weighting only: no rotation";
});

choices!(Option<RestitutionLaw> {
    None => "none": "skip the exact_impact stage";
    Some(RestitutionLaw::Newton) => "newton": "kinematic: u_n' = -e u_n0";
    Some(RestitutionLaw::Poisson) => "poisson":
        "kinetic: P_n = (1 + e) P_n at maximum compression";
    Some(RestitutionLaw::Stronge) => "stronge":
        "energetic: restitution work = -e² × compression work";
});

choices!(Solver {
    Solver::DeepestFirst => "deepest-first" ["deepest_first"]:
        "the lecture's: the deepest penetration, the largest desired Δv first";
    Solver::SequentialImpulse => "sequential-impulse" ["sequential_impulse"]:
        "projected Gauss–Seidel with accumulated, clamped impulses";
    Solver::SoftStep => "soft-step" ["soft_step"]:
        "Box2D v3's: substeps, soft contacts (a frequency and a damping ratio), relax and restitution passes";
    Solver::Xpbd => "xpbd":
        "extended position based dynamics (Müller et al. 2020): substeps, one position iteration each, then a velocity pass";
    Solver::Lcp => "lcp":
        "simultaneous impact: one linear complementarity problem over every contact (Lemke's method)";
});

choices!(LcpRestitution {
    LcpRestitution::Newton => "newton":
        "kinematic: each separating velocity after at least -e times the closing velocity before";
    LcpRestitution::Poisson => "poisson":
        "kinetic: compression to zero closing velocity, then e times each compression impulse";
});

choices!(RestitutionFrom {
    RestitutionFrom::Current => "current":
        "the contact velocity when the contact is taken (the reference engine)";
    RestitutionFrom::Initial => "initial":
        "the contact velocity before the velocity phase began (Box2D v3)";
});

// ---- one contact -------------------------------------------------

/// `friction_model`.
pub const FRICTION_MODEL: Knob = Knob {
    name: "friction_model",
    old_names: &[],
    level: Level::Contact,
    tables: &[Table::Settings, Table::ContactSettings, Table::Contact, Table::World],
    doc: "How friction is modelled: trades the lecture's exact sticking impulse for the companion lectures' cheaper rules (which can gain energy).",
    default: "millington",
    kind: Kind::Choice { choices: FrictionModel::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: FrictionModel::NAMES,
    needs: Needs::Friction,
    get: |s| Value::Choice(s.contact.friction_model.name()),
    set: |s, v| {
        if let Some(m) = FrictionModel::from_name(choice(v)) {
            s.contact.friction_model = m;
        }
    },
};

/// `velocity_limit`.
pub const VELOCITY_LIMIT: Knob = Knob {
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
    grid: &["0", "0.25", "1"],
    needs: Needs::Always,
    get: |s| Value::Number(s.contact.velocity_limit),
    set: |s, v| s.contact.velocity_limit = number(v),
};

/// `angular_limit`.
pub const ANGULAR_LIMIT: Knob = Knob {
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
};

/// `relaxation`.
pub const RELAXATION: Knob = Knob {
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
    grid: &["0.5"],
    needs: Needs::Always,
    get: |s| Value::Number(s.contact.relaxation),
    set: |s, v| s.contact.relaxation = number(v),
};

/// `duration`.
pub const DURATION: Knob = Knob {
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
};

/// `projection`.
pub const PROJECTION: Knob = Knob {
    name: "projection",
    old_names: &[],
    level: Level::Contact,
    tables: CONTACT_TABLES,
    doc: "How penetration is resolved: trades the lecture's believable rotation for a cheaper move without rotation.",
    default: "nonlinear",
    kind: Kind::Choice { choices: ProjectionMethod::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: &["linear", "nonlinear"],
    needs: Needs::Always,
    get: |s| Value::Choice(s.contact.projection.name()),
    set: |s, v| {
        if let Some(p) = ProjectionMethod::from_name(choice(v)) {
            s.contact.projection = p;
        }
    },
};

/// `exact`.
pub const EXACT: Knob = Knob {
    name: "exact",
    old_names: &[],
    level: Level::Contact,
    tables: CONTACT_TABLES,
    doc: "Integrate the impact exactly under this restitution law beside the one-shot impulse (the exact_impact stage): trades an integration's cost for the accuracy reference; applies nothing.",
    default: "none",
    kind: Kind::Choice { choices: <Option<RestitutionLaw>>::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No("it describes a contact and applies nothing: a run is the same with it"),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Choice(s.contact.exact.name()),
    set: |s, v| s.contact.exact = <Option<RestitutionLaw>>::from_name(choice(v)).flatten(),
};

// ---- a set of contacts -------------------------------------------

/// `solver`.
pub const SOLVER: Knob = Knob {
    name: "solver",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Which algorithm resolves a set of contacts: trades the lecture's one-shot impulses, exact for one contact, for accumulated impulses that settle coupled contacts.",
    default: "deepest-first",
    kind: Kind::Choice { choices: Solver::SPELLINGS },
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
};

/// `warm_start`.
pub const WARM_START: Knob = Knob {
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
};

/// `position_iterations`.
pub const POSITION_ITERATIONS: Knob = Knob {
    name: "position_iterations",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Most position-phase iterations (contact visits): trades time for penetration left.",
    default: "visits_per_contact × contacts",
    kind: Kind::Count {
        max: MAX_ITERATIONS,
        optional: true,
    },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(
        "a run's contacts change in number: vary visits_per_contact (the study's budget)",
    ),
    grid: &[],
    needs: Needs::Always,
    get: |s| {
        s.resolver
            .position_iterations
            .map_or(Value::Unset, |n| Value::Count(n as u64))
    },
    set: |s, v| s.resolver.position_iterations = count(v),
};

/// `velocity_iterations`.
pub const VELOCITY_ITERATIONS: Knob = Knob {
    name: "velocity_iterations",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Most velocity-phase iterations (contact visits): trades time for closing velocity left.",
    default: "visits_per_contact × contacts",
    kind: Kind::Count {
        max: MAX_ITERATIONS,
        optional: true,
    },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No(
        "a run's contacts change in number: vary visits_per_contact (the study's budget)",
    ),
    grid: &[],
    needs: Needs::Always,
    get: |s| {
        s.resolver
            .velocity_iterations
            .map_or(Value::Unset, |n| Value::Count(n as u64))
    },
    set: |s, v| s.resolver.velocity_iterations = count(v),
};

/// `visits_per_contact`.
pub const VISITS_PER_CONTACT: Knob = Knob {
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
};

/// `position_epsilon`.
pub const POSITION_EPSILON: Knob = Knob {
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
    grid: &["0.1", "0.001"],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.position_epsilon),
    set: |s, v| s.resolver.position_epsilon = number(v),
};

/// `velocity_epsilon`.
pub const VELOCITY_EPSILON: Knob = Knob {
    name: "velocity_epsilon",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc:
        "A desired Δv at or below this (m/s) is left alone: trades time for closing velocity left.",
    default: "0.01",
    kind: Kind::Number {
        range: Range::NonNegative,
        optional: false,
    },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: &["0.1", "0.001"],
    needs: Needs::Always,
    get: |s| Value::Number(s.resolver.velocity_epsilon),
    set: |s, v| s.resolver.velocity_epsilon = number(v),
};

/// `slip_speed`.
pub const SLIP_SPEED: Knob = Knob {
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
};

/// `restitution_from`.
pub const RESTITUTION_FROM: Knob = Knob {
    name: "restitution_from",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Which contact velocity restitution is applied to in the velocity phase (sequential impulses always take the initial one).",
    default: "current",
    kind: Kind::Choice { choices: RestitutionFrom::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::Yes,
    grid: RestitutionFrom::NAMES,
    needs: Needs::Always,
    get: |s| Value::Choice(s.resolver.restitution_from.name()),
    set: |s, v| {
        if let Some(r) = RestitutionFrom::from_name(choice(v)) {
            s.resolver.restitution_from = r;
        }
    },
};

/// `lcp_restitution`.
pub const LCP_RESTITUTION: Knob = Knob {
    name: "lcp_restitution",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "The simultaneous (lcp) solver's restitution law: Newton's targets each contact's velocity after; Poisson's scales each compression impulse (the two differ when contacts are coupled).",
    default: "newton",
    kind: Kind::Choice { choices: LcpRestitution::SPELLINGS },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No("only the lcp solver reads it, an impact solver the study does not run"),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Choice(s.resolver.lcp_restitution.name()),
    set: |s, v| {
        if let Some(r) = LcpRestitution::from_name(choice(v)) {
            s.resolver.lcp_restitution = r;
        }
    },
};

/// `substeps`.
pub const SUBSTEPS: Knob = Knob {
    name: "substeps",
    old_names: &[],
    level: Level::Resolver,
    tables: RESOLVER_TABLES,
    doc: "Soft step and XPBD: substeps per step, from 1 to 64: trades time for stiffer, more accurate contacts (Box2D's and rapier's 4).",
    default: "4",
    kind: Kind::Count { max: 64, optional: false },
    cli: Cli::Option,
    edit: Offered::Yes,
    study: Offered::No("only the soft step and XPBD read it: the study tries those solvers at its default"),
    grid: &[],
    needs: Needs::Always,
    get: |s| Value::Count(s.resolver.substeps as u64),
    set: |s, v| s.resolver.substeps = count(v).unwrap_or(4).max(1),
};
