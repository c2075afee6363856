//! The physics layer through `contact_lab::physics`: one contact's stages and
//! checks, the resolver, contact generation, time stepping, impact integration;
//! lessons only as input.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../collide_support/mod.rs"]
mod collide_support;
#[path = "../common/mod.rs"]
mod common;
#[path = "../exact_support/mod.rs"]
mod exact_support;

mod blow_up_rule;
mod broad_methods;
mod ccd_manifold;
mod ccd_matrix;
mod ccd_shapes;
mod ccd_step;
mod collide;
mod collide_properties;
mod convex_pairs;
mod energy_named;
mod exact_impact;
mod file_cycles;
mod floors;
mod hull_manifolds;
mod hull_pairs;
mod hull_tangled;
mod hull_work;
mod invariants;
mod kept_energy;
mod lcp;
mod lean_position;
mod lean_prepare;
mod mesh_contacts;
mod mesh_scenes;
mod models_and_options;
mod pile_work;
mod previous_normal;
mod properties;
mod resolver_alloc;
mod resolver_properties;
mod resolver_reference;
mod resolver_semantics;
mod resting_convex;
mod resting_hulls;
mod resting_slender;
mod rollback;
mod scale_invariance;
mod scenes;
mod sequential;
mod shape_matrix;
mod sleep_holds;
mod soft_step;
mod swept_reuse;
mod table_budget;
mod truth;
mod tunnelling;
mod world;
mod xpbd;
