//! `w` keeps the context (issue 28, item 4): a file written from a scene's
//! step, at a resolver stop, is named after the scene, time, step, phase,
//! iteration and contact, and its header carries them and a command line;
//! the command, run, prints the same resolution (the same numbers).

use std::process::Command;

use crate::common::tui::{app, key, keys};
use contact_lab::format::Fmt;
use contact_lab::physics::resolver::Phase;
use contact_lab::tui::app::Mode;
use ratatui::crossterm::event::KeyCode;

#[test]
fn w_from_stack_5_step_90_velocity_iteration_0_names_the_place_and_the_command_reproduces_it() {
    let dir = crate::common::scratch("tui-write-context");
    let mut a = app("stack-5", false);
    a.write_dir = dir.clone();
    keys(&mut a, KeyCode::Right, 90);
    key(&mut a, KeyCode::Enter);
    // → through the position phase to the velocity phase's first iteration.
    for _ in 0..1000 {
        let r = a.resolver.as_ref().expect("the step's resolver");
        let stop = r.trace.tables[r.stop].stop;
        if stop.phase == Phase::Velocity && stop.iteration == 0 {
            break;
        }
        key(&mut a, KeyCode::Right);
    }
    // Contact 13 selected (Tab), opened, written.
    while a.resolver.as_ref().unwrap().selected != 13 {
        key(&mut a, KeyCode::Tab);
    }
    let (taken, before) = {
        let r = a.resolver.as_ref().unwrap();
        let t = &r.trace.tables[r.stop];
        (
            t.next.expect("velocity iteration 0 takes a contact"),
            r.trace.tables[0].penetration[13],
        )
    };
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.contact, 13);
    // Issue 28 item 5: a narrow header keeps the scene's name (the middle
    // levels give way), not just "…".
    let crumb = contact_lab::tui::screens::breadcrumb_fit(&a, 50);
    assert!(crumb.starts_with("stack-5 › … › "), "{crumb}");
    assert!(crumb.ends_with("contact 13 › overview"), "{crumb}");
    key(&mut a, KeyCode::Char('w'));
    let Mode::Write { input, .. } = &a.mode else {
        panic!("w asks for a file name")
    };
    let name = "stack-5-t1.500-step90-velocity-it0-contact-13.md";
    assert_eq!(input, name);
    key(&mut a, KeyCode::Enter);
    let text = std::fs::read_to_string(dir.join(name)).expect("written");
    assert!(
        text.contains("at `stack-5` › t = 1.500 s, step 90 › velocity iteration 0 › contact 13."),
        "{text}"
    );
    let command = text
        .lines()
        .find_map(|l| l.strip_prefix("Reproduce: `"))
        .and_then(|l| l.split('`').next())
        .expect("a command line");
    assert_eq!(command, "contact-lab simulate stack-5 --trace-step 90");
    assert!(text.contains("row `v0` for velocity iteration 0"), "{text}");
    // The command, run: the same step, the same contact table, the same
    // contact taken at v0.
    let args: Vec<&str> = command.split(' ').skip(1).collect();
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(&args)
        .output()
        .unwrap();
    assert!(out.status.success());
    let printed = String::from_utf8(out.stdout).unwrap();
    assert!(printed.starts_with("Step 90 (t = 1.5 s)"), "{printed}");
    let f = Fmt::new(6);
    let row = printed
        .lines()
        .find(|l| l.trim_start().starts_with("13: box3 ↔ box4"))
        .expect("contact 13's row");
    assert_eq!(
        row.split_whitespace().nth(4),
        Some(f.num(before).as_str()),
        "{row}"
    );
    let v0 = printed
        .lines()
        .find(|l| l.trim_start().starts_with("v0 "))
        .expect("the v0 row");
    assert!(v0.contains(&format!("contact {taken}:")), "{v0}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn w_on_a_lesson_contact_names_the_solve_command() {
    let dir = crate::common::scratch("tui-write-context-lesson");
    let mut a = app("lecture-2", false);
    a.write_dir = dir.clone();
    key(&mut a, KeyCode::Char('w'));
    key(&mut a, KeyCode::Enter);
    let text = std::fs::read_to_string(dir.join("lecture-2-contact-0.md")).expect("written");
    assert!(
        text.contains("Reproduce: `contact-lab solve lecture-2 --contact 0`."),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
