//! The scene screens driven by scripted keys into a `TestBackend`: a scene
//! played to an event, its step's resolver iterations, an iteration's
//! contact and back up (snapshots at 100×30 and 80×24); playback on ticks;
//! stepping back over kept frames; clicks and the wheel; every scene and
//! lesson drawing every screen at sizes from 1×1 to 200×60.

use crate::common;
use crate::common::tui::{self as tui_helpers, draw, find, key, keys, snapshot, term, text};

use contact_lab::tui::screens::{Screen, RESOLVER_KEYS, RUN_KEYS};
use contact_lab::tui::{self, App, Theme};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::Terminal;

fn open(lesson: &str) -> App {
    let mut a = tui::open(Some(lesson), None).expect("opens");
    a.theme = Theme { color: true };
    a
}

fn frame(app: &App) -> usize {
    app.run.as_ref().expect("a run").frame
}

/// stack-5 → the first step a box falls asleep → that step's velocity
/// iteration 12 → its contact, on the impulse stage.
#[test]
fn from_a_frame_to_a_contacts_stage_and_back_up() {
    for (w, h) in [(100, 30), (80, 24)] {
        let mut t = term(w, h);
        let mut a = open("stack-5");
        assert_eq!(a.screen, Screen::Run);
        keys(&mut a, KeyCode::Char('f'), 3); // jump to: sleep
        key(&mut a, KeyCode::Char('n'));
        let step = frame(&a);
        let ev = &a.run.as_ref().unwrap().player.run.events;
        assert!(ev
            .iter()
            .any(|e| e.step as usize == step && e.kind == "sleep"));
        assert!(!ev
            .iter()
            .any(|e| (e.step as usize) < step && e.kind == "sleep"));
        draw(&mut t, &a);
        snapshot(&format!("tui_scene_run_{w}x{h}"), &t);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.screen, Screen::Resolver);
        let r = a.resolver.as_ref().unwrap();
        assert_eq!(r.trace.step as usize, step);
        assert!(r.trace.resolver.velocity.limit_reached);
        let to = r.trace.velocity_start() + 12;
        keys(&mut a, KeyCode::Right, to);
        draw(&mut t, &a);
        let crumb = contact_lab::tui::screens::breadcrumb(&a);
        assert!(
            crumb.starts_with("stack-5 › t = ")
                && crumb.ends_with(&format!(", step {step} › velocity iteration 12")),
            "{crumb}"
        );
        snapshot(&format!("tui_scene_resolver_{w}x{h}"), &t);
        // The contact the iteration takes is selected; Enter opens its stages.
        let r = a.resolver.as_ref().unwrap();
        let taken = r.trace.resolver.velocity.log[12].contact;
        assert_eq!(r.selected, taken);
        key(&mut a, KeyCode::Enter);
        assert_eq!((a.screen, a.contact), (Screen::Contact, taken));
        keys(&mut a, KeyCode::Right, 4);
        draw(&mut t, &a);
        let crumb = contact_lab::tui::screens::breadcrumb(&a);
        assert!(
            crumb.ends_with(&format!(
                "velocity iteration 12 › contact {taken} › impulse"
            )),
            "{crumb}"
        );
        snapshot(&format!("tui_scene_contact_{w}x{h}"), &t);
        // Issue 28: the stage keeps its capital Δ in the breadcrumb.
        key(&mut a, KeyCode::Left);
        let crumb = contact_lab::tui::screens::breadcrumb(&a);
        assert!(crumb.ends_with(" › desired Δv"), "{crumb}");
        // Up: the same iteration, then the same frame.
        key(&mut a, KeyCode::Esc);
        assert_eq!(a.screen, Screen::Resolver);
        assert_eq!(a.resolver.as_ref().unwrap().stop, to);
        key(&mut a, KeyCode::Backspace);
        assert_eq!((a.screen, frame(&a)), (Screen::Run, step));
        assert!(!a.quit);
    }
}

