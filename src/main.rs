//! Thin entry point: parse the command line, dispatch, map errors to exit codes.

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use clap::Parser;
use contact_lab::cli::Cli;
use contact_lab::error::AppError;

fn main() -> ExitCode {
    let cli = Cli::parse();
    // Standard error unlocked: a progress bar's ticking thread draws on it
    // too, and a lock held here for the whole command would deadlock the
    // bar (advise and simulate hung on a terminal at their first tick).
    let (stdout, mut err) = (std::io::stdout().lock(), std::io::stderr());
    let mut out: Box<dyn Write> = if stdout_probe::closed() {
        Box::new(Closed)
    } else {
        Box::new(stdout)
    };
    let result = contact_lab::commands::run(cli, &mut out, &mut err)
        .and_then(|()| out.flush().map_err(AppError::Output));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
            // Not eprint!, which panics when stderr itself cannot be written.
            let _ = write!(err, "{}", e.report(color));
            ExitCode::from(e.exit_code())
        }
    }
}

/// Standard output as it was when the process started closed (`>&-`): every
/// write fails, so output that cannot be delivered is reported (exit 1), not
/// silently dropped.
struct Closed;

impl Write for Closed {
    fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
        Err(std::io::Error::other("standard output is closed"))
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// Whether descriptor 1 was closed when the process started. The Rust
/// runtime reopens a closed standard descriptor on /dev/null before `main`,
/// where every write then succeeds unseen; this probe runs before the
/// runtime, as a constructor (`.init_array` / `__mod_init_func`).
#[cfg(unix)]
mod stdout_probe {
    use std::sync::atomic::{AtomicBool, Ordering};

    static CLOSED: AtomicBool = AtomicBool::new(false);

    extern "C" fn probe() {
        // SAFETY: F_GETFD only asks whether descriptor 1 is open; it touches no memory.
        if unsafe { libc::fcntl(1, libc::F_GETFD) } == -1 {
            CLOSED.store(true, Ordering::Relaxed);
        }
    }

    #[used]
    #[cfg_attr(
        any(
            target_os = "linux",
            target_os = "android",
            target_os = "freebsd",
            target_os = "netbsd",
            target_os = "openbsd",
            target_os = "dragonfly",
            target_os = "illumos",
            target_os = "solaris"
        ),
        link_section = ".init_array"
    )]
    #[cfg_attr(target_vendor = "apple", link_section = "__DATA,__mod_init_func")]
    static PROBE: extern "C" fn() = probe;

    pub fn closed() -> bool {
        CLOSED.load(Ordering::Relaxed)
    }
}

#[cfg(not(unix))]
mod stdout_probe {
    pub fn closed() -> bool {
        false
    }
}
