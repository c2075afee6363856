//! The two resolver implementations over random scenes (proptest): the scan
//! (the lecture's loop) and the indexed one take the same contacts in the
//! same order and leave bit-identical bodies and bookkeeping. Scenes include
//! exact ties, bodies shared by many contacts, immovable bodies, friction
//! of every model, and both restitution modes.

use contact_lab::physics::params::{ResolverParams, RestitutionFrom};
use contact_lab::physics::resolver::{
    Implementation, Observer, PositionMoves, Resolver, Silent, VelocityImpulse,
};
use contact_lab::physics::{
    Body, BodyId, Contact, ContactInput, ContactParams, FrictionModel, ProjectionMethod, RigidBody,
    StepParams, World,
};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// One report: (phase, iteration, contact, value bits, updates sorted by contact).
type Taken = (u8, usize, usize, u64, Vec<(usize, u64, u64)>);

/// Every report, as bits, so two runs compare exactly.
#[derive(Debug, Default, PartialEq)]
struct Log {
    taken: Vec<Taken>,
}

impl Observer<f64> for Log {
    fn position_taken(&mut self, i: usize, k: usize, p: f64, _: &PositionMoves<f64>) {
        self.taken.push((0, i, k, p.to_bits(), vec![]));
    }
    fn penetration_updated(&mut self, k: usize, from: f64, to: f64) {
        let last = self.taken.last_mut().unwrap();
        last.4.push((k, from.to_bits(), to.to_bits()));
        last.4.sort();
    }
    fn velocity_taken(&mut self, i: usize, k: usize, d: f64, _: &VelocityImpulse<f64>) {
        self.taken.push((1, i, k, d.to_bits(), vec![]));
    }
    fn desired_updated(&mut self, k: usize, from: f64, to: f64) {
        let last = self.taken.last_mut().unwrap();
        last.4.push((k, from.to_bits(), to.to_bits()));
        last.4.sort();
    }
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Everything the resolver leaves, as bits.
fn state(r: &Resolver<f64>) -> Vec<u64> {
    let mut out = vec![];
    for b in &r.bodies {
        out.extend(bits(b.position.as_slice()));
        out.extend(bits(b.orientation.coords.as_slice()));
        out.extend(bits(b.velocity.as_slice()));
        out.extend(bits(b.angular_velocity.as_slice()));
    }
    for c in &r.contacts {
        out.extend(bits(&[c.penetration, c.desired]));
        out.extend(bits(c.velocity.as_slice()));
    }
    out
}

/// A body: movable, mass, box sides, orientation (raw), position, velocity,
/// angular velocity, accelerating.
type BodySpec = (
    bool,
    f64,
    [f64; 3],
    [f64; 4],
    [f64; 3],
    [f64; 3],
    [f64; 3],
    bool,
);

/// A contact: body 1, body 2, point, normal, penetration and restitution
/// (indices into the sets below), friction kind, μ.
type ContactSpec = (
    usize,
    Option<usize>,
    [f64; 3],
    usize,
    usize,
    usize,
    usize,
    f64,
);

#[derive(Debug, Clone)]
struct Spec {
    bodies: Vec<BodySpec>,
    contacts: Vec<ContactSpec>,
    restitution_from: RestitutionFrom,
    projection: ProjectionMethod,
}

/// Penetrations and restitutions from small sets, so exact ties are common.
const PENETRATIONS: [f64; 6] = [-0.01, 0.0, 0.02, 0.05, 0.05, 0.3];
const RESTITUTIONS: [f64; 3] = [0.0, 0.5, 1.0];
const NORMALS: [[f64; 3]; 6] = [
    [0.0, 1.0, 0.0],
    [1.0, 0.0, 0.0],
    [0.0, 0.0, -1.0],
    [0.6, 0.8, 0.0],
    [-0.8, 0.0, 0.6],
    [0.48, 0.6, 0.64],
];

fn spec_of(contacts: std::ops::Range<usize>) -> impl Strategy<Value = Spec> {
    let body = (
        prop::bool::weighted(0.8),
        0.2..5.0f64,
        prop::array::uniform3(0.3..2.0f64),
        prop::array::uniform4(-1.0..1.0f64),
        prop::array::uniform3(-3.0..3.0f64),
        prop::array::uniform3(-2.0..2.0f64),
        prop::array::uniform3(-1.0..1.0f64),
        prop::bool::weighted(0.3),
    );
    (prop::collection::vec(body, 1..7), contacts).prop_flat_map(|(bodies, n)| {
        let nb = bodies.len();
        let contact = (
            0..nb,
            prop::option::weighted(0.6, 0..nb),
            prop::array::uniform3(-2.0..2.0f64),
            0..NORMALS.len(),
            0..PENETRATIONS.len(),
            0..RESTITUTIONS.len(),
            0..5usize,
            0.0..1.0f64,
        );
        (
            Just(bodies),
            prop::collection::vec(contact, n),
            prop_oneof![
                Just(RestitutionFrom::Current),
                Just(RestitutionFrom::Initial)
            ],
            prop_oneof![
                3 => Just(ProjectionMethod::Nonlinear),
                1 => Just(ProjectionMethod::Linear)
            ],
        )
            .prop_map(|(bodies, contacts, restitution_from, projection)| Spec {
                bodies,
                contacts,
                restitution_from,
                projection,
            })
    })
}

fn world(spec: &Spec) -> World<f64> {
    let mut bodies: Vec<Body<f64>> = spec
        .bodies
        .iter()
        .map(|&(movable, m, sides, q, p, v, w, accelerating)| {
            let q = Quaternion::new(q[0], q[1], q[2], q[3] + 2.0);
            let orientation = UnitQuaternion::new_normalize(q).into_inner();
            let position = Vector3::from(p);
            if !movable {
                return Body::immovable(position, orientation, None);
            }
            let [x, y, z] = sides.map(|s| s * s);
            let inertia = Matrix3::from_diagonal(&Vector3::new(y + z, x + z, x + y)) * (m / 12.0);
            Body {
                state: RigidBody {
                    mass: m,
                    inverse_mass: 1.0 / m,
                    inertia_body: inertia,
                    inverse_inertia_body: inertia.try_inverse().unwrap(),
                    position,
                    orientation,
                    velocity: Vector3::from(v),
                    angular_velocity: Vector3::from(w),
                    acceleration: if accelerating {
                        Vector3::new(0.0, -9.81, 0.0)
                    } else {
                        Vector3::zeros()
                    },
                },
                shape: None,
                movable: true,
            }
        })
        .collect();
    // At least one movable body, so every contact can have one.
    if !bodies.iter().any(|b| b.movable) {
        let b = &mut bodies[0];
        *b = Body {
            state: RigidBody {
                mass: 1.0,
                inverse_mass: 1.0,
                inertia_body: Matrix3::identity(),
                inverse_inertia_body: Matrix3::identity(),
                ..b.state.clone()
            },
            shape: None,
            movable: true,
        };
    }
    let first_movable = bodies.iter().position(|b| b.movable).unwrap();
    let contacts = spec
        .contacts
        .iter()
        .map(|&(b1, b2, point, n, pen, e, friction, mu)| {
            // Body 1 must differ from body 2 and the pair must hold a movable body.
            let mut b1 = b1;
            let b2 = b2.filter(|&b| b != b1);
            if !bodies[b1].movable && b2.is_none_or(|b| !bodies[b].movable) {
                b1 = first_movable;
            }
            let b2 = b2.filter(|&b| b != b1);
            let (model, mu) = match friction {
                0 | 1 => (FrictionModel::Millington, 0.0),
                2 => (FrictionModel::Millington, mu),
                3 => (FrictionModel::KineticDirection, mu),
                _ => (FrictionModel::VelocityScaling, mu),
            };
            Contact {
                body1: BodyId(b1),
                body2: b2.map(BodyId),
                input: ContactInput {
                    point: Vector3::from(point),
                    normal: Vector3::from(NORMALS[n]),
                    penetration: PENETRATIONS[pen],
                    restitution: RESTITUTIONS[e],
                    static_friction: mu,
                    dynamic_friction: mu * 0.8,
                    friction_model: model,
                    settings: ContactParams {
                        velocity_limit: 0.25,
                        projection: spec.projection,
                        ..ContactParams::default()
                    },
                },
                duration: None,
            }
        })
        .collect();
    World {
        bodies,
        contacts,
        step: StepParams::default(),
    }
}

/// Scenes of up to 23 contacts: the indexed resolver scans its values.
fn spec() -> impl Strategy<Value = Spec> {
    spec_of(1..24)
}

/// Resolves `spec` with both implementations: the same contacts taken, the same bits left.
fn same_bits(spec: &Spec) -> Result<(), TestCaseError> {
    let w = world(spec);
    let params = ResolverParams {
        restitution_from: spec.restitution_from,
        ..ResolverParams::default()
    };
    let mut scan_log = Log::default();
    let (scan, scan_out) = Resolver::resolve(&w, &params, Implementation::Scan, &mut scan_log);
    let mut indexed_log = Log::default();
    let (indexed, indexed_out) =
        Resolver::resolve(&w, &params, Implementation::Indexed, &mut indexed_log);
    prop_assert_eq!(&scan_log, &indexed_log);
    prop_assert_eq!(state(&scan), state(&indexed));
    // Debug text, so that a NaN left by a runaway scene compares equal to itself.
    prop_assert_eq!(format!("{scan_out:?}"), format!("{indexed_out:?}"));
    // The fast path (nothing recorded: the neighbours visited by slot
    // pattern) leaves the same bits too.
    let (silent, silent_out) = Resolver::resolve(&w, &params, Implementation::Indexed, &mut Silent);
    prop_assert_eq!(state(&scan), state(&silent));
    prop_assert_eq!(format!("{scan_out:?}"), format!("{silent_out:?}"));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn scan_and_indexed_take_the_same_contacts_and_leave_the_same_bits(spec in spec()) {
        same_bits(&spec)?;
    }
}

proptest! {
    // From 64 contacts on the indexed resolver uses its tournament tree.
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn with_the_tournament_tree_too(spec in spec_of(64..90)) {
        same_bits(&spec)?;
    }
}

/// `spec` with nothing bouncing and no gap (restitution 0 from the current
/// velocity, no contact apart): every contact's desired Δv takes the fast
/// path's plain rule.
fn plain(spec: &Spec) -> Spec {
    let mut plain = spec.clone();
    for contact in &mut plain.contacts {
        contact.4 = contact.4.max(1);
        contact.5 = 0;
    }
    plain.restitution_from = RestitutionFrom::Current;
    plain
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn with_the_plain_desired_rule_too(spec in spec()) {
        same_bits(&plain(&spec))?;
    }
}

/// Two contacts at exactly the same penetration: both implementations take
/// the first in file order, as the lecture's strict `>` does.
#[test]
fn ties_go_to_the_first_contact_in_file_order() {
    let spec = Spec {
        bodies: vec![
            (
                true,
                1.0,
                [1.0; 3],
                [1.0, 0.0, 0.0, -2.0],
                [0.0; 3],
                [0.0; 3],
                [0.0; 3],
                false,
            ),
            (
                true,
                1.0,
                [1.0; 3],
                [1.0, 0.0, 0.0, -2.0],
                [5.0, 0.0, 0.0],
                [0.0; 3],
                [0.0; 3],
                false,
            ),
        ],
        contacts: vec![
            (1, None, [5.0, -0.5, 0.0], 0, 3, 0, 0, 0.0),
            (0, None, [0.0, -0.5, 0.0], 0, 4, 0, 0, 0.0),
        ],
        restitution_from: RestitutionFrom::Current,
        projection: ProjectionMethod::Nonlinear,
    };
    let w = world(&spec);
    assert_eq!(
        w.contacts[0].input.penetration,
        w.contacts[1].input.penetration
    );
    for implementation in [Implementation::Scan, Implementation::Indexed] {
        let mut log = Log::default();
        Resolver::resolve(&w, &ResolverParams::default(), implementation, &mut log);
        let order: Vec<usize> = log.taken.iter().filter(|t| t.0 == 0).map(|t| t.2).collect();
        assert_eq!(order, vec![0, 1], "{implementation:?}");
    }
}
