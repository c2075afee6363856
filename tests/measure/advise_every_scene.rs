//! advise on every embedded scene (issue 27's checks), at the run length and
//! reference solver the command takes by default (`advise::run_of`: the
//! study's for its nine scenes, else the scene's own length up to 2 s) and
//! a target of 1 cm per run on each. Why 1 cm: the scenes' bodies are 5 cm
//! (plate-drop's and bullet-wall's balls) to 1 m across, so 1 cm is a
//! difference a reader sees on the smallest and well above round-off (f32
//! leaves micrometres), while the failures the knobs guard against (a
//! tunnelled ball, a box creeping down a slope, a stack that falls) are off
//! by decimetres to metres.
//!
//! For each scene: the printed configuration, pasted into the scene and
//! run, meets the target; every knob reported as not needed moves the error
//! by less than the target at its cheap setting and every knob kept goes
//! over it (`common::advise::check`). The table (`--nocapture`) gives the
//! scene, the chosen configuration, its cost against the reference's, its
//! error and the search's wall time, which is printed, never asserted.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

use crate::common::advise::{check, lesson};
use contact_lab::lesson::embedded;
use contact_lab::study::advise::{advise, run_of, value_of, Advice, Per, MAX_PASSES};
use contact_lab::study::{grid, run};

/// The most the knobs reported as not needed buy when turned, one at a
/// time with the rest as chosen, to the reference's setting: the choice's
/// error less the error then (m; negative: the dear setting is worse), and
/// the knob. Printed, not asserted: a knob at its cheap setting meets the
/// target by construction; this says how much accuracy it leaves.
fn dear_setting_buys(a: &Advice, solver: contact_lab::physics::Solver) -> (f64, String) {
    let l = crate::common::advise::lesson(&a.scene);
    let reference = grid::reference(&grid::default_config(&l).unwrap(), solver);
    let positions = run::measure(&l, &reference, a.seconds).positions;
    let mut most = (f64::NEG_INFINITY, String::from("-"));
    for name in &a.not_needed {
        let dear = value_of(&reference, name);
        let mut x = a.choice.config;
        if grid::set(&mut x, name, &dear).is_err() || x == a.choice.config {
            continue;
        }
        let e = run::rms_distance(&run::measure(&l, &x, a.seconds).positions, &positions);
        let buys = a.choice.error - e;
        if buys > most.0 {
            most = (buys, format!("{name}={dear}"));
        }
    }
    most
}

/// The choice's per-step error (the largest over the run), measured by the
/// study's run (not advise's lean runner): the advice's `worst_step_error`
/// must be the same.
fn step_error(
    l: &contact_lab::lesson::Lesson,
    a: &Advice,
    solver: contact_lab::physics::Solver,
) -> f64 {
    let reference = grid::reference(&grid::default_config(l).unwrap(), solver);
    let trajectory = run::trajectory(l, &reference, a.seconds);
    run::measure_against(
        l,
        &a.choice.config,
        a.seconds,
        usize::MAX,
        Some(&trajectory),
    )
    .step_error
}

/// The error target, m (per run).
const TARGET: f64 = 0.01;

/// mass-ratio-stack at 1 cm per run, under the settled rule (the error
/// within the target at the run's end and over its last tenth,
/// docs/study.md). An exhaustive scan (`examples/advise_scan.rs`, 55,296
/// configurations, capped at 2492, 389 s at a load of 12) finds one
/// configuration cheaper that meets 1 cm at the end: 1523 (dt = 1/60 s,
/// sequential impulses warm-started at 2 visits per contact, both epsilons
/// 10⁻³, rollback), which is 3 cm off a tenth of the run before its end
/// (and 12 cm at worst): a coincidence of the end time, not settled
/// ([`mass_ratio_stacks_best_scanned_meets_the_target_only_at_the_runs_end`]).
/// The cheapest settled is 2120 (dt = 1/60 s, warm sequential impulses
/// converged, `position_epsilon` 10⁻³, `velocity_epsilon` 0.1, rollback),
/// within 1 cm at every step too, and the search reaches it from its
/// time-step starts (before them, 2492; before the rule, 2414, 4 cm at its
/// worst step and 2.2 cm a tenth before the end). Since the merge of the
/// resting-manifold, sleep and continuous-detection changes (session 14),
/// the search finds 1857 (the default with the budget converged, f64:
/// 2.8 mm at its worst step), cheaper than that hand-picked 2120; which of
/// those changes let the converged budget alone meet 1 cm was not measured.
const MASS_RATIO_SEARCH: f64 = 1857.0;

