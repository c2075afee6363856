//! The interactive terminal app (ratatui + crossterm), TEA style:
//! [`app`] holds the state and its update, [`router`] hands each key to the
//! screen on show (and handles the keys every screen has), [`ui`] draws it,
//! [`event`] reads the terminal. It reads only the trace: no physics here.

pub mod answer;
pub mod app;
mod edited;
pub mod event;
pub mod form;
pub mod keys;
mod lists;
pub(crate) mod more;
mod overlay;
pub mod picker;
pub(crate) mod quit;
mod router;
pub mod scene;
pub mod screens;
pub mod stage;
pub mod theme;
pub mod ui;
pub mod wrap;
pub mod write;
mod write_context;

use std::ffi::OsStr;

use crate::error::AppError;
use crate::lesson::{embedded, Lesson};
pub use app::App;
pub use theme::Theme;

/// The embedded lessons and scenes, plus `lesson` when it names a file;
/// returns them and the index to open. Student lessons come first, then the
/// robustness lessons (`extreme-*`), then the scenes ([`group`] names them).
pub fn lessons<N: AsRef<OsStr> + ?Sized>(
    lesson: Option<&N>,
) -> Result<(Vec<Lesson>, usize), AppError> {
    let (extreme, student): (Vec<&str>, Vec<&str>) = embedded::ids()
        .into_iter()
        .partition(|id| id.starts_with("extreme-"));
    let mut all: Vec<Lesson> = student
        .into_iter()
        .chain(extreme)
        .chain(embedded::scene_ids())
        .map(Lesson::load)
        .collect::<Result<_, _>>()
        .map_err(|e| AppError::Runtime(format!("an embedded lesson is invalid: {e}")))?;
    let at = match lesson.map(AsRef::as_ref) {
        None => all.iter().position(|l| l.id == "lecture-2").unwrap_or(0),
        Some(name) => match all
            .iter()
            .position(|l| name.to_str() == Some(l.id.as_str()))
        {
            Some(i) => i,
            None => {
                all.push(Lesson::load(name)?);
                all.len() - 1
            }
        },
    };
    Ok((all, at))
}

/// The heading of the list group lesson `l` belongs to.
pub fn group(l: &Lesson) -> &'static str {
    if l.simulation.is_some() {
        "Scenes (in time)"
    } else if l.id.starts_with("extreme-") {
        "Robustness (extreme-*)"
    } else {
        "Lessons"
    }
}

/// The app on `lesson` (embedded id or path; lecture-2 when `None`): a
/// scene on its run; contact `contact`'s stages when given; else a lesson
/// with several contacts on its resolver iterations, one with one contact
/// on its stages.
pub fn open<N: AsRef<OsStr> + ?Sized>(
    lesson: Option<&N>,
    contact: Option<usize>,
) -> Result<App, AppError> {
    let (all, at) = lessons(lesson)?;
    let n = all[at].contacts.len();
    let scene = all[at].simulation.is_some();
    match contact {
        Some(k) if scene => {
            return Err(AppError::Usage(format!(
                "--contact {k}: '{}' is a scene: its contacts are generated at each step (open a step's resolver iterations with Enter)",
                all[at].id
            )))
        }
        Some(k) if k >= n => {
            return Err(AppError::Usage(format!(
                "--contact {k}: lesson '{}' has {n} contact(s), numbered from 0",
                all[at].id
            )))
        }
        _ => {}
    }
    let mut app = App::new(all, at, contact.unwrap_or(0), Theme::from_env());
    if contact.is_none() && !scene {
        app.open_lesson_screen(true);
    }
    app.write_dir = std::env::current_dir().unwrap_or_else(|_| ".".into());
    Ok(app)
}

/// Runs the app until the user quits; the terminal is restored on return,
/// on error, on panic (ratatui's hook) and on the signals that end a
/// program (SIGTERM, SIGHUP, SIGINT, SIGQUIT: the app stops at once, restores
/// the terminal, then dies of the same signal, as its parent expects).
pub fn run(mut app: App) -> Result<(), AppError> {
    let signal = signals::watch()?;
    signals::watchdog(std::sync::Arc::clone(&signal));
    let mut terminal = ratatui::try_init().map_err(|e| {
        // Raw mode may be on although the alternate screen failed.
        ratatui::restore();
        AppError::Runtime(format!("cannot open the terminal: {e}"))
    })?;
    // Mouse reports off again however the app ends (the panic hook first).
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        mouse(false);
        show_cursor();
        hook(info)
    }));
    mouse(true);
    let result = run_loop(&mut terminal, &mut app, &signal);
    mouse(false);
    ratatui::restore();
    // The terminal shows the cursor again when it is dropped; a signal ends
    // the process before that, so it is shown here on every path.
    show_cursor();
    signals::end_if_signalled(&signal);
    result.map_err(|e| AppError::Runtime(format!("terminal: {e}")))
}

