//! `advise`: the configuration it prints, pasted into the scene and run,
//! meets the target; every knob it reports as not needed changes the error
//! by less than the target at its cheap setting, every knob it keeps buys
//! more than the target; the known findings (ramp-stick does not take the
//! lecture's order, the cradle does not take sequential impulses); and the
//! study's verdicts hold (twice the same, quick against full, the SVG).

use crate::common::advise::{check_advice, lesson, pasted};
use contact_lab::physics::Solver;
use contact_lab::study::advise::{settings_snippet, value_of};
use contact_lab::study::{grid, sweep, Budget, CONVERGED};

#[test]
fn ball_drop_advice_pasted_meets_the_target_and_each_knob_is_what_it_says() {
    let a = check_advice("ball-drop", 0.5, Solver::SequentialImpulse, 0.01, true);
    // A bouncing ball needs no more than one visit per contact.
    assert_eq!(a.choice.config.budget, Budget::PerContact(1));
    assert!(a.needed.iter().any(|n| n.knob == "dt"), "{:?}", a.needed);
}

#[test]
fn resting_box_advice_pasted_meets_the_target() {
    let a = check_advice("resting-box", 0.5, Solver::SequentialImpulse, 0.001, true);
    let f = contact_lab::study::exercised::findings(&a.exercised);
    let resting = f.iter().find(|f| f.feature == "resting contacts").unwrap();
    assert!(
        resting.present,
        "a box on the floor rests: {}",
        resting.evidence
    );
}

#[test]
fn a_knob_the_scene_sets_in_world_is_overridden_by_the_pasted_snippet() {
    // sliding-box sets friction_model in [world], which the lesson reads
    // after [settings]: a snippet that put the choice in [settings] left the
    // scene's kinetic-direction in force (found by the measure layer's
    // advise_every_scene). The advice at 1 cm keeps the scene's model now
    // (cost 440), so the choice is given another one here.
    let mut a = check_advice("sliding-box", 2.0, Solver::SequentialImpulse, 0.01, false);
    let scene = grid::default_config(&lesson("sliding-box")).unwrap();
    grid::set(&mut a.choice.config, "friction_model", "millington").unwrap();
    assert_ne!(
        value_of(&a.choice.config, "friction_model"),
        value_of(&scene, "friction_model"),
        "the choice changes the scene's friction model"
    );
    let snippet = settings_snippet(&a);
    let world = snippet.split("[world]").nth(1).unwrap();
    assert!(world.contains("friction_model = "), "{snippet}");
    let p = pasted("sliding-box", &snippet);
    assert_eq!(
        value_of(&grid::default_config(&p).unwrap(), "friction_model"),
        "millington",
        "{snippet}"
    );
}

#[test]
fn ramp_stick_does_not_take_the_lectures_order() {
    // The lecture's order creeps half a metre down the slope in 2 s.
    let a = check_advice("ramp-stick", 2.0, Solver::SequentialImpulse, 1e-3, false);
    assert_ne!(a.choice.config.solver(), Solver::DeepestFirst);
    let s = a.needed.iter().find(|n| n.knob == "solver").unwrap();
    assert!(s.error_without > 0.1, "{}", s.error_without);
}

#[test]
fn the_cradle_does_not_take_sequential_impulses() {
    // Sequential impulses move the balls together: 0.43 m off in 1 s.
    let a = check_advice("cradle-over-time", 1.0, Solver::DeepestFirst, 1e-3, false);
    assert_ne!(a.choice.config.solver(), Solver::SequentialImpulse);
}

#[test]
fn a_budget_written_in_the_lesson_is_the_scenes_budget() {
    let p = pasted("ball-drop", "[settings]\nvisits_per_contact = 1000\n");
    assert_eq!(grid::default_config(&p).unwrap().budget, Budget::Converged);
    let p = pasted("ball-drop", "[settings]\nvisits_per_contact = 3\n");
    assert_eq!(
        grid::default_config(&p).unwrap().budget,
        Budget::PerContact(3)
    );
    assert_eq!(CONVERGED, 1000);
}

fn specs(ids: &[&str], seconds: f64) -> Vec<sweep::SceneSpec> {
    ids.iter()
        .map(|id| sweep::SceneSpec {
            lesson: lesson(id),
            seconds,
            reference_solver: Solver::SequentialImpulse,
        })
        .collect()
}

#[test]
fn the_same_timed_study_twice_gives_the_same_marks_and_sentences() {
    let o = sweep::Options {
        timed: true,
        repeats: 3,
        quick: true,
        grid: Vec::new(),
    };
    let s = specs(&["resting-box", "ball-drop"], 0.5);
    let a = sweep::study(&s, &o, &mut |_, _| {});
    let b = sweep::study(&s, &o, &mut |_, _| {});
    for (x, y) in a.scenes.iter().zip(&b.scenes) {
        let marks = |s: &contact_lab::study::SceneStudy| {
            s.rows
                .iter()
                .map(|r| (r.value.clone(), r.pareto))
                .collect::<Vec<_>>()
        };
        assert_eq!(marks(x), marks(y), "{}", x.scene);
        assert_eq!(x.verdict, y.verdict);
    }
}

