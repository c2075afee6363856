//! The running state of one integration (impulse, works, phases so far) and
//! the closed-form stretches: while the impulse rate dP/dP_n is constant
//! (frictionless, sticking, or slipping in a constant direction) the contact
//! velocity is linear in P_n, `u = u_s + a δ` with `a = K dP/dP_n`, and every
//! event (maximum compression, the law's end, slip halting) is a root of a
//! polynomial of degree ≤ 2 in δ.

use nalgebra::{Matrix3, Vector2, Vector3};

use super::outcome::{Cost, Phase, PhaseKind, Sample};
use super::tangent::{tangential, with_unit_normal};
use super::{ExactError, ImpactInput, RestitutionLaw};
use crate::physics::{c, to_f64, Real};

/// What the contact is doing between two events.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Mode<T: Real> {
    Frictionless,
    /// Stuck, with the sticking ratio τ.
    Stick(Vector2<T>),
    /// Slipping along a constant direction s (closed form).
    Slide(Vector2<T>),
    /// Slipping with a turning direction (Runge–Kutta, `rotating.rs`).
    Rotating,
}

/// What ended a stretch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Event<T: Real> {
    Compression,
    Termination,
    /// The slip speed reached zero.
    Halt,
    /// The turning slip direction settled on this stable invariant direction;
    /// the closed form continues along it.
    Settled(Vector2<T>),
}

struct Open<T: Real> {
    kind: PhaseKind<T>,
    from_pn: T,
    u_from: Vector3<T>,
}

pub(super) struct Run<'a, T: Real> {
    pub input: &'a ImpactInput<T>,
    /// K made exactly symmetric.
    pub k: Matrix3<T>,
    pub mu_d: T,
    /// Impulse so far (contact space).
    pub p: Vector3<T>,
    /// Work of the normal impulse in the current phase (compression, then
    /// restitution: reset at maximum compression, so that W_r = -e² W_c is
    /// tested without cancellation when e is small) and of friction so far.
    pub w_n: T,
    pub w_t: T,
    /// `(P_c, W_c)` once maximum compression has passed.
    pub compression: Option<(T, T)>,
    /// Slip speed below which slip counts as halted: `rtol·|u0|`.
    pub h_stop: T,
    /// Scales of the absolute tolerances: `|u0|/K_nn` and `|u0|²/K_nn`.
    pub p_ref: T,
    pub e_ref: T,
    /// Last slip direction seen while slipping.
    pub direction: Vector2<T>,
    /// Runge–Kutta step carried from one rotating stretch to the next.
    pub sigma_step: Option<T>,
    pub phases: Vec<Phase<T>>,
    pub samples: Vec<Sample<T>>,
    pub cost: Cost,
    open: Option<Open<T>>,
}

impl<'a, T: Real> Run<'a, T> {
    pub fn new(input: &'a ImpactInput<T>, k: Matrix3<T>) -> Self {
        let speed = input.u0.norm();
        let p_ref = speed / k[(0, 0)];
        let mut run = Run {
            input,
            k,
            mu_d: input.dynamic_friction,
            p: Vector3::zeros(),
            w_n: T::zero(),
            w_t: T::zero(),
            compression: None,
            h_stop: input.tolerance.rtol * speed,
            p_ref,
            e_ref: p_ref * speed,
            direction: Vector2::zeros(),
            sigma_step: None,
            phases: Vec::new(),
            samples: Vec::new(),
            cost: Cost::default(),
            open: None,
        };
        run.sample();
        run
    }

    /// Contact velocity `u = u0 + K P` for an impulse P.
    pub fn u_at(&self, p: &Vector3<T>) -> Vector3<T> {
        self.input.u0 + self.k * p
    }

    pub fn u(&self) -> Vector3<T> {
        self.u_at(&self.p)
    }

    pub fn sample(&mut self) {
        let u = self.u();
        let ut = tangential(&u);
        if ut.norm() > self.h_stop {
            self.direction = ut / ut.norm();
        }
        self.samples.push(Sample {
            p: self.p,
            u,
            work_normal: self.w_n + self.compression.map_or(T::zero(), |(_, w_c)| w_c),
        });
    }

    /// Starts an interval phase at the current impulse.
    pub fn open(&mut self, kind: PhaseKind<T>) {
        self.open = Some(Open {
            kind,
            from_pn: self.p.x,
            u_from: self.u(),
        });
    }

    /// Ends the open interval phase at the current impulse; returns its kind.
    pub fn close(&mut self) -> Option<PhaseKind<T>> {
        let open = self.open.take()?;
        let mut kind = open.kind;
        if let PhaseKind::Slides { end_direction, .. } = &mut kind {
            *end_direction = self.direction;
        }
        self.phases.push(Phase {
            kind,
            from_pn: open.from_pn,
            to_pn: self.p.x,
            u_from: open.u_from,
            u_to: self.u(),
        });
        Some(kind)
    }

    /// Records an instant phase at the current impulse.
    pub fn instant(&mut self, kind: PhaseKind<T>) {
        let u = self.u();
        self.phases.push(Phase {
            kind,
            from_pn: self.p.x,
            to_pn: self.p.x,
            u_from: u,
            u_to: u,
        });
    }

    /// Maximum compression: record P_c and W_c, split the open phase there;
    /// W_n counts restitution work from here on.
    pub fn mark_compression(&mut self) {
        self.compression = Some((self.p.x, self.w_n));
        self.w_n = T::zero();
        let kind = self.close();
        self.instant(PhaseKind::MaxCompression);
        if let Some(mut kind) = kind {
            if let PhaseKind::Slides { direction, .. } = &mut kind {
                *direction = self.direction;
            }
            self.open(kind);
        }
    }

