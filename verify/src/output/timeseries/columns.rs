//! The columns of `timeseries.csv`: their names (with units) and where their values come from.

use solver::observables::PhaseStats;
use solver::Observables;

/// A coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// x.
    X,
    /// y.
    Y,
    /// z.
    Z,
}

impl Axis {
    /// x, y, z.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// `x`, `y` or `z`.
    pub fn name(self) -> &'static str {
        ["x", "y", "z"][self.index()]
    }

    /// 0, 1 or 2.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// A column of the whole run; its name carries its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunColumn {
    /// Simulated time [s].
    Time,
    /// Last time step [s].
    Dt,
    /// Steps taken.
    Step,
    /// Total kinetic energy [J].
    KineticEnergy,
    /// Interfacial energy [J].
    InterfacialEnergy,
    /// Compression (EOS) energy of the liquid [J].
    CompressionEnergy,
    /// Gravitational potential energy `−Σ m g·x` [J].
    GravityEnergy,
    /// Potential energy of the liquid–wall repulsion [J].
    WallRepulsionEnergy,
    /// Energy dissipated by laminar viscosity between liquid particles [J].
    DissipatedLaminar,
    /// Energy the liquid lost through laminar viscosity at no-slip walls [J].
    DissipatedLaminarWalls,
    /// Energy dissipated by artificial viscosity [J].
    DissipatedArtificial,
    /// Energy the liquid lost to the walls' own (extrapolated) pressure [J].
    DissipatedWallPressure,
    /// Energy the liquid lost to the difference form of the pressure force beyond the
    /// symmetric form's work (zero with the symmetric form) [J].
    DissipatedPressureDifference,
    /// Compression energy removed by density re-initialisation [J].
    DissipatedDensityReinit,
    /// Energy taken out by particle shifting [J].
    DissipatedShifting,
    /// The energy budget: the energies plus everything dissipated [J].
    EnergyBalance,
    /// The work of the continuum models' interfacial force on the liquid [J] (not in the
    /// budget; zero under the potential).
    InterfacialForceWork,
    /// Total momentum along an axis [kg m/s].
    Momentum(Axis),
    /// Largest particle speed [m/s].
    MaxSpeed,
    /// Largest `|ρ/ρ0 − 1|` [-].
    MaxDensityDeviation,
    /// Largest compression `ρ/ρ0 − 1` [-].
    MaxCompression,
}

impl RunColumn {
    /// Every column of the whole run, in file order.
    pub const ALL: [RunColumn; 23] = [
        RunColumn::Time,
        RunColumn::Dt,
        RunColumn::Step,
        RunColumn::KineticEnergy,
        RunColumn::InterfacialEnergy,
        RunColumn::CompressionEnergy,
        RunColumn::GravityEnergy,
        RunColumn::WallRepulsionEnergy,
        RunColumn::DissipatedLaminar,
        RunColumn::DissipatedLaminarWalls,
        RunColumn::DissipatedArtificial,
        RunColumn::DissipatedWallPressure,
        RunColumn::DissipatedPressureDifference,
        RunColumn::DissipatedDensityReinit,
        RunColumn::DissipatedShifting,
        RunColumn::EnergyBalance,
        RunColumn::InterfacialForceWork,
        RunColumn::Momentum(Axis::X),
        RunColumn::Momentum(Axis::Y),
        RunColumn::Momentum(Axis::Z),
        RunColumn::MaxSpeed,
        RunColumn::MaxDensityDeviation,
        RunColumn::MaxCompression,
    ];

    /// The column's name in `timeseries.csv`.
    pub fn name(self) -> String {
        match self {
            RunColumn::Time => "time_s".into(),
            RunColumn::Dt => "dt_s".into(),
            RunColumn::Step => "step".into(),
            RunColumn::KineticEnergy => "kinetic_energy_J".into(),
            RunColumn::InterfacialEnergy => "interfacial_energy_J".into(),
            RunColumn::CompressionEnergy => "compression_energy_J".into(),
            RunColumn::GravityEnergy => "gravity_energy_J".into(),
            RunColumn::WallRepulsionEnergy => "wall_repulsion_energy_J".into(),
            RunColumn::DissipatedLaminar => "dissipated_laminar_J".into(),
            RunColumn::DissipatedLaminarWalls => "dissipated_laminar_walls_J".into(),
            RunColumn::DissipatedArtificial => "dissipated_artificial_J".into(),
            RunColumn::DissipatedWallPressure => "dissipated_wall_pressure_J".into(),
            RunColumn::DissipatedPressureDifference => "dissipated_pressure_difference_J".into(),
            RunColumn::DissipatedDensityReinit => "dissipated_density_reinit_J".into(),
            RunColumn::DissipatedShifting => "dissipated_shifting_J".into(),
            RunColumn::EnergyBalance => "energy_balance_J".into(),
            RunColumn::InterfacialForceWork => "interfacial_force_work_J".into(),
            RunColumn::Momentum(ax) => format!("momentum_{}_kg_m_s", ax.name()),
            RunColumn::MaxSpeed => "max_speed_m_s".into(),
            RunColumn::MaxDensityDeviation => "max_density_deviation".into(),
            RunColumn::MaxCompression => "max_compression".into(),
        }
    }

