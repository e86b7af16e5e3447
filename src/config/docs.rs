//! The schema as text: the commented case (`gearwear config`, `--new-pair`) and the key
//! reference `docs/CONFIG.md` (`gearwear config --markdown`).

use super::case::Case;
use super::schema::{KEYS, OPTIONAL_SECTIONS, TABLE_ARRAYS};

/// How the key reference shows the default of a key the default case leaves out: the
/// per-tooth inputs are absent (perfect teeth), the others derived by the model.
fn absent_default(section: &str) -> &'static str {
    match section {
        "teeth" | "modification" | "fault" | "planetary" => "(none)",
        _ => "(derived)",
    }
}
use toml::{Table, Value};

/// The value of `key` (dotted within its section: `lumped.mass_sun_kg`) in `section`.
fn lookup<'a>(tree: &'a Table, section: &str, key: &str) -> Option<&'a Value> {
    key.split('.')
        .try_fold(tree.get(section)?, |v, part| v.as_table()?.get(part))
}

fn tree_of(case: &Case) -> Table {
    let mut t = match Value::try_from(case) {
        Ok(Value::Table(t)) => t,
        _ => Table::new(),
    };
    // A section left out of the serialisation while it holds its defaults is shown too.
    if !t.contains_key("signals") {
        if let Ok(v) = Value::try_from(&case.signals) {
            t.insert("signals".into(), v);
        }
    }
    if !t.contains_key("output") {
        if let Ok(v) = Value::try_from(&case.output) {
            t.insert("output".into(), v);
        }
    }
    t
}

/// One key of `section` as commented TOML: its doc line, then its value in `table` or a
/// commented `(unset)`.
fn key_lines(out: &mut String, s: &super::schema::KeySpec, key: &str, table: Option<&Value>) {
    out.push_str(&format!(
        "# {} [{}] Valid: {}.\n",
        s.doc,
        s.unit,
        s.valid.describe()
    ));
    // A sub-table's key is dotted (`lumped.mass_sun_kg` in `[planetary]`).
    let value = table.and_then(|t| {
        key.split('.')
            .try_fold(t, |v, part| v.as_table()?.get(part))
    });
    match value {
        Some(v) => out.push_str(&format!("{key} = {v}\n")),
        None => out.push_str(&format!("# {key} = (unset)\n")),
    }
}

/// The entries of `table` no schema key of its section covers (a sub-table such as
/// `[planetary.lumped]`), as inline TOML, so nothing of the case is lost.
fn uncovered_lines(out: &mut String, section: &str, table: Option<&Value>) {
    let Some(Value::Table(t)) = table else { return };
    for (k, v) in t {
        // A schema key `section.k` or `section.k.sub` (a sub-table's dotted key) covers k.
        let covered = KEYS.iter().any(|s| {
            s.key.split_once('.').is_some_and(|(sec, rest)| {
                sec == section && rest.split('.').next() == Some(k.as_str())
            })
        });
        if !covered && k != "bins" {
            out.push_str(&format!("{k} = {v}\n"));
        }
    }
}

/// `case` as commented TOML under `header`: every key with its unit, meaning and range.
/// Reads back to the same case: the `[[stage]]` and `[[fault]]` tables the case has are
/// written one by one, and sections or sub-tables the schema does not list as they are.
fn commented(case: &Case, header: &str) -> String {
    let tree = tree_of(case);
    let mut out = String::from(header);
    let sections: Vec<&str> = {
        let mut v: Vec<&str> = Vec::new();
        for s in KEYS {
            let section = s.key.split_once('.').map_or("", |(a, _)| a);
            if v.last() != Some(&section) {
                v.push(section);
            }
        }
        v
    };
    for section in &sections {
        let specs: Vec<_> = KEYS
            .iter()
            .filter(|s| s.key.split_once('.').map_or("", |(a, _)| a) == *section)
            .collect();
        let key_of = |s: &super::schema::KeySpec| {
            s.key.split_once('.').map_or(s.key, |(_, k)| k).to_string()
        };
        if TABLE_ARRAYS.contains(section) {
            out.push_str(&format!(
                "\n# [[{section}]]  (one table per {section}, none by default; uncomment to add one)\n"
            ));
            let elements = match tree.get(*section) {
                Some(Value::Array(a)) => a.clone(),
                _ => Vec::new(),
            };
            if elements.is_empty() {
                for s in &specs {
                    key_lines(&mut out, s, &key_of(s), None);
                }
            }
            for e in &elements {
                out.push_str(&format!("[[{section}]]\n"));
                for s in &specs {
                    key_lines(&mut out, s, &key_of(s), Some(e));
                }
                uncovered_lines(&mut out, section, Some(e));
            }
            continue;
        }
        let table = tree.get(*section);
        // A section whose mere presence changes the model (`[planetary]`): its header is
        // commented while the case has none, so the text reads back to the same case.
        if table.is_none() && OPTIONAL_SECTIONS.contains(section) {
            out.push_str(&format!(
                "\n# [{section}]  (optional, absent by default; uncomment to add one, docs/CONFIG.md)\n"
            ));
        } else {
            out.push_str(&format!("\n[{section}]\n"));
        }
        // The spectrum's bins are a list of tables, not a schema key: written as the
        // resolved inline list (a `file` read, hours and rpm converted), so the text
        // reads back to the same case.
        if let Some(bins) = table.and_then(|t| t.get("bins")) {
            out.push_str(&format!(
                "# The bins: torque_nm [N m], input_speed_hz [Hz], share of the load cycles.\nbins = {bins}\n"
            ));
        }
        for s in &specs {
            key_lines(&mut out, s, &key_of(s), table);
        }
        uncovered_lines(&mut out, section, table);
    }
    // Whole sections the schema does not list (none is lost).
    for (k, v) in &tree {
        if !sections.contains(&k.as_str()) {
            if let Value::Table(t) = v {
                let mut one = Table::new();
                one.insert(k.clone(), Value::Table(t.clone()));
                out.push_str(&format!("\n{one}"));
            }
        }
    }
    out
}

