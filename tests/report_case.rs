//! `gearwear run` on a pair that is not the paper's (issue 10's 25/50-tooth pair: module
//! 3 mm, 30 mm face width, 40 Hz, 100 N m) describes that pair: no sentence or number of
//! the paper's case, and the case's own load, speed and mesh frequency, checked against
//! hand values.

use std::process::Command;

/// The report's visible text: tags, the style sheet and embedded images dropped, the
/// few entities the HTML writer uses decoded.
fn visible_text(html: &str) -> String {
    let body = html.split("</style>").last().unwrap_or(html);
    let mut out = String::new();
    let mut in_tag = false;
    for c in body.chars() {
        match c {
            '<' => in_tag = true,
            '>' => {
                in_tag = false;
                out.push(' ');
            }
            _ if !in_tag => out.push(c),
            _ => {}
        }
    }
    out.replace("&#39;", "'")
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

#[test]
fn the_report_of_another_pair_describes_that_pair() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r");
    let sets = [
        "gear.module_mm=3",
        "gear.teeth_pinion=25",
        "gear.teeth_gear=50",
        "gear.face_width_mm=30",
        "operating.input_speed_hz=40",
        "operating.load_torque_nm=100",
        // A short wear study (one block) keeps the test well under a second.
        "wear.total_cycles=3000",
        // The parameters the geometry gives, as for a pair of one's own.
        "gear.hub_bore_radius_pinion_mm=derived",
        "gear.hub_bore_radius_gear_mm=derived",
        "dynamics.mass_pinion_kg=derived",
        "dynamics.mass_gear_kg=derived",
        "dynamics.inertia_pinion_kg_m2=derived",
        "dynamics.inertia_gear_kg_m2=derived",
    ];
    let mut args = vec!["run".to_string()];
    for s in sets {
        args.extend(["--set".to_string(), s.to_string()]);
    }
    args.extend(["--out".to_string(), out.to_str().unwrap().to_string()]);
    let o = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(&args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let headline = String::from_utf8(o.stdout).unwrap();
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let text = visible_text(&html);

    // Sentences and numbers that belong to the paper's case only: its title, its
    // comparison, its load (60 N m on r_pb = 17.854 mm gives 3361 N), its mesh frequency
    // (19 x 30 Hz = 570 Hz), its old fixed mode sentence and its cycle count.
    for phrase in [
        "paper's spur pair",
        "beside the paper",
        "paper Fig.",
        "paper section",
        "Reproduction of section 4",
        "60 N m",
        "3361",
        "570 Hz",
        "850 Hz",
        "4e4",
        "40000",
    ] {
        assert!(!text.contains(phrase), "report says {phrase:?}");
        assert!(!headline.contains(phrase), "headline says {phrase:?}");
    }

    // The case's own numbers, by hand: mesh frequency z1 f_in = 25 x 40 Hz = 1000 Hz;
    // without friction the mean mesh force is T / r_pb with r_pb = m z1 cos(20 deg) / 2
    // = 35.238 mm, so 100 N m / 35.238 mm = 2838 N.
    let r_pb_mm = 3.0 * 25.0 * 20f64.to_radians().cos() / 2.0;
    let force = format!("{:.0} N", 100.0 / (r_pb_mm * 1e-3));
    assert_eq!(force, "2838 N");
    for phrase in [
        "z = 25/50, m = 3 mm, b = 30 mm",
        "100 N m on the pinion",
        "40 Hz input",
        "1000 Hz mesh frequency",
        // 35.238 mm to four significant digits (gearwear::format).
        &format!("{r_pb_mm:.2} mm = {force}"),
        "3000 cycles",
        "damped mesh pole",
    ] {
        assert!(text.contains(phrase), "report lacks {phrase:?}");
    }
    for phrase in [
        "100 N m on the pinion",
        "40 Hz input",
        "mesh frequency 1000 Hz",
    ] {
        assert!(
            headline.contains(phrase),
            "headline lacks {phrase:?}:\n{headline}"
        );
    }

    // The case table lists the values the model used where the case said "derived":
    // the blank of the pinion, a steel disk out to its pitch radius r = 37.5 mm with a
    // bore of half its root radius (33.75 / 2 mm), 30 mm wide: m = 7850 pi (37.5^2 -
    // 16.875^2) mm^2 x 30 mm = 0.8297 kg, as geometry::blank's hand check.
    for phrase in [
        "gear.hub_bore_radius_pinion_mm (mm) 16.88 (derived)",
        "dynamics.mass_pinion_kg (kg) 0.8297 (derived)",
        "torque on the pinion / gear shaft (N m) 100 / 200",
    ] {
        let squeezed = text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(squeezed.contains(phrase), "case table lacks {phrase:?}");
    }

    // summary.json: not the paper's case, with the keys that differ and the case itself.
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["paper_case"], false);
    assert!(s.get("paper_comparison").is_none());
    let differs: Vec<&str> = s["differs_from_paper_case_in"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|v| v.as_str())
        .collect();
    for k in [
        "gear.module_mm",
        "gear.teeth_pinion",
        "operating.load_torque_nm",
    ] {
        assert!(differs.contains(&k), "{differs:?}");
    }
    let case = &s["case_summary"]["case"];
    // 1e-9 relative: the product of two exact small integers in floating point.
    let f_mesh = case["mesh_frequency_hz"].as_f64().unwrap();
    assert!((f_mesh - 1000.0).abs() < 1e-9 * 1000.0, "{f_mesh}");
}
