//! One resolution recorded stop by stop, for the TUI's resolver screen and
//! `simulate --trace-step`: the resolver trace of a time step (or of a
//! lesson's contacts), the bodies as each iteration finds them, and the
//! contact table (penetration, desired Δv) at every stop of both phases.

use super::resolver::{describe_prepared, describe_world, Names, ResolverTrace};
use super::stop::{Stop, Table};
use super::{BodyView, ContactView};
use crate::lesson::{ContactDef, Lesson};
use crate::physics::params::ContactSettings;
use crate::physics::resolver::{Implementation, Observer, Phase, Resolver, ResolverBody};
use crate::physics::step::previous_frame::previous_normal;
use crate::physics::step::{BlowUp, Simulation, StepReport};
use crate::physics::World;

/// One resolution, recorded for stepping through.
#[derive(Debug, Clone)]
pub struct StepTrace {
    /// The time step (0 for a lesson's contacts) and the time after it.
    pub step: u64,
    pub time: f64,
    /// The world as the resolver is handed it.
    pub world: World<f64>,
    pub names: Names,
    pub resolver: ResolverTrace,
    /// Per stop, in order: the position phase's, then the velocity phase's.
    pub tables: Vec<Table>,
    /// A time step's: per contact, the normal from the previous frame
    /// (t − Δt) where it penetrates and its pair was apart then.
    pub previous_normals: Vec<Option<[f64; 3]>>,
    /// Under the soft step or XPBD: the step's own record of its substeps
    /// (the resolver phases above are the lecture's, not what moved the
    /// bodies).
    pub substeps: Option<super::substeps::SubstepsRecord>,
    /// Resolver bodies before each position iteration; before each velocity
    /// iteration and, last, after both phases.
    bodies: [Vec<Vec<ResolverBody<f64>>>; 2],
}

impl StepTrace {
    /// Resolves `world` and records every stop; from `prepared` when given
    /// (a time step's resolver, warm-started where it is).
    pub fn of_world(
        world: World<f64>,
        prepared: Option<Resolver<f64>>,
        names: Names,
        params: &crate::physics::ResolverParams,
        implementation: Implementation,
        step: u64,
        time: f64,
    ) -> StepTrace {
        let (resolver, bodies) = match prepared {
            Some(r) => describe_prepared(&world, r, &names, params, implementation, true, true),
            None => describe_world(&world, &names, params, implementation, true, true),
        };
        let tables = match resolver.elision {
            None => tables(&resolver),
            Some(_) => super::elided::tables(&resolver),
        };
        StepTrace {
            step,
            time,
            world,
            names,
            resolver,
            tables,
            previous_normals: Vec::new(),
            substeps: None,
            bodies,
        }
    }

    /// A lesson's contacts resolved together, as `resolve` does.
    pub fn of_lesson(lesson: &Lesson) -> StepTrace {
        StepTrace::of_world(
            lesson.world(),
            None,
            Names::of_lesson(lesson),
            &lesson.resolver,
            Implementation::Indexed,
            0,
            0.0,
        )
    }

    /// The stop whose bodies [`StepTrace::bodies_at`] shows for stop `t`:
    /// `t` itself, or in a huge step whose recording elided `t`'s bodies the
    /// nearest earlier stop that kept them.
    pub fn bodies_stop(&self, t: usize) -> usize {
        (0..=t)
            .rev()
            .find(|&s| self.resolver_bodies(s).is_some_and(|b| !b.is_empty()))
            .unwrap_or(t)
    }

    fn resolver_bodies(&self, t: usize) -> Option<&Vec<ResolverBody<f64>>> {
        let stop = self.tables.get(t)?.stop;
        match stop.phase {
            Phase::Position => self.bodies[0]
                .get(stop.iteration)
                .or_else(|| self.bodies[1].first()),
            Phase::Velocity => self.bodies[1].get(stop.iteration),
        }
    }