/// The scan's cheapest configuration within 1 cm settled and at every step (above).
const MASS_RATIO_BEST_EVERY_STEP: f64 = 2120.0;

/// Each scene's cost at 1 cm per run: no scene may do worse. Under the
/// settled rule, a choice that met the target only at the run's end costs
/// more: ball-drop 63 → 242 (its bouncing ball 1.6 mm off at 2 s, 16 cm
/// 0.1 s before and after), mass-ratio-stack 2414 → 2120 (above; cheaper:
/// the time-step starts). The time-step starts brought sliding-box 440 →
/// 194. ramp-stick costs 48 where it cost 46 before the rule (its 46 is
/// settled too, but the descent's path changed with the measure; see
/// docs/study.md). ball-drop 242 → 482 (session 14): continuous detection
/// now searches a body against a half-space, so the reference (which runs
/// with ccd) bounces the ball at the time it meets the floor, and the
/// advice needs dt = 1/480 s with conservative advancement to stay within
/// 1 cm of it. ball-floor-fast (new) costs 66. The mesh scenes (new):
/// mesh-floor-slide 156, mesh-bowl-ball 60, mesh-ramp-ball 117.
const BEFORE: [(&str, f64); 28] = [
    ("ball-drop", 482.0),
    ("resting-box", 38.0),
    ("sliding-box", 194.0),
    ("ramp-stick", 48.0),
    ("cradle-gaps", 38.0),
    ("mesh-floor-slide", 156.0),
    ("mesh-bowl-ball", 60.0),
    ("mesh-ramp-ball", 117.0),
    ("ramp-slide", 1108.0),
    ("stack-5", 1140.0),
    ("cradle-over-time", 34.0),
    ("sleep-and-wake", 672.0),
    ("sleep-modes", 3762.0),
    ("kane-rod-bounce", 1930.0),
    ("sphere-row-20", 5302.0),
    ("mass-ratio-stack", MASS_RATIO_SEARCH),
    ("overlap-recovery", 62.0),
    ("hull-stack", 396.0),
    ("gjk-separated", 30.0),
    ("gjk-touching", 30.0),
    ("epa-edge-edge", 31.0),
    ("cylinder-on-box", 4173.0),
    ("bullet-wall", 34.0),
    ("spinning-edge", 550.0),
    ("plate-drop", 122.0),
    ("tetra-on-floor", 30.0),
    ("capsule-on-slope", 46.0),
    ("ball-floor-fast", 66.0),
];
const MASS_RATIO_BEST_SCANNED: f64 = 1523.0;

