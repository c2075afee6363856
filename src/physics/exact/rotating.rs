//! Slip whose direction turns: the slip-direction ODE
//! `du_t/dP_n = K_tn - μ_d K_tt s`, `s = u_t/|u_t|`, integrated with
//! Dormand–Prince 5(4), with event location for maximum compression, the
//! law's end and slip halting.
//!
//! The ODE is singular where slip halts (s turns ever faster as |u_t| → 0).
//! It is integrated in the rescaled impulse σ with `dP_n = |u_t| dσ` (a
//! Sundman transformation), which removes the singularity:
//!
//! `dP_n/dσ = |u_t|`, `dP_t/dσ = -μ_d u_t`, `dW_n/dσ = |u_t| u_n`, `dW_t/dσ = -μ_d |u_t|²`,
//!
//! with `u = u0 + K P`. In σ the direction follows an autonomous flow on the
//! circle toward an invariant direction and |u_t| decays exponentially when
//! slip halts, so a halt is reached when |u_t| falls below the threshold
//! `rtol·|u0|`; the remaining `|u_t|/|s·du_t/dP_n|` of normal impulse is
//! then done in closed form along the last direction. When the direction
//! settles on a stable invariant direction before that, the closed form
//! takes over from there.

use nalgebra::{Vector2, Vector3};

use super::rk::{next_size, step, State, EVALS_PER_STEP};
use super::run::{Event, Run};
use super::tangent::{is_invariant, k_tt, slip_rate, tangential};
use super::ExactError;
use crate::physics::{c, to_f64, Real};

fn impulse<T: Real>(y: &State<T>) -> Vector3<T> {
    Vector3::new(y[0], y[1], y[2])
}

/// Which sign change ends the current step: maximum compression before it,
/// the law's end after it.
fn event_g<T: Real>(run: &Run<T>, y: &State<T>) -> T {
    let p = impulse(y);
    match run.termination_g(&p, y[3]) {
        Some(g) => g,
        None => run.u_at(&p).x,
    }
}

/// The error measure of a step: RMS over the state components, each against
/// `atol_i + rtol·|y_i|`, and over the tangential velocity error `K_t·err_P`
/// against `rtol·|u0|/100 + |u_t|/1000`. P's tolerance, mapped through K,
/// would leave noise of about `rtol·|u0|` in u_t, as large as the halt
/// threshold; the u_t term binds only where |u_t| < 1000 rtol |u0| and keeps
/// the slip speed resolved to 1 % of the threshold.
struct Norm<T: Real> {
    atol: State<T>,
    atol_ut: T,
    rtol: T,
    rtol_ut: T,
}

impl<T: Real> Norm<T> {
    fn of(&self, run: &Run<T>, y: &State<T>, y1: &State<T>, err: &State<T>) -> T {
        let mut sum = T::zero();
        let mut add = |e: T, scale: T| {
            let r = e / scale;
            sum += r * r;
        };
        for i in 0..5 {
            add(
                err[i],
                self.atol[i] + self.rtol * y[i].abs().max(y1[i].abs()),
            );
        }
        let (u, u1) = (run.u_at(&impulse(y)), run.u_at(&impulse(y1)));
        let du = run.k * impulse(err);
        for i in 1..3 {
            add(
                du[i],
                self.atol_ut + self.rtol_ut * u[i].abs().max(u1[i].abs()),
            );
        }
        (sum / c(7.0)).sqrt()
    }
}

