//! advise's checks (issue 27), shared by the cli and measure layers: the
//! snippet it prints pasted into the scene and run meets the target; every
//! knob reported as not needed moves the error by less than the target at
//! its cheap setting; every knob kept buys more than the target.

use contact_lab::lesson::{embedded, validate, Lesson};
use contact_lab::physics::Solver;
use contact_lab::study::advise::{advise, dimensions, settings_snippet, Advice, Per};
use contact_lab::study::{grid, run, Config};

pub fn lesson(id: &str) -> Lesson {
    Lesson::load(id).unwrap()
}

/// The scene's file with the snippet's tables merged over its own by the
/// rule advise prints: a key the scene already sets is replaced, the same
/// key (as written) and nothing else, so the snippet must spell each knob
/// as the scene does (`[sleep] enabled`, not `sleep`, where the scene says
/// `enabled`), or the scene is refused for setting a knob twice.
pub fn pasted(id: &str, snippet: &str) -> Lesson {
    let mut file: toml::Table = embedded::find(id).unwrap().parse().unwrap();
    let add: toml::Table = snippet.parse().expect("the snippet is TOML");
    for (table, keys) in add {
        let target = file
            .entry(table.clone())
            .or_insert_with(|| toml::Value::Table(Default::default()))
            .as_table_mut()
            .unwrap();
        for (key, value) in keys.as_table().unwrap() {
            target.insert(key.clone(), value.clone());
        }
    }
    validate::parse(id, &toml::to_string(&file).unwrap()).expect("the pasted scene loads")
}

/// The error of a configuration against the reference, run for `seconds`.
pub fn error(l: &Lesson, c: &Config, reference: &Config, seconds: f64) -> f64 {
    let r = run::measure(l, reference, seconds);
    run::rms_distance(&run::measure(l, c, seconds).positions, &r.positions)
}

/// advise's per-run measure, the settled error: the end's against the
/// reference's final positions or the largest over the run's last tenth
/// against its trajectory, the larger (NaN: the run blew up).
pub fn settled(
    l: &Lesson,
    c: &Config,
    seconds: f64,
    end: &[nalgebra::Vector3<f64>],
    trajectory: &run::Trajectory,
) -> (f64, run::Measured) {
    let m = run::measure_against(l, c, seconds, usize::MAX, Some(trajectory));
    let e = if m.failure.is_some() {
        f64::NAN
    } else {
        run::rms_distance(&m.positions, end).max(m.settle_error)
    };
    (e, m)
}

/// Advice on `id`, its snippet pasted and run; with `knobs`, every knob
/// at its cheap setting run again as well (the slow part).
pub fn check_advice(id: &str, seconds: f64, solver: Solver, target: f64, knobs: bool) -> Advice {
    let a = advise(&lesson(id), seconds, solver, target, Per::Run).unwrap();
    check(&a, solver, knobs);
    a
}

/// What [`check`] measured besides the advice: the pasted scene's error.
pub struct Checked {
    pub pasted_error: f64,
}

/// Checks advice `a` (per run) on its scene: the choice meets the target
/// and costs no more than the reference; the pasted snippet is the choice
/// and meets the target; with `knobs`, each knob at its cheap setting (the
/// value of least cost, ties to the earlier, with the rest as chosen): not
/// needed moves the settled error by less than the target, needed goes
/// over it.
pub fn check(a: &Advice, solver: Solver, knobs: bool) -> Checked {
    let (id, seconds, target) = (a.scene.as_str(), a.seconds, a.target);
    assert_eq!(a.per, Per::Run, "{id}: the checks measure the run's error");
    let l = lesson(id);
    assert!(
        a.choice.error <= target,
        "{id}: {} > {target}",
        a.choice.error
    );
    assert!(a.choice.cost <= a.reference_cost);
    let reference = grid::reference(&grid::default_config(&l).unwrap(), solver);

    // The snippet pasted into the scene and run meets the target.
    let p = pasted(id, &settings_snippet(a));
    let mut c = grid::default_config(&p).unwrap();
    c.precision = a.choice.config.precision;
    assert_eq!(
        (run::params(&c), c.budget, c.precision),
        (
            run::params(&a.choice.config),
            a.choice.config.budget,
            a.choice.config.precision
        ),
        "{id}: the pasted scene is the choice"
    );
    let pasted_error = error(&p, &c, &reference, seconds);
    assert!(
        pasted_error <= target,
        "{id}: pasted, error {pasted_error} > {target}"
    );
    let checked = Checked { pasted_error };
    if !knobs {
        return checked;
    }
    // Each knob at its cheap setting: not needed moves the error by less
    // than the target; needed goes over it.
    let reference_positions = run::measure(&l, &reference, seconds).positions;
    let trajectory = run::trajectory(&l, &reference, seconds);
    let (dims, _) = dimensions(
        &grid::default_config(&l).unwrap(),
        &reference,
        grid::features(&l),
    );
    let cheap = |name: &str| -> (String, f64, f64) {
        let dim = dims.iter().find(|d| d.name == name).unwrap();
        let mut best: Option<(String, f64, f64)> = None;
        for v in &dim.values {
            let mut x = a.choice.config;
            grid::set(&mut x, name, v).unwrap();
            let (err, m) = settled(&l, &x, seconds, &reference_positions, &trajectory);
            let cost = contact_lab::study::advise::cost(&m, seconds);
            if best.as_ref().is_none_or(|b| cost < b.1 * (1.0 - 1e-9)) {
                best = Some((v.clone(), cost, err));
            }
        }
        best.unwrap()
    };
    for name in &a.not_needed {
        let (v, _, e) = cheap(name);
        assert!(
            (e - a.choice.error).abs() < target,
            "{id}: {name} = {v} moves the error to {e}"
        );
    }
    for n in &a.needed {
        let (v, _, e) = cheap(n.knob);
        assert_eq!(v, n.cheap, "{id}: {}'s cheap setting", n.knob);
        assert!(
            e > target,
            "{id}: {} = {v} stays within the target ({e})",
            n.knob
        );
        assert_eq!(e, n.error_without, "{id}: {} = {v}", n.knob);
    }
    checked
}
