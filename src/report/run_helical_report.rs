//! The HTML report of `gearwear run` on a helical pair (`report::run_helical`): the pair
//! (helix, contact ratios, the slice mesh stiffness beside ISO 6336's, the static face
//! load), the dynamic response of the new teeth and at the wear states (the axial force,
//! the dynamic face load, the spur run's Fig. 4-10), and the wear of both runs (Fig.
//! 11-13, the wear maps across the face, the worn profiles). Every number is read from a
//! study's `summary.json` or from the run's `wear_states` (`run_train_report::at`: four
//! significant digits), so the report shows what the files hold.

use super::html::{FigureBlock, Report, Section, TableBlock};
use super::run_train_report::at;
use crate::store::RunMetadata;
use crate::study::paper::PaperStudy;
use serde_json::Value;

/// The studies' summaries, and the report's figures by section.
pub(crate) struct Parts {
    /// `stiffness/summary.json`.
    pub stiffness: Value,
    /// `dynamics/summary.json`.
    pub dynamics: Value,
    /// `wear/summary.json`.
    pub wear: Value,
    /// The stiffness section's figures (slice stiffness, static face load).
    pub stiffness_figures: Vec<FigureBlock>,
    /// The dynamics section's figures (dynamic face load, Fig. 4-10 at the wear states).
    pub dynamics_figures: Vec<FigureBlock>,
    /// The wear section's figures (Fig. 11-13, the wear maps, the worn profiles).
    pub wear_figures: Vec<FigureBlock>,
}

