//! One lesson contact solved N times, for callgrind: the stage maths
//! (`solve_stages`, or `solve_stages_into` one `Stages` the loop holds),
//! the stages with their checks (`solve`) or the worked solution with its
//! trace (`worked_solution`).
//!
//! `cargo build --release --features measure --example one_contact`, then
//! `valgrind --tool=callgrind target/release/examples/one_contact stages lecture-2 0 1000`
//! and the same with 0 iterations: the difference / 1000 is one solve.

use std::hint::black_box;

use contact_lab::lesson::Lesson;
use contact_lab::physics::solve::{solve, solve_stages, solve_stages_into, Stages};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [what, id, k, n] = args.as_slice() else {
        panic!("usage: one_contact stages|into|checked|trace LESSON K N");
    };
    let (k, n): (usize, usize) = (k.parse().unwrap(), n.parse().unwrap());
    let lesson = Lesson::load(id).unwrap();
    let problem = lesson.problem::<f64>(k);
    let mut held = Stages::empty();
    for _ in 0..n {
        match what.as_str() {
            "stages" => drop(black_box(solve_stages(black_box(&problem)))),
            "into" => {
                solve_stages_into(black_box(&problem), &mut held);
                black_box(&mut held);
            }
            "checked" => drop(black_box(solve(black_box(&problem)))),
            "trace" => drop(black_box(contact_lab::worked_solution(
                black_box(&lesson),
                k,
            ))),
            _ => panic!("stages, into, checked or trace"),
        }
    }
}