/// Switches the terminal's mouse reports on or off.
fn mouse(on: bool) {
    use ratatui::crossterm::event::{DisableMouseCapture, EnableMouseCapture};
    let mut out = std::io::stdout();
    let _ = if on {
        ratatui::crossterm::execute!(out, EnableMouseCapture)
    } else {
        ratatui::crossterm::execute!(out, DisableMouseCapture)
    };
}

/// Shows the cursor the frames hid (`ESC [ ? 25 h`).
fn show_cursor() {
    use ratatui::crossterm::cursor::Show;
    let _ = ratatui::crossterm::execute!(std::io::stdout(), Show);
}

/// Playback redraws at 60 frames per second.
const TICK: std::time::Duration = std::time::Duration::from_micros(16_667);

fn run_loop(
    terminal: &mut ratatui::DefaultTerminal,
    app: &mut App,
    signal: &std::sync::atomic::AtomicUsize,
) -> std::io::Result<()> {
    while !app.quit {
        terminal.draw(|f| f.render_widget(&*app, f.area()))?;
        // Test builds only: prove the terminal is restored when the app panics.
        #[cfg(debug_assertions)]
        if std::env::var_os("CONTACT_LAB_TEST_PANIC").is_some() {
            panic!("CONTACT_LAB_TEST_PANIC: a deliberate panic after the first frame");
        }
        let tick = app.playing().then_some(TICK);
        match event::next(signal, tick)? {
            Some(event::Event::Key(k)) => app.key(k),
            Some(event::Event::Mouse(m)) => app.mouse(m),
            Some(event::Event::Tick(seconds)) => app.tick(seconds),
            Some(event::Event::Resize) => {}
            None => break,
        }
    }
    Ok(())
}

/// The signals that end the app, caught so that the terminal is restored first.
mod signals {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;

    use crate::error::AppError;

    /// A flag the handlers set to the signal's number.
    #[cfg(unix)]
    pub fn watch() -> Result<Arc<AtomicUsize>, AppError> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
        let flag = Arc::new(AtomicUsize::new(0));
        for sig in [SIGTERM, SIGHUP, SIGINT, SIGQUIT] {
            signal_hook::flag::register_usize(sig, Arc::clone(&flag), sig as usize)
                .map_err(|e| AppError::Runtime(format!("cannot watch signal {sig}: {e}")))?;
        }
        Ok(flag)
    }

    #[cfg(not(unix))]
    pub fn watch() -> Result<Arc<AtomicUsize>, AppError> {
        Ok(Arc::new(AtomicUsize::new(0)))
    }

    /// A signalled app whose loop does not end is ended anyway: a second
    /// after the signal this thread ends the process by it. (A terminal that
    /// hung up keeps the terminal library reading end-of-file, holding its
    /// locks, and never returns to the loop; such a terminal is gone, so
    /// there is nothing to restore.)
    pub fn watchdog(flag: Arc<AtomicUsize>) {
        std::thread::spawn(move || loop {
            std::thread::sleep(std::time::Duration::from_millis(100));
            if flag.load(Ordering::Relaxed) != 0 {
                std::thread::sleep(std::time::Duration::from_secs(1));
                restore_directly();
                end_if_signalled(&flag);
            }
        });
    }

    /// The loop did not come back to restore the terminal: raw mode off,
    /// and the escape codes that end mouse reports and the alternate screen
    /// and show the cursor written to the terminal device itself (standard
    /// output's lock may be held by the stuck loop). Errors are ignored: a
    /// terminal that hung up has nothing left to restore.
    fn restore_directly() {
        use std::io::Write;
        let _ = ratatui::crossterm::terminal::disable_raw_mode();
        if let Ok(mut tty) = std::fs::OpenOptions::new().write(true).open("/dev/tty") {
            let _ = tty.write_all(
                b"\x1b[?1000l\x1b[?1002l\x1b[?1003l\x1b[?1015l\x1b[?1006l\x1b[?1049l\x1b[?25h",
            );
        }
    }

    /// After the terminal is restored: end the process by the signal that
    /// stopped the app (its default action), if one did.
    pub fn end_if_signalled(flag: &AtomicUsize) {
        let sig = flag.load(Ordering::Relaxed);
        if sig == 0 {
            return;
        }
        #[cfg(unix)]
        {
            let _ = signal_hook::low_level::emulate_default_handler(sig as i32);
        }
        std::process::exit(128 + sig as i32);
    }
}
