//! Time from a key press to a redrawn frame: the key's update (solving the
//! contact again where the key changes it) plus drawing the whole screen into
//! a `TestBackend` buffer. One 60 Hz frame is 16.7 ms; playback must advance
//! a step and redraw the run screen in under 5 ms. Also: opening a frame's
//! resolver screen (recording that step again from the nearest checkpoint).

use contact_lab::tui::{self, App, Theme};
use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

fn app(lesson: &str) -> App {
    let (lessons, at) = tui::lessons(Some(lesson)).unwrap();
    App::new(lessons, at, 0, Theme { color: true })
}

fn press(app: &mut App, code: KeyCode) {
    app.key(KeyEvent::new(code, KeyModifiers::NONE));
}

/// An app in the edit form with `value` typed for the field at `row`: the
/// next Enter sets it and solves again.
fn typed(lesson: &str, row: usize, value: &str) -> App {
    let mut a = app(lesson);
    press(&mut a, KeyCode::Char('e'));
    for _ in 0..row {
        press(&mut a, KeyCode::Down);
    }
    press(&mut a, KeyCode::Enter);
    a.key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
    for c in value.chars() {
        press(&mut a, KeyCode::Char(c));
    }
    a
}

fn key_to_frame(c: &mut Criterion, name: &str, start: App, key: KeyCode, size: (u16, u16)) {
    let mut term = Terminal::new(TestBackend::new(size.0, size.1)).unwrap();
    term.draw(|f| f.render_widget(&start, f.area())).unwrap();
    c.bench_function(name, |b| {
        b.iter_batched(
            || start.clone(),
            |mut a| {
                press(&mut a, key);
                term.draw(|f| f.render_widget(&a, f.area())).unwrap();
                a
            },
            BatchSize::SmallInput,
        )
    });
}

fn benches(c: &mut Criterion) {
    let mut on_impulse = app("lecture-2");
    for _ in 0..3 {
        press(&mut on_impulse, KeyCode::Right);
    }
    key_to_frame(
        c,
        "key → frame: next stage (lecture-2, 100×30)",
        on_impulse,
        KeyCode::Right,
        (100, 30),
    );
    key_to_frame(
        c,
        "key → frame: set restitution 0.5, solve again (lecture-2, 100×30)",
        typed("lecture-2", 0, "0.5"),
        KeyCode::Enter,
        (100, 30),
    );
    key_to_frame(
        c,
        "key → frame: set μ_s 0.3, solve again with friction (two-boxes, 100×30)",
        typed("two-boxes", 1, "0.3"),
        KeyCode::Enter,
        (100, 30),
    );
    key_to_frame(
        c,
        "key → frame: next lesson, solve (lecture-2 → lecture-3, 200×60)",
        app("lecture-2"),
        KeyCode::Down,
        (200, 60),
    );
}

/// stack-5 on its run screen, `steps` steps played (all of them computed).
fn played(steps: usize) -> App {
    let mut a = tui::open(Some("stack-5"), None).unwrap();
    a.theme = Theme { color: true };
    for _ in 0..steps {
        press(&mut a, KeyCode::Right);
    }
    a
}

fn scenes(c: &mut Criterion) {
    // → on the last computed frame computes the next step, then the redraw.
    for size in [(100, 30), (200, 60)] {
        key_to_frame(
            c,
            &format!(
                "run screen: advance one step + redraw (stack-5 at step 90, {}×{})",
                size.0, size.1
            ),
            played(90),
            KeyCode::Right,
            size,
        );
    }
    // Enter on a frame: record its step again from the nearest checkpoint
    // and draw it. The best case replays no step; the worst CHECKPOINT − 1.
    let k = contact_lab::session::CHECKPOINT as usize;
    for (step, replayed) in [(12 * k + 1, 0), (16 * k, k - 1)] {
        key_to_frame(
            c,
            &format!(
                "open a frame's resolver screen (stack-5 step {step}, {replayed} steps replayed, 100×30)"
            ),
            played(step),
            KeyCode::Enter,
            (100, 30),
        );
    }
}

criterion_group!(tui_benches, benches, scenes);
criterion_main!(tui_benches);
