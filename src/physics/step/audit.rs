//! The energy check of one step, by experiment. Impulses of one contact with
//! restitution ≤ 1 and Coulomb friction remove energy; a step that gains
//! kinetic energy anyway is re-resolved from the same inputs (the bodies
//! after the velocity update, this step's contacts, last step's warm-start
//! cache) with one ingredient switched off at a time (see [`Switch`]). A
//! cause is named only when switching it off removes the gain; where no
//! narrow switch does, the broad ones (friction, restitution at all) are tried, then
//! the lecture's order (the step by sequential impulses), then all of them together; where that fails
//! too, the event says which switches were tried. The re-runs happen only
//! on a step that reports a gain (`replay`), never on the fast path.
//! The trace (`trace::run`) says the cause in words.

/// An ingredient of a step that can add energy, and that an audit can
/// switch off for one re-run of the step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Switch {
    /// Restitution with friction (Newton's law with sticking friction, the
    /// Kane example); switched off: restitution 0 on the contacts that also
    /// have friction.
    RestitutionWithFriction,
    /// The velocity-scaling friction model's rule; switched off: those
    /// contacts take the lecture's Coulomb clamp instead.
    VelocityScaling,
    /// The kinetic-direction friction model's rule; switched off likewise.
    KineticDirection,
    /// Sequential impulses' warm start from last step's impulses.
    WarmStart,
    /// Acceleration compensation (a desired Δv from last frame's acceleration).
    AccelerationCompensation,
    /// The position phase (projection); switched off: skipped.
    Projection,
    /// Friction at all (tried only when no narrower switch explains a
    /// gain): with several contacts solved together, a friction impulse
    /// clamped against a normal impulse that later changes can add energy.
    Friction,
    /// Restitution at all (tried likewise): Newton's law applied at
    /// contacts solved together can ask for more than the energy brought.
    Restitution,
    /// The lecture's order: a deepest-first solver takes the contacts one
    /// at a time and never takes an impulse back, so a corner taken first
    /// can stop a whole body and leave the others separating (tried last,
    /// when neither a narrow nor a broad switch explains a gain); switched
    /// off: the same contacts by sequential impulses (accumulated impulses,
    /// no warm start).
    OneAtATime,
}

impl Switch {
    pub const ALL: [Switch; 9] = [
        Switch::RestitutionWithFriction,
        Switch::VelocityScaling,
        Switch::KineticDirection,
        Switch::WarmStart,
        Switch::AccelerationCompensation,
        Switch::Projection,
        Switch::Friction,
        Switch::Restitution,
        Switch::OneAtATime,
    ];

    /// The broad switches, tried only when no narrow one removes a gain.
    pub fn is_broad(self) -> bool {
        matches!(self, Switch::Friction | Switch::Restitution)
    }

    /// When a switch is tried: 0 the narrow ones, 1 the broad ones (when no
    /// narrow one removes the gain), 2 the order (when no broad one does).
    pub fn tier(self) -> u8 {
        match self {
            Switch::OneAtATime => 2,
            s if s.is_broad() => 1,
            _ => 0,
        }
    }

    fn bit(self) -> u16 {
        1 << Self::ALL.iter().position(|s| *s == self).unwrap_or(0)
    }
}

/// A set of switches (a bit set, so events stay `Copy`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Switches(u16);

impl Switches {
    pub fn empty() -> Self {
        Switches(0)
    }

    pub fn one(s: Switch) -> Self {
        Switches(s.bit())
    }

    pub fn insert(&mut self, s: Switch) {
        self.0 |= s.bit();
    }

    pub fn contains(self, s: Switch) -> bool {
        self.0 & s.bit() != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    pub fn len(self) -> usize {
        self.0.count_ones() as usize
    }

    /// The switches in [`Switch::ALL`] order.
    pub fn iter(self) -> impl Iterator<Item = Switch> {
        Switch::ALL.into_iter().filter(move |s| self.contains(*s))
    }
}

impl FromIterator<Switch> for Switches {
    fn from_iter<I: IntoIterator<Item = Switch>>(iter: I) -> Self {
        let mut set = Switches::empty();
        for s in iter {
            set.insert(s);
        }
        set
    }
}

/// What the experiments found about a gain.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EnergyCause {
    /// Switching off any one of these on its own removes the gain.
    Each(Switches),
    /// No one switch removes it; these switched off together do.
    Together(Switches),
    /// No switch removes it (not even all together): the ones tried.
    Unexplained { tried: Switches },
}

impl EnergyCause {
    /// The switches that, turned off together, remove the gain (none when
    /// unexplained): for `Each`, any one of them does.
    pub fn switches(self) -> Switches {
        match self {
            EnergyCause::Each(s) | EnergyCause::Together(s) => s,
            EnergyCause::Unexplained { .. } => Switches::empty(),
        }
    }
}

/// The gain worth reporting: above rounding, relative to the scene's energy
/// scale and to the energy it acted on.
pub fn gain(before: f64, after: f64, scale: f64) -> Option<f64> {
    let gained = after - before;
    let rounding = 1e-9 * scale.max(before.abs()).max(1e-12);
    (gained > rounding).then_some(gained)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_not_a_gain_and_a_real_gain_is() {
        assert_eq!(gain(1.0, 1.0 + 1e-12, 10.0), None);
        assert_eq!(gain(1.0, 0.5, 10.0), None);
        assert_eq!(gain(1.0, 1.5, 10.0), Some(0.5));
        // A tiny scene's gain is judged against its own scale.
        assert_eq!(gain(1e-6, 2e-6, 1e-6), Some(1e-6));
    }

    #[test]
    fn a_set_of_switches_holds_what_was_put_in_it() {
        let s: Switches = [Switch::WarmStart, Switch::Projection]
            .into_iter()
            .collect();
        assert!(s.contains(Switch::WarmStart) && !s.contains(Switch::KineticDirection));
        assert_eq!(s.len(), 2);
        assert_eq!(
            s.iter().collect::<Vec<_>>(),
            vec![Switch::WarmStart, Switch::Projection]
        );
        assert!(Switches::empty().is_empty());
    }
}
