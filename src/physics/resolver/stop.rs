//! A request to stop a long resolution (Ctrl-C in `simulate`): a thread that
//! [`watch`]es a flag has its deepest-first phases poll it every
//! [`POLL`] iterations and end there, as if their iteration limit had been
//! reached (without a limit event). A resolution is never cut unless the
//! flag is set, so results are unchanged; the caller that set the flag
//! discards the step it cut. Per thread: other threads (tests running side
//! by side, the TUI's background work) never see another's flag.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Iterations between two polls of the flag (a power of two).
pub const POLL: usize = 1024;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// This thread's resolutions stop once `flag` is set.
pub fn watch(flag: Arc<AtomicBool>) {
    FLAG.with(|f| *f.borrow_mut() = Some(flag));
}

/// This thread's resolutions no longer poll a flag.
pub fn unwatch() {
    FLAG.with(|f| *f.borrow_mut() = None);
}

/// Whether a phase at iteration `used` should stop: at every [`POLL`]-th
/// iteration (the first included), the watched flag is set.
#[inline]
pub fn asked(used: usize) -> bool {
    used & (POLL - 1) == 0
        && FLAG.with(|f| {
            f.borrow()
                .as_ref()
                .is_some_and(|f| f.load(Ordering::Relaxed))
        })
}