    /// Normal velocity at which Newton's law ends the impact, `-e u_n0`.
    pub fn newton_target(&self) -> T {
        -self.input.restitution * self.input.u0.x
    }

    /// The law's end condition as `g ≥ 0`, for a state (P, W_r) after
    /// maximum compression; `None` before it.
    pub fn termination_g(&self, p: &Vector3<T>, w_n: T) -> Option<T> {
        let (p_c, w_c) = self.compression?;
        let e = self.input.restitution;
        Some(match self.input.law {
            RestitutionLaw::Newton => self.u_at(p).x - self.newton_target(),
            RestitutionLaw::Poisson => p.x - (T::one() + e) * p_c,
            RestitutionLaw::Stronge => w_n + e * e * w_c,
        })
    }

    /// The impulse rate `dP/dP_n` of a closed-form mode.
    fn rate(&self, mode: &Mode<T>) -> Vector3<T> {
        match mode {
            Mode::Stick(tau) => with_unit_normal(tau),
            Mode::Slide(s) => with_unit_normal(&(-s * self.mu_d)),
            Mode::Frictionless | Mode::Rotating => Vector3::x(),
        }
    }

    /// Advances a closed-form stretch to its first event.
    pub fn linear(&mut self, mode: &Mode<T>) -> Result<Event<T>, ExactError> {
        let dp = self.rate(mode);
        let a = self.k * dp;
        let u = self.u();
        let mut best: Option<(T, Event<T>)> = None;
        let mut offer = |delta: Option<T>, event: Event<T>| {
            if let Some(d) = delta.filter(|d| d.is_finite()) {
                let d = d.max(T::zero());
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, event));
                }
            }
        };
        if self.compression.is_none() {
            offer(self.compression_delta(u.x, a.x), Event::Compression);
        } else {
            offer(self.termination_delta(&u, &a), Event::Termination);
        }
        if let Mode::Slide(s) = mode {
            offer(self.halt_delta(s, &u, &a), Event::Halt);
        }
        let Some((delta, event)) = best else {
            return Err(ExactError::NoTermination {
                p_n: to_f64(self.p.x),
                during: "the normal velocity no longer rises",
            });
        };
        self.advance(&dp, &a, &u, delta);
        Ok(event)
    }

    /// δ at which u_n reaches 0 from below.
    fn compression_delta(&self, u_n: T, a_n: T) -> Option<T> {
        if u_n >= T::zero() {
            Some(T::zero())
        } else {
            (a_n > T::zero()).then(|| -u_n / a_n)
        }
    }

    /// δ at which the law ends the impact.
    fn termination_delta(&self, u: &Vector3<T>, a: &Vector3<T>) -> Option<T> {
        let (p_c, w_c) = self.compression?;
        let e = self.input.restitution;
        match self.input.law {
            RestitutionLaw::Newton => {
                let gap = self.newton_target() - u.x;
                if gap <= T::zero() {
                    Some(T::zero())
                } else {
                    (a.x > T::zero()).then(|| gap / a.x)
                }
            }
            RestitutionLaw::Poisson => Some((T::one() + e) * p_c - self.p.x),
            RestitutionLaw::Stronge => {
                // W_r(δ) = W_r + u_n δ + ½ a_n δ² reaches -e² W_c: the smaller
                // positive root of ½ a_n δ² + u_n δ - D = 0, in the stable form.
                let gap = -e * e * w_c - self.w_n;
                if gap <= T::zero() {
                    return Some(T::zero());
                }
                let disc = u.x * u.x + c::<T>(2.0) * a.x * gap;
                if disc < T::zero() {
                    return None;
                }
                let denominator = u.x + disc.sqrt();
                (denominator > T::zero()).then(|| c::<T>(2.0) * gap / denominator)
            }
        }
    }

    /// δ at which slip along s halts. With friction, where the slip speed
    /// along s reaches zero, `u_t·s + δ a_t·s = 0`, when it is decelerating:
    /// friction along s must never act past that point, where it would push
    /// the slip instead of opposing it. (Along an invariant direction u_t ∥ s;
    /// a direction settled from the integration leaves a perpendicular part of
    /// at most the halt threshold, which counts as zero.) Without kinetic
    /// friction (μ_d = 0) u_t moves on a straight line, and halts only if the
    /// line passes through zero (within the threshold, plus rtol of |u_t|).
    fn halt_delta(&self, s: &Vector2<T>, u: &Vector3<T>, a: &Vector3<T>) -> Option<T> {
        let (ut, at) = (tangential(u), tangential(a));
        if self.mu_d > T::zero() {
            let rate = at.dot(s);
            return (rate < T::zero()).then(|| ut.dot(s).max(T::zero()) / -rate);
        }
        if ut.dot(&at) >= T::zero() {
            return None;
        }
        let delta = -ut.dot(&at) / at.norm_squared();
        let miss = self.h_stop + c::<T>(2.0) * self.input.tolerance.rtol * ut.norm();
        ((ut + at * delta).norm() <= miss).then_some(delta)
    }

    /// Moves along a closed-form stretch by δ, accumulating the works exactly:
    /// `W_n += u_n δ + ½ a_n δ²`, `W_t += (u_t·dp_t) δ + ½ (a_t·dp_t) δ²`.
    fn advance(&mut self, dp: &Vector3<T>, a: &Vector3<T>, u: &Vector3<T>, delta: T) {
        if delta <= T::zero() {
            return;
        }
        let half = c::<T>(0.5);
        let (dpt, ut, at) = (tangential(dp), tangential(u), tangential(a));
        self.p += dp * delta;
        self.w_n += u.x * delta + half * a.x * delta * delta;
        self.w_t += ut.dot(&dpt) * delta + half * at.dot(&dpt) * delta * delta;
        self.sample();
    }
}
