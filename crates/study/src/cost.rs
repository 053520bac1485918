//! What a run will cost, estimated before it runs: the number of steps times a per-step cost linear in the DOFs,
//! the friction sections and the wheels, at rates measured on the project machine (2 cores, release build, one
//! run on one core; BENCHMARKS.md). An estimate to within a factor of about 2–3, for deciding whether to wait.

use crate::scenario::Case;

/// Seconds per DOF and step of a friction-free run: the two banded solves and products of the step and the
/// observers (measured 7.9e-9 s with 40 002 DOFs × 20 000 steps, 1.4e-8 s on the 402-DOF reference case, where the
/// fixed costs weigh more).
const PER_DOF_STEP: f64 = 1.0e-8;
/// Seconds per friction section and step (distributed friction on the reference track: 0.25–0.3 s for 799 sections
/// × 2000 steps beyond the friction-free run; devices cost about the same per section).
const PER_SECTION_STEP: f64 = 2.0e-7;
/// Seconds per wheel and step (a quarter car with Hertz contact on the reference track: 20 ms against 11 ms for the
/// moving force over 2000 steps).
const PER_WHEEL_STEP: f64 = 5.0e-6;

/// The size of a run and its estimated wall time on one core.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunCost {
    /// Time steps.
    pub steps: f64,
    /// Free DOFs of the system (beam and vehicles).
    pub dofs: usize,
    /// Friction sections and devices.
    pub sections: usize,
    /// Wheels.
    pub wheels: usize,
    /// Estimated wall time (s).
    pub seconds: f64,
}

impl RunCost {
    /// The cost of one run of `case` at its own speed.
    pub fn of(case: &Case) -> Self {
        let steps = case.settings.step_count(case.model.mesh().length);
        let dofs = case.model.dofs().free_len();
        let sections = case.interactions.len();
        let wheels = case.settings.moving.load.vehicles().map_or(0, |v| v.wheels().count());
        let per_step = PER_DOF_STEP * dofs as f64 + PER_SECTION_STEP * sections as f64 + PER_WHEEL_STEP * wheels as f64;
        Self { steps, dofs, sections, wheels, seconds: steps * per_step }
    }
}

#[cfg(test)]
mod tests {
    use super::RunCost;
    use crate::Scenario;

    /// The reference case is instant; 20 000 elements with a 0.01 m load advance take seconds (measured 6.4 s); a
    /// million elements are hours, and the estimate says so before the run.
    #[test]
    fn estimates_grow_with_steps_dofs_and_sections() {
        let reference = RunCost::of(&Scenario::default().build().unwrap());
        assert_eq!((reference.steps, reference.dofs, reference.sections), (2000.0, 400, 0));
        assert!(reference.seconds < 0.1, "{reference:?}");
        let mut fine = Scenario::default();
        fine.mesh.elements = 20_000;
        fine.integration.load_advance = 0.01;
        let fine = RunCost::of(&fine.build().unwrap());
        assert!((3.0..15.0).contains(&fine.seconds), "{fine:?}");
        let mut distributed = Scenario::default();
        distributed.friction.distributed =
            Some(crate::scenario::DistributedSection { force_per_length: 1e3, ..Default::default() });
        let distributed = RunCost::of(&distributed.build().unwrap());
        assert!(distributed.sections > 700 && (0.1..1.0).contains(&distributed.seconds), "{distributed:?}");
    }
}
