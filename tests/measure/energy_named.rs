//! Every joule named over 200 random elastic scenes (the property test of
//! physics/energy_named.rs on 24): 8 bodies each, 2 s, restitution 1, warm
//! sequential impulses. Prints the rises above the tolerance and the
//! energy events, and holds that no rise goes unnamed and every event has a
//! cause.

use crate::common::energy_scenes::{audit, scene};

#[test]
fn every_rise_of_total_energy_in_200_random_elastic_scenes_is_named() {
    let mut failures = Vec::new();
    let (mut rises, mut events) = (0, 0);
    for seed in 0..200 {
        let a = audit(scene(seed, 8, 120), 120);
        rises += a.rises;
        events += a.events;
        if !a.unnamed.is_empty() {
            failures.push(format!("seed {seed}: rises with no event: {:?}", a.unnamed));
        }
        if !a.unexplained.is_empty() {
            failures.push(format!("seed {seed}: no cause found: {:?}", a.unexplained));
        }
    }
    println!("200 random elastic scenes: {rises} steps rose above the tolerance, {events} energy events, {} failures", failures.len());
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
    assert!(rises > 0 && events > 0);
}
