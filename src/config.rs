//! Input types shared by every front end (CLI config files, the wasm API): one source of truth.
//! `Default` gives the paper's forward-flight case.

use crate::error::{check_positive, check_range, Result, WingbeatError};
use crate::kinematics::Kinematics;
use crate::model::{ModalModel, Mode};
use crate::presets;
use serde::{Deserialize, Serialize};

/// Longest simulated duration accepted, s.
pub const MAX_DURATION_S: f64 = 3600.0;
/// Highest output sample rate accepted, Hz.
pub const MAX_SAMPLE_RATE_HZ: f64 = 1.0e6;
/// Most output samples per series.
pub const MAX_SAMPLES: usize = 2_000_000;
/// Most output values per run (samples × modes). Measured peak memory at the cap (release
/// build, the CLI writing the whole result, 4 modes × 1 999 901 samples): 1.42 GB with JSON
/// output (0.90 GB of it the text) and 1.39 GB with CSV (docs/limits.md, "Memory"); the
/// browser has its own, lower cap (`wasm::helpers::WEB_MAX_SAMPLE_VALUES`).
pub const MAX_SAMPLE_VALUES: usize = 8_000_000;

/// A simulation request.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SimConfig {
    /// Rotation kinematics.
    pub kinematics: Kinematics,
    /// Modes (frequency, a_k, damping, strains).
    pub modes: Vec<Mode>,
    /// Simulated time, s.
    pub duration_s: f64,
    /// Output sample rate, Hz (samples at t = i / rate, i = 0..).
    pub sample_rate_hz: f64,
    /// Initial conditions (q_k(0), q̇_k(0)) per mode; missing entries are zero.
    pub initial_conditions: Vec<[f64; 2]>,
    /// The fluid around the wing (default: vacuum, the paper's assumption). Left out of the
    /// serialised config when it is a vacuum with the default model.
    #[serde(
        skip_serializing_if = "crate::aero::AeroConfig::is_default",
        deserialize_with = "crate::error::object_only"
    )]
    pub aero: crate::aero::AeroConfig,
    /// The wing's mesh and mode shapes, which air needs (the FE wing or a `wingbeat modes`
    /// document); not part of the JSON config: front ends attach it from the modes source.
    #[serde(skip)]
    pub wing: Option<std::sync::Arc<crate::aero::WingGeometry>>,
}

impl Default for SimConfig {
    fn default() -> Self {
        SimConfig {
            kinematics: presets::paper_kinematics(),
            modes: presets::paper_modes(0.0),
            duration_s: 2.0,
            sample_rate_hz: 10_000.0,
            initial_conditions: vec![],
            aero: crate::aero::AeroConfig::default(),
            wing: None,
        }
    }
}

impl SimConfig {
    /// The paper's forward-flight case (Tables 3–6), zero initial conditions, 2 s at 10 kHz.
    pub fn paper() -> Self {
        Self::default()
    }

    /// The `fe-wing` preset: the paper's forward-flight kinematics (Table 5) with the first
    /// [`presets::FE_WING_MODES`] shell-FE modes of the default wing
    /// ([`presets::fe_wing_modes`]). Takes about a second natively.
    pub fn fe_wing() -> Result<Self> {
        let (modes, wing) = presets::fe_wing_modes_and_wing()?;
        Ok(SimConfig {
            modes,
            wing: Some(std::sync::Arc::new(wing)),
            ..SimConfig::paper()
        })
    }

    /// Parses a JSON config; unknown fields are errors at every level (kinematics, angles,
    /// harmonics, modes, strains), missing ones take the paper's values. A failure names the
    /// field's path (``at `modes[0]`: unknown field `damping`…``).
    pub fn from_json(text: &str) -> Result<Self> {
        crate::error::parse_json(text, "config JSON")
    }

    /// Number of output samples.
    pub fn n_samples(&self) -> usize {
        (self.duration_s * self.sample_rate_hz).floor() as usize + 1
    }

    /// Validates every field and the resource caps.
    pub fn validate(&self) -> Result<()> {
        self.model().validate()?;
        self.aero.validate()?;
        crate::modes_doc::check_strain_names(&self.modes, "modes")?;
        check_positive("duration_s", self.duration_s, MAX_DURATION_S, "s")?;
        check_positive(
            "sample_rate_hz",
            self.sample_rate_hz,
            MAX_SAMPLE_RATE_HZ,
            "Hz",
        )?;
        let n = self.duration_s * self.sample_rate_hz;
        if n + 1.0 > MAX_SAMPLES as f64 {
            return Err(WingbeatError::ResourceCap {
                field: "duration_s × sample_rate_hz".into(),
                requested: format!("{:.0} samples", n + 1.0),
                cap: format!("{MAX_SAMPLES} samples"),
                why: "memory for the output series".into(),
            });
        }
        if (n + 1.0) * self.modes.len() as f64 > MAX_SAMPLE_VALUES as f64 {
            return Err(WingbeatError::ResourceCap {
                field: "samples × modes".into(),
                requested: format!("{:.0}", (n + 1.0) * self.modes.len() as f64),
                cap: format!("{MAX_SAMPLE_VALUES}"),
                why: "memory for the output series".into(),
            });
        }
        let points: std::collections::HashSet<&str> = self
            .modes
            .iter()
            .flat_map(|m| m.strains.iter().map(|s| s.point.as_str()))
            .collect();
        if points.len() > crate::model::MAX_STRAIN_POINTS {
            return Err(WingbeatError::invalid(
                "modes[].strains",
                format!("{} distinct points", points.len()),
                format!(
                    "at most {} strain points in one run",
                    crate::model::MAX_STRAIN_POINTS
                ),
            ));
        }
        if (n + 1.0) * 3.0 * points.len() as f64 > MAX_SAMPLE_VALUES as f64 {
            return Err(WingbeatError::ResourceCap {
                field: "samples × strain points × 3".into(),
                requested: format!("{:.0}", (n + 1.0) * 3.0 * points.len() as f64),
                cap: format!("{MAX_SAMPLE_VALUES}"),
                why: "memory for the strain series".into(),
            });
        }
        if n < 1.0 {
            return Err(WingbeatError::invalid(
                "duration_s × sample_rate_hz",
                n,
                "at least 1 sample interval (raise the duration or the sample rate)",
            ));
        }
        if self.initial_conditions.len() > self.modes.len() {
            return Err(WingbeatError::invalid(
                "initial_conditions",
                format!("{} entries", self.initial_conditions.len()),
                format!(
                    "at most one [q0, qdot0] per mode ({} modes)",
                    self.modes.len()
                ),
            ));
        }
        for (k, ic) in self.initial_conditions.iter().enumerate() {
            check_range(
                &format!("initial_conditions[{k}][0]"),
                ic[0],
                -1.0e6,
                1.0e6,
                "(q units)",
            )?;
            check_range(
                &format!("initial_conditions[{k}][1]"),
                ic[1],
                -1.0e9,
                1.0e9,
                "(q units per s)",
            )?;
        }
        Ok(())
    }

    /// The modal model part.
    pub fn model(&self) -> ModalModel {
        ModalModel {
            kinematics: self.kinematics.clone(),
            modes: self.modes.clone(),
        }
    }

    /// Initial condition of mode k.
    pub fn ic(&self, k: usize) -> [f64; 2] {
        self.initial_conditions
            .get(k)
            .copied()
            .unwrap_or([0.0, 0.0])
    }

    /// Warnings that do not stop the run.
    pub fn warnings(&self) -> Vec<String> {
        self.kinematics.warnings()
    }
}
