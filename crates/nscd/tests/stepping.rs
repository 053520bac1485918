//! Verification of the Moreau–Jean stepper and its solvers on small systems with closed-form answers: the Coulomb
//! oscillator, a bouncing ball and a mass against a stop (docs/theory.md §5, §8, §9). The runs on the beam are the
//! `track` crate's tests.

mod stepping {
    mod contact;
    mod damped_contact;
    mod generalized_alpha;
    mod moving;
    mod oscillator;
}