#[test]
fn the_opened_contact_has_the_bodies_as_the_iteration_finds_them() {
    let mut a = open("stack-5");
    keys(&mut a, KeyCode::Right, 40);
    key(&mut a, KeyCode::Enter);
    let r = a.resolver.as_ref().unwrap();
    let stop = r.trace.velocity_start() + 3;
    let views = r.trace.bodies_at(stop);
    let taken = r.trace.tables[stop]
        .next
        .expect("an iteration at this stop");
    keys(&mut a, KeyCode::Right, stop);
    key(&mut a, KeyCode::Enter);
    let lesson = &a.entry().lesson;
    for (def, v) in lesson.bodies.iter().zip(&views) {
        assert_eq!(<[f64; 3]>::from(def.velocity), v.velocity, "{}", def.name);
    }
    assert_eq!(a.trace.contact, taken);
    // The scene's own lesson keeps its values.
    assert_eq!(a.lessons[a.lesson].lesson.contacts.len(), 0);
}

#[test]
fn playback_runs_on_ticks_at_the_chosen_speed_and_steps_back_instantly() {
    let mut a = open("stack-5");
    let dt = 1.0 / 60.0;
    a.tick(dt);
    assert_eq!(frame(&a), 0, "paused: a tick does nothing");
    key(&mut a, KeyCode::Char(' '));
    assert!(a.playing());
    for _ in 0..10 {
        a.tick(dt);
    }
    assert_eq!(frame(&a), 10);
    key(&mut a, KeyCode::Char('+'));
    for _ in 0..10 {
        a.tick(dt);
    }
    assert_eq!(frame(&a), 30, "2× takes two steps a tick");
    keys(&mut a, KeyCode::Char('-'), 3);
    for _ in 0..8 {
        a.tick(dt);
    }
    assert_eq!(frame(&a), 32, "¼× takes a step every four ticks");
    key(&mut a, KeyCode::Char(' '));
    assert!(!a.playing());
    keys(&mut a, KeyCode::Left, 12);
    assert_eq!(frame(&a), 20);
    assert_eq!(
        a.run.as_ref().unwrap().player.computed(),
        32,
        "kept, not recomputed"
    );
    keys(&mut a, KeyCode::Right, 2);
    assert_eq!(frame(&a), 22);
    key(&mut a, KeyCode::Char('g'));
    assert_eq!(frame(&a), 0);
    key(&mut a, KeyCode::End);
    assert_eq!(frame(&a), 32);
    // Step 0 has nothing resolved: Enter says so and stays.
    key(&mut a, KeyCode::Home);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Run);
    assert!(a.status.as_ref().unwrap().text.contains("step 0"));
}

#[test]
fn clicks_select_table_rows_and_contacts_in_the_picture() {
    let mut a = open("sphere-row");
    assert_eq!(
        a.screen,
        Screen::Resolver,
        "several contacts: the resolver first"
    );
    let mut t = term(100, 30);
    draw(&mut t, &a);
    let click = |a: &mut App, column: u16, row: u16| {
        a.mouse(MouseEvent {
            kind: MouseEventKind::Down(MouseButton::Left),
            column,
            row,
            modifiers: KeyModifiers::NONE,
        })
    };
    let table = a.targets.table.get();
    click(&mut a, table.x + 4, table.y + 2 + 3);
    assert_eq!(a.resolver.as_ref().unwrap().selected, 3);
    // Contact 1's point, where the picture put it.
    let r = a.resolver.as_ref().unwrap();
    assert_ne!(r.selected, 1);
    let q = r.trace.contact_views(0)[1].point;
    let area = a.targets.picture.get();
    let [x0, x1, y0, y1] = a.targets.bounds.get();
    let col = area.x + ((q[0] - x0) / (x1 - x0) * f64::from(area.width)) as u16;
    let row = area.y + ((y1 - q[1]) / (y1 - y0) * f64::from(area.height)) as u16;
    click(&mut a, col, row);
    assert_eq!(a.resolver.as_ref().unwrap().selected, 1);
    key(&mut a, KeyCode::Enter);
    assert_eq!((a.screen, a.contact), (Screen::Contact, 1));
    // The wheel scrolls the stage panel there.
    draw(&mut t, &a);
    a.mouse(MouseEvent {
        kind: MouseEventKind::ScrollDown,
        column: 50,
        row: 10,
        modifiers: KeyModifiers::NONE,
    });
    assert!(a.scroll <= a.scroll_max.get());
}

