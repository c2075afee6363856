//! Progress on a terminal for the long commands (`simulate`, `study`,
//! `resolve`): an estimate up front and a bar with the time left, on stderr
//! and only when stderr is a terminal (a script's output stays clean); and
//! the work caps beyond which a command asks for `--force`.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use crate::error::AppError;

/// `simulate`: steps × movable bodies beyond which `--force` is asked for.
pub const SIMULATE_WORK_CAP: u64 = 100_000_000;
/// `study`: configurations beyond which `--force` is asked for.
pub const STUDY_CONFIGURATIONS_CAP: u64 = 2_000;
/// `study`: simulated steps (every configuration, timing repeats included).
pub const STUDY_STEPS_CAP: u64 = 10_000_000;
/// `resolve`: contacts from which a spinner shows that it is working.
pub const RESOLVE_SPINNER_FROM: usize = 10_000;

/// The refusal of work beyond a cap: what was asked, the cap, and `--force`.
pub fn beyond_cap(what: String, cap: &str) -> AppError {
    AppError::Usage(format!(
        "{what}, over the cap of {cap}: this may take very long; add --force to run it anyway"
    ))
}

/// A bar of `total` units (`unit` names them), drawn on stderr when it is a
/// terminal, with the time elapsed and an estimate of the time left; hidden
/// otherwise. `plan` is said first, on its own line (the estimate up front).
pub fn bar(total: u64, unit: &str, plan: &str) -> Progress {
    let terminal = std::io::stderr().is_terminal();
    let target = if terminal {
        eprintln!("{plan}");
        ProgressDrawTarget::stderr_with_hz(10)
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(Some(total), target);
    // Redrawn on its own thread too: a step that takes long still shows
    // the time going by.
    if terminal {
        bar.enable_steady_tick(Duration::from_millis(250));
    }
    bar.set_style(
        ProgressStyle::with_template(&format!(
            "{{bar:40}} {{pos}}/{{len}} {unit} · {{msg}} · {{elapsed}} elapsed, about {{eta}} left"
        ))
        .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    Progress {
        bar,
        last: Instant::now(),
    }
}

/// Ctrl-C as a request: the first sets the flag returned (a long command
/// checks it between its units of work, stops there and ends its output
/// cleanly); a second, with the flag still set, ends the process at once
/// (exit 130). The handlers are installed once per process; each call
/// clears the flag.
pub fn interrupted() -> &'static std::sync::atomic::AtomicBool {
    let flag = flag();
    flag.store(false, std::sync::atomic::Ordering::SeqCst);
    flag
}

/// [`interrupted`], and the resolutions of this thread stop once it is set
/// ([`crate::physics::resolver::stop`]): a step Ctrl-C lands in ends within
/// a thousand iterations, and the caller discards it (a pile of 1,000
/// coincident spheres takes minutes a step).
pub fn interrupted_mid_step() -> &'static std::sync::atomic::AtomicBool {
    let flag = interrupted();
    crate::physics::resolver::stop::watch(std::sync::Arc::clone(self::flag()));
    flag
}

/// The Ctrl-C flag, its handlers installed on first use.
fn flag() -> &'static std::sync::Arc<std::sync::atomic::AtomicBool> {
    use std::sync::atomic::AtomicBool;
    use std::sync::{Arc, OnceLock};
    static FLAG: OnceLock<Arc<AtomicBool>> = OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        #[cfg(unix)]
        {
            use signal_hook::consts::SIGINT;
            let _ =
                signal_hook::flag::register_conditional_shutdown(SIGINT, 130, Arc::clone(&flag));
            let _ = signal_hook::flag::register(SIGINT, Arc::clone(&flag));
        }
        flag
    })
}

/// Ctrl-C ends the process at once with exit code 130: for a command
/// whose output is written only at its end (`detect`, `resolve`), so there
/// is nothing to end cleanly. Installed once per process.
pub fn exit_on_interrupt() {
    #[cfg(unix)]
    {
        use std::sync::atomic::AtomicBool;
        use std::sync::{Arc, Once};
        static ONCE: Once = Once::new();
        ONCE.call_once(|| {
            let at_once = Arc::new(AtomicBool::new(true));
            let _ = signal_hook::flag::register_conditional_shutdown(
                signal_hook::consts::SIGINT,
                130,
                at_once,
            );
        });
    }
}

/// How long work runs before [`later`] shows that it is working.
pub const SHOW_AFTER: Duration = Duration::from_millis(500);

/// A counter of `unit`s (none: a spinner) with `text` that shows on a terminal only once the
/// work has run [`SHOW_AFTER`] (a quick command draws nothing), then ticks
/// on its own thread (a long unit still shows the time going by); its
/// length is set when the work knows it ([`Progress::of`]).
pub fn later(text: String, unit: &str) -> Progress {
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
    let template = match unit {
        "" => "{spinner} {msg} · {elapsed}".to_string(),
        unit => format!("{{spinner}} {{msg}} · {{pos}} of {{len}} {unit} · {{elapsed}}"),
    };
    bar.set_style(
        ProgressStyle::with_template(&template)
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    bar.set_message(text);
    if std::io::stderr().is_terminal() {
        let shown = bar.clone();
        std::thread::spawn(move || {
            std::thread::sleep(SHOW_AFTER);
            if !shown.is_finished() {
                shown.set_draw_target(ProgressDrawTarget::stderr_with_hz(10));
                shown.enable_steady_tick(Duration::from_millis(100));
            }
        });
    }
    Progress {
        bar,
        last: Instant::now(),
    }
}

/// A spinner with `text`, ticking on its own thread, on a terminal only.
pub fn spinner(text: String) -> Progress {
    let target = if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr_with_hz(10)
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(None, target);
    bar.set_style(
        ProgressStyle::with_template("{spinner} {msg} · {elapsed}")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    bar.set_message(text);
    bar.enable_steady_tick(Duration::from_millis(100));
    Progress {
        bar,
        last: Instant::now(),
    }
}

/// A bar or spinner; cleared when dropped.
pub struct Progress {
    pub bar: ProgressBar,
    last: Instant,
}

impl Progress {
    /// `done` units of `total` (the length set on the first call).
    pub fn of(&mut self, done: usize, total: usize) {
        if self.bar.length() != Some(total as u64) {
            self.bar.set_length(total as u64);
        }
        self.at(done as u64);
    }

    /// Sets the position, at most twenty times a second (a step of a fast
    /// run costs less than drawing it would).
    pub fn at(&mut self, done: u64) {
        if self.last.elapsed() >= Duration::from_millis(50) {
            self.last = Instant::now();
            self.bar.set_position(done);
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}
