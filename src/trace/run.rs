//! The description of a run in time: one frame per recorded step (the step's
//! numbers and every body's state) and the events in words, with body names.

use crate::physics::step::audit::{EnergyCause, Switch, Switches};
use crate::physics::step::{Event, Simulation, StepReport, WakeCause};
use crate::physics::{BodyId, Shape};
use crate::trace::movement::{self, Movement};

/// A body's state in a frame.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyFrame {
    pub position: [f64; 3],
    pub orientation: [f64; 4],
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
    pub awake: bool,
}

/// One recorded step.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub step: u64,
    pub time: f64,
    pub contacts: usize,
    pub awake: usize,
    pub max_penetration: f64,
    pub kinetic_energy: f64,
    pub potential_energy: f64,
    pub position_iterations: usize,
    pub velocity_iterations: usize,
    /// Every body, in lesson order.
    pub bodies: Vec<BodyFrame>,
    /// Contact points and normals of the step (for pictures).
    pub contact_points: Vec<([f64; 3], [f64; 3])>,
    /// With continuous detection on, each body's movement bounds over the
    /// step that ended here (empty when it is off).
    pub movement: Vec<Option<Movement>>,
}

/// An event in words.
#[derive(Debug, Clone, PartialEq)]
pub struct EventLine {
    pub step: u64,
    pub time: f64,
    pub kind: &'static str,
    pub text: String,
    /// Where and when (s, the run's clock) the pair met, for the events a
    /// picture marks (`tunnelled`, `toi`).
    pub mark: Option<([f64; 3], f64)>,
}

/// A run: its frames and events.
#[derive(Debug, Clone, PartialEq)]
pub struct RunTrace {
    pub lesson: String,
    pub title: String,
    pub dt: f64,
    pub names: Vec<String>,
    pub shapes: Vec<Option<Shape>>,
    pub movable: Vec<bool>,
    pub frames: Vec<Frame>,
    pub events: Vec<EventLine>,
    /// Set when the run stopped early: the reason.
    pub stopped: Option<String>,
}

impl RunTrace {
    pub fn new(lesson: &str, title: &str, names: Vec<String>, sim: &Simulation<f64>) -> Self {
        RunTrace {
            lesson: lesson.to_string(),
            title: title.to_string(),
            dt: sim.params.dt,
            names,
            shapes: sim.world.bodies.iter().map(|b| b.shape.clone()).collect(),
            movable: sim.world.bodies.iter().map(|b| b.movable).collect(),
            frames: Vec::new(),
            events: Vec::new(),
            stopped: None,
        }
    }

    /// The frame of the simulation as it is now, after `report`.
    pub fn frame(sim: &Simulation<f64>, report: &StepReport) -> Frame {
        Frame {
            step: report.step,
            time: report.time,
            contacts: report.contacts,
            awake: report.awake,
            max_penetration: report.max_penetration,
            kinetic_energy: report.kinetic_energy,
            potential_energy: report.potential_energy,
            position_iterations: report.position_iterations,
            velocity_iterations: report.velocity_iterations,
            bodies: sim
                .world
                .bodies
                .iter()
                .zip(&sim.sleep)
                .map(|(b, s)| {
                    let q = b.state.orientation;
                    BodyFrame {
                        position: b.state.position.into(),
                        orientation: [q.w, q.i, q.j, q.k],
                        velocity: b.state.velocity.into(),
                        angular_velocity: b.state.angular_velocity.into(),
                        awake: b.movable && s.awake,
                    }
                })
                .collect(),
            contact_points: sim
                .world
                .contacts
                .iter()
                .map(|k| (k.input.point.into(), k.input.normal.into()))
                .collect(),
            movement: if sim.params.ccd.method().is_some() && report.step > 0 {
                movement::of_bounds(sim.movement_bounds())
            } else {
                Vec::new()
            },
        }
    }

