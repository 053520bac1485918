//! The named studies (docs/theory.md §7, §10, §12, §14, §17, §18): which exist and in which order; what each is
//! called, sets, sweeps and runs is its row of the registry (`table`).

/// The studies of docs/theory.md §7.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// 1. Critical speed with discrete devices: N ∈ {3, 7, 15, 31}, F_u ∈ {10, 50, 100} kN, and no friction.
    DiscreteSpeed,
    /// 2. Equal-cost solutions: N·F_u ∈ {3100, 1550, 310} kN for N ∈ {31, 15, 7, 3}.
    EqualCost,
    /// 3. Optimal device force near v_cr (206 m/s for the reference case) for N ∈ {3, 7, 15, 31}.
    OptimalForce,
    /// 4. Critical speed with distributed friction f_u ∈ {0, 1, 2, 5, 10} kN/m.
    DistributedSpeed,
    /// 5. Dynamic amplification at mid-span for v ∈ {50, 100, 150, 200} m/s, f_u ∈ {1, 2} kN/m.
    Amplification,
    /// 6. 199 devices of 1 kN against f_u = 0.995 kN/m at 150 m/s: mid-span histories.
    DiscreteVsDistributed,
    /// 7. Eurocode HSLM-A1 … A10 (docs/theory.md §10): max deflection and deck acceleration vs speed.
    Hslm,
    /// 8. Vehicles against the moving force (docs/theory.md §12): deflection, wheel force, body acceleration vs speed.
    VehicleSpeed,
    /// 9. The stationary wave on the infinite track (docs/theory.md §14): peak deflection vs speed, finite beam beside.
    StationaryWave,
    /// 10. Voided sleepers under a quarter car (docs/theory.md §18): 0–3 hanging sleepers, voids 0–3 mm, 20–100 m/s.
    VoidedSleepers,
    /// Study 11: friction at the sleepers against friction in the ballast, and the discrete track's critical speed
    /// (docs/theory.md §18).
    SleeperFriction,
    /// Study 12: the track's receptance (docs/theory.md §17, §18): Euler–Bernoulli and Timoshenko rails on sleepers
    /// (mid-span, above a sleeper) and on the equivalent continuous support.
    Receptance,
    /// Ledsgård: the X2000 on the soft site beside the measurements, with ballast friction (docs/theory.md §19).
    Ledsgard,
}

impl Preset {
    /// The nine studies `frictrack reproduce` runs: the thesis's (§7), the trains' (§10), the vehicles' (§12) and the
    /// stationary wave's (§14). The discrete track's studies (§18) are run on their own (`frictrack study`).
    pub const REPRODUCED: [Preset; 9] = [
        Preset::DiscreteSpeed,
        Preset::EqualCost,
        Preset::OptimalForce,
        Preset::DistributedSpeed,
        Preset::Amplification,
        Preset::DiscreteVsDistributed,
        Preset::Hslm,
        Preset::VehicleSpeed,
        Preset::StationaryWave,
    ];

    /// All thirteen, in docs/theory.md order: the reproduced nine, then the discrete track's three and Ledsgård.
    pub const ALL: [Preset; 13] = {
        let mut all = [Preset::Receptance; 13];
        let mut i = 0;
        while i < Self::REPRODUCED.len() {
            all[i] = Self::REPRODUCED[i];
            i += 1;
        }
        all[9] = Preset::VoidedSleepers;
        all[10] = Preset::SleeperFriction;
        all[12] = Preset::Ledsgard;
        all
    };
}
