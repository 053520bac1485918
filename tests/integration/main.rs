//! Workspace-level integration tests: results that cross crate boundaries or cover a whole field.

mod figures;
mod layers;
mod references;
mod static_shape;
mod study_curves;