    /// The state before the first step, as frame 0.
    pub fn initial(sim: &Simulation<f64>) -> Frame {
        let report = StepReport {
            step: 0,
            time: 0.0,
            contacts: 0,
            awake: sim.awake(),
            max_penetration: 0.0,
            max_penetration_after: 0.0,
            kinetic_energy: crate::physics::step::energy::kinetic(&sim.world),
            potential_energy: crate::physics::step::energy::potential(
                &sim.world,
                &sim.params.world.gravity,
            ),
            position_iterations: 0,
            velocity_iterations: 0,
            ccd_tests: 0,
            events: Vec::new(),
        };
        Self::frame(sim, &report)
    }

    /// Adds the events of `report` in words.
    pub fn add_events(&mut self, report: &StepReport) {
        for e in &report.events {
            let (kind, text) = self.describe(e);
            let mark = match e {
                Event::Tunnelled { point, time, .. } => Some((*point, *time)),
                Event::Toi(h) => Some((h.point, h.time)),
                _ => None,
            };
            self.events.push(EventLine {
                step: report.step,
                time: report.time,
                kind,
                text,
                mark,
            });
        }
    }

    fn name(&self, id: BodyId) -> &str {
        self.names.get(id.0).map_or("?", String::as_str)
    }

    fn pair(&self, a: BodyId, b: Option<BodyId>) -> String {
        match b {
            Some(b) => format!("{} ↔ {}", self.name(a), self.name(b)),
            None => format!("{} ↔ world", self.name(a)),
        }
    }

    /// Why a sleeper woke, as the `wakes` line says it.
    fn wake_cause(&self, cause: WakeCause) -> String {
        match cause {
            WakeCause::Touched { by } => format!("touched by {}", self.name(by)),
            WakeCause::Impulse { contact, with } => {
                format!("impulse from contact {contact} (with {})", self.name(with))
            }
            WakeCause::Struck { by } => {
                format!("struck by {} inside the step", self.name(by))
            }
            WakeCause::Edit => "an edit changed it".to_string(),
        }
    }

