//! A knob's choices: each choice type's values, spellings, old spellings
//! and what each one is, written once in one list (the [`choices!`] macro),
//! which the knob table, the study grid, the command line (its value
//! parser and help), the TUI's edit form and `docs/knobs.md` read. Physics
//! declares only the types; their names live here.

/// One choice as it is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Spelling {
    /// The canonical spelling (kebab-case).
    pub name: &'static str,
    /// Old spellings still accepted.
    pub aliases: &'static [&'static str],
    /// What it is.
    pub doc: &'static str,
}

/// A type whose values are a knob's choices.
pub trait Choice: Copy + PartialEq + Sized + 'static {
    /// Every value, in the order of [`Choice::SPELLINGS`].
    const VALUES: &'static [Self];
    /// How each value is written, in the docs' order.
    const SPELLINGS: &'static [Spelling];
    /// Every canonical spelling, in the same order (the study's grid of a
    /// knob that tries them all).
    const NAMES: &'static [&'static str];

    /// The spelling used in lesson files, JSON and on the command line.
    fn name(self) -> &'static str {
        Self::VALUES
            .iter()
            .position(|v| *v == self)
            .map_or("", |i| Self::SPELLINGS[i].name)
    }

    /// The value `name` (a canonical spelling or an old one) stands for.
    fn from_name(name: &str) -> Option<Self> {
        Self::SPELLINGS
            .iter()
            .position(|s| s.name == name || s.aliases.contains(&name))
            .map(|i| Self::VALUES[i])
    }
}

/// Declares a type's choices once:
/// `choices!(Type { Value => "name" ["old"]: "what it is"; … })`.
macro_rules! choices {
    ($t:ty { $($value:expr => $name:literal $([$($alias:literal),*])? : $doc:expr;)* }) => {
        impl $crate::knobs::choice::Choice for $t {
            const VALUES: &'static [Self] = &[$($value),*];
            const SPELLINGS: &'static [$crate::knobs::choice::Spelling] = &[$(
                $crate::knobs::choice::Spelling {
                    name: $name,
                    aliases: &[$($($alias),*)?],
                    doc: $doc,
                }
            ),*];
            const NAMES: &'static [&'static str] = &[$($name),*];
        }
    };
}

pub(crate) use choices;