#[test]
fn advise_on_every_scene_meets_the_target_pasted_and_each_knob_is_what_it_says() {
    println!(
        "{:<18} {:>4} {:>7} {:>7} {:>9} {:>9} {:>9} {:>6} {:>5} {:>9} {:>6}  {:<34} choice: budget, float (knobs above their cheap setting)",
        "scene", "s", "cost", "ref", "error", "step err", "pasted", "search", "runs", "hit/rerun", "p/e/pairs", "not needed: the dear setting buys"
    );
    let mut failures = Vec::new();
    let ids = embedded::scene_ids();
    for id in &ids {
        let l = lesson(id);
        let (seconds, solver) = run_of(&l).expect("an embedded scene is a scene");
        let start = Instant::now();
        let a = advise(&l, seconds, solver, TARGET, Per::Run).expect("the scene runs");
        let wall = start.elapsed().as_secs_f64();
        let checked = catch_unwind(AssertUnwindSafe(|| check(&a, solver, true)));
        let buys = dear_setting_buys(&a, solver);
        let needed: Vec<String> = a
            .needed
            .iter()
            .map(|n| format!("{}={}", n.knob, n.value))
            .collect();
        println!(
            "{:<18} {:>4} {:>7.0} {:>7.0} {:>9.2e} {:>9.2e} {:>9} {:>5.1}s {:>5} {:>9} {:>9}  {:<34} budget {}, {} ({})",
            id,
            seconds,
            a.choice.cost,
            a.reference_cost,
            a.choice.error,
            a.worst_step_error,
            checked
                .as_ref()
                .map_or("FAILED".to_string(), |c| format!("{:.2e}", c.pasted_error)),
            wall,
            a.runs,
            format!("{}/{}", a.hits, a.reruns),
            format!("{}/{}/{}", a.passes, a.escapes, a.pairs),
            format!("{:.1e} ({})", buys.0, buys.1),
            a.choice.config.budget.per_contact(),
            a.choice.config.precision.name(),
            needed.join(", ")
        );
        // The worst step the advice states is the study's run's.
        let worst = step_error(&l, &a, solver);
        if worst != a.worst_step_error {
            failures.push(format!(
                "{id}: worst step {} stated, {worst} measured",
                a.worst_step_error
            ));
        }
        // The sentence that the run strays on the way: where the worst step
        // is over 10× the target (sphere-row-20: 18 cm, its row settling
        // back within 1 cm by the end), and nowhere else.
        let text = contact_lab::render::study::advise::text(&a, &contact_lab::format::Fmt::new(3));
        let says = text.contains(&format!("--error {TARGET} --per step"));
        if says != (a.worst_step_error > 10.0 * TARGET) || says != a.strays().is_some() {
            failures.push(format!(
                "{id}: worst step {} against the target {TARGET}; the sentence {}",
                a.worst_step_error,
                if says { "said" } else { "not said" }
            ));
        }
        if *id == "sphere-row-20" && !says {
            failures.push(format!("{id}: no sentence that the row strays on the way"));
        }
        // The descent ended on a pass that changed nothing, not at the cap
        // (mass-ratio-stack was still moving at the 4th pass when 4 was it).
        if *id == "mass-ratio-stack" && a.choice.cost > MASS_RATIO_SEARCH + 0.5 {
            failures.push(format!(
                "mass-ratio-stack: cost {} over the {MASS_RATIO_SEARCH} it reached (the best scanned settled is {MASS_RATIO_BEST_EVERY_STEP}, at the run's end only {MASS_RATIO_BEST_SCANNED})",
                a.choice.cost
            ));
        }
        match BEFORE.iter().find(|(s, _)| s == id) {
            // (Before: the printed cost, to the nearest unit.)
            Some((_, before)) if a.choice.cost > *before + 0.5 => failures.push(format!(
                "{id}: cost {} over its {before} before",
                a.choice.cost
            )),
            Some(_) => {}
            None => failures.push(format!("{id}: no cost recorded before (add it to BEFORE)")),
        }
        if a.capped {
            failures.push(format!("{id}: a descent stopped at {MAX_PASSES} passes"));
        }
        if let Err(e) = checked {
            let why = e
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            failures.push(format!("{id}: {why}"));
        }
    }
    // Every scene file is embedded, so every one was advised on.
    let mut files: Vec<String> =
        std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/lessons/scenes"))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter_map(|f| f.strip_suffix(".toml").map(String::from))
            .collect();
    files.sort();
    let mut advised: Vec<String> = ids.iter().map(|s| s.to_string()).collect();
    advised.sort();
    assert_eq!(advised, files, "every scene file is advised on");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Why the search does not stop at the scan's 1523 on mass-ratio-stack: 1523
/// meets 1 cm only at the run's end, and the settled rule (docs/study.md)
/// leaves it out: it is 3 cm off within the run's last tenth. Its stack, two visits per
/// contact at dt = 1/60 s, wobbles 3–4 cm off the reference through the run
/// (12 cm at worst), passes within 6 mm of it at 2 s, and is 4 cm off again
/// by 2.5 s; every change of its budget or of either epsilon (each of which,
/// but the budget, makes the model more accurate) misses 1 cm by 2.6 to 38
/// cm. An isolated point that a coincidence of the end time puts within the
/// target is not reachable one or two knobs at a time from anywhere, nor
/// worth advising. The scan's 2120 stays within the target at every step,
/// and the search reaches it.
#[test]
fn mass_ratio_stacks_best_scanned_meets_the_target_only_at_the_runs_end() {
    let l = lesson("mass-ratio-stack");
    let (seconds, solver) = run_of(&l).unwrap();
    let reference = grid::reference(&grid::default_config(&l).unwrap(), solver);
    let mut scanned = reference;
    for (k, v) in [
        ("dt", "1/60"),
        ("budget", "2"),
        ("position_epsilon", "0.001"),
        ("velocity_epsilon", "0.001"),
        ("rollback", "rollback"),
        ("ccd", "none"),
    ] {
        grid::set(&mut scanned, k, v).unwrap();
    }
    let trajectory = run::trajectory(&l, &reference, seconds);
    let end = run::measure(&l, &reference, seconds).positions;
    let m = run::measure_against(&l, &scanned, seconds, usize::MAX, Some(&trajectory));
    let cost = contact_lab::study::advise::cost(&m, seconds);
    let error = run::rms_distance(&m.positions, &end);
    println!(
        "scanned: cost {cost:.0}, error {error:.2e} at the end, {:.2e} at worst",
        m.step_error
    );
    assert_eq!(cost.round(), MASS_RATIO_BEST_SCANNED);
    assert!(error <= TARGET, "{error}");
    assert!(m.step_error > 10.0 * TARGET, "{}", m.step_error);
    // Not settled: over the target within the run's last tenth.
    assert!(m.settle_error > 2.0 * TARGET, "{}", m.settle_error);
    // Half a second later it is off by more than the target again.
    let later = |c| run::measure(&l, c, seconds + 0.5).positions;
    let off_later = run::rms_distance(&later(&scanned), &later(&reference));
    assert!(off_later > TARGET, "{off_later}");
    // Every other budget (but converged) and every other epsilon misses.
    for (k, values) in [
        ("budget", &["1", "4", "8", "16"][..]),
        ("position_epsilon", &["0.1", "0.01", "0.0001"][..]),
        ("velocity_epsilon", &["0.1", "0.01", "0.0001"][..]),
    ] {
        for v in values {
            let mut c = scanned;
            grid::set(&mut c, k, v).unwrap();
            let e = run::rms_distance(&run::measure(&l, &c, seconds).positions, &end);
            println!("  {k} = {v}: {e:.2e}");
            assert!(e > 2.0 * TARGET, "{k} = {v}: {e}");
        }
    }
    // The cheapest within the target at every step, and the search's choice.
    let mut every_step = reference;
    for (k, v) in [
        ("dt", "1/60"),
        ("budget", "converged"),
        ("position_epsilon", "0.001"),
        ("velocity_epsilon", "0.1"),
        ("rollback", "rollback"),
        ("ccd", "none"),
    ] {
        grid::set(&mut every_step, k, v).unwrap();
    }
    let m = run::measure_against(&l, &every_step, seconds, usize::MAX, Some(&trajectory));
    let cost = contact_lab::study::advise::cost(&m, seconds);
    let error = run::rms_distance(&m.positions, &end);
    println!(
        "every step: cost {cost:.0}, error {error:.2e} at the end, {:.2e} at worst",
        m.step_error
    );
    assert_eq!(cost.round(), MASS_RATIO_BEST_EVERY_STEP);
    assert!(
        error <= TARGET && m.step_error <= TARGET && m.settle_error <= TARGET,
        "{error}, {}",
        m.step_error
    );
    let a = advise(&l, seconds, solver, TARGET, Per::Run).unwrap();
    println!("advised: cost {:.0}", a.choice.cost);
    assert_eq!(a.choice.cost.round(), MASS_RATIO_SEARCH);
    assert!(a.worst_step_error <= TARGET, "{}", a.worst_step_error);
}
