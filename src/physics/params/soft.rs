//! The soft step's parameters (`solver = "soft-step"`, Box2D v3's solver):
//! how stiff a contact is, as a frequency and a damping ratio, how fast it
//! may push out, how many relax sweeps, and the restitution threshold.

/// The soft step's knobs beside the substep count (which XPBD shares:
/// [`super::ResolverParams::substeps`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftParams {
    /// The contact spring's frequency f (Hz): trades a stiffer contact (less
    /// overlap left) for one that stays stable with a long substep; 0 =
    /// rigid with no push-out (default: 30, Box2D's).
    pub contact_hertz: f64,
    /// The contact spring's damping ratio ζ: trades bounce-free push-out for
    /// a slower one (default: 10, Box2D's).
    pub contact_damping_ratio: f64,
    /// The fastest an overlap is pushed out (m/s): trades recovery time for
    /// bodies that do not fly apart (default: 3, Box2D's).
    pub push_out_speed: f64,
    /// Relax sweeps per substep (solve without bias): trades time for the
    /// push-out's velocity removed (default: 1, Box2D's and rapier's).
    pub relax_iterations: usize,
    /// Closing speeds at or below this (m/s) do not bounce (default: 1, Box2D's).
    pub restitution_threshold: f64,
}

impl Default for SoftParams {
    fn default() -> Self {
        SoftParams {
            contact_hertz: 30.0,
            contact_damping_ratio: 10.0,
            push_out_speed: 3.0,
            relax_iterations: 1,
            restitution_threshold: 1.0,
        }
    }
}

/// A soft constraint's coefficients at substep h (Box2D's `b2Softness`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Softness {
    /// ω/a₁ (1/s): the share of the separation asked back per second.
    pub bias_rate: f64,
    /// a₂a₃: the share of the rigid mass the contact pushes with.
    pub mass_scale: f64,
    /// a₃: the share of the accumulated impulse the contact lets go.
    pub impulse_scale: f64,
}

impl Softness {
    /// The coefficients of frequency `hertz` and damping ratio `zeta` at
    /// substep `h`: ω = 2πf, a₁ = 2ζ + hω, a₂ = hω·a₁, a₃ = 1/(1 + a₂).
    /// A frequency of 0 is rigid: no bias, the whole mass, nothing let go.
    pub fn new(hertz: f64, zeta: f64, h: f64) -> Softness {
        if hertz <= 0.0 {
            return Softness::RIGID;
        }
        let omega = 2.0 * std::f64::consts::PI * hertz;
        let a1 = 2.0 * zeta + h * omega;
        let a2 = h * omega * a1;
        let a3 = 1.0 / (1.0 + a2);
        Softness {
            bias_rate: omega / a1,
            mass_scale: a2 * a3,
            impulse_scale: a3,
        }
    }

    /// A rigid constraint: no bias, the whole mass, nothing let go.
    pub const RIGID: Softness = Softness {
        bias_rate: 0.0,
        mass_scale: 1.0,
        impulse_scale: 0.0,
    };
}
