//! Enter on the detection screen: the selected pair's contact as the
//! resolver gets it, its stages on the contact screen (Esc comes back to
//! the detection). The bodies after step N are what step N + 1 detects and
//! resolves, so the contact is looked up in step N + 1's resolution (the
//! one the run screen opens with Enter at step N + 1), at its first stop,
//! with the bodies as the resolver is handed them.

use std::cell::Cell;

use super::ResolverView;
use crate::tui::app::App;

impl App {
    /// The selected pair's selected contact, opened on its stages.
    pub(super) fn open_stages(&mut self) {
        let Some(d) = self.detect.as_deref() else {
            return;
        };
        let Some(p) = d.trace.pairs.get(d.pair) else {
            return self.say(
                "a pair the broad phase rules out gives the resolver no contact".into(),
                false,
            );
        };
        let Some(c) = p.contacts.get(d.contact) else {
            return self.say(
                format!(
                    "{} – {} gives the resolver no contact at this step",
                    p.a, p.b
                ),
                false,
            );
        };
        let (a, b, point) = (p.a.clone(), p.b.clone(), c.point);
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let step = run.frame as u64 + 1;
        run.playing = false;
        if !run.player.reach(step) {
            let end = run.player.computed();
            return self.say(
                format!("no step {step} resolves this contact: the run ends at step {end}"),
                false,
            );
        }
        let Some(trace) = run.player.record(step) else {
            return self.say(
                format!("step {step}'s resolution could not be recorded: the run blew up"),
                true,
            );
        };
        let near = trace.contact_near(&a, &b, point);
        let Some(k) = near else {
            return self.say(
                format!("step {step}'s resolver has no contact of {a} – {b}"),
                false,
            );
        };
        self.resolver = Some(Box::new(ResolverView {
            trace,
            stop: 0,
            selected: k,
            scroll: Cell::new(0),
        }));
        self.open_contact();
    }
}
