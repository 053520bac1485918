//! External forces F(t) on the DOFs of a system: the interface any load implements (the moving load of the track
//! application, docs/theory.md §3, or any time function).

/// A time-dependent external force over the free DOFs.
pub trait Forcing {
    /// out += scale·F(t).
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]);
    /// F(t)·v (W).
    fn power(&self, time: f64, v: &[f64]) -> f64;
}

/// No external force.
#[derive(Debug, Clone, Copy, Default)]
pub struct Unloaded;

impl Forcing for Unloaded {
    fn add_to(&self, _: f64, _: f64, _: &mut [f64]) {}
    fn power(&self, _: f64, _: &[f64]) -> f64 {
        0.0
    }
}

/// A force f(t) (N) on a single DOF, for oscillator tests and simple studies.
pub struct DofForce<F: Fn(f64) -> f64> {
    /// Free DOF index.
    pub dof: usize,
    /// The force history.
    pub force: F,
}

impl<F: Fn(f64) -> f64> Forcing for DofForce<F> {
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]) {
        out[self.dof] += scale * (self.force)(time);
    }

    fn power(&self, time: f64, v: &[f64]) -> f64 {
        (self.force)(time) * v[self.dof]
    }
}

/// A constant force (N) on every DOF, e.g. the weights of a vehicle's masses.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Constant {
    /// The force on each DOF (N; upward positive).
    pub force: Vec<f64>,
}

impl Forcing for Constant {
    fn add_to(&self, _: f64, scale: f64, out: &mut [f64]) {
        for (o, f) in out.iter_mut().zip(&self.force) {
            *o += scale * f;
        }
    }

    fn power(&self, _: f64, v: &[f64]) -> f64 {
        self.force.iter().zip(v).map(|(f, v)| f * v).sum()
    }
}

/// A forcing plus a constant force: F(t) + f₀ (a preload on the first DOFs when f₀ is shorter).
pub struct WithConstant<'a> {
    /// F(t).
    pub forcing: &'a dyn Forcing,
    /// f₀ (N).
    pub constant: &'a Constant,
}

impl Forcing for WithConstant<'_> {
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]) {
        self.forcing.add_to(time, scale, out);
        self.constant.add_to(time, scale, out);
    }

    fn power(&self, time: f64, v: &[f64]) -> f64 {
        self.forcing.power(time, v) + self.constant.power(time, v)
    }
}
