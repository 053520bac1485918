//! Verification of whole runs of a load across the beam (docs/theory.md §5–§8): linear limits, the friction law at
//! every step, the energy identity, the solvers against each other, the steady state against the closed form.

mod runs {
    mod active_set;
    mod ballast_bodies;
    mod co_moving;
    mod common;
    mod critical_speed;
    mod discrete_vs_continuous;
    mod energy;
    mod friction_law;
    mod homotopy;
    mod linear;
    mod nonlinear_foundation;
    mod rail_sections_on_sleepers;
    mod sleeper_weight;
    mod sleepers;
    mod solver_fallback;
    mod solvers_agree;
    mod span;
    mod steady_state;
    mod time_step;
    mod timoshenko_rail;
    mod trains;
    mod variable_speed;
    mod vehicles_in_runs;
    mod vehicles_in_trains;
    mod vehicles_on_beam;
    mod vehicles_on_ground;
    mod vehicles_on_span;
}
