//! A case's operating point and its duty: the `[operating]` section (input speed, load
//! torque and the shaft it is on, how the speed is held) and the `[load_spectrum]`
//! section (issue 20), as types and what they mean. Reading them from a case file is
//! `config::load` and `config::load_spectrum`.
//!
//! A load spectrum is a table of operating bins, each an operating point (a load torque on
//! the named shaft and an input speed) with its share of the load cycles (pinion
//! revolutions). Without the section the case's single operating point (`[operating]`)
//! applies. With it, the studies that accumulate wear (wear, run, calibrate, predict,
//! sweeps of wear) use the spectrum and ignore `operating.load_torque_nm` and
//! `operating.input_speed_hz`; the other operating keys (speed boundary, slip) hold for
//! every bin.

use serde::{Deserialize, Serialize};

/// Which shaft the load torque is referred to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TorqueShaft {
    /// The pinion (input, motor) shaft.
    Pinion,
    /// The gear (output, brake) shaft.
    Gear,
}

/// How the drivetrain's free rotation is held (docs/MODEL.md, "Speed boundary condition").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpeedBoundary {
    /// Motor angle imposed, theta_m = Omega t; brake torque constant.
    MotorSpeedImposed,
    /// Brake angle imposed; motor torque constant.
    BrakeSpeedImposed,
    /// Motor torque = mean torque + slip damping (Omega - dtheta_m/dt); brake torque constant.
    MotorSlip,
}

/// `[operating]`: the nominal operating point and how the speed is held.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OperatingSection {
    /// Pinion (input) shaft speed f_in, Hz (paper 4.1: 30 Hz); a case file may give it in
    /// rpm instead (`operating.input_speed_rpm`, read as Hz = rpm / 60, [`SpeedUnit`]).
    pub input_speed_hz: f64,
    /// Load torque, N m (paper: 60 N m), on [`OperatingSection::load_torque_shaft`].
    pub load_torque_nm: f64,
    /// Shaft the load torque is referred to (paper: the pinion's).
    pub load_torque_shaft: TorqueShaft,
    /// How the mean speed is held.
    pub speed_boundary: SpeedBoundary,
    /// Slope c_slip of the motor torque-speed law of [`SpeedBoundary::MotorSlip`],
    /// N m s/rad.
    pub motor_slip_damping_nm_s_per_rad: f64,
    /// Mesh misalignment: the difference across the face width of the separation of the
    /// mating flanks, µm, positive opening it towards the face end y = b; in
    /// `misalignment_plane` (docs/MODEL.md 11.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub misalignment_um: Option<f64>,
    /// Plane of the misalignment (absent: the plane of action).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub misalignment_plane: Option<MisalignmentPlane>,
}

/// The plane a mesh misalignment lies in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum MisalignmentPlane {
    /// The plane of action: the flanks separate along the line of action.
    #[default]
    Action,
    /// The plane through the axis normal to the plane of action: to first order the
    /// flanks slide along each other and no gap opens (docs/MODEL.md 11.2).
    Normal,
}

impl Default for OperatingSection {
    fn default() -> Self {
        Self {
            input_speed_hz: 30.0,
            load_torque_nm: 60.0,
            // The paper's 3311 N mean force matches 60 N m / r_pb (docs/MODEL.md).
            load_torque_shaft: TorqueShaft::Pinion,
            // Paper eq. (1) keeps the motor as a free inertia driven by T_mor: a motor
            // torque law with a speed term is the closest reading (docs/MODEL.md).
            speed_boundary: SpeedBoundary::MotorSlip,
            // Induction motor with ~3 % rated slip at this load: 60 N m / (0.03 x 188 rad/s).
            motor_slip_damping_nm_s_per_rad: 10.0,
            misalignment_um: None,
            misalignment_plane: None,
        }
    }
}

/// The part of `[operating]` a duty varies: input speed, load torque and the shaft the
/// torque is on. A load-spectrum bin, a dataset's speeds and loads and a transient's
/// fastest speed each put a case at one, through the one function that does it
/// (`Case::set_load_point`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadPoint {
    /// Pinion (input) shaft speed, Hz.
    pub input_speed_hz: f64,
    /// Load torque on `load_torque_shaft`, N m.
    pub load_torque_nm: f64,
    /// Shaft the load torque is on.
    pub load_torque_shaft: TorqueShaft,
}

/// The unit a shaft speed is written in: Hz, or revolutions per minute, the unit engineers
/// think in. The one reading of an input speed given under either name
/// ([`SpeedUnit::given`]) and its one conversion (1 Hz = 60 rpm), used by the case's
/// `[operating]`, its load spectrum's bins and a measured load-time history's columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpeedUnit {
    /// Revolutions per second.
    Hz,
    /// Revolutions per minute.
    Rpm,
}

/// An input speed given both in Hz and in rpm (an input problem).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "`{prefix}input_speed_hz` and `{prefix}input_speed_rpm` are both given: give the input speed once, in Hz or in rpm (not both)"
)]
pub struct BothSpeedsGiven {
    /// What the key names stand behind: a section's `operating.`, or nothing.
    pub prefix: String,
}

impl SpeedUnit {
    /// `x` in this unit, in Hz.
    pub(crate) fn to_hz(self, x: f64) -> f64 {
        match self {
            SpeedUnit::Hz => x,
            // 1 Hz = 60 rpm.
            SpeedUnit::Rpm => x / 60.0,
        }
    }

    /// `hz` (Hz) in this unit.
    pub(crate) fn of_hz(self, hz: f64) -> f64 {
        match self {
            SpeedUnit::Hz => hz,
            // 1 Hz = 60 rpm.
            SpeedUnit::Rpm => hz * 60.0,
        }
    }

