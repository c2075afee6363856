//! The resolver screen under `solver = "lcp"` (issue 43): after the
//! position phase, A and b, then each pivot of Lemke's method one at a time
//! (entering, leaving, the tableau's column, the ratio test, λ so far) with
//! the keys that step iterations, then the impulses and the bodies after.

use contact_lab::format::Fmt;
use contact_lab::tui::screens::Screen;
use contact_lab::tui::{self, App, Theme};
use ratatui::crossterm::event::KeyCode;

use crate::common::tui::{key, keys, screen};

fn open(id: &str) -> App {
    let mut a = tui::open(Some(id), None).expect("opens");
    a.theme = Theme { color: false };
    assert_eq!(a.screen, Screen::Resolver, "{id}");
    a
}

fn shown(a: &App) -> String {
    screen(a, 160, 50).join("\n")
}

/// The number of position stops (the first LCP stop's index).
fn start(a: &App) -> usize {
    a.resolver.as_ref().unwrap().trace.velocity_start()
}

#[test]
fn the_row_of_three_steps_to_pivot_2_and_shows_the_traces_pivot() {
    let mut a = open("impact-row-3");
    let f = Fmt::new(4);
    let record = a.resolver.as_ref().unwrap().trace.resolver.lcp.clone();
    let record = record.expect("the lesson is solved with lcp");
    let pivots: Vec<_> = record.pivots().map(|(_, p)| p.clone()).collect();
    assert_eq!(pivots.len(), 3, "the row of three takes three pivots");
    let s = start(&a);
    keys(&mut a, KeyCode::Right, s);
    assert_eq!(a.resolver.as_ref().unwrap().pivot, Some(0));
    let text = shown(&a);
    assert!(text.contains("A and b"), "{text}");
    assert!(
        text.contains(&format!("A = [{}]", f.list(&record.matrix[0]))),
        "{text}"
    );
    assert!(
        text.contains(&format!("b = [{}]", f.list(&record.problems[0].b))),
        "{text}"
    );
    keys(&mut a, KeyCode::Right, 3);
    assert_eq!(a.resolver.as_ref().unwrap().pivot, Some(3));
    let text = shown(&a);
    let p = &pivots[2];
    assert!(text.contains("pivot 2 of 3"), "{text}");
    let want = format!(
        "entering: {}   leaving: {} (row {})",
        p.entering.name(),
        p.leaving.name(),
        p.row
    );
    assert!(text.contains(&want), "{want}\n{text}");
    assert_eq!(
        (p.entering.name(), p.leaving.name()),
        ("lambda1".into(), "z0".into())
    );
    assert!(
        text.contains(&format!(
            "tableau column of lambda1: [{}]",
            f.list(&p.column)
        )),
        "{text}"
    );
    assert!(
        text.contains(&format!("ratio chosen: {}", f.num(p.ratio))),
        "{text}"
    );
    // z0 has left: λ so far is the answer, 4/3 and 2/3.
    assert!(
        text.contains(&format!("λ so far: [{}]", f.list(&record.impulses))),
        "{text}"
    );
    assert!(text.contains("λ so far: [1.333, 0.6667]"), "{text}");
    // Then the impulses and the bodies after; Left comes back to pivot 2.
    key(&mut a, KeyCode::Right);
    let text = shown(&a);
    assert!(text.contains("impulses applied: [1.333, 0.6667]"), "{text}");
    assert!(
        text.contains("ball0: velocity (-0.3333, 0, 0) m/s"),
        "{text}"
    );
    assert!(
        text.contains("ball2: velocity (0.6667, 0, 0) m/s"),
        "{text}"
    );
    key(&mut a, KeyCode::Left);
    assert_eq!(a.resolver.as_ref().unwrap().pivot, Some(3));
    key(&mut a, KeyCode::Home);
    let r = a.resolver.as_ref().unwrap();
    assert_eq!((r.stop, r.pivot), (0, None));
    key(&mut a, KeyCode::End);
    let r = a.resolver.as_ref().unwrap();
    assert_eq!((r.stop, r.pivot), (r.trace.tables.len() - 1, None));
}

#[test]
fn the_pivot_at_show_is_in_the_breadcrumb_and_the_note_says_what_comes_next() {
    let mut a = open("impact-row-3");
    let n = start(&a) + 1;
    keys(&mut a, KeyCode::Right, n);
    let text = shown(&a);
    assert!(text.contains("lcp pivot 0"), "{text}");
    assert!(
        text.contains("Next: pivot 1 (newton): lambda0 enters, w1 leaves (row 1)"),
        "{text}"
    );
    assert!(
        text.contains("Last: z0 entered at ratio 2, w0 left."),
        "{text}"
    );
}

/// Poisson's law solves a compression LCP (and a correcting one when
/// needed): each pivot names its problem and that problem's b.
#[test]
fn poissons_pivots_name_their_problem() {
    let mut a = open("impact-row-poisson");
    let record = a
        .resolver
        .as_ref()
        .unwrap()
        .trace
        .resolver
        .lcp
        .clone()
        .unwrap();
    let total = record.pivots().count();
    let n = start(&a) + total;
    keys(&mut a, KeyCode::Right, n);
    let text = shown(&a);
    let (stage, _) = record.pivots().last().unwrap();
    assert!(text.contains(&format!("({} LCP)", stage.name())), "{text}");
    assert!(
        text.contains(&format!("pivot {} of {total}", total - 1)),
        "{text}"
    );
}
