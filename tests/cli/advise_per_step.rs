//! `advise --per step` (issue 27): the per-step error is the largest, over
//! the steps, of the distance to the reference at the same time; checked in
//! closed form on a free fall, and shown to choose differently from the
//! run's error on a drop that comes to rest (every time step ends at the
//! same place, but a coarse one falls behind on the way).

use contact_lab::lesson::{validate, Lesson};
use contact_lab::physics::Solver;
use contact_lab::study::advise::{advise, Per};
use contact_lab::study::{grid, run};

const G: f64 = 9.81;

/// A sphere of radius 0.5 whose lowest point is 1.5 m up; with a floor
/// (restitution 0) or in free fall; no damping.
fn drop(floor: bool) -> Lesson {
    let mut s = String::from(
        "id = \"drop\"\ntitle = \"A sphere dropped\"\nsource = \"test\"\nsummary = \"test\"\n\n[world]\ngravity = [0, -9.81, 0]\nlinear_damping = 1.0\nangular_damping = 1.0\nrestitution = 0.0\n\n[step]\ndt = 0.016666666666666666\nsteps = 90\n\n[sleep]\nenabled = false\n\n[[body]]\nname = \"ball\"\nmass = 1.0\nshape = { sphere = 0.5 }\nposition = [0, 2, 0]\n",
    );
    if floor {
        s.push_str("\n[[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nnormal = [0, 1, 0]\nposition = [0, 0, 0]\n");
    }
    validate::parse("drop", &s).expect("the scene loads")
}

#[test]
fn per_step_error_of_a_free_fall_is_the_closed_form() {
    // Symplectic Euler from rest: y_k = y0 - g dt² k (k + 1) / 2, so at
    // t = k dt the fall is g t (t + dt) / 2; against the reference's dt_r
    // the gap at t is g t (dt - dt_r) / 2, largest at the end.
    let l = drop(false);
    let default = grid::default_config(&l).unwrap();
    let reference = grid::reference(&default, Solver::SequentialImpulse);
    let seconds = 0.5;
    let trajectory = run::trajectory(&l, &reference, seconds);
    let dt_r = grid::REFERENCE_DT;
    for dt in [1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0] {
        let mut c = reference;
        c.params.dt = dt;
        let m = run::measure_against(&l, &c, seconds, usize::MAX, Some(&trajectory));
        let t = run::steps(seconds, dt) as f64 * dt;
        let expected = G * t * (dt - dt_r) / 2.0;
        assert!(
            (m.step_error - expected).abs() <= 1e-9 * expected,
            "dt {dt}: per-step error {} against g t (dt - dt_r) / 2 = {expected}",
            m.step_error
        );
        // Here the gap only grows: the run's error (at the end) is the same.
        let run_error = run::rms_distance(&m.positions, trajectory.positions.last().unwrap());
        assert!((run_error - expected).abs() <= 1e-9 * expected);
    }
}

#[test]
fn a_drop_to_rest_per_step_and_per_run_choose_different_time_steps() {
    let l = drop(true);
    let default = grid::default_config(&l).unwrap();
    let reference = grid::reference(&default, Solver::SequentialImpulse);
    let seconds = 1.5;
    let trajectory = run::trajectory(&l, &reference, seconds);
    // At 1/30 s the ball rests where the reference's does, but on the way,
    // at t = 0.4 s (both still falling), it is g t (dt - dt_r) / 2 behind.
    let mut coarse = reference;
    coarse.params.dt = 1.0 / 30.0;
    let m = run::measure_against(&l, &coarse, seconds, usize::MAX, Some(&trajectory));
    let behind = G * 0.4 * (1.0 / 30.0 - grid::REFERENCE_DT) / 2.0;
    assert!(m.step_error >= behind, "{} < {behind}", m.step_error);
    let at_rest = run::rms_distance(&m.positions, trajectory.positions.last().unwrap());
    assert!(at_rest < 0.01, "the run's error at rest: {at_rest}");

    let target = 0.01;
    let by_run = advise(&l, seconds, Solver::SequentialImpulse, target, Per::Run).unwrap();
    let by_step = advise(&l, seconds, Solver::SequentialImpulse, target, Per::Step).unwrap();
    assert_eq!(by_step.per, Per::Step);
    let (dt_run, dt_step) = (
        by_run.choice.config.params.dt,
        by_step.choice.config.params.dt,
    );
    assert!(
        dt_step < dt_run,
        "per step needs a finer time step: {dt_step} against per run {dt_run}"
    );
    // Each choice meets its own measure; the run's choice misses per step.
    assert!(by_run.choice.error <= target && by_step.choice.error <= target);
    let again = run::measure_against(
        &l,
        &by_run.choice.config,
        seconds,
        usize::MAX,
        Some(&trajectory),
    );
    assert!(
        again.step_error > target,
        "the run's choice per step: {}",
        again.step_error
    );
    let again = run::measure_against(
        &l,
        &by_step.choice.config,
        seconds,
        usize::MAX,
        Some(&trajectory),
    );
    assert!((again.step_error - by_step.choice.error).abs() <= 1e-12);
}
