//! Validation of one `[[printed]]` entry: the contact it names, its texts
//! (no control characters: `check` prints them), the body a `resolver`
//! entry names, and the shape of its value.

use std::collections::HashMap;

use super::rules;
use super::Validator;
use crate::lesson::printed::Printed;

impl Validator {
    pub(super) fn printed(
        &mut self,
        raw: &crate::lesson::raw::RawPrinted,
        contacts: usize,
        bodies: &HashMap<&str, usize>,
    ) -> Option<Printed> {
        if let Some(b) = raw
            .body
            .as_ref()
            .filter(|b| !bodies.contains_key(b.get_ref().as_str()))
        {
            let mut names: Vec<&&str> = bodies.keys().collect();
            names.sort();
            self.err(
                b.span(),
                format!(
                    "printed entry names body '{}' but the lesson has no body of that name (bodies: {})",
                    b.get_ref(),
                    names.iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", ")
                ),
            );
            return None;
        }
        if let Some(k) = raw
            .contact
            .as_ref()
            .filter(|k| *k.get_ref() >= contacts.max(1))
        {
            self.err(
                k.span(),
                format!(
                    "printed entry names contact {} but the lesson has {contacts} (numbered from 0)",
                    k.get_ref()
                ),
            );
            return None;
        }
        // `check` prints these strings: no control characters.
        for (what, text) in [("value", &raw.value), ("where", &raw.location)] {
            if let Err(e) = rules::line(text.get_ref()) {
                self.err(text.span(), format!("{what} {e}"));
            }
        }
        if let Some(Err(e)) = raw.erratum.as_ref().map(|t| rules::text(t.get_ref())) {
            let span = raw.erratum.as_ref().map_or(0..0, |t| t.span());
            self.err(span, format!("erratum {e}"));
        }
        match Printed::from_raw(raw) {
            Ok(p) => Some(p),
            Err(note) => {
                self.errors.push(note);
                None
            }
        }
    }
}