    /// The column's value in `o`.
    pub(super) fn value(self, o: &Observables) -> f64 {
        match self {
            RunColumn::Time => o.time_s,
            RunColumn::Dt => o.dt_s,
            RunColumn::Step => o.step as f64,
            RunColumn::KineticEnergy => o.kinetic_energy_j,
            RunColumn::InterfacialEnergy => o.interfacial_energy_j,
            RunColumn::CompressionEnergy => o.compression_energy_j,
            RunColumn::GravityEnergy => o.gravity_energy_j,
            RunColumn::WallRepulsionEnergy => o.wall_repulsion_energy_j,
            RunColumn::DissipatedLaminar => o.dissipated_laminar_j,
            RunColumn::DissipatedLaminarWalls => o.dissipated_laminar_walls_j,
            RunColumn::DissipatedArtificial => o.dissipated_artificial_j,
            RunColumn::DissipatedWallPressure => o.dissipated_wall_pressure_j,
            RunColumn::DissipatedPressureDifference => o.dissipated_pressure_difference_j,
            RunColumn::DissipatedDensityReinit => o.dissipated_density_reinit_j,
            RunColumn::DissipatedShifting => o.dissipated_shifting_j,
            RunColumn::EnergyBalance => o.energy_balance_j,
            RunColumn::InterfacialForceWork => o.interfacial_force_work_j,
            RunColumn::Momentum(ax) => o.momentum_kg_m_s[ax.index()],
            RunColumn::MaxSpeed => o.max_speed_m_s,
            RunColumn::MaxDensityDeviation => o.max_density_deviation,
            RunColumn::MaxCompression => o.max_compression,
        }
    }
}

/// A column of each liquid phase; its name is the liquid's name, the quantity and its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiquidColumn {
    /// Number of particles.
    Count,
    /// Mass [kg].
    Mass,
    /// Mass centroid [m].
    Centroid(Axis),
    /// Velocity of the centroid [m/s].
    CentroidVelocity(Axis),
    /// Extent (max − min of the particle positions) [m].
    Extent(Axis),
    /// Lowest particle position [m].
    Min(Axis),
    /// Highest particle position [m].
    Max(Axis),
    /// Kinetic energy [J].
    KineticEnergy,
    /// The l = 4 shape moment ([`crate::measure::shape::cubic_harmonic_q4`]) [-].
    Q4,
}

impl LiquidColumn {
    /// Every column of a liquid, in file order.
    pub const ALL: [LiquidColumn; 19] = {
        use Axis::{X, Y, Z};
        use LiquidColumn::*;
        [
            Count,
            Mass,
            Centroid(X),
            Centroid(Y),
            Centroid(Z),
            CentroidVelocity(X),
            CentroidVelocity(Y),
            CentroidVelocity(Z),
            Extent(X),
            Extent(Y),
            Extent(Z),
            Min(X),
            Min(Y),
            Min(Z),
            Max(X),
            Max(Y),
            Max(Z),
            KineticEnergy,
            Q4,
        ]
    };

    /// The column's name in `timeseries.csv` for the liquid named `liquid`.
    pub fn name(self, liquid: &str) -> String {
        let axis = |q: &str, ax: Axis, unit: &str| format!("{liquid}_{q}_{}_{unit}", ax.name());
        match self {
            LiquidColumn::Count => format!("{liquid}_count"),
            LiquidColumn::Mass => format!("{liquid}_mass_kg"),
            LiquidColumn::Centroid(ax) => axis("centroid", ax, "m"),
            LiquidColumn::CentroidVelocity(ax) => axis("centroid_velocity", ax, "m_s"),
            LiquidColumn::Extent(ax) => axis("extent", ax, "m"),
            LiquidColumn::Min(ax) => axis("min", ax, "m"),
            LiquidColumn::Max(ax) => axis("max", ax, "m"),
            LiquidColumn::KineticEnergy => format!("{liquid}_kinetic_energy_J"),
            LiquidColumn::Q4 => format!("{liquid}_q4"),
        }
    }

    /// The column's value for the liquid of `p`, whose shape moment is `q4`.
    pub(super) fn value(self, p: &PhaseStats, q4: f64) -> f64 {
        match self {
            LiquidColumn::Count => p.count as f64,
            LiquidColumn::Mass => p.mass_kg,
            LiquidColumn::Centroid(ax) => p.centroid_m[ax.index()],
            LiquidColumn::CentroidVelocity(ax) => p.centroid_velocity_m_s[ax.index()],
            LiquidColumn::Extent(ax) => p.extent_m[ax.index()],
            LiquidColumn::Min(ax) => p.min_m[ax.index()],
            LiquidColumn::Max(ax) => p.max_m[ax.index()],
            LiquidColumn::KineticEnergy => p.kinetic_energy_j,
            LiquidColumn::Q4 => q4,
        }
    }
}
