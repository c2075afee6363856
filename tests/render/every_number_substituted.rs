//! The impulse shows its numbers (issue 16, item 4): for each lesson,
//! contact and friction model, every formula of the impulse and friction
//! clamp stages has a substituted line, not only its symbols and result
//! (velocity scaling's g_contact = M⁻¹(…) once had none). Other stages
//! have definitions shown by their value alone (C = [d̂ t₀ t₁], [r]×).

use contact_lab::knobs::Choice;
use contact_lab::lesson::{Lesson, Overrides};
use contact_lab::physics::{FrictionModel, StageId};

#[test]
fn every_formula_has_its_numbers_substituted() {
    let mut missing = vec![];
    let mut formulas = 0;
    for id in contact_lab::lesson::embedded::ids() {
        let lesson = Lesson::load(id).unwrap();
        for model in FrictionModel::ALL {
            let mut l = lesson.clone();
            l.apply(&Overrides::from_pairs(&[("friction_model", model.name())]).unwrap());
            for k in 0..l.contacts.len() {
                let t = contact_lab::worked_solution(&l, k);
                let impulse = [StageId::Impulse, StageId::FrictionClamp];
                for step in t.stages.iter().filter(|s| impulse.contains(&s.id)) {
                    for f in &step.formulas {
                        formulas += 1;
                        if f.substituted.is_none() {
                            missing.push(format!(
                                "{id} #{k} {model:?} {:?}: {} = {}",
                                step.id, f.lhs, f.rhs
                            ));
                        }
                    }
                }
            }
        }
    }
    missing.sort();
    missing.dedup();
    assert!(formulas > 300, "{formulas}");
    assert!(
        missing.is_empty(),
        "{} formulas without numbers:\n{}",
        missing.len(),
        missing.join("\n")
    );
}