    fn describe(&self, e: &Event) -> (&'static str, String) {
        let f = crate::format::Fmt::new(3);
        match *e {
            Event::ContactMade { body1, body2 } => (
                "contact",
                format!("contact made: {}", self.pair(body1, body2)),
            ),
            Event::ContactLost { body1, body2 } => (
                "contact",
                format!("contact lost: {}", self.pair(body1, body2)),
            ),
            Event::Bounce {
                body1,
                body2,
                closing,
                separating,
            } => (
                "bounce",
                format!(
                    "bounce: {} closing at {} m/s, separating at {} m/s (ratio {})",
                    self.pair(body1, body2),
                    f.num(closing),
                    f.num(separating),
                    f.num(separating / closing)
                ),
            ),
            Event::Sticks { body1, body2 } => {
                ("friction", format!("sticks: {}", self.pair(body1, body2)))
            }
            Event::Slides { body1, body2, .. } => {
                ("friction", format!("slides: {}", self.pair(body1, body2)))
            }
            Event::FallsAsleep { body } => ("sleep", format!("{} falls asleep", self.name(body))),
            Event::Wakes { body, cause } => (
                "sleep",
                format!("{} wakes: {}", self.name(body), self.wake_cause(cause)),
            ),
            Event::PositionLimit { left } => (
                "limit",
                format!(
                    "position iteration limit reached (and reached every step until this line shows again): deepest penetration left {} m",
                    f.num(left)
                ),
            ),
            Event::VelocityLimit { left } => (
                "limit",
                format!(
                    "velocity iteration limit reached (from now on, each step, until it stops): largest desired Δv left {} m/s",
                    f.num(left)
                ),
            ),
            Event::EnergyGain { gained, cause } => (
                "energy",
                format!(
                    "the resolution added {} J of kinetic energy (from now on, each step, until it stops); cause: {}",
                    f.num(gained),
                    cause_text(cause)
                ),
            ),
            Event::EnergyRise {
                gained,
                tolerance,
                cause,
            } => {
                let (gained, tolerance) = apart(gained, tolerance);
                (
                    "energy",
                    format!(
                        "the step raised the total energy (kinetic + potential) of the bodies in contact by {gained} J, over the tolerance {tolerance} J (from now on, each step, until it stops); cause: {}",
                        cause_text(cause)
                    ),
                )
            }
            Event::WhollyInside {
                body1,
                body2,
                penetration,
                width,
            } => (
                "overlap",
                format!(
                    "wholly inside: {} overlap by {} m, at least the smaller body's width along the normal ({} m): the contact cannot tell which way is out",
                    self.pair(body1, body2),
                    f.num(penetration),
                    f.num(width)
                ),
            ),
            Event::WhollyInsideEnded {
                body1,
                body2,
                steps,
            } => (
                "overlap",
                format!(
                    "no longer wholly inside: {}, after {steps} steps ({} s) inside one another",
                    self.pair(body1, body2),
                    f.num(steps as f64 * self.dt)
                ),
            ),
            Event::StillWhollyInside {
                body1,
                body2,
                steps,
            } => (
                "overlap",
                format!(
                    "still wholly inside at the end: {}, for {steps} steps ({} s)",
                    self.pair(body1, body2),
                    f.num(steps as f64 * self.dt)
                ),
            ),
            Event::PushedThrough { body, through } => (
                "overlap",
                format!(
                    "pushed through: {} crossed the middle of {} in one step, and the position phase pushes it out through the far side",
                    self.name(body),
                    self.name(through)
                ),
            ),
            Event::ProjectionLift { gained } => (
                "energy",
                format!(
                    "projection lifted bodies out of penetration, adding {} J of potential energy (from now on, each step, until it stops)",
                    f.num(gained)
                ),
            ),
            Event::RollbackLift { gained } => (
                "energy",
                format!(
                    "rollback moved bodies back along their motion against gravity, adding {} J of potential energy (from now on, each step, until it stops)",
                    f.num(gained)
                ),
            ),
            Event::Tunnelled {
                body1,
                body2,
                time,
                point,
            } => (
                "tunnelled",
                format!(
                    "tunnelled: {} met at t = {} s near ({}, {}, {}) and were apart again at the step's end, with no contact (the poses at t and t + Δt miss it)",
                    self.pair(body1, Some(body2)),
                    f.num(time),
                    f.num(point[0]),
                    f.num(point[1]),
                    f.num(point[2])
                ),
            ),
            Event::Toi(h) => (
                "toi",
                format!(
                    "time of collision ({}, {} tests): {} met at t = {} s near ({}, {}, {}); resolved there, closing at {} m/s and separating at {} m/s, then the rest of the step",
                    crate::knobs::toi_method_name(h.method),
                    h.tests,
                    self.pair(h.body1, Some(h.body2)),
                    f.num(h.time),
                    f.num(h.point[0]),
                    f.num(h.point[1]),
                    f.num(h.point[2]),
                    f.num(h.closing),
                    f.num(h.separating)
                ),
            ),
        }
    }
}

/// The switches of an energy audit in words.
/// Two numbers with three significant digits, or as many more (up to nine)
/// as it takes for them to read differently when they differ.
fn apart(a: f64, b: f64) -> (String, String) {
    let pair = |d| {
        let f = crate::format::Fmt::new(d);
        (f.num(a), f.num(b))
    };
    (3..=9)
        .map(pair)
        .find(|(x, y)| x != y)
        .unwrap_or_else(|| pair(3))
}

fn switch_text(s: Switch) -> &'static str {
    match s {
        Switch::RestitutionWithFriction => "restitution with friction (Newton's law with sticking friction, as in the Kane example)",
        Switch::VelocityScaling => "the velocity-scaling friction model's rule",
        Switch::KineticDirection => "the kinetic-direction friction model's rule",
        Switch::WarmStart => "warm starting from last step's impulses",
        Switch::AccelerationCompensation => "acceleration compensation (a desired Δv from last frame's acceleration)",
        Switch::Projection => "projection (the position phase)",
        Switch::Friction => "friction at contacts solved together",
        Switch::Restitution => "restitution at contacts solved together",
        Switch::OneAtATime => "the lecture's order (the contacts taken one at a time, an impulse never taken back; the same contacts by sequential impulses hold the energy)",
    }
}