#[test]
fn help_lists_each_screens_keys_and_the_readme_has_them() {
    let readme = concat!(
        include_str!("../../README.md"),
        include_str!("../../docs/tui.md")
    );
    for (lesson, list) in [("stack-5", RUN_KEYS), ("box-stack", RESOLVER_KEYS)] {
        let mut a = open(lesson);
        key(&mut a, KeyCode::Char('?'));
        let mut t = term(100, 30);
        draw(&mut t, &a);
        let shown = text(t.backend().buffer());
        for (k, what) in contact_lab::tui::keys::help(list) {
            assert!(shown.contains(k), "{lesson}: help lacks {k}\n{shown}");
            assert!(
                readme.contains(&format!("| {k} | {what} |")),
                "README and docs/tui.md lack {k}"
            );
        }
        key(&mut a, KeyCode::Char('x'));
        assert_eq!(a.mode, contact_lab::tui::app::Mode::Normal);
    }
}

#[test]
fn a_scene_takes_no_contact_number() {
    let e = tui::open(Some("stack-5"), Some(0)).expect_err("refused");
    assert!(e.to_string().contains("is a scene"), "{e}");
}

const SIZES: [(u16, u16); 8] = [
    (1, 1),
    (10, 5),
    (40, 12),
    (60, 18),
    (80, 24),
    (100, 30),
    (140, 45),
    (200, 60),
];

fn every_size(t: &mut Terminal<TestBackend>, a: &App) {
    for (w, h) in SIZES {
        t.backend_mut().resize(w, h);
        draw(t, a);
    }
}

#[test]
fn every_scene_draws_every_screen_at_every_size() {
    let mut t = term(1, 1);
    for id in contact_lab::lesson::embedded::scene_ids() {
        let mut a = open(id);
        every_size(&mut t, &a);
        for toggle in ['c', 'o', 's', 'b', 'v'] {
            key(&mut a, KeyCode::Char(toggle));
        }
        keys(&mut a, KeyCode::Right, 3);
        every_size(&mut t, &a);
        key(&mut a, KeyCode::Char('?'));
        every_size(&mut t, &a);
        key(&mut a, KeyCode::Esc);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.screen, Screen::Resolver, "{id}");
        every_size(&mut t, &a);
        key(&mut a, KeyCode::End);
        every_size(&mut t, &a);
        key(&mut a, KeyCode::Enter);
        if a.screen == Screen::Contact {
            every_size(&mut t, &a);
            keys(&mut a, KeyCode::Right, 4);
            every_size(&mut t, &a);
            key(&mut a, KeyCode::Esc);
        }
        key(&mut a, KeyCode::Esc);
        assert_eq!(a.screen, Screen::Run, "{id}");
        assert!(!a.quit);
    }
}

#[test]
fn every_lesson_with_several_contacts_draws_its_resolver_at_every_size() {
    let mut t = term(1, 1);
    for lesson in common::all_lessons() {
        let mut a = open(&lesson.id);
        if lesson.contacts.len() < 2 {
            assert_eq!(a.screen, Screen::Contact, "{}", lesson.id);
            continue;
        }
        assert_eq!(a.screen, Screen::Resolver, "{}", lesson.id);
        every_size(&mut t, &a);
        keys(&mut a, KeyCode::Right, 3);
        key(&mut a, KeyCode::Tab);
        every_size(&mut t, &a);
        key(&mut a, KeyCode::End);
        every_size(&mut t, &a);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.screen, Screen::Contact);
        every_size(&mut t, &a);
        key(&mut a, KeyCode::Esc);
        assert_eq!(a.screen, Screen::Resolver);
        key(&mut a, KeyCode::Esc);
        assert!(a.quit, "Esc at the top quits, as it always has");
    }
}

/// Opens the edit form on the field labelled `label`, types `value`, sets
/// it and closes the form; returns what the status line said.
fn edit(app: &mut App, label: &str, value: &str) -> String {
    tui_helpers::edit(app, label, value);
    let said = app.status.clone().expect("said").text;
    key(app, KeyCode::Esc);
    said
}

