//! The resolver screen for a step of the soft step or XPBD: the step's own
//! record ([`SubstepsRecord`]) walked substep by substep for the selected
//! contact — soft step: its coefficients, then per substep the biased
//! solve and relax (the impulse and separation after them), then the
//! restitution pass (the stored impulses); XPBD: per substep the position
//! pass (C, w, λ_n, Δλ_n, α̃, static friction) then the velocity pass. The
//! values are the record's, formatted, never computed again. ← → move the
//! substep cursor, Tab the contact; the lecture's stages do not apply.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::picture::{self, Scene};
use super::{Key, Outcome, ResolverView, Toggles};
use crate::format::Fmt;
use crate::physics::step::soft::SoftTrace;
use crate::physics::step::xpbd::SubstepRecord;
use crate::trace::substeps::SubstepsRecord;
use crate::tui::app::App;

/// The key bar on this screen.
pub(super) const BAR: &[(&str, &str)] = &[
    ("←→", "substep"),
    ("⇥", "contact"),
    ("Esc", "up"),
    ("?", "help"),
    ("q", "quit"),
];

/// How many substeps the record holds.
pub fn substep_count(rec: &SubstepsRecord) -> usize {
    match rec {
        SubstepsRecord::Soft(t) => t.substeps,
        SubstepsRecord::Xpbd(s) => s.len(),
    }
}

/// How many contacts the record holds.
pub fn contact_count(rec: &SubstepsRecord, world_contacts: usize) -> usize {
    match rec {
        SubstepsRecord::Soft(t) => t.contacts.len(),
        SubstepsRecord::Xpbd(_) => world_contacts,
    }
}

/// What the screen says it shows (its first line).
pub fn heading(rec: &SubstepsRecord, step: u64) -> String {
    match rec {
        SubstepsRecord::Soft(t) => format!(
            "Step {step} under the soft step (Box2D v3's order), from the step's own record: {} substeps of h = {} s; per substep the biased solve, relax ×{}, then the restitution pass. Not the lecture's phases.",
            t.substeps,
            Fmt::new(4).num(t.h),
            t.relax_iterations
        ),
        SubstepsRecord::Xpbd(s) => format!(
            "Step {step} under XPBD, from the step's own record: {} substeps of h = {} s; per substep one position pass, then the velocity pass. Not the lecture's phases.",
            s.len(),
            s.first().map_or("?".into(), |x| Fmt::new(4).num(x.h))
        ),
    }
}

/// The lines the screen shows for contact `k`, the substep cursor at
/// `cursor` (0-based; marked ›), values formatted by `f` from the record.
pub fn lines(rec: &SubstepsRecord, k: usize, cursor: usize, f: &Fmt) -> Vec<String> {
    match rec {
        SubstepsRecord::Soft(t) => soft_lines(t, k, cursor, f),
        SubstepsRecord::Xpbd(s) => xpbd_lines(s, k, cursor, f),
    }
}

fn mark(i: usize, cursor: usize) -> &'static str {
    if i == cursor {
        "›"
    } else {
        " "
    }
}

fn soft_lines(t: &SoftTrace, k: usize, cursor: usize, f: &Fmt) -> Vec<String> {
    let Some(c) = t.contacts.get(k) else {
        return vec![format!("Contact {k}: not in this step's record.")];
    };
    let mut out = vec![
        format!(
            "Contact {k}: f = {} Hz, ζ = {}: bias rate ω/a₁ = {} 1/s, mass scale a₂a₃ = {}, impulse scale a₃ = {}, push-out speed at most {} m/s",
            f.num(t.contact_hertz),
            f.num(t.contact_damping_ratio),
            f.num(c.bias_rate),
            f.num(c.mass_scale),
            f.num(c.impulse_scale),
            f.num(t.push_out_speed)
        ),
        format!(
            "  at the start: penetration {} m, v_n {} m/s, m_n {} kg, μ {}, e {}; warm start P_warm = {} N·s",
            f.num(c.penetration),
            f.num(c.relative_velocity),
            f.num(c.normal_mass),
            f.num(c.friction),
            f.num(c.restitution),
            f.num(c.warm_impulse)
        ),
    ];
    for (i, (p, s)) in c
        .substep_impulses
        .iter()
        .zip(&c.substep_separations)
        .enumerate()
    {
        out.push(format!(
            "{} substep {}: biased solve, relax ×{} → P_n = {} N·s, separation {} m",
            mark(i, cursor),
            i + 1,
            t.relax_iterations,
            f.num(*p),
            f.num(*s)
        ));
    }
    out.push(format!(
        "  restitution pass (closing faster than {} m/s), stored: P_n = {} N·s, P_t = ({}, {}) N·s",
        f.num(t.restitution_threshold),
        f.num(c.normal_impulse),
        f.num(c.tangent_impulse[0]),
        f.num(c.tangent_impulse[1])
    ));
    out
}