/// Integrates from the run's state to the first event.
pub(super) fn run<T: Real>(run: &mut Run<T>) -> Result<Event<T>, ExactError> {
    let (k, u0, mu) = (run.k, run.input.u0, run.mu_d);
    let f = move |y: &State<T>| {
        let u = u0 + k * impulse(y);
        let ut = tangential(&u);
        let h = ut.norm();
        State::from_column_slice(&[h, -mu * ut.x, -mu * ut.y, h * u.x, -mu * h * h])
    };
    let tol = run.input.tolerance;
    let (ap, ae) = (tol.rtol * run.p_ref, tol.rtol * run.e_ref);
    let norm = Norm {
        atol: State::from_column_slice(&[ap, ap, ap, ae, ae]),
        atol_ut: run.h_stop * c(0.01),
        rtol: tol.rtol,
        rtol_ut: c(1e-3),
    };
    let mut y = State::from_column_slice(&[run.p.x, run.p.y, run.p.z, run.w_n, run.w_t]);
    let mut fy = f(&y);
    run.cost.rhs_evals += 1;
    let event = if run.compression.is_some() {
        Event::Termination
    } else {
        Event::Compression
    };
    if event_g(run, &y) >= T::zero() {
        return Ok(event);
    }
    let scale = run.k.trace() * (T::one() + mu);
    let mut h = run.sigma_step.unwrap_or(c::<T>(0.1) / scale);
    loop {
        check_budget(run, y[0], "slipping with a turning direction")?;
        let trial = step(&f, &y, &fy, h);
        run.cost.rhs_evals += EVALS_PER_STEP;
        let error = norm.of(run, &y, &trial.y, &trial.error);
        if !error.is_finite() || error > T::one() || !trial.y.iter().all(|x| x.is_finite()) {
            run.cost.rejected_steps += 1;
            h = if error.is_finite() {
                next_size(h, error)
            } else {
                h * c(0.2)
            };
            if !h.is_finite() || h <= T::zero() {
                return Err(ExactError::Overflow { p_n: to_f64(y[0]) });
            }
            continue;
        }
        run.cost.accepted_steps += 1;
        if event_g(run, &trial.y) >= T::zero() {
            let located = locate(run, &f, &y, &fy, h)?;
            set(run, &located);
            run.sigma_step = Some(h);
            return Ok(event);
        }
        y = trial.y;
        fy = trial.f;
        set(run, &y);
        h = next_size(h, error);
        run.sigma_step = Some(h);
        let ut = tangential(&run.u());
        if ut.norm() <= run.h_stop {
            tail(run);
            return Ok(Event::Halt);
        }
        if !tol.always_integrate {
            if let Some(s) = settled(run, &ut) {
                return Ok(Event::Settled(s));
            }
        }
    }
}

fn check_budget<T: Real>(run: &Run<T>, p_n: T, during: &'static str) -> Result<(), ExactError> {
    let budget = run.input.tolerance.max_steps;
    if run.cost.steps() >= budget {
        return Err(ExactError::BudgetExceeded {
            budget,
            p_n: to_f64(p_n),
            during,
        });
    }
    Ok(())
}

/// The last `|u_t|/|λ|` of normal impulse before the halt, in closed form
/// along the last direction s (λ = s·(K_tn - μ_d K_tt s) < 0): at most
/// `rtol·|u0|/|λ|`, so the direction's last turn changes P by less than that.
fn tail<T: Real>(run: &mut Run<T>) {
    let s = run.direction;
    let u = run.u();
    let h = tangential(&u).norm();
    let lambda = s.dot(&slip_rate(&run.k, run.mu_d, &s));
    if !lambda.is_finite() || lambda >= T::zero() || h <= T::zero() {
        return;
    }
    let delta = h / -lambda;
    let dp = Vector3::new(T::one(), -s.x * run.mu_d, -s.y * run.mu_d);
    let a_n = (run.k * dp).x;
    let half = c::<T>(0.5);
    run.p += dp * delta;
    run.w_n += u.x * delta + half * a_n * delta * delta;
    // |u_t| falls linearly from h to 0: friction works -μ_d h δ / 2.
    run.w_t -= run.mu_d * h * delta * half;
    run.sample();
}

fn set<T: Real>(run: &mut Run<T>, y: &State<T>) {
    run.p = impulse(y);
    run.w_n = y[3];
    run.w_t = y[4];
    run.sample();
}

