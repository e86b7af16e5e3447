//! The HTML report of `gearwear run` on a planetary set (`report::run_planetary`): the
//! set (configuration, teeth, ratio, speeds, mesh and planet-pass frequencies), the
//! natural frequencies of its lumped model with each mode's class, every mesh's force and
//! the planets' load sharing, every member's wear with the limiting member, and what a
//! sensor on the fixed ring hears. Every number is read from a study's `summary.json`
//! (`run_train_report::at`: four significant digits), so the report shows what the
//! studies wrote.

use super::html::{FigureBlock, Report, Section, TableBlock};
use super::run_train_report::at;
use super::teeth::own_and_others_line;
use crate::store::RunMetadata;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use serde_json::Value;

/// The studies' summaries (each the `summary.json` in its folder).
pub(crate) struct Summaries {
    /// `stiffness/summary.json`.
    pub stiffness: Value,
    /// `dynamics/summary.json`.
    pub dynamics: Value,
    /// `signals/summary.json`, if the run made the ring sensor's record.
    pub signals: Option<Value>,
    /// `wear/summary.json`.
    pub wear: Value,
}

/// The report (see the module docs): `figures` are the wear figures and the ring
/// sensor's sideband figure.
pub(crate) fn build(
    s: &Summaries,
    runs: &[&PlanetaryWearRun],
    (wear_figures, sidebands): (Vec<FigureBlock>, Vec<FigureBlock>),
    meta: &RunMetadata,
) -> Report {
    let p = &s.stiffness["planetary"];
    let n = at(p, "/geometry/planets");
    let mut sections = vec![set_section(p), modes_section(p), load_section(s)];
    sections.push(wear_section(s, runs, wear_figures));
    sections.push(sensor_section(s, sidebands));
    Report {
        title: format!("gearwear: dynamic wear prediction of a {n}-planet planetary set"),
        intro_html: "<p>Dynamic wear study of a spur planetary set: the lumped model of Lin &amp; Parker with time-varying, phased meshes and contact loss, every sun-planet and ring-planet mesh worn by the response of the whole set (docs/MODEL.md section 12). Each study's files are in its folder, as its own command writes them: <code>stiffness/</code>, <code>dynamics/</code>, <code>signals/</code> (a ring held fixed), <code>wear/</code>.</p>".into(),
        sections,
        footer: format!(
            "gearwear {} | case sha256 {} | command: run",
            meta.version, meta.case_sha256
        ),
    }
}

/// A two-column table of (quantity, value) rows.
fn pairs(caption: &str, rows: Vec<(&str, String)>) -> TableBlock {
    TableBlock {
        caption: caption.into(),
        header: vec!["quantity".into(), "value".into()],
        rows: rows
            .into_iter()
            .map(|(k, v)| vec![k.to_string(), v])
            .collect(),
        highlight_col: None,
    }
}

/// The set: configuration, teeth, ratio, speeds and frequencies (stiffness study).
fn set_section(p: &Value) -> Section {
    let k = &p["kinematics"];
    let word = |key: &str| k[key].as_str().unwrap_or("?").to_string();
    let angles: Vec<String> = p["geometry"]["planet_angles_deg"]
        .as_array()
        .map(|a| {
            (0..a.len())
                .map(|i| at(p, &format!("/geometry/planet_angles_deg/{i}")))
                .collect()
        })
        .unwrap_or_default();
    let paragraph = format!(
        "{} in, {} out, {} fixed: ratio {} (input over output speed). {} planets at {} deg on the carrier.",
        word("input"),
        word("output"),
        word("fixed"),
        at(k, "/ratio_input_to_output"),
        at(p, "/geometry/planets"),
        angles.join(", "),
    );
    let rows = vec![
        ("teeth of the sun", at(p, "/geometry/teeth_sun")),
        ("teeth of each planet", at(p, "/geometry/teeth_planet")),
        ("teeth of the ring", at(p, "/geometry/teeth_ring")),
        ("carrier radius (mm)", at(p, "/geometry/carrier_radius_mm")),
        (
            "contact ratio, sun-planet",
            at(p, "/geometry/contact_ratio_sun_planet"),
        ),
        (
            "contact ratio, ring-planet",
            at(p, "/geometry/contact_ratio_ring_planet"),
        ),
        (
            "ratio, input / output speed",
            at(k, "/ratio_input_to_output"),
        ),
        ("sun speed (Hz)", at(k, "/speed_sun_hz")),
        ("carrier speed (Hz)", at(k, "/speed_carrier_hz")),
        ("ring speed (Hz)", at(k, "/speed_ring_hz")),
        ("mesh frequency (Hz)", at(k, "/mesh_frequency_hz")),
        (
            "planet-pass frequency (Hz)",
            at(k, "/planet_pass_frequency_hz"),
        ),
        (
            "mean sun-planet mesh stiffness (N/m)",
            at(p, "/mesh_stiffness_sun_planet/mean_n_per_m"),
        ),
        (
            "mean ring-planet mesh stiffness (N/m)",
            at(p, "/mesh_stiffness_ring_planet/mean_n_per_m"),
        ),
    ];
    Section {
        heading: "The planetary set".into(),
        paragraphs: vec![paragraph],
        figures: vec![],
        tables: vec![pairs(
            "The set's geometry and kinematics (from the stiffness study).",
            rows,
        )],
    }
}