/// The case as commented TOML (`gearwear config`).
pub fn commented_template(case: &Case) -> String {
    commented(
        case,
        "# gearwear case file. Defaults: the paper's case (Coatings 2022, 12, 1250).\n\
         # Every key is optional; an omitted key takes the value shown.\n",
    )
}

/// A case for a pair of one's own (`gearwear config --new-pair`): the built-in case with
/// the hub bores, masses and inertias of pinion and gear set to "derived".
pub fn new_pair_template() -> String {
    commented(
        &Case::new_pair_template(),
        "# gearwear case file for a new gear pair: edit [gear] (and the operating point).\n\
         # Values set to \"derived\" follow the geometry: hub bores r_int = r_f / 2\n\
         # (h_f = 2, mid-range of Sainsot's fillet-foundation fit); masses and polar\n\
         # inertias of solid blanks of the face width between the bore and the pitch\n\
         # circle, with dynamics.blank_density_kg_per_m3 (docs/MODEL.md, section 7).\n\
         # Give a number instead to use your own value. The other values are the paper's\n\
         # (Coatings 2022, 12, 1250); motor and brake inertias cannot follow the geometry:\n\
         # set them for your drive. Every key is optional; an omitted key takes the\n\
         # built-in (paper's) value, not the one shown here.\n",
    )
}

/// How a case may be written, for the reference page.
const FORM: &str = "\
## Form of a case

- A case is a TOML file (`--config`) and/or `--set section.key=value` overrides on top of
  the built-in case (the paper's). Every key is optional.
- A section may be written as a `[section]` table, an inline table
  (`gear = { module_mm = 3 }`) or dotted keys (`gear.module_mm = 3`): TOML defines the
  three as the same table, so they give the same case. Anything else in a section's place
  (a number, an array of tables `[[gear]]`) is an error, as are unknown sections and keys.
- Tooth faults are the one array of tables: one `[[fault]]` table per fault, each with
  `kind`, `gear`, `tooth` and its kind's own keys (below). An override
  `--set fault.KEY=value` sets the key of the case's only fault (and makes one when there
  is none), so a sweep can vary a fault's size; with several faults,
  `--set fault.N.KEY=value` sets the key of the N-th (from 1), and likewise
  `--set stage.N.KEY=value` for the N-th `[[stage]]` table of a gear train.
- The per-tooth inputs (`[teeth]`, `[modification]`, `[[fault]]`) are absent by default:
  the paper's perfect, identical teeth. Arrays of one value per tooth must have as many
  values as the gear has teeth (an error names both numbers).
- Number keys accept integers (`30`) and decimals (`30.0`); whole-number keys accept
  `25` and `25.0`, not `25.5`. Infinite, NaN and subnormal numbers (below 2.2e-308 in
  magnitude) are rejected everywhere, arrays included.