/// The state where the event function crosses zero inside the step of size
/// `h` from y: Illinois false position on the step length, each trial a full
/// Dormand–Prince step from y (so the event is located to the integrator's
/// own accuracy). Returns a state with g ≥ 0 (just past the event).
fn locate<T: Real>(
    run: &mut Run<T>,
    f: &impl Fn(&State<T>) -> State<T>,
    y: &State<T>,
    fy: &State<T>,
    h: T,
) -> Result<State<T>, ExactError> {
    let rtol = run.input.tolerance.rtol;
    let (mut a, mut ga) = (T::zero(), event_g(run, y));
    let mut b = h;
    let mut yb = step(f, y, fy, h).y;
    let mut gb = event_g(run, &yb);
    let mut gb_true = gb;
    run.cost.event_steps += 1;
    run.cost.rhs_evals += EVALS_PER_STEP;
    let g_scale = ga.abs() + gb.abs();
    let mut side = 0i8;
    let half = c::<T>(0.5);
    for _ in 0..100 {
        // The state is only rtol-accurate: locating the event far below that is wasted.
        let enough = rtol * c(1e-3);
        if b - a <= enough * h || gb_true <= enough * g_scale {
            break;
        }
        check_budget(run, y[0], "locating an event")?;
        let m = (a * gb - b * ga) / (gb - ga);
        let m = if m > a && m < b { m } else { (a + b) * half };
        let ym = step(f, y, fy, m).y;
        run.cost.event_steps += 1;
        run.cost.rhs_evals += EVALS_PER_STEP;
        let gm = event_g(run, &ym);
        if gm >= T::zero() {
            (b, gb, gb_true, yb) = (m, gm, gm, ym);
            if side == -1 {
                ga *= half;
            }
            side = -1;
        } else {
            (a, ga) = (m, gm);
            if side == 1 {
                gb *= half;
            }
            side = 1;
        }
    }
    Ok(yb)
}

/// The invariant direction the slip has settled on, if it has. With
/// `b(s) = K_tn - μ_d K_tt s`, the direction turns at `ω = s⊥·b` per unit σ,
/// `dω/dθ = -s·b - μ_d s⊥ᵀ K_tt s⊥`; the invariant direction nearby (Newton on
/// ω(θ) = 0) is stable when dω/dθ < 0, and it is θ ≈ |ω/(dω/dθ)| away.
/// Freezing the direction there changes P by about μ_d θ |u_t| / |dω/dθ + λ|
/// per unit of remaining slip, so it is done when the slip decelerates
/// (λ = s·b < 0) and `θ |u_t| ≤ rtol·|u0|`, or when it does not and θ ≤ rtol.
/// From there u is linear in P_n again and the closed form takes over.
fn settled<T: Real>(run: &Run<T>, u_t: &Vector2<T>) -> Option<Vector2<T>> {
    let (k, mu, rtol) = (&run.k, run.mu_d, run.input.tolerance.rtol);
    let rate = |s: &Vector2<T>| {
        let b = slip_rate(k, mu, s);
        let perp = Vector2::new(-s.y, s.x);
        let slope = -s.dot(&b) - mu * perp.dot(&(k_tt(k) * perp));
        (perp.dot(&b), slope, s.dot(&b))
    };
    let speed = u_t.norm();
    let mut s = u_t / speed;
    let (omega, slope, lambda) = rate(&s);
    if !slope.is_finite() || slope >= T::zero() {
        return None;
    }
    let theta = (omega / slope).abs();
    let close = if lambda < T::zero() {
        theta * speed <= run.h_stop
    } else {
        theta <= rtol
    };
    if !close {
        return None;
    }
    for _ in 0..4 {
        let (omega, slope, _) = rate(&s);
        let turned = s + Vector2::new(-s.y, s.x) * (-omega / slope);
        s = turned / turned.norm();
    }
    (rate(&s).1 < T::zero() && is_invariant(k, mu, &s)).then_some(s)
}
