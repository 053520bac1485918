//! # analytic: the closed forms of the track, the references the finite elements are checked against
//!
//! The second floor of frictrack, beside the finite elements (docs/theory.md §2, §8, §10, §15, §16): what an
//! infinite or simply supported beam on a viscoelastic foundation does, written in closed form or as a series, in
//! the words of `fem-beam` (its [`fem_beam::Beam`], [`fem_beam::Foundation`], [`fem_beam::Train`],
//! [`fem_beam::Extreme`]). Nothing here discretises; the finite-element model is used only to build the reference
//! case's mesh ([`reference::ReferenceCase::model`]).
//!
//! - [`moving_beam`]: **the moving-frame beam** — either rail on its foundation, as the run's scenario gives it:
//!   the steady wave of a moving force with its decay rates, the static limit, the critical speed.
//!   Euler–Bernoulli is the κGA → ∞ case of the Timoshenko quartic; [`steady_wave`]: the wave it gives.
//! - [`reference`](mod@reference): the reference case and Frýba's closed form of the Euler–Bernoulli beam (β, w₀,
//!   M₀, v_cr, the moving-load steady state: the independent check of the moving-frame beam, and the static
//!   closed forms); [`steady_train`]: a train's axles superposed.
//! - [`dispersion`]: free waves, their least phase velocity (the critical speed), the point receptance.
//! - [`tensionless`]: a point load on a tensionless Winkler soil (Weitsman's lift-off).
//! - [`span`], [`span_oscillator`]: the simply supported span under a moving force or a moving oscillator.
//! - [`golden`]: the golden-section search every peak and minimum is refined with; [`interpolation`]: the cubic
//!   through four equally spaced samples every wave is read between its points with.
//! - [`ground`]: a layered visco-elastic half-space and its surface flexibility F_zz(k, ω) (the first part of the
//!   ground under the track).
//!
//! Units are SI; deflections are positive upward unless a module says otherwise.

pub mod dispersion;
pub mod golden;
pub mod ground;
pub mod interpolation;
pub mod moving_beam;
pub mod quadrature;
pub mod reference;
pub mod span;
pub mod span_oscillator;
pub mod steady_train;
pub mod steady_wave;
pub mod tensionless;

pub use moving_beam::MovingBeam;
pub use steady_wave::SteadyWave;