fn xpbd_lines(subs: &[SubstepRecord], k: usize, cursor: usize, f: &Fmt) -> Vec<String> {
    let mut out = vec![format!(
        "Contact {k}: α̃ = α/h² = {} kg⁻¹ (the compliance per substep)",
        subs.first().map_or("?".into(), |s| f.num(s.alpha_tilde))
    )];
    for (i, s) in subs.iter().enumerate() {
        let m = mark(i, cursor);
        let Some(c) = s.contacts.iter().find(|c| c.contact == k) else {
            out.push(format!(
                "{m} substep {}: not penetrating: no position or velocity pass",
                s.substep
            ));
            continue;
        };
        out.push(format!(
            "{m} substep {} position pass: C = {} m, w = {} kg⁻¹, Δλ_n = {} kg·m, λ_n = {} kg·m; static friction λ_t = {} against μ_s λ_n = {}: {}",
            s.substep,
            f.num(c.c),
            f.num(c.w),
            f.num(c.delta_lambda),
            f.num(c.lambda),
            f.num(c.lambda_t),
            f.num(c.lambda_t_max),
            if c.sticks { "sticks" } else { "slides" }
        ));
        out.push(format!(
            "    velocity pass: |v_t| = {} m/s, Δv_t = {} m/s; ṽ_n = {} m/s, v_n′ = {} m/s, e = {}, Δv_n = {} m/s",
            f.num(c.slip),
            f.num(c.friction_dv),
            f.num(c.vn_before),
            f.num(c.vn),
            f.num(c.restitution),
            f.num(c.restitution_dv)
        ));
    }
    out
}

/// The screen: the scene (after the step) on the left, the record's lines
/// on the right.
pub(super) fn render(
    app: &App,
    r: &ResolverView,
    rec: &SubstepsRecord,
    area: Rect,
    buf: &mut Buffer,
) {
    let t = &app.theme;
    let left_w = (area.width * 9 / 20).max(20);
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_w), Constraint::Fill(1)]).areas(area);
    let bodies = r.trace.bodies_at(0);
    let contacts = r.trace.contact_views(0);
    let scene = Scene {
        title: format!("{} contact(s), after the step", contacts.len()),
        asleep: vec![],
        bodies: &bodies,
        contacts: &contacts,
        next: None,
        selected: Some(r.selected),
        toggles: Toggles::default(),
        also: &[],
        movement: &[],
    };
    picture::render(app, &scene, left, buf);
    let f = Fmt::new(4);
    let mut shown = vec![Line::styled(heading(rec, r.trace.step), t.title())];
    shown.extend(
        lines(rec, r.selected, r.stop, &f)
            .into_iter()
            .map(Line::raw),
    );
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" Substep {} of {} ", r.stop + 1, substep_count(rec).max(1)),
            t.title(),
        ));
    let inner = block.inner(right);
    block.render(right, buf);
    Paragraph::new(shown)
        .wrap(Wrap { trim: true })
        .render(inner, buf);
}

/// A key on this screen: ← → the substep cursor, Tab the contact; Enter
/// says why there are no lecture stages to open.
pub(super) fn key(r: &mut ResolverView, action: Key) -> Outcome {
    let Some(rec) = r.trace.substeps.as_ref() else {
        return Outcome::Done;
    };
    let last = substep_count(rec).saturating_sub(1);
    let contacts = contact_count(rec, r.trace.world.contacts.len());
    match action {
        Key::Forward => r.stop = (r.stop + 1).min(last),
        Key::Back => r.stop = r.stop.saturating_sub(1),
        Key::First => r.stop = 0,
        Key::Last => r.stop = last,
        Key::NextContact if contacts > 0 => r.selected = (r.selected + 1) % contacts,
        Key::PrevContact if contacts > 0 => r.selected = (r.selected + contacts - 1) % contacts,
        Key::Open => {
            return Outcome::Say(
                "this step's solver has no lecture stages: the screen shows its own record".into(),
            )
        }
        Key::Up => return Outcome::Up,
        _ => {}
    }
    Outcome::Done
}

/// The level in the breadcrumb: the substep on show.
pub(super) fn crumb(r: &ResolverView, rec: &SubstepsRecord) -> String {
    let solver = match rec {
        SubstepsRecord::Soft(_) => "soft step",
        SubstepsRecord::Xpbd(_) => "XPBD",
    };
    format!(
        "{solver} substep {} of {}",
        r.stop + 1,
        substep_count(rec).max(1)
    )
}
