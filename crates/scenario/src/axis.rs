//! A figure's axis, labelled from the list of quantities ([`crate::quantities`]): a caption in words and symbols, the
//! quantity it shows and how (its SI unit or a multiple of it), so the unit a figure prints is the unit of the data
//! under it — the same list the CSV headers, the JSON and Python's `units` read. `Axis::new("load speed v", "speed",
//! Shown::Si)` labels "load speed v (m/s)"; `Shown::Milli` on a deflection "(mm)", `Shown::Kilo` on a force "(kN)",
//! on a moment "(kN·m)"; a ratio (unit "1") "(-)".

use crate::quantities::unit;
use crate::units::KMH;

/// How a figure shows a quantity: in its SI unit or a multiple of it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// The SI unit itself.
    Si,
    /// A thousandth of it (m → mm), values × 1e3.
    Milli,
    /// A millionth of it (m → µm), values × 1e6.
    Micro,
    /// A thousand of it (N → kN, N·m → kN·m), values × 1e-3.
    Kilo,
    /// A speed in km/h (from m/s), values × 3.6.
    KilometresPerHour,
}

/// One axis of a figure: its label and the factor from the quantity's SI values to the values plotted.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    caption: String,
    label: String,
    factor: f64,
}

impl Axis {
    /// The axis of `quantity` (a name in [`crate::quantities::QUANTITIES`]; any other is a bug and panics) captioned
    /// `caption`, shown as `shown`.
    pub fn new(caption: impl Into<String>, quantity: &str, shown: Shown) -> Self {
        Self::noted(caption, quantity, shown, "")
    }

    /// The same with a note after the unit inside the brackets, e.g. "(mm, upward positive)"; a ratio's note in
    /// place of its "-", e.g. "(−1 … 1)".
    pub fn noted(caption: impl Into<String>, quantity: &str, shown: Shown, note: &str) -> Self {
        let si = unit(quantity);
        let (unit, factor) = match (shown, si) {
            (_, "1") => ("-".to_string(), 1.0),
            (Shown::Si, "deg") => ("°".to_string(), 1.0),
            (Shown::Si, _) => (si.to_string(), 1.0),
            (Shown::Milli, _) => (format!("m{si}"), 1e3),
            (Shown::Micro, _) => (format!("µ{si}"), 1e6),
            (Shown::Kilo, _) => (format!("k{si}"), 1e-3),
            (Shown::KilometresPerHour, "m/s") => ("km/h".to_string(), KMH),
            (Shown::KilometresPerHour, other) => panic!("{quantity} is not a speed ({other}): no km/h"),
        };
        let caption = caption.into();
        // A ratio's note is its unit's place: "(−1 … 1)", not "(-, −1 … 1)".
        let inside = match (unit.as_str(), note) {
            (_, "") => unit,
            ("-", note) => note.to_string(),
            (unit, note) => format!("{unit}, {note}"),
        };
        Self { label: format!("{caption} ({inside})"), caption, factor }
    }

    /// No axis label (a figure whose panels carry theirs).
    pub fn none() -> Self {
        Self { caption: String::new(), label: String::new(), factor: 1.0 }
    }

    /// The caption alone, without the unit (a title's words).
    pub fn caption(&self) -> &str {
        &self.caption
    }

    /// The label, "caption (unit)".
    pub fn label(&self) -> &str {
        &self.label
    }

    /// What a value in the quantity's SI unit is multiplied by to be plotted on this axis.
    pub fn factor(&self) -> f64 {
        self.factor
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit printed is the quantity's, in the multiple asked for, with the factor that goes with it.
    #[test]
    fn the_label_carries_the_quantitys_unit() {
        let cases = [
            (Axis::new("load speed v", "speed", Shown::Si), "load speed v (m/s)", 1.0),
            (Axis::new("train speed", "speed", Shown::KilometresPerHour), "train speed (km/h)", 3.6),
            (Axis::new("W", "deflection", Shown::Milli), "W (mm)", 1e3),
            (Axis::new("M", "moment", Shown::Kilo), "M (kN·m)", 1e-3),
            (Axis::new("arg α", "phase", Shown::Si), "arg α (°)", 1.0),
            (Axis::new("τ = x/L", "tau", Shown::Si), "τ = x/L (-)", 1.0),
            (Axis::noted("w", "deflection", Shown::Milli, "upward positive"), "w (mm, upward positive)", 1e3),
            (Axis::noted("f/f_u", "mobilised_friction", Shown::Si, "−1 … 1"), "f/f_u (−1 … 1)", 1.0),
        ];
        for (axis, label, factor) in cases {
            assert_eq!((axis.label(), axis.factor()), (label, factor));
        }
        assert_eq!(Axis::none().label(), "");
    }

    #[test]
    #[should_panic(expected = "quantities")]
    fn a_quantity_not_listed_is_a_bug() {
        Axis::new("nonsense", "not_a_quantity", Shown::Si);
    }
}
