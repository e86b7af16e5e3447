//! The signal chain of a case: its `[signals]` section, a transfer path, and the checks
//! that need the pair (mesh frequency, modes against the Nyquist frequency).

use super::antialias::SAMPLING_OVER_PASSBAND;
use super::chain::{Acquisition, NoiseSpec, RecordLength, SignalChain, TachometerSpec};
use super::components::ComponentSettings;
use super::transfer::{PathModel, TransferPath};
use crate::config::signals::LengthUnit;
use crate::config::Case;
use crate::remedy::Problems;

/// A chain that can be recorded, and what the user should know about it.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainSetup {
    /// The chain to record with.
    pub chain: SignalChain,
    /// Which orders count as the regular meshing components.
    pub components: ComponentSettings,
    /// What the user should know about the chain (one line each).
    pub warnings: Vec<String>,
}

/// The chain of `case` with `path` (the generic housing when `None`), checked against
/// the pair at its operating point, and at the highest input speed `max_input_hz` a
/// record will see (a run-up's end, a dataset's fastest case).
pub fn chain_of(
    case: &Case,
    path: Option<TransferPath>,
    max_input_hz: f64,
) -> Result<ChainSetup, Problems> {
    let s = &case.signals;
    let path = path.unwrap_or_else(TransferPath::generic_housing);
    let fs = s.sampling_rate_hz;
    let mut problems = path.problems_at(fs, "signals.sampling_rate_hz");
    let mut warnings = Vec::new();
    let z1 = case.gear.teeth_pinion.max(1) as f64;
    let top_harmonic_hz = s.mesh_harmonics as f64 * z1 * max_input_hz;
    let band = fs / SAMPLING_OVER_PASSBAND;
    if top_harmonic_hz >= band {
        problems.push(format!(
            "`signals.sampling_rate_hz` = {fs} is too low for `signals.mesh_harmonics` = {}: mesh harmonic {} lies at {top_harmonic_hz} Hz (input {max_input_hz} Hz x {z1} teeth), and the alias-free band ends at f_s / {SAMPLING_OVER_PASSBAND} = {band} Hz; expected a sampling rate above {} Hz (twice the harmonic is the bare Nyquist limit, 2.56 times it leaves the anti-alias filter its transition band)",
            s.mesh_harmonics,
            s.mesh_harmonics,
            SAMPLING_OVER_PASSBAND * top_harmonic_hz
        ));
    }
    if let PathModel::Table(t) = &path.model {
        if t.max_frequency_hz() < 0.5 * fs {
            warnings.push(format!(
                "the FRF table ends at {} Hz, below the Nyquist frequency {} Hz: above it the path transmits nothing",
                crate::format::shown(t.max_frequency_hz()),
                crate::format::shown(0.5 * fs)
            ));
        }
    }
    if !problems.is_empty() {
        return Err(problems.into());
    }
    let noise = match (s.snr_db, s.noise_density_ug_per_sqrt_hz) {
        (Some(snr), _) => NoiseSpec::SnrDb(snr),
        (None, Some(d)) => NoiseSpec::DensityUgPerSqrtHz(d),
        (None, None) => NoiseSpec::None,
    };
    let chain = SignalChain {
        path,
        acquisition: Acquisition {
            sampling_rate_hz: fs,
            anti_alias_attenuation_db: s.anti_alias_attenuation_db,
            unit: s.channel_unit,
            sensitivity_mv_per_g: s.sensitivity_mv_per_g,
            noise,
            noise_seed: s.noise_seed.max(0) as u64,
        },
        tachometer: TachometerSpec {
            shaft: s.tachometer_shaft,
            pulses_per_revolution: s.tachometer_pulses_per_revolution.max(1) as usize,
        },
        length: match s.record_length_unit {
            LengthUnit::S => RecordLength::Seconds(s.record_length),
            LengthUnit::Revolutions => RecordLength::Revolutions(s.record_length),
        },
    };
    Ok(ChainSetup {
        chain,
        components: ComponentSettings {
            mesh_harmonics: s.mesh_harmonics.max(1) as usize,
            ..ComponentSettings::default()
        },
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;

    #[test]
    fn a_sampling_rate_below_the_highest_harmonic_is_refused_with_the_key_and_limit() {
        // Paper case: mesh 570 Hz; 4 harmonics -> 2280 Hz needs f_s > 5836.8 Hz.
        let mut case = Case::default();
        case.signals.sampling_rate_hz = 5_000.0;
        let e = chain_of(&case, None, 30.0).unwrap_err().messages();
        let msg = e.iter().find(|m| m.contains("mesh_harmonics")).unwrap();
        assert!(
            msg.contains("`signals.sampling_rate_hz` = 5000") && msg.contains("5836.8"),
            "{msg}"
        );
        // The generic housing's 3.7 and 6.3 kHz modes lie above 2.5 kHz as well.
        assert!(
            e.iter().filter(|m| m.contains("Nyquist")).count() >= 2,
            "{e:?}"
        );
        case.signals.sampling_rate_hz = 25_600.0;
        assert!(chain_of(&case, None, 30.0).is_ok());
    }

    #[test]
    fn case_keys_reach_the_chain_and_bad_ones_name_themselves() {
        let text = "[signals]\nsnr_db = 30\ntachometer_shaft = \"gear\"\ntachometer_pulses_per_revolution = 10\nrecord_length = 20\nrecord_length_unit = \"revolutions\"\nchannel_unit = \"g\"\n";
        let case = load_case(text, &[]).unwrap();
        let c = chain_of(&case, None, 30.0).unwrap().chain;
        assert_eq!(c.acquisition.noise, NoiseSpec::SnrDb(30.0));
        assert_eq!(c.tachometer.pulses_per_revolution, 10);
        assert_eq!(c.length, RecordLength::Revolutions(20.0));
        let e = load_case("[signals]\ntachometer_shaft = \"motor\"\n", &[]).unwrap_err();
        assert!(
            e.problems[0]
                .to_string()
                .contains("`signals.tachometer_shaft`")
                && e.problems[0].to_string().contains("\"pinion\", \"gear\""),
            "{e}"
        );
        let e = load_case(
            "[signals]\nsnr_db = 30\nnoise_density_ug_per_sqrt_hz = 10\n",
            &[],
        )
        .unwrap_err();
        assert!(e.problems[0].to_string().contains("both given"), "{e}");
    }
}