- Units: names that programs read carry their unit as an ASCII suffix (keys such as
  `wear.threshold_um`, the CSV columns such as `max_wear_pinion_um`, JSON keys, flags
  such as `--limit-um`, the units of a dataset's index), so no reader needs a non-ASCII
  character; text meant for people (the unit column below, messages, reports, figures,
  these docs) writes the micrometre µm.
- A `--set` value is one line of TOML (a bare word is read as a string). A line break or
  another control character in it is an error: multi-line values belong in a `--config`
  file. Values echoed in error messages are cut to 80 characters.
- `\"derived\"` is accepted by the hub bores and the pinion's and gear's masses and
  inertias: the model computes them from the geometry (`gearwear config --new-pair` prints
  a case that uses it; docs/MODEL.md, section 7).
- `[load_spectrum]` (optional) gives the duty cycle as bins of torque, speed and share
  instead of the single operating point (docs/MODEL.md, section 10):
  `bins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 80, input_speed_hz = 45, share = 0.3}]`,
  or `file = \"spectrum.csv\"` with a header of those names (a relative path is read from the
  case file's folder). Per bin, `input_speed_rpm` may replace `input_speed_hz`
  (Hz = rpm / 60) and `hours` may replace `share` (the cycles of bin i are 3600 h_i f_i,
  its share h_i f_i / sum h_j f_j), the same choice at every bin. Torques are on
  `load_spectrum.torque_shaft`; the shares must sum to 1 (within 1e-6), the hours to more
  than 0; each bin's torque and speed, scales applied, must lie in the ranges of
  `operating.load_torque_nm` and `operating.input_speed_hz`. A resolved case (every
  `summary.json`) holds the bins inline, in Hz and shares. The studies that accumulate wear
  use the spectrum (wear, run, calibrate, predict, sweeps with `--run wear`, where
  `load_spectrum.torque_scale` and `speed_scale` are sweep axes); `stiffness` and
  `dynamics` use `[operating]`. `gearwear load-spectrum --history FILE --out DIR` turns a
  measured torque / speed history into `spectrum.csv` for `file` and `load_spectrum.toml`
  to paste (example: examples/duty_cycle/).
- Beyond these ranges, a case is checked against its geometry (a bore inside the root
  circle, teeth that touch, a Hertz pressure below 10 GPa, a friction coefficient below 1,
  Sainsot's fitted range) and its cost against the run budget (`--budget-scale`, `--no-budget`;
  docs/RELIABILITY.md) before anything is computed. Every problem exits with code 2 and a
  message naming the key.

## Keys

";

/// `docs/CONFIG.md` body: how a case is written, and a table of every key.
pub fn markdown_reference(case: &Case) -> String {
    // The spectrum's scalar keys show their defaults (the section is absent by default).
    let mut shown = case.clone();
    if shown.load_spectrum.is_none() {
        shown.load_spectrum = Some(super::LoadSpectrumSection::of_bins(Vec::new()));
    }
    // The planetary set's keys show the built-in set's values (the section is absent by
    // default).
    if shown.planetary.is_none() {
        shown.planetary = Some(super::planetary::PlanetarySection::default());
    }
    let tree = tree_of(&shown);
    let mut out = String::from(
        "# Case file reference\n\n\
         Generated from `src/config/schema.rs` by `gearwear config --markdown`; \
         a test keeps this file equal to that output.\n\n",
    );
    out.push_str(FORM);
    out.push_str(
        "| key | unit | default | valid | meaning | why this range |\n|---|---|---|---|---|---|\n",
    );
    for s in KEYS {
        let (section, key) = s.key.split_once('.').unwrap_or(("", s.key));
        let default = lookup(&tree, section, key)
            .map(|v| v.to_string())
            .unwrap_or_else(|| absent_default(section).into());
        out.push_str(&format!(
            "| `{}` | {} | `{}` | {} | {} | {} |\n",
            s.key,
            s.unit,
            default,
            s.valid.describe(),
            s.doc.replace('|', "\\|"),
            s.reason.replace('|', "\\|")
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;

    /// Round trip (an invariant, independent of the printed text): a case with a load
    /// spectrum, written as its template, reads back to the same case, bins included.
    #[test]
    fn a_case_with_a_load_spectrum_parses_back_to_itself() {
        let case = load_case(
            "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, \
             {torque_nm = 80, input_speed_hz = 45, share = 0.3}]\ntorque_scale = 1.2\n",
            &[],
        )
        .unwrap();
        assert_eq!(case.load_spectrum.as_ref().map(|s| s.bins.len()), Some(2));
        assert_eq!(load_case(&commented_template(&case), &[]).unwrap(), case);
    }

    #[test]
    fn templates_parse_back_to_their_cases() {
        let t = commented_template(&Case::default());
        assert_eq!(load_case(&t, &[]).unwrap(), Case::default());
        assert_eq!(
            load_case(&new_pair_template(), &[]).unwrap(),
            Case::new_pair_template()
        );
        // Every spec key is a real field (the template prints a value or the optional marker).
        for s in KEYS {
            let key = s.key.split_once('.').unwrap().1;
            assert!(t.contains(&format!("{key} =")), "{key} missing in template");
        }
    }

    #[test]
    fn new_pair_template_says_derived_where_the_geometry_gives_the_value() {
        let t = new_pair_template();
        for key in [
            "hub_bore_radius_pinion_mm",
            "hub_bore_radius_gear_mm",
            "mass_pinion_kg",
            "mass_gear_kg",
            "inertia_pinion_kg_m2",
            "inertia_gear_kg_m2",
        ] {
            assert!(t.contains(&format!("{key} = \"derived\"")), "{key}");
        }
        assert!(t.contains("inertia_motor_kg_m2 = 0.0021"));
    }
}
