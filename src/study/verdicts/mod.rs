//! The verdict matrix (`study --verdicts`, docs/study.md "The verdict
//! matrix"): a fixed set of Solver2D-style scenes in 3-D ([`scenes`]), each
//! run under every solver of the `solver` knob's choice list ([`columns`]),
//! each judged by its criteria ([`criteria::SCENES`]) as a pass or a fail
//! with the figure behind it. The (scene, solver) cells are independent and
//! run on every core; the matrix is the same on one.

pub mod criteria;
pub mod record;
pub mod scenes;

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

use crate::knobs::Choice;
use crate::lesson::Lesson;
use crate::physics::Solver;
use criteria::{Scene, SCENES};

/// The scenes' sizes: as the issue states them, or reduced (fewer bodies,
/// shorter runs) for the debug tests and `--quick`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Size {
    Full,
    Reduced,
}

/// One column: a solver of the knob's choice list, warm-started or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Column {
    pub solver: Solver,
    pub warm_start: bool,
}

impl Column {
    /// The solver's spelling, `+warm` when warm-started (the study's label).
    pub fn label(&self) -> String {
        format!(
            "{}{}",
            self.solver.name(),
            if self.warm_start { "+warm" } else { "" }
        )
    }
}

/// Solvers of the `solver` knob the matrix leaves out, and why (said in
/// its output).
pub const EXCLUDED: &[(Solver, &str)] = &[(
    Solver::Lcp,
    "lcp is an impact solver (one simultaneous solve of a set of contacts at an instant, `resolve --solver lcp`): the matrix judges resting and stacking over time, where its frictionless velocity phase is not meant to hold",
)];

/// Every solver of the `solver` knob's choice list but the [`EXCLUDED`],
/// in its order, each cold and, where the `warm_start` knob changes what
/// it does, warm too.
pub fn columns() -> Vec<Column> {
    let mut out = Vec::new();
    for &solver in Solver::VALUES {
        if EXCLUDED.iter().any(|(s, _)| *s == solver) {
            continue;
        }
        out.push(Column {
            solver,
            warm_start: false,
        });
        if warm_start_applies(solver) {
            out.push(Column {
                solver,
                warm_start: true,
            });
        }
    }
    out
}

/// Whether `warm_start` changes the solver's steps (the step reads it for
/// sequential impulses only: src/physics/step/simulation.rs).
fn warm_start_applies(solver: Solver) -> bool {
    solver == Solver::SequentialImpulse
}

/// One cell's judgement on one criterion.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    pub scene: &'static str,
    /// The criterion's row name.
    pub name: &'static str,
    /// The criterion in words.
    pub criterion: &'static str,
    pub unit: &'static str,
    pub bound: f64,
    pub solver: String,
    pub pass: bool,
    /// Not a number when there is none (the stack never separated).
    pub measured: f64,
    /// Why the run stopped early (it fails then).
    pub failure: Option<String>,
}

/// The matrix: a verdict per criterion row and column, rows in
/// [`SCENES`]' order, columns in [`columns`]' order.
#[derive(Debug, Clone, PartialEq)]
pub struct Matrix {
    pub size: Size,
    pub columns: Vec<String>,
    /// Every criterion row, row-major with the columns; `None`: not run
    /// (interrupted).
    pub cells: Vec<Vec<Option<Verdict>>>,
    /// (scene, criterion) of each row: indices into [`SCENES`] and its
    /// criteria.
    pub rows: Vec<(usize, usize)>,
    /// Cells not run (Ctrl-C), of the total.
    pub not_run: usize,
}

impl Matrix {
    /// Every verdict, row by row.
    pub fn verdicts(&self) -> impl Iterator<Item = &Verdict> {
        self.cells.iter().flatten().flatten()
    }
}