    /// The name of an input speed in this unit, as keys and columns spell it.
    pub(crate) fn input_speed_key(self) -> &'static str {
        match self {
            SpeedUnit::Hz => "input_speed_hz",
            SpeedUnit::Rpm => "input_speed_rpm",
        }
    }

    /// The unit an input speed is given in, from whether it is given as `input_speed_hz`
    /// and as `input_speed_rpm`: `None` when neither is; when both are, the problem, each
    /// name behind `prefix` (a section's `operating.`, or nothing).
    pub fn given(hz: bool, rpm: bool, prefix: &str) -> Result<Option<SpeedUnit>, BothSpeedsGiven> {
        match (hz, rpm) {
            (true, true) => Err(BothSpeedsGiven {
                prefix: prefix.to_string(),
            }),
            (true, false) => Ok(Some(SpeedUnit::Hz)),
            (false, true) => Ok(Some(SpeedUnit::Rpm)),
            (false, false) => Ok(None),
        }
    }

    /// The two names of an input speed, for a message that misses it.
    pub(crate) fn either_key(prefix: &str) -> String {
        format!("`{prefix}input_speed_hz` (or `{prefix}input_speed_rpm`)")
    }
}

/// One operating bin, as the model uses it: SI-style units of its names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpectrumBin {
    /// Load torque on the spectrum's shaft, N m (before `torque_scale`).
    pub torque_nm: f64,
    /// Input (pinion) speed, Hz (before `speed_scale`).
    pub input_speed_hz: f64,
    /// Share of the load cycles (pinion revolutions), in [0, 1]; the shares sum to 1.
    pub share: f64,
}

/// The `[load_spectrum]` section, resolved (file read, rpm and hours converted): the
/// case keeps the converted values (Hz, shares of the cycles), so a resolved case states
/// what was used.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpectrumSection {
    /// The operating bins, in the order given.
    pub bins: Vec<SpectrumBin>,
    /// Shaft the bins' torques are on; absent: `operating.load_torque_shaft`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torque_shaft: Option<TorqueShaft>,
    /// Factor on every bin's torque (a sweep axis: "all torques x 1.2").
    #[serde(default = "one")]
    pub torque_scale: f64,
    /// Factor on every bin's speed.
    #[serde(default = "one")]
    pub speed_scale: f64,
    /// Bin (1-based) at which vibration is observed for calibration; absent: the bin with
    /// the largest share (the first of equals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub monitoring_bin: Option<i64>,
    /// Maximum pinion wear depth that ends the flanks' life in the `run` report's life
    /// table (under the spectrum and at each bin alone), um.
    #[serde(default = "default_life_limit")]
    pub life_wear_limit_um: f64,
}

fn one() -> f64 {
    1.0
}

/// 10 um: a fifth of a 2 mm module's 0.05 m wear allowance, the limit of
/// docs/PROGNOSTICS.md's worked example.
fn default_life_limit() -> f64 {
    10.0
}

/// Largest number of bins: each is a dynamic evaluation per wear update (the run budget
/// checks the cost); 10 000 is far beyond any published load spectrum (ISO 6336-6 examples
/// and wind-turbine LDDs use tens to a few hundred bins).
pub(crate) const MAX_BINS: usize = 10_000;

/// How far the shares may be from summing to 1: six significant digits, the precision a
/// spectrum written by hand in decimals carries (0.333 + 0.333 + 0.334).
pub(crate) const SHARE_SUM_TOLERANCE: f64 = 1e-6;

impl LoadSpectrumSection {
    /// A spectrum of the given bins with no scale, on the operating shaft.
    pub(crate) fn of_bins(bins: Vec<SpectrumBin>) -> Self {
        Self {
            bins,
            torque_shaft: None,
            torque_scale: 1.0,
            speed_scale: 1.0,
            monitoring_bin: None,
            life_wear_limit_um: default_life_limit(),
        }
    }

    /// Torque of bin `i` as applied (scale included), N m.
    pub fn torque_nm(&self, i: usize) -> f64 {
        self.bins[i].torque_nm * self.torque_scale
    }

    /// Input speed of bin `i` as applied (scale included), Hz.
    pub fn input_speed_hz(&self, i: usize) -> f64 {
        self.bins[i].input_speed_hz * self.speed_scale
    }

    /// Shaft of the torques, given the case's operating section.
    pub fn shaft(&self, operating: TorqueShaft) -> TorqueShaft {
        self.torque_shaft.unwrap_or(operating)
    }

    /// The load point of bin `i` (scales included), its torque on the spectrum's shaft
    /// (`operating`: the case's shaft, for a spectrum that names none).
    pub(crate) fn load_point(&self, i: usize, operating: TorqueShaft) -> LoadPoint {
        LoadPoint {
            input_speed_hz: self.input_speed_hz(i),
            load_torque_nm: self.torque_nm(i),
            load_torque_shaft: self.shaft(operating),
        }
    }

    /// Index (0-based) of the bin vibration is observed at.
    pub(crate) fn monitoring_index(&self) -> usize {
        match self.monitoring_bin {
            Some(b) if b >= 1 && (b as usize) <= self.bins.len() => b as usize - 1,
            _ => self.bins.iter().enumerate().fold(0, |best, (i, b)| {
                if b.share > self.bins[best].share {
                    i
                } else {
                    best
                }
            }),
        }
    }

    /// Mean time per pinion cycle, s: sum_i share_i / f_i (cycles of bin i take 1 / f_i
    /// each). Life in hours = cycles x this / 3600.
    pub(crate) fn seconds_per_cycle(&self) -> f64 {
        (0..self.bins.len())
            .map(|i| self.bins[i].share / self.input_speed_hz(i))
            .sum()
    }
}