#[test]
fn quick_agrees_with_full_on_the_solvers_or_says_it_is_partial() {
    let run = |quick| {
        let o = sweep::Options {
            timed: false,
            repeats: 1,
            quick,
            grid: Vec::new(),
        };
        sweep::study(&specs(&["stack-5"], 0.5), &o, &mut |_, _| {})
    };
    let (q, f) = (run(true), run(false));
    let (q, f) = (&q.scenes[0], &f.scenes[0]);
    // The comparison to the sentence's end: a full stop and a space, or the
    // last character (cut at the first '.', it stopped at an error's
    // decimal point and never reached the winner).
    let solvers = |v: &str| {
        v.split("; at equal work").nth(1).map(|s| {
            let s = s.split(". ").next().unwrap_or("");
            s.strip_suffix('.').unwrap_or(s).to_string()
        })
    };
    let compared = solvers(&f.verdict);
    assert!(
        compared
            .as_ref()
            .is_some_and(|s| s.ends_with(" win") || s.ends_with(" wins")),
        "{}",
        f.verdict
    );
    assert_eq!(solvers(&q.verdict), solvers(&f.verdict));
    assert!(q.partial.is_some_and(|n| n > 0));
    assert!(q.verdict.contains("partial"), "{}", q.verdict);
    assert!(f.partial.is_none() && !f.verdict.contains("partial"));
}

#[test]
fn the_study_svg_keeps_its_legend_inside_one_family_per_colour_front_and_reference() {
    let o = sweep::Options {
        timed: false,
        repeats: 1,
        quick: false,
        grid: Vec::new(),
    };
    let st = sweep::study(&specs(&["stack-5"], 0.25), &o, &mut |_, _| {});
    let svg = contact_lab::render::study::svg::render(&st);
    // A number attribute of the first tag in `tag` (` name="…"`).
    let attr = |tag: &str, name: &str| -> Option<f64> {
        let head = tag.split('>').next().unwrap();
        (" ".to_string() + head)
            .split(&format!(" {name}=\""))
            .nth(1)
            .map(|v| v.split('"').next().unwrap().parse().unwrap())
    };
    let width = attr(&svg, "width").unwrap();
    let height = attr(&svg, "height").unwrap();
    // Every text's baseline lies inside the canvas, below its own type size
    // from the top.
    for t in svg.split("<text ").skip(1) {
        let y = attr(t, "y").unwrap();
        let size = attr(t, "font-size").unwrap_or(12.0);
        assert!(
            y >= size * 0.7 && y <= height,
            "text outside the canvas at y {y} of {height}: {t}"
        );
    }
    // Every text ends inside the canvas (11–14 px type: at most 0.62 em a character).
    for t in svg.split("<text ").skip(1) {
        let x = attr(t, "x").unwrap();
        let body = t.split('>').nth(1).unwrap().split('<').next().unwrap();
        let size = attr(t, "font-size").unwrap_or(12.0);
        let anchor_end = t.contains("text-anchor=\"end\"") || t.contains("text-anchor=\"middle\"");
        let end = if anchor_end {
            x
        } else {
            x + 0.62 * size * body.chars().count() as f64
        };
        assert!(end <= width, "text runs off the canvas at {end}: {body}");
    }
    // Every row in the legend once, in its family's colour with a marker
    // of its own within the family (tests/cli/study.rs holds the rest).
    let families = contact_lab::render::study::svg::families(&st.scenes[0].rows);
    assert!(families.len() <= contact_lab::render::study::svg::MAX_FAMILIES);
    assert_eq!(
        families.iter().map(|f| f.members.len()).sum::<usize>(),
        st.scenes[0].rows.len()
    );
    assert!(svg.contains("<polyline"), "the front is drawn");
    assert!(svg.contains("reference: sequential impulses, warm-started"));
    for f in &families {
        assert!(svg.contains(&f.name.replace('&', "&amp;")), "{}", f.name);
        for (_, _, value) in &f.members {
            assert!(svg.contains(&value.replace('&', "&amp;")), "{value}");
        }
    }
}