fn switch_list(s: Switches, joint: &str) -> String {
    let words: Vec<&str> = s.iter().map(switch_text).collect();
    match words.as_slice() {
        [] => "nothing".to_string(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{}{joint}{last}", init.join(", ")),
    }
}

/// What the audit's re-runs of the step showed, as the event says it.
fn cause_text(cause: EnergyCause) -> String {
    match cause {
        EnergyCause::Each(s) if s.len() == 1 => format!(
            "{} (the same step without it gains nothing)",
            switch_list(s, "")
        ),
        EnergyCause::Each(s) => format!(
            "{} (the same step without any one of them gains nothing)",
            switch_list(s, " or ")
        ),
        EnergyCause::Together(s) => format!(
            "{} together (no one of them alone removes the gain; all of them switched off do)",
            switch_list(s, " and ")
        ),
        EnergyCause::Unexplained { tried } => format!(
            "none found: the same step still gains with each of these switched off, and with all of them: {}",
            switch_list(tried, ", ")
        ),
    }
}

/// A tolerance the bodies' size lowered, as a warning says it.
pub fn lowered_text(l: &crate::physics::step::tolerance::Lowered) -> String {
    use crate::physics::step::tolerance::Tolerance;
    let f = crate::format::Fmt::new(3);
    let (name, unit, bound) = match l.which {
        Tolerance::PositionEpsilon => {
            ("position epsilon", "m", "at most a tenth of its half-width")
        }
        Tolerance::ContactMargin => ("contact margin", "m", "at most a tenth of its half-width"),
        Tolerance::VelocityEpsilon => (
            "velocity epsilon",
            "m/s",
            "at most a tenth of √(g × its half-width), and at most a thousandth of its half-width a step where gravity moves it more than a tenth of it in a step",
        ),
        Tolerance::SleepEpsilon => ("sleep epsilon", "m²/s²", "at most g × its half-width"),
    };
    format!(
        "the {name} {} {unit} is lowered to {} {unit} for the smallest body ({bound})",
        f.num(l.given),
        f.num(l.used)
    )
}

/// A body below the rounding of its position, as a warning says it.
pub fn below_rounding_text(
    name: &str,
    b: &crate::physics::step::tolerance::BelowRounding,
) -> String {
    let f = crate::format::Fmt::new(3);
    format!(
        "{name} (half-width {} m) is smaller than ten times the rounding of its position ({} m, {} of its half-widths): it cannot be placed closer than that, and its contacts' depths are rounding, not geometry",
        f.num(b.size),
        f.num(b.rounding),
        f.num(b.rounding / b.size)
    )
}

/// A scene whose steps are split into substeps for its small bodies, as a
/// warning says it.
pub fn split_text(s: &crate::physics::step::split::Split) -> String {
    let f = crate::format::Fmt::new(3);
    format!(
        "each step is split into {} substeps: gravity moves a body {} m in a step (g × dt²), \
         more than the smallest body's half-width {} m",
        s.substeps,
        f.num(s.fall),
        f.num(s.radius)
    )
}

#[cfg(test)]
mod tests {
    use super::apart;

    #[test]
    fn a_rise_and_its_tolerance_never_read_alike() {
        // 3 digits: 0.00169 and 0.00169; they differ at the fourth.
        assert_eq!(
            apart(0.0016912, 0.0016883),
            ("0.001691".to_string(), "0.001688".to_string())
        );
        assert_eq!(
            apart(0.00279, 0.00169),
            ("0.00279".into(), "0.00169".into())
        );
        assert_eq!(apart(1.0, 1.0), ("1".into(), "1".into()));
    }
}
