//! Verification of the Moreau–Jean stepper and its friction solvers (docs/theory.md §5–§8).

mod stepping {
    mod common;
    mod contact;
    mod critical_speed;
    mod discrete_vs_continuous;
    mod energy;
    mod friction_law;
    mod linear;
    mod oscillator;
    mod solvers_agree;
    mod steady_state;
}
