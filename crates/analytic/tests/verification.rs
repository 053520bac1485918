//! Verification of the finite elements of `fem-beam` against the closed forms of this crate (docs/theory.md §2, §8).
//! One test binary; each module checks one family of results with stated tolerances.

mod verification {
    mod closed_form;
    mod frequencies;
    mod invalid_input;
    mod loads;
    mod receptance;
    mod sleepers;
    mod statics;
    mod timoshenko;
}