/// The rollback knob is in the full default grid where bodies can end deep
/// in one another (mass-ratio-stack's 1:100 masses, bullet-wall's bullet)
/// and not elsewhere (resting-box). On mass-ratio-stack the heavy box sinks
/// into the light one under projection; rolled back it is lifted to where
/// the pair met, so the row leaves a seventh of the penetration and gains
/// the potential energy of the lift; the same timed study twice gives the
/// same marks and says the same sentence about it.
#[test]
fn rollback_is_in_the_grid_where_pairs_end_deep_and_its_sentence_holds() {
    let in_grid = |id: &str| {
        let l = lesson(id);
        let d = grid::default_config(&l).unwrap();
        grid::rows(&d, grid::features(&l), false, &[])
            .iter()
            .any(|(knob, _, _)| knob == "rollback")
    };
    assert!(in_grid("mass-ratio-stack") && in_grid("bullet-wall"));
    assert!(!in_grid("resting-box"));
    let o = sweep::Options {
        timed: true,
        repeats: 1,
        quick: false,
        grid: Vec::new(),
    };
    let s = specs(&["mass-ratio-stack"], 0.5);
    let (a, b) = (
        sweep::study(&s, &o, &mut |_, _| {}),
        sweep::study(&s, &o, &mut |_, _| {}),
    );
    let marks = |s: &contact_lab::study::SceneStudy| {
        s.rows
            .iter()
            .map(|r| (r.value.clone(), r.pareto))
            .collect::<Vec<_>>()
    };
    let (x, y) = (&a.scenes[0], &b.scenes[0]);
    assert_eq!(marks(x), marks(y));
    assert_eq!(x.verdict, y.verdict);
    let row = |knob: &str| x.rows.iter().find(|r| r.knob == knob).unwrap();
    let (projected, rolled) = (row("default"), row("rollback"));
    assert!(
        rolled.max_penetration < projected.max_penetration / 5.0,
        "{} vs {}",
        rolled.max_penetration,
        projected.max_penetration
    );
    assert!(rolled.energy_gain > projected.energy_gain + 1.0);
    assert!(
        x.verdict.contains(
            "Rollback: with rollback = rollback instead of projection (the default) the run leaves less penetration"
        ),
        "{}",
        x.verdict
    );
}

/// The choice's worst-step error (text, Markdown, JSON) is the largest,
/// over the run's steps, of the RMS distance to the reference at the same
/// time: computed here from runs of k steps of the choice and of the
/// reference (whose 1/480 s step divides the choice's), not from advise's
/// runner or the reference's trajectory. The sentence that the run strays
/// on the way is said exactly when the worst step passes 10× the target;
/// given the worst step ball-drop's choice had when only the run's end
/// counted (27 cm at 1 cm over 2 s), it names the per-step command. (Under
/// the settled rule ball-drop's choice strays 1.1 cm at worst over 2 s;
/// sphere-row-20's says it: the measure layer.)
#[test]
fn the_worst_step_error_is_the_largest_step_error_and_is_printed() {
    let seconds = 0.5;
    let target = 0.01;
    let l = lesson("ball-drop");
    let a = contact_lab::study::advise::advise(
        &l,
        seconds,
        Solver::SequentialImpulse,
        target,
        contact_lab::study::advise::Per::Run,
    )
    .unwrap();
    let reference = grid::reference(
        &grid::default_config(&l).unwrap(),
        Solver::SequentialImpulse,
    );
    let dt = a.choice.config.params.dt;
    let n = contact_lab::study::run::steps(seconds, dt);
    let at = |c, k: usize| contact_lab::study::run::measure(&l, c, k as f64 * dt).positions;
    let worst = (1..=n)
        .map(|k| {
            contact_lab::study::run::rms_distance(&at(&a.choice.config, k), &at(&reference, k))
        })
        .fold(0.0, f64::max);
    assert!(
        (a.worst_step_error - worst).abs() <= 1e-12 + 1e-9 * worst,
        "stated {}, measured {worst}",
        a.worst_step_error
    );
    assert!(a.worst_step_error >= a.end_error);
    let end = contact_lab::study::run::rms_distance(&at(&a.choice.config, n), &at(&reference, n));
    assert!((a.end_error - end).abs() <= 1e-12 + 1e-9 * end);
    let fmt = contact_lab::format::Fmt::new(3);
    let json: serde_json::Value =
        serde_json::from_str(&contact_lab::render::study::advise::json(&a)).unwrap();
    assert_eq!(
        json["choice"]["worst_step_error"].as_f64(),
        Some(a.worst_step_error)
    );
    assert_eq!(json["choice"]["end_error"].as_f64(), Some(a.end_error));
    let strays = a.worst_step_error > 10.0 * target;
    assert_eq!(a.strays().is_some(), strays);
    for shown in [
        contact_lab::render::study::advise::text(&a, &fmt),
        contact_lab::render::study::advise::markdown(&a, &fmt),
    ] {
        assert!(shown.contains("at its worst step"), "{shown}");
        assert_eq!(shown.contains("--per step"), strays, "{shown}");
    }
    let mut end_only = a.clone();
    end_only.worst_step_error = 0.274;
    let shown = contact_lab::render::study::advise::text(&end_only, &fmt);
    assert!(
        shown.contains("only as it ends")
            && shown.contains("contact-lab advise ball-drop --error 0.01 --per step"),
        "{shown}"
    );
}
