//! The study's loop: per scene, the reference first, then every row of the
//! grid (measured, then timed unless timing is off), the front marked and
//! the trade said in one sentence. Progress is reported to a callback so the
//! command can draw a bar; nothing here prints.

use super::{grid, pareto, run, Row, SceneStudy, Study};
use crate::lesson::Lesson;
use crate::physics::Solver;

/// One scene to study.
#[derive(Debug, Clone)]
pub struct SceneSpec {
    pub lesson: Lesson,
    pub seconds: f64,
    pub reference_solver: Solver,
}

/// How the study runs.
#[derive(Debug, Clone, Default)]
pub struct Options {
    pub timed: bool,
    pub repeats: usize,
    pub quick: bool,
    pub grid: Vec<(String, Vec<String>)>,
}

/// The rows each scene will run (for a progress total).
pub fn planned(specs: &[SceneSpec], o: &Options) -> usize {
    specs
        .iter()
        .map(|s| {
            grid::default_config(&s.lesson).map_or(0, |d| {
                1 + grid::rows(&d, grid::features(&s.lesson), o.quick, &o.grid).len()
            })
        })
        .sum()
}

/// Runs the study; `progress(done, scene)` after each configuration.
pub fn study(specs: &[SceneSpec], o: &Options, progress: &mut dyn FnMut(usize, &str)) -> Study {
    let mut done = 0;
    let mut scenes = Vec::new();
    for spec in specs {
        let lesson = &spec.lesson;
        let Some(default) = grid::default_config(lesson) else {
            continue;
        };
        let reference_config = grid::reference(&default, spec.reference_solver);
        let reference = run::measure(lesson, &reference_config, spec.seconds);
        done += 1;
        progress(done, &lesson.id);
        let mut rows = Vec::new();
        let planned = grid::rows(&default, grid::features(lesson), o.quick, &o.grid);
        let partial = (o.quick && o.grid.is_empty()).then(|| {
            let full = grid::rows(&default, grid::features(lesson), false, &o.grid);
            full.iter()
                .filter(|(_, _, c)| !planned.iter().any(|(_, _, q)| q == c))
                .count()
        });
        for (knob, value, config) in planned {
            let m = run::measure(lesson, &config, spec.seconds);
            let microseconds = if o.timed && m.failure.is_none() {
                run::spread(&run::time(lesson, &config, spec.seconds, o.repeats.max(1)))
            } else {
                None
            };
            let error = if m.failure.is_some() {
                f64::NAN
            } else {
                run::rms_distance(&m.positions, &reference.positions)
            };
            let per_second = m.steps as f64 / spec.seconds;
            rows.push(Row {
                knob,
                value,
                config,
                microseconds,
                microseconds_per_second: microseconds.map(|t| t.map(|x| x * per_second)),
                work_per_second: super::advise::cost(&m, spec.seconds),
                visits_per_step: m.visits_per_step,
                ccd_tests_per_step: m.ccd_tests_per_step,
                limit_steps: m.limit_steps,
                steps: m.steps,
                max_penetration: m.max_penetration,
                max_closing_velocity: m.max_closing_velocity,
                energy_gain: m.energy_gain,
                drift: m.drift,
                missed_collisions: m.missed_collisions,
                error_vs_reference: error,
                pareto: false,
                failure: m.failure,
            });
            done += 1;
            progress(done, &lesson.id);
        }
        pareto::mark(&mut rows);
        let mut scene = SceneStudy {
            scene: lesson.id.clone(),
            title: lesson.title.clone(),
            seconds: spec.seconds,
            reference: grid::describe_reference(&reference_config),
            reference_config,
            rows,
            verdict: String::new(),
            partial,
        };
        scene.verdict = pareto::verdict(&scene);
        scenes.push(scene);
    }
    Study {
        scenes,
        timed: o.timed,
        repeats: o.repeats,
    }
}
