//! Golden-section search for the extremum of a unimodal function on an interval (Kiefer 1953): the one search the
//! workspace refines a peak or a minimum with — a critical wave here, critical speeds, optimal forces and resonances
//! above (`runner`, `study`).

/// Golden-section search for the maximum (`maximise`) or minimum of f on [a, b] to an interval width `tolerance`;
/// returns (argmax, max) — or (argmin, min) — among the evaluated points. An error of f ends the search with it.
pub fn golden_section<E>(
    f: &mut dyn FnMut(f64) -> Result<f64, E>,
    mut a: f64,
    mut b: f64,
    tolerance: f64,
    maximise: bool,
) -> Result<(f64, f64), E> {
    let sign = if maximise { 1.0 } else { -1.0 };
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (sign * f(c)?, sign * f(d)?);
    while (b - a).abs() > tolerance {
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = sign * f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = sign * f(d)?;
        }
    }
    Ok(if fc >= fd { (c, sign * fc) } else { (d, sign * fd) })
}