    /// The bodies at the stop at `t` (an index into `tables`), every world
    /// body (as at [`StepTrace::bodies_stop`] where `t`'s were elided).
    pub fn bodies_at(&self, t: usize) -> Vec<BodyView> {
        let resolver = self.resolver_bodies(self.bodies_stop(t));
        self.world
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let s = &b.state;
                let mut position: [f64; 3] = s.position.into();
                let mut q = s.orientation;
                let mut velocity: [f64; 3] = s.velocity.into();
                let mut spin: [f64; 3] = s.angular_velocity.into();
                if let Some(r) = resolver.and_then(|r| r.iter().find(|r| r.id.0 == i)) {
                    position = r.position.into();
                    q = r.unit_orientation();
                    velocity = r.velocity.into();
                    spin = r.angular_velocity.into();
                }
                let orientation = [q.w, q.i, q.j, q.k];
                BodyView {
                    name: self.names.bodies.get(i).cloned().unwrap_or_default(),
                    movable: b.movable,
                    slot: 0,
                    shape: b.shape.clone(),
                    position,
                    orientation,
                    position_after: position,
                    orientation_after: orientation,
                    velocity,
                    velocity_after: velocity,
                    angular_velocity: spin,
                    angular_velocity_after: spin,
                }
            })
            .collect()
    }

    /// The contacts for a picture (bodies by world index), penetration at
    /// stop `t`; the contact the velocity iteration just before `t` took
    /// carries the impulse it applied.
    pub fn contact_views(&self, t: usize) -> Vec<ContactView> {
        let stop = self.tables[t].stop;
        let last = match stop.phase {
            Phase::Velocity => stop
                .iteration
                .checked_sub(1)
                .and_then(|i| self.resolver.velocity.log.get(i)),
            Phase::Position => None,
        };
        self.world
            .contacts
            .iter()
            .enumerate()
            .map(|(k, c)| ContactView {
                number: k,
                bodies: [Some(c.body1.0), c.body2.map(|b| b.0)],
                point: c.input.point.into(),
                normal: c.input.normal.into(),
                penetration: self.penetration_at(t, k),
                impulse: last
                    .filter(|it| it.contact == k)
                    .and_then(|it| it.impulse_world),
            })
            .collect()
    }

    /// The index of the first stop of the velocity phase.
    pub fn velocity_start(&self) -> usize {
        self.resolver.position.iterations_used + 1
    }

    /// `lesson` with the bodies as stop `t` finds them and contact `k` as
    /// the resolver sees it, for the single-contact stages. A scene's
    /// contacts are the step's generated ones (the lesson has none); at a
    /// velocity stop the penetration is left out (0): the position phase
    /// has dealt with it.
    pub fn lesson_at(&self, lesson: &Lesson, t: usize) -> Lesson {
        let mut at = lesson.clone();
        for (def, b) in at.bodies.iter_mut().zip(self.bodies_at(t)) {
            def.position = b.position.into();
            let q = b.orientation;
            def.orientation = nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]);
            def.velocity = b.velocity.into();
            def.angular_velocity = b.angular_velocity.into();
        }
        if lesson.simulation.is_some() {
            let duration = self.world.step.duration;
            at.settings.duration = duration;
            at.contacts = self
                .world
                .contacts
                .iter()
                .map(|c| {
                    let i = &c.input;
                    ContactDef {
                        name: None,
                        bodies: (c.body1.0, c.body2.map(|b| b.0)),
                        point: i.point,
                        normal: i.normal,
                        normal_length: 1.0,
                        penetration: i.penetration,
                        restitution: i.restitution,
                        static_friction: i.static_friction,
                        dynamic_friction: i.dynamic_friction,
                        settings: ContactSettings::of_contact(
                            &i.settings,
                            c.duration.unwrap_or(duration),
                            i.friction_model,
                        ),
                        previous_normal: None,
                    }
                })
                .collect();
            for (def, n) in at.contacts.iter_mut().zip(&self.previous_normals) {
                def.previous_normal = n.map(Into::into);
            }
            for (def, b) in at.bodies.iter_mut().zip(&self.world.bodies) {
                def.acceleration = b.state.acceleration;
            }
        }
        let velocity = self.tables[t].stop.phase == Phase::Velocity;
        for (k, c) in at.contacts.iter_mut().enumerate() {
            c.penetration = if velocity {
                0.0
            } else {
                self.penetration_at(t, k)
            };
        }
        at
    }

    /// Contact `k`'s penetration at stop `t`: from the table, or where a huge
    /// step elided it, from the stop's changes, else as the phase began.
    pub fn penetration_at(&self, t: usize, k: usize) -> f64 {
        let table = &self.tables[t];
        if !table.elided {
            return table.penetration.get(k).copied().unwrap_or(0.0);
        }
        if let Some(c) = table.changed.iter().rev().find(|c| c.0 == k) {
            return c.2;
        }
        self.resolver.before.get(k).map_or(0.0, |r| r.penetration)
    }
}

/// The table at every stop, from the contacts before and each iteration's updates.
fn tables(trace: &ResolverTrace) -> Vec<Table> {
    let mut penetration: Vec<f64> = trace.before.iter().map(|r| r.penetration).collect();
    let mut desired: Vec<f64> = trace.before.iter().map(|r| r.desired).collect();
    let mut out = vec![];
    for (phase, log) in [
        (Phase::Position, &trace.position.log),
        (Phase::Velocity, &trace.velocity.log),
    ] {
        let mut changed = vec![];
        for i in 0..=log.len() {
            out.push(Table {
                stop: Stop {
                    phase,
                    iteration: i,
                },
                penetration: penetration.clone(),
                desired: desired.clone(),
                next: log.get(i).map(|it| it.contact),
                changed: std::mem::take(&mut changed),
                elided: false,
            });
            let Some(it) = log.get(i) else { break };
            let values = match phase {
                Phase::Position => &mut penetration,
                Phase::Velocity => &mut desired,
            };
            changed.push((it.contact, it.value, it.own_after));
            if let Some(v) = values.get_mut(it.contact) {
                *v = it.own_after;
            }
            for u in &it.updated {
                changed.push((u.contact, u.from, u.to));
                if let Some(v) = values.get_mut(u.contact) {
                    *v = u.to;
                }
            }
        }
    }
    out
}

