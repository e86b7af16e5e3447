//! The sections of the case file against the schema table (`config::schema`), which
//! prints the commented template and docs/CONFIG.md: every public field of a section
//! struct is documented, is a key of the schema (and every key of a section a field), and
//! its doc names the key's unit, so the code's docs and the user's cannot disagree on it.

use super::schema::KEYS;

/// The files holding the section structs.
const SOURCES: [&str; 9] = [
    include_str!("case.rs"),
    include_str!("output.rs"),
    include_str!("planetary.rs"),
    include_str!("gear.rs"),
    include_str!("lumped.rs"),
    include_str!("operating.rs"),
    include_str!("signals.rs"),
    include_str!("teeth.rs"),
    include_str!("train.rs"),
];

/// Fields of a section that are not keys of the schema: the spectrum's bins (a table or a
/// file, read apart), the planetary set's lumped table (a sub-table, its own section
/// below) and its fault tables (`[[planetary.fault]]`: `planetary.fault.kind`, `gear`,
/// `planet` and `tooth` are schema keys; its sizes are the pair's `fault.*` keys).
const NOT_KEYS: [&str; 3] = ["load_spectrum.bins", "planetary.lumped", "planetary.fault"];

/// Sub-tables of a section whose keys are schema keys `section.sub.key`: (dotted
/// section, struct).
const SUBTABLES: [(&str, &str); 1] = [("planetary.lumped", "LumpedPlanetarySection")];

/// Keys of the schema that are not fields: the input speed in rpm, read into
/// `operating.input_speed_hz`.
const NOT_FIELDS: [&str; 1] = ["operating.input_speed_rpm"];

/// One public field: its name, type and doc text.
struct Field {
    name: String,
    ty: String,
    doc: String,
}

/// The public fields of `pub struct name` in the sources.
fn fields_of(name: &str) -> Vec<Field> {
    let head = format!("pub struct {name}");
    let text = SOURCES
        .iter()
        .find_map(|s| {
            s.find(&format!("{head} {{"))
                .or_else(|| s.find(&format!("{head}<")))
                .map(|at| &s[at..])
        })
        .unwrap_or_else(|| panic!("no `{head}` in the config sources"));
    let body = &text[..text.find("\n}").expect("struct end")];
    let mut out = Vec::new();
    let mut doc: Vec<&str> = Vec::new();
    for line in body.lines().skip(1) {
        let l = line.trim();
        if let Some(d) = l.strip_prefix("///") {
            doc.push(d.trim());
        } else if l.starts_with("#[") {
            continue;
        } else if let Some(f) = l.strip_prefix("pub ") {
            let (n, ty) = f.split_once(':').expect("field");
            out.push(Field {
                name: n.trim().into(),
                ty: ty.trim().trim_end_matches(',').into(),
                doc: doc.join(" "),
            });
            doc.clear();
        } else {
            doc.clear();
        }
    }
    out
}

/// The sections of a case: (section, the struct its keys are fields of).
fn sections() -> Vec<(String, String)> {
    fields_of("Case")
        .into_iter()
        .map(|f| {
            let ty = match f.ty.as_str() {
                "Vec<ToothFault>" => "FaultTable".to_string(),
                "Vec<StageSpec>" => "StageSpec".to_string(),
                t => t
                    .trim_start_matches("Option<")
                    .trim_end_matches('>')
                    .to_string(),
            };
            (f.name, ty)
        })
        .chain(
            SUBTABLES
                .iter()
                .map(|(s, t)| (s.to_string(), t.to_string())),
        )
        .collect()
}

/// The micrometre written either way.
fn plain(s: &str) -> String {
    s.replace('µ', "u")
}

#[test]
fn every_field_of_a_section_is_a_documented_schema_key_naming_its_unit() {
    let mut problems = Vec::new();
    for f in fields_of("Case") {
        if f.doc.is_empty() {
            problems.push(format!("`Case::{}` has no doc comment", f.name));
        }
    }
    for (section, ty) in sections() {
        let fields = fields_of(&ty);
        for f in &fields {
            let key = format!("{section}.{}", f.name);
            if f.doc.is_empty() {
                problems.push(format!("`{ty}::{}` ({key}) has no doc comment", f.name));
            }
            if NOT_KEYS.contains(&key.as_str()) {
                continue;
            }
            match KEYS.iter().find(|k| k.key == key) {
                None => problems.push(format!("`{ty}::{}`: no key `{key}` in the schema", f.name)),
                Some(k) if k.unit != "-" && !plain(&f.doc).contains(&plain(k.unit)) => problems
                    .push(format!(
                        "`{ty}::{}`: its doc does not name the unit of `{key}`, {}",
                        f.name, k.unit
                    )),
                Some(_) => {}
            }
        }
        for k in KEYS
            .iter()
            .filter(|k| k.key.starts_with(&format!("{section}.")))
        {
            let name = &k.key[section.len() + 1..];
            // A sub-table's key (`lumped.mass_sun_kg`) is checked as its own section's.
            if name.contains('.') {
                continue;
            }
            if !NOT_FIELDS.contains(&k.key) && !fields.iter().any(|f| f.name == name) {
                problems.push(format!("schema key `{}` is no field of `{ty}`", k.key));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
