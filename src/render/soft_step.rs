//! `simulate --solver soft-step --trace-step K`: a soft step's record as
//! text or JSON: the step's coefficients from f, ζ and h, then each
//! contact's constraint, its normal impulse and separation after every
//! substep, and the impulses it ends with (named as docs/simulate.md's
//! solver contract names them: `bias_rate`, `mass_scale`, `impulse_scale`).

use std::fmt::Write;

use serde_json::{json, Value};

use crate::format::Fmt;
use crate::physics::step::soft::SoftTrace;

fn body(names: &[String], i: Option<usize>) -> String {
    match i {
        None => "world".into(),
        Some(i) => names.get(i).cloned().unwrap_or_else(|| format!("body {i}")),
    }
}

/// The record as text.
pub fn text(t: &SoftTrace, names: &[String], step: u64, f: &Fmt) -> String {
    let mut out = format!(
        "Step {step}: a soft step (Box2D v3's order) over {} contact(s).\n\
         Substeps: {}, h = Δt/{} = {} s; per substep: integrate velocities, warm start, solve with bias, integrate positions, relax ×{}; then restitution (closing faster than {} m/s), store impulses.\n\
         Soft coefficients from f = {} Hz, ζ = {}: ω = 2πf, a₁ = 2ζ + hω, a₂ = hω·a₁, a₃ = 1/(1 + a₂); push-out speed at most {} m/s.\n",
        t.contacts.len(),
        t.substeps,
        t.substeps,
        f.num(t.h),
        t.relax_iterations,
        f.num(t.restitution_threshold),
        f.num(t.contact_hertz),
        f.num(t.contact_damping_ratio),
        f.num(t.push_out_speed),
    );
    if let Some(k) = t.contacts.first() {
        let _ = writeln!(
            out,
            "bias rate ω/a₁ = {} 1/s, mass scale a₂a₃ = {}, impulse scale a₃ = {}\n",
            f.num(k.bias_rate),
            f.num(k.mass_scale),
            f.num(k.impulse_scale)
        );
    }
    for (n, k) in t.contacts.iter().enumerate() {
        let _ = writeln!(
            out,
            "Contact {n}: {} ↔ {}: penetration {} m, normal velocity {} m/s, normal mass {} kg, μ {}, e {}; warm start {} N·s",
            body(names, Some(k.body1)),
            body(names, k.body2),
            f.num(k.penetration),
            f.num(k.relative_velocity),
            f.num(k.normal_mass),
            f.num(k.friction),
            f.num(k.restitution),
            f.num(k.warm_impulse),
        );
        for (i, (p, s)) in k
            .substep_impulses
            .iter()
            .zip(&k.substep_separations)
            .enumerate()
        {
            let _ = writeln!(
                out,
                "  substep {}: normal impulse {} N·s, separation {} m",
                i + 1,
                f.num(*p),
                f.num(*s)
            );
        }
        let _ = writeln!(
            out,
            "  stored: normal {} N·s, friction ({}, {}) N·s",
            f.num(k.normal_impulse),
            f.num(k.tangent_impulse[0]),
            f.num(k.tangent_impulse[1])
        );
    }
    out
}

/// The record as JSON.
pub fn json(t: &SoftTrace, names: &[String], step: u64) -> Value {
    let contacts: Vec<Value> = (t.contacts.iter().enumerate())
        .map(|(n, k)| {
            json!({
                "contact": n,
                "body1": body(names, Some(k.body1)),
                "body2": body(names, k.body2),
                "penetration": k.penetration,
                "relative_velocity": k.relative_velocity,
                "normal_mass": k.normal_mass,
                "bias_rate": k.bias_rate,
                "mass_scale": k.mass_scale,
                "impulse_scale": k.impulse_scale,
                "friction": k.friction,
                "restitution": k.restitution,
                "warm_impulse": k.warm_impulse,
                "substeps": (k.substep_impulses.iter().zip(&k.substep_separations))
                    .map(|(p, s)| json!({ "normal_impulse": p, "separation": s }))
                    .collect::<Vec<_>>(),
                "normal_impulse": k.normal_impulse,
                "tangent_impulse": k.tangent_impulse,
            })
        })
        .collect();
    json!({
        "solver": "soft-step",
        "step": step,
        "dt": t.dt,
        "substeps": t.substeps,
        "h": t.h,
        "contact_hertz": t.contact_hertz,
        "contact_damping_ratio": t.contact_damping_ratio,
        "push_out_speed": t.push_out_speed,
        "relax_iterations": t.relax_iterations,
        "restitution_threshold": t.restitution_threshold,
        "contacts": contacts,
    })
}
