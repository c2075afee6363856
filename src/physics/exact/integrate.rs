//! The impact as a sequence of stretches: which mode the contact starts in,
//! what follows each event (maximum compression, slip halting), and the
//! outcome once the restitution law ends the impact.

use nalgebra::Vector3;

use super::input::validate;
use super::outcome::{Cost, ImpactOutcome, PhaseKind};
use super::run::{Event, Mode, Run};
use super::tangent::{is_invariant, restart_direction, stick_ratio, tangential};
use super::{rotating, ExactError, ImpactInput};
use crate::physics::{c, to_f64, Real};

/// Events one impact can go through are few (compression, at most two halts,
/// a near-halt tail, the end); this bound only guards against a logic error.
const MAX_EVENTS: usize = 32;

/// Integrates one impact in the normal-impulse domain (see the module docs
/// of [`crate::physics::exact`]).
pub fn integrate<T: Real>(input: &ImpactInput<T>) -> Result<ImpactOutcome<T>, ExactError> {
    let k = validate(input)?;
    if input.u0.x >= T::zero() {
        return Ok(separating(input));
    }
    let mut run = Run::new(input, k);
    let mut mode = start(&mut run);
    for _ in 0..MAX_EVENTS {
        let event = match mode {
            Mode::Rotating => rotating::run(&mut run)?,
            _ => run.linear(&mode)?,
        };
        match event {
            Event::Compression => run.mark_compression(),
            Event::Termination => return finish(run),
            Event::Halt => mode = after_halt(&mut run, true),
            Event::Settled(s) => mode = Mode::Slide(s),
        }
    }
    Err(ExactError::BudgetExceeded {
        budget: MAX_EVENTS,
        p_n: to_f64(run.p.x),
        during: "changing phase",
    })
}

/// The first mode: frictionless; at rest (stick or start slipping); slipping
/// in an invariant direction (closed form); or slipping and turning.
fn start<T: Real>(run: &mut Run<T>) -> Mode<T> {
    let input = run.input;
    if input.static_friction <= T::zero() && input.dynamic_friction <= T::zero() {
        run.open(PhaseKind::Frictionless);
        return Mode::Frictionless;
    }
    let ut = tangential(&input.u0);
    if ut.norm() <= run.h_stop {
        return after_halt(run, false);
    }
    let s = ut / ut.norm();
    let constant = run.mu_d <= T::zero() || is_invariant(&run.k, run.mu_d, &s);
    if constant && !input.tolerance.always_integrate {
        run.open(PhaseKind::Slides {
            direction: s,
            end_direction: s,
            rotating: false,
        });
        Mode::Slide(s)
    } else {
        run.open(PhaseKind::Slides {
            direction: s,
            end_direction: s,
            rotating: true,
        });
        Mode::Rotating
    }
}

/// The contact is at rest tangentially (after a halt, or from the start):
/// it sticks when `|τ| ≤ μ_s`; otherwise slip restarts along the consistent
/// direction, which in the planar case is the reverse of the old one. When
/// `μ_s < |τ| ≤ μ_d` no slip direction is consistent (kinetic friction would
/// stop any slip at once), so the contact sticks.
fn after_halt<T: Real>(run: &mut Run<T>, halted: bool) -> Mode<T> {
    let previous = run.direction;
    run.close();
    if halted {
        run.instant(PhaseKind::SlipHalts);
    }
    let tau = stick_ratio(&run.k);
    let restart = (tau.norm() > run.input.static_friction)
        .then(|| restart_direction(&run.k, run.mu_d))
        .flatten();
    let Some((s, _)) = restart else {
        run.open(PhaseKind::Sticks { ratio: tau });
        return Mode::Stick(tau);
    };
    let reverses = s.dot(&previous) <= -(T::one() - T::default_epsilon() * c(100.0));
    run.instant(if !halted {
        PhaseKind::SlipStarts { direction: s }
    } else if reverses {
        PhaseKind::SlipReverses { direction: s }
    } else {
        PhaseKind::SlipResumes { direction: s }
    });
    run.direction = s;
    run.open(PhaseKind::Slides {
        direction: s,
        end_direction: s,
        rotating: false,
    });
    Mode::Slide(s)
}

fn finish<T: Real>(mut run: Run<T>) -> Result<ImpactOutcome<T>, ExactError> {
    run.close();
    let u0 = run.input.u0;
    let p = run.p;
    let (p_c, w_c) = run.compression.unwrap_or((p.x, T::zero()));
    let energy_change = p.dot(&u0) + c::<T>(0.5) * p.dot(&(run.k * p));
    let outcome = ImpactOutcome {
        law: run.input.law,
        closing: true,
        impulse: p,
        velocity: run.u(),
        compression_pn: p_c,
        work_compression: w_c,
        work_restitution: run.w_n,
        work_friction: run.w_t,
        energy_change,
        phases: run.phases,
        samples: run.samples,
        cost: run.cost,
    };
    let finite = outcome
        .impulse
        .iter()
        .chain(outcome.velocity.iter())
        .all(|x| x.is_finite())
        && [
            energy_change,
            outcome.work_restitution,
            outcome.work_friction,
        ]
        .iter()
        .all(|x| x.is_finite());
    if finite {
        Ok(outcome)
    } else {
        Err(ExactError::Overflow { p_n: to_f64(p.x) })
    }
}

fn separating<T: Real>(input: &ImpactInput<T>) -> ImpactOutcome<T> {
    ImpactOutcome {
        law: input.law,
        closing: false,
        impulse: Vector3::zeros(),
        velocity: input.u0,
        compression_pn: T::zero(),
        work_compression: T::zero(),
        work_restitution: T::zero(),
        work_friction: T::zero(),
        energy_change: T::zero(),
        phases: Vec::new(),
        samples: Vec::new(),
        cost: Cost::default(),
    }
}
