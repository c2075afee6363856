//! Why a run stopped early, in words: [`BlowUp`]'s numbers through the
//! number formatter (its `Display` prints them raw, as physics holds them).

use crate::format::Fmt;
use crate::physics::step::report::SURGE_FACTOR;
use crate::physics::step::BlowUp;

/// `e` in words, each body by `name` (its index when `None`).
pub fn words(e: &BlowUp, name: &dyn Fn(usize) -> String) -> String {
    let f = Fmt::new(3);
    match e {
        BlowUp::NonFinite { step, body, what } => {
            format!("step {step}: body {} has a non-finite {what}", name(*body))
        }
        BlowUp::Energy {
            step,
            body,
            energy,
            scale,
            released,
        } => format!(
            "step {step}: the kinetic energy {} J is over 10⁶ times the scene's starting energy scale {} J and the {} J gravity has released since the start; body {} moves fastest",
            f.num(*energy),
            f.num(*scale),
            f.num(*released),
            name(*body)
        ),
        BlowUp::Surge {
            step,
            before,
            after,
            bound,
            bodies,
        } => {
            let list: Vec<String> = bodies
                .iter()
                .map(|(b, v0, v1)| format!("{} {} → {} m/s", name(*b), f.num(*v0), f.num(*v1)))
                .collect();
            format!(
                "step {step}: the kinetic energy rose from {} J to {} J in one step, over {SURGE_FACTOR} times the {} J that the bodies' speeds and one step of acceleration account for; the bodies that sped up most: {}",
                f.num(*before),
                f.num(*after),
                f.num(*bound),
                list.join(", ")
            )
        }
    }
}

/// `e` in words, bodies by their index.
pub fn plain(e: &BlowUp) -> String {
    words(e, &|b| b.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every number of a blow-up goes through the formatter (three
    /// significant digits), not `{:e}` with every digit f64 holds.
    #[test]
    fn a_blow_up_prints_its_numbers_through_the_formatter() {
        let energy = BlowUp::Energy {
            step: 12,
            body: 1,
            energy: 1.234_567_89e9,
            scale: 0.000_123_456_7,
            released: 0.0,
        };
        let said = plain(&energy);
        assert_eq!(
            said,
            "step 12: the kinetic energy 1.23e9 J is over 10⁶ times the scene's starting energy scale 0.000123 J and the 0 J gravity has released since the start; body 1 moves fastest"
        );
        let named = words(
            &BlowUp::NonFinite {
                step: 2,
                body: 0,
                what: "position",
            },
            &|_| "'ball'".into(),
        );
        assert_eq!(named, "step 2: body 'ball' has a non-finite position");
    }
}