/// The natural frequencies of the time-invariant lumped model, each with its class.
fn modes_section(p: &Value) -> Section {
    let m = &p["modes"];
    let count = m["undamped_natural_frequencies_hz"]
        .as_array()
        .map_or(0, Vec::len);
    let rows = (0..count)
        .map(|i| {
            vec![
                (i + 1).to_string(),
                at(m, &format!("/undamped_natural_frequencies_hz/{i}")),
                m["mode_classes"][i].as_str().unwrap_or("?").to_string(),
                at(m, &format!("/multiplicities/{i}")),
            ]
        })
        .collect();
    Section {
        heading: "Natural frequencies".into(),
        paragraphs: vec!["The undamped natural frequencies of the time-invariant lumped model (mean mesh stiffness, carrier frame without gyroscopic terms; docs/MODEL.md 12.3), each with the class Lin & Parker (1999) proved for equally spaced identical planets: rotational (multiplicity one), translational (two) and planet modes (N - 3).".into()],
        figures: vec![],
        tables: vec![TableBlock {
            caption: "Natural frequencies and mode classes (from the stiffness study).".into(),
            header: ["mode", "frequency (Hz)", "class", "multiplicity"]
                .map(String::from)
                .to_vec(),
            rows,
            highlight_col: None,
        }],
    }
}

/// Every mesh's force and each planet's load sharing (dynamics study).
fn load_section(s: &Summaries) -> Section {
    let d = &s.dynamics["planetary_dynamics"];
    let n = d["load_sharing_factor"].as_array().map_or(0, Vec::len);
    let paragraph = format!(
        "New teeth, steady state: nominal mesh force {} N (the input torque split equally over the planets), dynamic factor {} on the sun-planet meshes and {} on the ring-planet meshes (largest force over the nominal).",
        at(d, "/nominal_mesh_force_n"),
        at(d, "/dynamic_factor_sun_planet"),
        at(d, "/dynamic_factor_ring_planet"),
    );
    let rows = (0..n)
        .map(|i| {
            let mesh = |j: usize, key: &str| at(d, &format!("/meshes/{j}/{key}"));
            vec![
                (i + 1).to_string(),
                at(d, &format!("/planet_tangential_error_um/{i}")),
                at(d, &format!("/planet_radial_error_um/{i}")),
                at(d, &format!("/load_sharing_factor_static/{i}")),
                at(d, &format!("/load_sharing_factor/{i}")),
                at(d, &format!("/load_sharing_factor_ring/{i}")),
                at(d, &format!("/load_sharing_factor_peak/{i}")),
                mesh(i, "mean_force_n"),
                mesh(i, "max_force_n"),
                mesh(n + i, "mean_force_n"),
                mesh(n + i, "max_force_n"),
            ]
        })
        .collect();
    let header = [
        "planet",
        "tangential pin error (µm)",
        "radial pin error (µm)",
        "static share (-)",
        "sun mesh share (-)",
        "ring mesh share (-)",
        "sun mesh peak share (-)",
        "sun mesh mean force (N)",
        "sun mesh max force (N)",
        "ring mesh mean force (N)",
        "ring mesh max force (N)",
    ];
    Section {
        heading: "Mesh forces and planet load sharing".into(),
        paragraphs: vec![paragraph],
        figures: vec![],
        tables: vec![TableBlock {
            caption: "Each planet's load sharing factor (its mean load over the planets' mean; docs/MODEL.md 12.8) and its meshes' forces (from the dynamics study).".into(),
            header: header.map(String::from).to_vec(),
            rows,
            highlight_col: None,
        }],
    }
}

/// Every member's wear at the end of each run, and the limiting member (wear study).
fn wear_section(s: &Summaries, runs: &[&PlanetaryWearRun], figures: Vec<FigureBlock>) -> Section {
    let w = &s.wear["planetary_wear"];
    let mut paragraphs = Vec::new();
    for r in runs {
        let mode = r.mode.name();
        let limit = &w["limiting_member"][mode];
        if limit.is_null() {
            continue;
        }
        paragraphs.push(format!(
            "{}: after {} revolutions of the input member, the {} limits the life (deepest wear {} µm).",
            r.mode.label(),
            at(w, &format!("/input_cycles/{mode}")),
            limit["member"].as_str().unwrap_or("?").replace('_', " "),
            at(limit, "/max_wear_um"),
        ));
    }
    paragraphs.extend(faulty_tooth_lines(w, runs));
    let mut header = vec!["member".to_string(), "teeth".to_string()];
    for r in runs {
        header.push(format!("max wear, {} (µm)", r.mode.label()));
        header.push(format!("volume, {} (mm³)", r.mode.label()));
    }
    let members = w["members"].as_array().map_or(0, Vec::len);
    let rows = (0..members)
        .map(|i| {
            let m = &w["members"][i];
            let mut row = vec![
                m["member"].as_str().unwrap_or("?").replace('_', " "),
                at(m, "/teeth"),
            ];
            for r in runs {
                let mode = r.mode.name();
                row.push(at(m, &format!("/final/{mode}/max_wear_um")));
                row.push(at(m, &format!("/final/{mode}/volume_mm3")));
            }
            row
        })
        .collect();
    Section {
        heading: "Wear of every member".into(),
        paragraphs,
        figures,
        tables: vec![TableBlock {
            caption: "Each member's deepest wear and worn volume at the end of each run, the sun's and ring's over all their meshes, a planet's over both its flanks (from the wear study; docs/MODEL.md 12.9).".into(),
            header,
            rows,
            highlight_col: None,
        }],
    }
}

