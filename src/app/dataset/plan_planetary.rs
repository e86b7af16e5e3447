//! A planetary condition in a dataset's first step (`super::plan`): what a set's record
//! cannot take (named, exit 2), its chain setup (the ring sensor's channel and the
//! acquisition's rate, length and noise), and what the description states of a set.

use super::request::DatasetRequest;
use crate::app::signals_planetary::{ring_sensor_of, ring_sensor_problem};
use crate::config::case::Case;
use crate::signals::setup::{chain_of, ChainSetup};
use crate::study::dataset::planetary_records::{
    record_samples, RING_CHANNEL, RING_COLUMN, TACHOMETER_COLUMN,
};
use crate::study::dataset::DatasetDesign;
use crate::study::planetary_wear::PlanetaryWearModel;
use serde_json::{json, Value};

/// What of `case` a planetary set's dataset record cannot honour: each key, its value and
/// why (the design's refusal, before any work).
fn planetary_case_problems(req: &DatasetRequest, case: &Case) -> Vec<String> {
    let mut p = Vec::new();
    if let Some(rel) = &req.design.transfer_path {
        p.push(format!("`transfer_path` = {rel:?}: a planetary set's record is the ring sensor's window model (`signals.ring_sensor_angle_deg`, `signals.ring_sensor_half_width_deg`); a housing transfer path is not taken for a set yet; remove the key"));
    }
    if let Some(e) = ring_sensor_problem(case) {
        p.push(e.to_string());
    }
    let s = &case.signals;
    let d = crate::config::signals::SignalsSection::default();
    if let Some(v) = s.noise_density_ug_per_sqrt_hz {
        p.push(format!("`signals.noise_density_ug_per_sqrt_hz` = {v}: an accelerometer's noise density means nothing for the ring sensor's force (N) of a planetary set; give `signals.snr_db` instead"));
    }
    if s.channel_unit != d.channel_unit {
        p.push(format!("`signals.channel_unit` = \"{}\": a planetary set's ring sensor records a force in N (column `{RING_COLUMN}`), not an acceleration; remove the key", s.channel_unit.symbol()));
    }
    if s.tachometer_shaft != d.tachometer_shaft {
        p.push(format!("`signals.tachometer_shaft` = \"{}\": a pair's shaft; a planetary set's tachometer is on the carrier; remove the key", s.tachometer_shaft.name()));
    }
    if let Some(k) = s.sensor_stage {
        p.push(format!("`signals.sensor_stage` = {k}: a gear train's stage; a planetary set has none; remove the key"));
    }
    if !case.fault.is_empty() {
        p.push(format!("{} `[[fault]]` table(s): a fault of a pair's tooth; a planetary set's tooth fault is a `[[planetary.fault]]` table in `[condition.case]`; remove them", case.fault.len()));
    }
    if let Err(e) = PlanetaryWearModel::from_case(case) {
        p.extend(e.0);
    }
    p
}

/// The chain setup of a planetary condition at the design's fastest speed: the ring
/// sensor's one channel ([`RING_CHANNEL`]), the acquisition's rate, length and noise as
/// `signals` gives them (the pair's mesh-harmonic check left out: a set's record has no
/// pair); or what the set cannot take.
pub(super) fn planetary_setup(
    req: &DatasetRequest,
    case: &Case,
) -> Result<ChainSetup, Vec<String>> {
    let p = planetary_case_problems(req, case);
    if !p.is_empty() {
        return Err(p);
    }
    let mut c = case.clone();
    c.signals.mesh_harmonics = 0;
    let mut s = chain_of(&c, None, c.signals.max_input_speed_hz(&c)).map_err(|p| p.messages())?;
    s.chain.path.sensors = vec![RING_CHANNEL.to_owned()];
    s.warnings.clear();
    Ok(s)
}

/// What a planetary design's conditions must share: every condition a set (or none),
/// all with the same planets (their index columns are the members').
pub(super) fn mixed_problems(d: &DatasetDesign) -> Vec<String> {
    let planets = |c: &Case| c.planetary.as_ref().map(|p| p.planets);
    let first = planets(&d.conditions[0].case);
    d.conditions
        .iter()
        .filter(|c| planets(&c.case) != first)
        .map(|c| {
            format!(
                "condition `{}`: {}, but condition `{}` is {}: a design's conditions share one kind of gearing (the index's columns are its members')",
                c.name,
                kind(planets(&c.case)),
                d.conditions[0].name,
                kind(first)
            )
        })
        .collect()
}