/// The report (see the module docs); `states` is the run's `wear_states`.
pub(crate) fn build(p: &Parts, study: &PaperStudy, states: &Value, meta: &RunMetadata) -> Report {
    let beta = at(&p.stiffness, "/helical/helix_angle_deg");
    Report {
        title: format!("gearwear: dynamic wear prediction of a helical pair (beta {beta} deg)"),
        intro_html: "<p>Dynamic wear study of a helical pair on its planar model: every contact line a spring of its face slices' stiffness, every face slice worn by Archard's law under its own share of the load, the worn slices fed back into the mesh (docs/MODEL.md sections 11 to 11.5). Each study's files are in its folder, as its own command writes them: <code>stiffness/</code>, <code>dynamics/</code>, <code>wear/</code>; the figures of the dynamic response at the wear states are beside this report, their data under <code>csv/</code>.</p>".into(),
        sections: vec![
            pair_section(p),
            dynamics_section(p, states),
            wear_section(p, study),
        ],
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

/// The pair: helix and contact ratios, the slice stiffness beside ISO 6336's, the static
/// face load (stiffness study).
fn pair_section(p: &Parts) -> Section {
    let s = &p.stiffness;
    let mut paragraphs = vec![format!(
        "Helix angle {} deg ({} hand pinion; base helix angle {} deg): transverse contact ratio {}, overlap ratio {}, total {}. The face is cut into {} slices; the mesh stiffness over a mesh period runs from {} to {} N/m (mean {} N/m).",
        at(s, "/helical/helix_angle_deg"),
        s["helical"]["hand_pinion"].as_str().unwrap_or("?"),
        at(s, "/helical/base_helix_angle_deg"),
        at(s, "/helical/epsilon_alpha"),
        at(s, "/helical/epsilon_beta"),
        at(s, "/helical/epsilon_gamma"),
        at(s, "/helical/slices"),
        at(s, "/mesh_stiffness/min_n_per_m"),
        at(s, "/mesh_stiffness/max_n_per_m"),
        at(s, "/mesh_stiffness/mean_n_per_m"),
    )];
    if !s["face_load"].is_null() {
        paragraphs.push(format!(
            "Static face load (lead gaps, docs/MODEL.md 11.2): K_Hbeta {}, centre of pressure {} mm of the {} mm face.",
            at(s, "/face_load/k_h_beta"),
            at(s, "/face_load/centre_of_pressure_mm"),
            at(s, "/face_load/face_width_mm"),
        ));
    }
    let iso = pairs(
        "ISO 6336-1 Method B beside the slice model (from the stiffness study).",
        vec![
            (
                "c'_th (N/(mm µm))",
                at(s, "/iso6336/c_prime_th_n_per_mm_um"),
            ),
            ("c' (N/(mm µm))", at(s, "/iso6336/c_prime_n_per_mm_um")),
            (
                "c_gamma_alpha (N/(mm µm))",
                at(s, "/iso6336/c_gamma_alpha_n_per_mm_um"),
            ),
            (
                "c_gamma_beta (N/(mm µm))",
                at(s, "/iso6336/c_gamma_beta_n_per_mm_um"),
            ),
            (
                "c_gamma_alpha b (N/m)",
                at(s, "/iso6336/c_gamma_alpha_n_per_m"),
            ),
            (
                "slice model mean / c_gamma_alpha b",
                at(s, "/iso6336/ratio_potential_energy_mean_to_c_gamma_alpha"),
            ),
        ],
    );
    Section {
        heading: "The pair and its mesh stiffness".into(),
        paragraphs,
        figures: p.stiffness_figures.clone(),
        tables: vec![iso],
    }
}

/// The dynamic response: the new teeth's axial force and dynamic face load (dynamics
/// study), and each wear state's headline numbers with Fig. 4-10.
fn dynamics_section(p: &Parts, states: &Value) -> Section {
    let d = &p.dynamics;
    // With an elastic axial bearing (docs/MODEL.md 11.6) the pinion moves axially and
    // its bearing's reaction is the spring's; with a rigid one it is the mesh's axial force.
    let elastic = d["helical"]["axial_bearings"]["pinion"]["bearing"] == "elastic";
    let axial = if elastic {
        format!(
            "the pinion's elastic axial bearing takes a mean reaction of {} N (mean axial displacement {} m, amplitude {} m)",
            at(d, "/helical/axial_bearings/pinion/reaction_mean_n"),
            at(d, "/helical/axial_bearings/pinion/displacement_mean_m"),
            at(d, "/helical/axial_bearings/pinion/displacement_amplitude_m"),
        )
    } else {
        format!(
            "the axial force on the pinion, F tan(beta_b) on a rigid axial bearing, has a mean of {} N",
            at(d, "/helical/axial_force_pinion/mean_n"),
        )
    };
    let mut paragraphs = vec![format!(
        "New teeth: largest dynamic transmission error {} µm, mean mesh force {} N (dynamic factor {}); {axial}.",
        at(d, "/dte/max_um"),
        at(d, "/mesh_force/mean_n"),
        at(d, "/mesh_force/dynamic_factor"),
    )];
    if !d["face_load"].is_null() {
        paragraphs.push(format!(
            "Dynamic face load of the new teeth: K_Hbeta {} (static {}), centre of pressure {} mm, mean tilting moment {} N m.",
            at(d, "/face_load/k_h_beta"),
            at(d, "/face_load/static/k_h_beta"),
            at(d, "/face_load/centre_of_pressure_mm"),
            at(d, "/face_load/tilting_moment_nm/mean"),
        ));
    }
    paragraphs.push("The worn states are the dynamic wear run's own wear map at its first update reaching each depth (or its last), scaled so that its deepest pinion wear over every face slice is that depth, as the spur pair's run takes them (section 4.1 of the paper).".into());
    let n = states.as_array().map_or(0, Vec::len);
    let rows = (0..n)
        .map(|i| {
            let f = |k: &str| at(states, &format!("/{i}/{k}"));
            let state = if states[i]["max_wear_um"].as_f64() == Some(0.0) {
                "new teeth".to_string()
            } else {
                format!("{} µm", f("max_wear_um"))
            };
            vec![
                state,
                f("roughness_um"),
                f("dte_max_um"),
                f("mesh_force_mean_n"),
                f("mesh_force_max_n"),
                f("velocity_y_pinion_rms_mm_per_s"),
                f("mesh_harmonics_mm_per_s/0"),
                f("friction_coefficient_max"),
            ]
        })
        .collect();
    let header = [
        "deepest pinion wear",
        "roughness (µm)",
        "max DTE (µm)",
        "mean mesh force (N)",
        "max mesh force (N)",
        "RMS dy_p/dt (mm/s)",
        "1st mesh harmonic (mm/s)",
        "max friction coefficient",
    ];
    Section {
        heading: "Dynamic response: new teeth and worn states".into(),
        paragraphs,
        figures: p.dynamics_figures.clone(),
        tables: vec![TableBlock {
            caption: "The steady state at each wear state (summary.json, helical_run.wear_states)."
                .into(),
            header: header.iter().map(|h| h.to_string()).collect(),
            rows,
            highlight_col: None,
        }],
    }
}

/// The wear of both runs: cycles, the deepest wear and where across the face, the volume
/// (wear study).
fn wear_section(p: &Parts, study: &PaperStudy) -> Section {
    let w = &p.wear;
    let mut paragraphs = Vec::new();
    if let Some(x) = w["ratio_max_wear_dynamic_to_static"].as_f64() {
        paragraphs.push(format!(
            "Dynamic over quasi-static deepest accumulated pinion wear at {} cycles: {}.",
            at(w, "/ratio_at_cycles"),
            crate::format::shown(x)
        ));
    }
    let rows = [&study.dynamic, &study.quasi_static]
        .iter()
        .map(|r| {
            let m = r.mode.name();
            let map = |k: &str| at(w, &format!("/wear_map/{m}/{k}"));
            vec![
                r.mode.label().to_string(),
                at(w, &format!("/updates/{m}")),
                r.last()
                    .map_or("-".into(), |l| crate::format::shown(l.wear.cycles)),
                map("pinion/max_wear_um"),
                map("pinion/max_wear_position_mm"),
                map("pinion/volume_mm3"),
                map("gear/max_wear_um"),
                map("gear/max_wear_position_mm"),
                map("gear/volume_mm3"),
            ]
        })
        .collect();
    let header = [
        "run",
        "updates",
        "pinion cycles",
        "pinion: deepest wear (µm)",
        "at face position (mm)",
        "volume (mm³)",
        "gear: deepest wear (µm)",
        "at face position (mm)",
        "volume (mm³)",
    ];
    Section {
        heading: "Wear across the face".into(),
        paragraphs,
        figures: p.wear_figures.clone(),
        tables: vec![TableBlock {
            caption: "Each run's deepest wear over every face slice, where across the face, and the volume removed from one flank (from the wear study's wear_map; docs/MODEL.md 11.3).".into(),
            header: header.iter().map(|h| h.to_string()).collect(),
            rows,
            highlight_col: None,
        }],
    }
}