/// A faulty tooth's lines, read from the wear summary `w`'s `faulty_tooth`: the fault,
/// then per run and flank its deepest wear beside the deepest of its member's other
/// teeth; none without a fault.
fn faulty_tooth_lines(w: &Value, runs: &[&PlanetaryWearRun]) -> Vec<String> {
    let f = &w["faulty_tooth"];
    if f.is_null() {
        return Vec::new();
    }
    let member = match f["planet"].as_i64() {
        Some(p) => format!("planet {p}"),
        None => f["member"].as_str().unwrap_or("?").to_string(),
    };
    let tooth = at(f, "/tooth");
    let mut lines = vec![format!(
        "Fault: {} on {member} tooth {tooth}. Each of its teeth wears from its own contacts over the fault's period (docs/MODEL.md 12.16):",
        f["kind"].as_str().unwrap_or("?")
    )];
    for r in runs {
        let Some(flanks) = f["final"][r.mode.name()].as_object() else {
            continue;
        };
        for (flank, v) in flanks {
            let who = if f["member"].as_str() == Some(flank.as_str()) {
                format!("{member} tooth {tooth}")
            } else {
                format!("{member} tooth {tooth} ({})", flank.replace('_', " "))
            };
            lines.push(own_and_others_line(
                r.mode.label(),
                &who,
                &member,
                (
                    &at(v, "/tooth_max_wear_um"),
                    &at(v, "/other_teeth_max_wear_um"),
                ),
            ));
        }
    }
    lines
}

/// What a sensor on the fixed ring hears: each mesh harmonic with its sidebands.
fn sensor_section(s: &Summaries, figures: Vec<FigureBlock>) -> Section {
    let Some(g) = &s.signals else {
        return Section {
            heading: "What a sensor on the ring hears".into(),
            paragraphs: vec!["No ring sensor record: the ring turns, or the case asks for a record the ring sensor's steady model does not make (docs/SIGNALS.md section 6).".into()],
            ..Default::default()
        };
    };
    let g = &g["planetary_signals"];
    let paragraph = format!(
        "A sensor at {} deg on the ring hears each planet's ring mesh through a window of half-width {} deg as it passes (McFadden & Smith 1985): the mesh frequency {} Hz with sidebands at multiples of the planet-pass frequency {} Hz.",
        at(g, "/sensor_angle_deg"),
        at(g, "/window_half_width_deg"),
        at(g, "/mesh_frequency_hz"),
        at(g, "/planet_pass_hz"),
    );
    let mut rows: Vec<Vec<String>> = Vec::new();
    let harmonics = g["mesh_harmonics"].as_array().map_or(0, Vec::len);
    for h in 0..harmonics {
        let base = format!("/mesh_harmonics/{h}");
        rows.push(row_of(g, &base, "0"));
        let sb = g["mesh_harmonics"][h]["sidebands"]
            .as_array()
            .map_or(0, Vec::len);
        for k in 0..sb {
            let p = format!("{base}/sidebands/{k}");
            rows.push(row_of(g, &p, &at(g, &format!("{p}/offset_orders"))));
        }
    }
    Section {
        heading: "What a sensor on the ring hears".into(),
        paragraphs: vec![paragraph],
        figures,
        tables: vec![TableBlock {
            caption: "Each mesh harmonic and its sidebands in the ring sensor's spectrum (from the signals study).".into(),
            header: [
                "carrier order",
                "offset from the harmonic (orders)",
                "frequency (Hz)",
                "amplitude (N)",
            ]
            .map(String::from)
            .to_vec(),
            rows,
            highlight_col: None,
        }],
    }
}

/// A row of the sideband table: the entry at `pointer` under `g` and its offset.
fn row_of(g: &Value, pointer: &str, offset: &str) -> Vec<String> {
    vec![
        at(g, &format!("{pointer}/order")),
        offset.to_string(),
        at(g, &format!("{pointer}/frequency_hz")),
        at(g, &format!("{pointer}/amplitude_n")),
    ]
}