#[test]
fn an_edit_on_a_scenes_contact_computes_the_run_again_from_that_step() {
    let mut a = open("stack-5");
    keys(&mut a, KeyCode::Right, 50);
    keys(&mut a, KeyCode::Left, 10);
    let before = a.run.as_ref().unwrap().player.run.clone();
    assert_eq!(before.frames.len(), 51);
    key(&mut a, KeyCode::Enter);
    let start = a.resolver.as_ref().unwrap().trace.velocity_start();
    keys(&mut a, KeyCode::Right, start);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Contact);
    let (b1, _) = a.entry().lesson.contacts[a.contact].bodies;
    let name = a.entry().lesson.bodies[b1].name.clone();
    let status = edit(&mut a, &format!("{name}: velocity"), "0, 3, 0");
    assert!(
        status.contains("the run is computed again from step 40"),
        "{status}"
    );
    let run = &a.run.as_ref().unwrap().player;
    assert_eq!(run.computed(), 40, "computed again up to the step edited");
    assert_eq!(
        run.run.frames[..40],
        before.frames[..40],
        "earlier frames kept"
    );
    let (now, then) = (
        &run.run.frames[40].bodies[b1],
        &before.frames[40].bodies[b1],
    );
    assert!(
        now.velocity[1] > then.velocity[1] + 0.2,
        "{now:?} vs {then:?}"
    );
    // The resolution recorded again: up, it is the new one.
    key(&mut a, KeyCode::Esc);
    let r = a.resolver.as_ref().unwrap();
    assert_eq!(r.trace.step, 40);
    assert!(r.stop < r.trace.tables.len());
    // A field that is no input of the run says so and changes nothing.
    key(&mut a, KeyCode::Enter);
    let status = edit(&mut a, "penetration", "0.5");
    assert!(status.contains("the run is unchanged"), "{status}");
    assert_eq!(a.run.as_ref().unwrap().player.computed(), 40);
}

#[test]
fn highlighting_marks_the_next_contact_the_changes_and_sleeping_bodies() {
    use ratatui::style::{Color, Modifier};
    let mut a = open("box-four-corners");
    key(&mut a, KeyCode::Right);
    let mut t = term(100, 30);
    draw(&mut t, &a);
    let r = a.resolver.as_ref().unwrap();
    let table = r.trace.tables[1].clone();
    let buf = t.backend().buffer();
    // The contact the next iteration takes: ▶ in the impulse's red.
    let next = table.next.expect("an iteration follows");
    let label = &r.trace.names.contacts[next];
    let (x, y) = find(
        buf,
        &format!("▶ {}", &label[..label.find(':').unwrap() + 1]),
    );
    assert_eq!(buf[(x, y)].fg, Color::Red);
    // A value the last iteration changed, and its change, highlighted.
    let (k, from, to) = table.changed[0];
    let f = contact_lab::format::Fmt::new(4);
    let row = find(buf, &format!("{}: ", k)).1;
    let (x, y) = find(buf, &f.num(to - from).to_string());
    assert_eq!(y, row);
    assert_eq!(buf[(x, y)].fg, Color::Yellow);
    assert!(buf[(x, y)].modifier.contains(Modifier::UNDERLINED));
    // Sleeping bodies: dimmed and named so.
    let mut a = open("stack-5");
    keys(&mut a, KeyCode::Char('f'), 3);
    key(&mut a, KeyCode::Char('n'));
    draw(&mut t, &a);
    let buf = t.backend().buffer();
    let (x, y) = find(buf, "box1 (asleep)");
    assert_eq!(buf[(x, y)].fg, Color::DarkGray);
    let (x, y) = find(buf, "box5");
    assert_eq!(buf[(x, y)].fg, Color::White);
    key(&mut a, KeyCode::Char('s'));
    draw(&mut t, &a);
    assert!(
        !text(t.backend().buffer()).contains("(asleep)"),
        "s hides the sleep state"
    );
}

#[test]
fn the_run_and_resolver_tables_dispatch_their_keys() {
    use contact_lab::tui::keys::find;
    // A key bound twice in one table would make its second row a lie.
    for table in [RUN_KEYS, RESOLVER_KEYS] {
        let mut seen = Vec::new();
        for row in table {
            for (code, bound) in row.keys {
                assert!(!seen.contains(code), "{code:?} bound twice");
                seen.push(*code);
                assert_eq!(find(table, *code), Some(*bound), "{}", row.label);
            }
        }
    }
}

/// The run screen's key bar names the detection key and all five picture
/// toggles (m, the movement bounds, was in the help only); at 80 columns the
/// bar drops middle entries but keeps help and quit.
#[test]
fn the_run_key_bar_names_detection_and_every_picture_toggle() {
    let a = open("stack-5");
    let rows = tui_helpers::screen(&a, 140, 30);
    let bar = rows.last().expect("a bottom row");
    assert!(bar.contains("d detection"), "{bar}");
    assert!(bar.contains("cosbm show"), "{bar}");
    let narrow = tui_helpers::screen(&a, 80, 24);
    let bar = narrow.last().expect("a bottom row");
    assert!(bar.contains("? help") && bar.contains("q quit"), "{bar}");
}