/// The lesson of `scene` at `size`.
pub fn lesson(scene: &Scene, size: Size) -> Lesson {
    let text = (scene.build)(size, scene.seconds(size));
    crate::lesson::validate::parse(scene.id, &text)
        .unwrap_or_else(|e| panic!("the verdict scene {} is a valid lesson: {e:?}", scene.id))
}

/// The configuration of `column` on `lesson`: the lesson's settings (the
/// solver's defaults) with that solver.
pub fn config(lesson: &Lesson, column: Column) -> crate::study::Config {
    let mut c = crate::study::grid::default_config(lesson).expect("a verdict scene is a scene");
    c.params.resolver.solver = column.solver;
    c.params.resolver.warm_start = column.warm_start;
    c
}

/// Runs one cell: `scene` under `column`; `None` when stopped first.
pub fn cell(
    scene: &'static Scene,
    lesson: &Lesson,
    size: Size,
    column: Column,
    stop: &AtomicBool,
) -> Option<Vec<Verdict>> {
    let c = config(lesson, column);
    let steps = crate::study::run::steps(scene.seconds(size), c.params.dt);
    let r = record::run(lesson, &c, steps, scene.penetration, stop)?;
    Some(
        scene
            .criteria
            .iter()
            .map(|k| {
                let measured = (k.measure)(&r);
                Verdict {
                    scene: scene.id,
                    name: k.name,
                    criterion: k.text,
                    unit: k.unit,
                    bound: k.bound,
                    solver: column.label(),
                    pass: r.failure.is_none() && measured <= k.bound,
                    measured,
                    failure: r.failure.clone(),
                }
            })
            .collect(),
    )
}

/// Runs the matrix on `threads` threads (at least one); `done(cells done,
/// cells, the scene just done)` after each cell; `stop` (Ctrl-C) leaves
/// the cells not begun, and the one running, not run.
pub fn run(
    size: Size,
    threads: usize,
    stop: &AtomicBool,
    done: &(dyn Fn(usize, usize, &str) + Sync),
) -> Matrix {
    let columns = columns();
    let lessons: Vec<Lesson> = SCENES.iter().map(|s| lesson(s, size)).collect();
    let n = SCENES.len() * columns.len();
    // The dearest cells first (bodies × seconds), so the last cell to
    // finish is a cheap one; results go by index, so the order is not seen.
    let mut order: Vec<usize> = (0..n).collect();
    let weight = |i: usize| {
        let s = i / columns.len();
        lessons[s].bodies.len() as f64 * SCENES[s].seconds(size)
    };
    order.sort_by(|a, b| weight(*b).total_cmp(&weight(*a)).then(a.cmp(b)));
    let results: Mutex<Vec<Option<Vec<Verdict>>>> = Mutex::new(vec![None; n]);
    let next = AtomicUsize::new(0);
    let finished = AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..threads.max(1).min(n) {
            s.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                if k >= n || stop.load(Ordering::SeqCst) {
                    break;
                }
                let i = order[k];
                let scene = &SCENES[i / columns.len()];
                let column = columns[i % columns.len()];
                let Some(v) = cell(scene, &lessons[i / columns.len()], size, column, stop) else {
                    break;
                };
                if let Ok(mut r) = results.lock() {
                    r[i] = Some(v);
                }
                done(finished.fetch_add(1, Ordering::SeqCst) + 1, n, scene.id);
            });
        }
    });
    let results = results.into_inner().unwrap_or_default();
    let not_run = results.iter().filter(|r| r.is_none()).count();
    let mut rows = Vec::new();
    let mut cells = Vec::new();
    for (s, scene) in SCENES.iter().enumerate() {
        for k in 0..scene.criteria.len() {
            rows.push((s, k));
            cells.push(
                (0..columns.len())
                    .map(|c| {
                        results[s * columns.len() + c]
                            .as_ref()
                            .map(|v| v[k].clone())
                    })
                    .collect(),
            );
        }
    }
    Matrix {
        size,
        columns: columns.iter().map(Column::label).collect(),
        cells,
        rows,
        not_run,
    }
}