/// A condition's kind of gearing in words.
fn kind(planets: Option<i64>) -> String {
    match planets {
        Some(n) => format!("a planetary set of {n} planets"),
        None => "not a planetary set".into(),
    }
}

/// The description's parts for a planetary design (`super::plan::description`): the
/// record (the ring sensor and the carrier tachometer), its columns, the set's members
/// and frequencies per design speed, and what a set's labels mean.
pub(super) fn planetary_description(body: &mut Value, d: &DatasetDesign) {
    let case = &d.conditions[0].case;
    let Ok(model) = PlanetaryWearModel::from_case(case) else {
        return;
    };
    let n = model.planets();
    let sensor = ring_sensor_of(case, n);
    let s = &case.signals;
    body["record"] = json!({
        "sampling_rate_hz": sensor.sampling_rate_hz,
        "samples": record_samples(&sensor),
        "duration_s": record_samples(&sensor) as f64 / sensor.sampling_rate_hz,
        "channel_unit": "N",
        "noise": s.snr_db.map(|v| json!({"snr_db": v})),
        "tachometer": {
            "shaft": "carrier (relative to the ring)",
            "pulses_per_revolution": s.tachometer_pulses_per_revolution.max(1),
            "high_level_v": 5.0,
            "duty": 0.5,
        },
        "sensors": [RING_CHANNEL],
        "sensor_placement": "on the fixed ring, hearing each planet's ring mesh through its window as it passes (as `gearwear signals` on a set)",
        "sensor_angle_deg": sensor.angle_rad.to_degrees(),
        "window_half_width_deg": sensor.half_width_rad.to_degrees(),
    });
    body["signal_columns"] = json!({RING_COLUMN: "N", TACHOMETER_COLUMN: "V"});
    body["run_to_failure"]["failure"] = json!("the deepest wear of any member of the set (the sun's and the ring's flanks sum their meshes' wear; a planet's deeper flank) reaches wear_limit_um");
    let members: Vec<String> = (0..n + 2)
        .map(|i| crate::study::dataset::planetary::member_name(i, n))
        .collect();
    let conditions: Vec<Value> = d
        .conditions
        .iter()
        .filter_map(|c| {
            let m = PlanetaryWearModel::from_case(&c.case).ok()?;
            let set = &m.dynamics.study.set;
            Some(json!({
                "condition": c.name,
                "planets": m.planets(),
                "teeth": {"sun": set.teeth_sun(), "planet": set.teeth_planet(), "ring": set.teeth_ring()},
                "pinion_revolutions_per_input_revolution": {"sun_meshes": m.pinion_cycles_per_input[0], "ring_meshes": m.pinion_cycles_per_input[1]},
                "tooth_contacts_per_input_revolution": crate::study::planetary_wear::contacts_per_input(&m),
            }))
        })
        .collect();
    body["planetary"] = json!({
        "planets": n,
        "members": members,
        "conditions": conditions,
        "labels": "a planetary set's record: `cycles` and `remaining_cycles` are input cycles (revolutions of the input member, `planetary.input`); `mesh_hz` the set's mesh frequency z_r |f_carrier - f_ring|; `max_wear_pinion_um` the deepest wear of the meshes' driving flanks (the sun's, each planet's ring side), `max_wear_gear_um` of their driven flanks (each planet's sun side, the ring's); each member's deepest wear and tooth contacts in `<name>_<member>` columns (sidecar: `members`), the deepest-worn member in `limiting_member`; the signal is the ring sensor's (`gearwear signals` on the set, force in N) with a carrier tachometer; indicators: RMS, crest factor and kurtosis of the record (no shaft TSA for a set); a condition whose case has `[[planetary.fault]]` tables (a sun, planet or ring tooth's crack, spall or broken tip) is labelled `fault` by their kinds, its wear is the faulty set's (the mean over each member's teeth, docs/MODEL.md 12.15), its signal the faulty set's, and its sidecar holds the tables under `planetary_faults`",
    });
}
