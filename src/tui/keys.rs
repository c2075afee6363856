//! A screen's keys as one table: each row is what the help shows (the keys
//! as written, what they do) and the keys it binds to actions, so dispatch
//! and help cannot drift apart.

use ratatui::crossterm::event::KeyCode;

/// One row of a screen's key table.
#[derive(Clone, Copy)]
pub struct Binding<A: 'static> {
    /// The keys as the help writes them (`→ l / ← h`).
    pub label: &'static str,
    /// What they do.
    pub help: &'static str,
    /// Each key and its action; empty for keys read as text elsewhere
    /// (the predict mode's digits).
    pub keys: &'static [(KeyCode, A)],
}

/// The action `code` is bound to in `table`.
pub fn find<A: Copy>(table: &[Binding<A>], code: KeyCode) -> Option<A> {
    table
        .iter()
        .flat_map(|b| b.keys.iter())
        .find(|(k, _)| *k == code)
        .map(|(_, a)| *a)
}

/// The help rows of `table`: keys as written, what they do.
pub fn help<A>(table: &[Binding<A>]) -> Vec<(&'static str, &'static str)> {
    table.iter().map(|b| (b.label, b.help)).collect()
}