/// Keeps a copy of the world a time step hands the resolver, and of the
/// resolver as prepared for it.
#[derive(Default)]
struct Grab(Option<(World<f64>, Resolver<f64>)>);

impl Observer<f64> for Grab {
    fn resolving(&mut self, world: &World<f64>, resolver: &Resolver<f64>) {
        self.0 = Some((world.clone(), resolver.clone()));
    }
}

/// A step's world as its resolver was handed it, the resolver as prepared
/// for it (when it ran), the names with the step's contacts labelled, and
/// the step's report.
type Grabbed = (World<f64>, Option<Resolver<f64>>, Names, StepReport);

/// Advances `sim` one step and grabs what its resolution started from.
fn grab_next(sim: &mut Simulation<f64>, names: &Names) -> Result<Grabbed, BlowUp> {
    let mut grab = Grab::default();
    let report = sim.advance_observed(&mut grab)?;
    let (world, prepared) = match grab.0 {
        Some((w, r)) => (w, Some(r)),
        None => (sim.world.clone(), None),
    };
    let mut names = names.clone();
    names.contacts = world
        .contacts
        .iter()
        .enumerate()
        .map(|(k, c)| Names::pair_label(&names.bodies, k, c.body1.0, c.body2.map(|b| b.0)))
        .collect();
    Ok((world, prepared, names, report))
}

impl StepTrace {
    /// The contact between the bodies named `a` and `b` (either order)
    /// nearest `point`: the resolver's contact for one the detection found.
    pub fn contact_near(&self, a: &str, b: &str, point: [f64; 3]) -> Option<usize> {
        let name = |i: usize| self.names.bodies.get(i).map(String::as_str);
        (self.world.contacts.iter().enumerate())
            .filter(|(_, x)| {
                let pair = [Some(x.body1.0), x.body2.map(|b| b.0)].map(|i| i.and_then(name));
                pair == [Some(a), Some(b)] || pair == [Some(b), Some(a)]
            })
            .map(|(k, x)| {
                let q = x.input.point;
                let d2 = (0..3).map(|i| (q[i] - point[i]).powi(2)).sum::<f64>();
                (k, d2)
            })
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .map(|(k, _)| k)
    }
}

/// A step's resolution as `simulate --trace-step` prints it.
pub struct Described {
    pub resolver: ResolverTrace,
    /// How many contacts the step resolved.
    pub contacts: usize,
    pub previous: Vec<super::previous_frame::PreviousNormal>,
    /// The step's report (its frame and events, for `simulate`'s page).
    pub report: StepReport,
}

/// Advances `sim` one step and describes its resolution, iterations
/// recorded (no tables or bodies per stop: what `simulate --trace-step`
/// prints); with the number of the step's contacts.
pub fn describe_next(sim: &mut Simulation<f64>, names: &Names) -> Result<Described, BlowUp> {
    let (world, prepared, names, report) = grab_next(sim, names)?;
    let params = sim.params.resolver;
    let normals: Vec<Option<[f64; 3]>> = (world.contacts.iter())
        .map(|k| previous_normal(&world, sim.previous_poses(), k).map(Into::into))
        .collect();
    let previous = super::previous_frame::rows(&world, &names, &normals);
    let (resolver, _) = match prepared {
        Some(r) => describe_prepared(
            &world,
            r,
            &names,
            &params,
            Implementation::Indexed,
            true,
            false,
        ),
        None => describe_world(
            &world,
            &names,
            &params,
            Implementation::Indexed,
            true,
            false,
        ),
    };
    Ok(Described {
        resolver,
        contacts: world.contacts.len(),
        previous,
        report,
    })
}

/// Advances `sim` one step and records its resolution; `names` holds the
/// lesson's names and its bodies' (contacts are labelled from the step's).
/// Under the soft step or XPBD it keeps the step's own record of its substeps.
pub fn record_next(sim: &mut Simulation<f64>, names: &Names) -> Result<StepTrace, BlowUp> {
    let substepped = super::substeps::ask(sim);
    let grabbed = grab_next(sim, names);
    let substeps = if substepped {
        super::substeps::take(sim)
    } else {
        None
    };
    let (world, prepared, names, _) = grabbed?;
    let params = sim.params.resolver;
    let previous_normals = (world.contacts.iter())
        .map(|k| previous_normal(&world, sim.previous_poses(), k).map(Into::into))
        .collect();
    Ok(StepTrace {
        previous_normals,
        substeps,
        ..StepTrace::of_world(
            world,
            prepared,
            names,
            &params,
            Implementation::Indexed,
            sim.step,
            sim.time,
        )
    })
}
