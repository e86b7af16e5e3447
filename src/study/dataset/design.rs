//! The study design of a labelled dataset (`design.toml`, docs/SIGNALS.md "Datasets").
//!
//! ```toml
//! case = "case.toml"            # optional, relative to the design; default: built-in case
//! set = ["signals.snr_db=30"]   # optional case overrides, as --set
//! transfer_path = "frf.csv"     # optional; default: the generic housing
//! seed = 7                      # every record's noise seed derives from it
//!
//! [run_to_failure]
//! states = 5                    # states evenly spaced from 0 to the trajectory's end, or
//! cycles = [0, 1e4, 2e4]        # ... the pinion cycle counts of the states
//! max_cycles = 4e4              # longest trajectory (default: the case's wear.total_cycles)
//! wear_limit_um = 10            # failure: the deepest wear (pinion or gear) reaches this
//!
//! [operating]                   # every state is recorded at each speed x load
//! input_speed_hz = [20, 30]     # default: the case's
//! load_torque_nm = [40, 60]     # default: the case's
//!
//! [records]
//! noise_realisations = 10       # records per physical state, each its own noise
//! csv = false                   # a PHM 2009-style CSV per record as well
//! disk_budget_gib = 10          # refuse a dataset estimated larger than this
//!
//! [[condition]]                 # fault types and severities (default: one, "none")
//! name = "healthy"
//! fault = "none"
//! severity = 0.0
//! [condition.case]              # merged into the case: any keys of the case file
//! ```

use super::design_checks::{
    chain_problems, label_problems, records_problems, run_to_failure_problems, steady_problems,
    train_problems,
};
pub use super::design_file::{Condition, DatasetDesign, StateChoice};
use super::design_file::{ConditionFile, DesignFile, RunToFailureFile};
use crate::config::{load_case, Case};
use crate::io::input::InputError;
use toml::{Table, Value};

/// Problems of a design, one message each, naming the key (`design.toml: key ...`).
pub type DesignErrors = Vec<String>;

/// Most records a dataset may have: 2^53, so every record id is exact in every number
/// format that reads the index (and no count of the plan can wrap).
pub const MAX_RECORDS: u64 = 1 << 53;

/// The record count of axes of these sizes (conditions, states, speeds, loads,
/// realisations), in checked arithmetic; `None` when it overflows or exceeds
/// [`MAX_RECORDS`].
pub fn record_count(axes: &[usize]) -> Option<u64> {
    axes.iter()
        .try_fold(1_u64, |acc, n| acc.checked_mul(*n as u64))
        .filter(|n| *n <= MAX_RECORDS)
}

/// Deep merge of `over` into `base` (tables merged key by key, other values replaced).
fn merge(base: &mut Table, over: &Table) {
    for (k, v) in over {
        match (base.get_mut(k), v) {
            (Some(Value::Table(b)), Value::Table(o)) => merge(b, o),
            _ => {
                base.insert(k.clone(), v.clone());
            }
        }
    }
}

/// Parse and validate a design. `name` names the file in messages; `read` returns the
/// text of the `case` file it names (the caller resolves it against the design's folder),
/// or why it cannot (its `reason` is quoted in the message).
pub fn parse_design(
    text: &str,
    name: &str,
    read: &dyn Fn(&str) -> Result<String, InputError>,
) -> Result<DatasetDesign, DesignErrors> {
    let f: DesignFile =
        toml::from_str(text).map_err(|e| vec![format!("{name}: {}", type_error(&e, text))])?;
    let (base, base_case) = base_case(&f, name, read)?;
    let defaults = Defaults {
        max_cycles: base_case.wear.total_cycles,
        speed_hz: base_case.operating.input_speed_hz,
        torque_nm: base_case.operating.load_torque_nm,
    };
    let case_of = |c: &ConditionFile| {
        let mut t = base.clone();
        merge(&mut t, &c.case);
        let text = toml::to_string(&t).unwrap_or_default();
        load_case(&text, &f.set).map_err(|e| e.problems.iter().map(ToString::to_string).collect())
    };
    build(&f, text, name, defaults, &case_of)
}

/// What a design takes from its base case when it does not say: the longest trajectory
/// (`wear.total_cycles`) and the one speed and load of its operating axes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Defaults {
    /// Longest trajectory, pinion cycles (the base case's `wear.total_cycles`).
    pub max_cycles: f64,
    /// Input speed, Hz (the base case's `operating.input_speed_hz`).
    pub speed_hz: f64,
    /// Load torque, N m (the base case's `operating.load_torque_nm`).
    pub torque_nm: f64,
}

/// A design rebuilt from what a dataset's description keeps (a merge recomputes a shard's
/// records from it, docs/RELIABILITY.md "Datasets"): its `text`, each condition's case as
/// the description gives it (`cases`, the TOML of the case the design resolved, in the
/// conditions' order) and the `defaults` its base case gave (the description's axes; the
/// base case file itself is not kept). Checked as [`parse_design`] checks a design.
pub(crate) fn design_of_cases(
    text: &str,
    name: &str,
    cases: &[String],
    defaults: Defaults,
) -> Result<DatasetDesign, DesignErrors> {
    let f: DesignFile =
        toml::from_str(text).map_err(|e| vec![format!("{name}: {}", type_error(&e, text))])?;
    let n = f.condition.len().max(1);
    if cases.len() != n {
        return Err(vec![format!(
            "{name}: {} cases kept for {n} conditions",
            cases.len()
        )]);
    }
    let case_of = |c: &ConditionFile| {
        let i = if f.condition.is_empty() {
            0
        } else {
            f.condition
                .iter()
                .position(|o| o.name == c.name)
                .unwrap_or(0)
        };
        load_case(&cases[i], &[]).map_err(|e| e.problems.iter().map(ToString::to_string).collect())
    };
    build(&f, text, name, defaults, &case_of)
}

/// A design's checks and axes (`defaults` where it does not say), each condition's case
/// given by `case_of`.
fn build(
    f: &DesignFile,
    text: &str,
    name: &str,
    defaults: Defaults,
    case_of: &dyn Fn(&ConditionFile) -> Result<Case, Vec<String>>,
) -> Result<DatasetDesign, DesignErrors> {
    let key = |k: &str| format!("{name}: `{k}`");
    let mut p = Vec::new();
    let r = &f.run_to_failure;
    let states = state_choice(r, &key, &mut p);
    let max_cycles = r.max_cycles.unwrap_or(defaults.max_cycles);
    let wear_limit_um = r.wear_limit_um.unwrap_or(10.0);
    p.extend(run_to_failure_problems(
        &states,
        max_cycles,
        wear_limit_um,
        &key,
    ));
    let speeds_hz = axis(
        &key("operating.input_speed_hz"),
        &f.operating.input_speed_hz,
        defaults.speed_hz,
        (1e-6, 1000.0),
        &mut p,
    );
    let torques_nm = axis(
        &key("operating.load_torque_nm"),
        &f.operating.load_torque_nm,
        defaults.torque_nm,
        (1e-3, 1e7),
        &mut p,
    );
    let rec = &f.records;
    p.extend(records_problems(rec, &key));
    let conditions = conditions(f, case_of, name, &mut p);
    let states_n = match &states {
        StateChoice::Count(n) => *n,
        StateChoice::Cycles(c) => c.len(),
    };
    let axes = [
        f.condition.len().max(1),
        states_n,
        speeds_hz.len(),
        torques_nm.len(),
        usize::try_from(rec.noise_realisations).unwrap_or(0),
    ];
    if record_count(&axes).is_none() {
        p.push(format!(
            "{name}: the design has {} conditions x {} states x {} speeds x {} loads x {} noise realisations = {} records, more than the {MAX_RECORDS} (2^53) a dataset can number: make fewer",
            axes[0],
            axes[1],
            axes[2],
            axes[3],
            axes[4],
            axes.iter().fold(1.0, |a, n| a * *n as f64)
        ));
    }
    if !p.is_empty() {
        return Err(p);
    }
    Ok(DatasetDesign {
        seed: f.seed,
        transfer_path: f.transfer_path.clone().map(Into::into),
        states,
        max_cycles,
        wear_limit_um,
        speeds_hz,
        torques_nm,
        noise_realisations: rec.noise_realisations as usize,
        csv: rec.csv,
        disk_budget_gib: rec.disk_budget_gib,
        conditions,
        text: text.to_owned(),
    })
}

/// A design that does not read: the parser's words, with the key they concern when the
/// text is valid TOML (a value of the wrong type: `states = nan`), found from the
/// error's place as `[section]` and key. Nothing else of the text is quoted (a file that
/// is not a design at all must not be echoed).
fn type_error(e: &toml::de::Error, text: &str) -> String {
    let words = e.message().trim().chars().take(400).collect::<String>();
    let key = e
        .span()
        .filter(|_| text.parse::<Table>().is_ok())
        .and_then(|s| {
            let before = text.get(..s.start.min(text.len()))?;
            let line_start = before.rfind('\n').map_or(0, |i| i + 1);
            let line = text[line_start..].lines().next()?;
            let key = line.split('=').next()?.trim();
            let section = before[..line_start]
                .lines()
                .rev()
                .map(str::trim)
                .find(|l| l.starts_with('['))
                .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim());
            let plain = |k: &str| {
                !k.is_empty()
                    && k.len() <= 64
                    && k.chars()
                        .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c))
            };
            let key = match section {
                Some(sec) if plain(sec) => format!("{sec}.{key}"),
                _ => key.to_owned(),
            };
            plain(&key).then_some(key)
        });
    match key {
        Some(k) => format!("`{k}`: {words}"),
        None => words,
    }
}

/// The design's base case: the `case` file's TOML tree (the conditions merge into it)
/// and the case it gives with the design's `set` overrides.
fn base_case(
    f: &DesignFile,
    name: &str,
    read: &dyn Fn(&str) -> Result<String, InputError>,
) -> Result<(Table, Case), DesignErrors> {
    let key = format!("{name}: `case`");
    let base_text = match &f.case {
        Some(path) => read(path).map_err(|e| {
            vec![format!(
                "{key}: cannot read the case file {path}: {}",
                e.reason
            )]
        })?,
        None => String::new(),
    };
    let base: Table = toml::from_str(&base_text).map_err(|e| {
        vec![format!(
            "{key}: the case file is not valid TOML: {}",
            e.message().trim()
        )]
    })?;
    let base_case = load_case(&base_text, &f.set).map_err(|e| {
        e.problems
            .iter()
            .map(|m| format!("{name}: case: {m}"))
            .collect::<Vec<_>>()
    })?;
    Ok((base, base_case))
}

/// Which states of each trajectory are recorded (`run_to_failure.states` or `.cycles`).
fn state_choice(
    r: &RunToFailureFile,
    key: &dyn Fn(&str) -> String,
    p: &mut Vec<String>,
) -> StateChoice {
    match (&r.states, &r.cycles) {
        (Some(_), Some(_)) => {
            p.push(format!(
                "{} and `run_to_failure.cycles` are both given: choose one",
                key("run_to_failure.states")
            ));
            StateChoice::Count(1)
        }
        (Some(n), None) if !(1..=10_000).contains(n) => {
            p.push(format!(
                "{} = {n} is invalid: expected a whole number in [1, 10000]",
                key("run_to_failure.states")
            ));
            StateChoice::Count(1)
        }
        (Some(n), None) => StateChoice::Count(*n as usize),
        (None, Some(c)) => {
            if c.is_empty()
                || c.iter().any(|x| !x.is_finite() || *x < 0.0)
                || c.windows(2).any(|w| w[1] <= w[0])
            {
                p.push(format!(
                    "{} = {c:?} is invalid: expected non-negative cycle counts, strictly ascending",
                    key("run_to_failure.cycles")
                ));
            }
            StateChoice::Cycles(c.clone())
        }
        (None, None) => StateChoice::Count(1),
    }
}

/// An operating axis (`shown`: its key as messages name it): the values given, each in
/// [lo, hi], or the base case's one value `dflt`.
fn axis(
    shown: &str,
    v: &Option<Vec<f64>>,
    dflt: f64,
    (lo, hi): (f64, f64),
    p: &mut Vec<String>,
) -> Vec<f64> {
    match v {
        None => vec![dflt],
        Some(v) if v.is_empty() || v.iter().any(|x| !(lo..=hi).contains(x)) => {
            p.push(format!(
                "{shown} = {v:?} is invalid: expected a non-empty list of numbers in [{lo}, {hi}]"
            ));
            vec![dflt]
        }
        Some(v) => v.clone(),
    }
}

/// The conditions (one healthy condition when the design gives none), each its name
/// checked and its case given by `case_of` (a design file's: merged into the base case
/// and loaded with the design's `set`); their problems pushed to `p`. Compared with each
/// other (healthy against faulty), they share one load-sharing law.
fn conditions(
    f: &DesignFile,
    case_of: &dyn Fn(&ConditionFile) -> Result<Case, Vec<String>>,
    name: &str,
    p: &mut Vec<String>,
) -> Vec<Condition> {
    let mut conditions = Vec::new();
    let files = if f.condition.is_empty() {
        vec![ConditionFile {
            name: "healthy".into(),
            fault: None,
            severity: None,
            case: Table::new(),
        }]
    } else {
        f.condition.clone()
    };
    for (i, c) in files.iter().enumerate() {
        let at = format!("{name}: condition {} (`{}`)", i + 1, c.name);
        if c.name.is_empty()
            || !c
                .name
                .chars()
                .all(|ch| ch.is_ascii_alphanumeric() || ch == '_' || ch == '-')
        {
            p.push(format!(
                "{at}: `name` must be a non-empty word of letters, digits, _ and -"
            ));
        }
        if files[..i].iter().any(|o| o.name == c.name) {
            p.push(format!("{at}: `name` is used twice"));
        }
        match case_of(c) {
            Ok(case) => {
                let label = fault_label(&case);
                p.extend(label_problems(c, &label, &at));
                p.extend(steady_problems(&case, &at));
                conditions.push(Condition {
                    name: c.name.clone(),
                    severity: c.severity.unwrap_or(0.0),
                    fault: label,
                    case,
                })
            }
            Err(e) => p.extend(e.iter().map(|m| format!("{at}: {m}"))),
        }
    }
    p.extend(chain_problems(&conditions, name));
    p.extend(train_problems(&conditions, name));
    let any_per_tooth = conditions.iter().any(|c| c.case.has_per_tooth_inputs());
    for c in &mut conditions {
        c.case.share_one_law(any_per_tooth);
    }
    conditions
}

/// What a condition's case models, as its `fault` label: the kinds of its `[[fault]]`
/// tables, then of a planetary set's `[[planetary.fault]]` tables ("crack", "spall",
/// "broken_tip"; several joined by "+", in the order of the tables), else "tooth_errors" when `[teeth]` gives manufacturing errors, else "none".
pub fn fault_label(case: &Case) -> String {
    let mut kinds: Vec<&str> = Vec::new();
    let set_faults = case.planetary.iter().flat_map(|p| p.fault.iter());
    for k in case
        .fault
        .iter()
        .map(|f| f.kind().name())
        .chain(set_faults.map(|f| f.kind.name()))
    {
        if !kinds.contains(&k) {
            kinds.push(k);
        }
    }
    if !kinds.is_empty() {
        kinds.join("+")
    } else if !case.teeth.is_empty() {
        "tooth_errors".into()
    } else {
        "none".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn no_file(path: &str) -> Result<String, InputError> {
        Err(InputError {
            path: path.into(),
            reason: "no files in this test".into(),
        })
    }

    #[test]
    fn the_design_seed_takes_two_to_the_53_in_either_notation_and_names_its_range() {
        // Issue 33: 2^53 written as a float was refused by the type, with no range named.
        let design = |seed: &str| parse_design(&format!("seed = {seed}\n"), "d.toml", &no_file);
        for ok in [
            "9007199254740992",
            "0",
            "7.0",
            "4.503599627370495e15",
            "9.007199254740992e15",
        ] {
            let d = design(ok).unwrap();
            assert_eq!(d.seed as f64, ok.parse::<f64>().unwrap(), "{ok}");
        }
        for bad in ["9007199254740993", "9.1e15", "-1", "2.5", "\"7\""] {
            let e = design(bad).unwrap_err().join("; ");
            assert!(
                e.contains("`seed`") && e.contains("[0, 9007199254740992]"),
                "{bad}: {e}"
            );
        }
    }

    #[test]
    fn a_full_design_parses_and_conditions_merge_into_the_case() {
        let text = r#"
seed = 3
set = ["signals.snr_db=25"]
[run_to_failure]
cycles = [0, 1e4]
max_cycles = 2e4
wear_limit_um = 5
[operating]
input_speed_hz = [20, 30]
[records]
noise_realisations = 4
[[condition]]
name = "healthy"
[[condition]]
name = "rough"
[condition.case.surface]
roughness_table_rms_um = [0.42, 0.38, 0.30]
"#;
        let d = parse_design(text, "design.toml", &no_file).unwrap();
        assert_eq!(d.conditions.len(), 2);
        assert_eq!(
            d.conditions[1].case.surface.roughness_table_rms_um,
            vec![0.42, 0.38, 0.30]
        );
        assert_eq!(d.conditions[0].case.signals.snr_db, Some(25.0));
        assert_eq!(d.speeds_hz, vec![20.0, 30.0]);
        assert_eq!(d.torques_nm, vec![60.0]);
        assert_eq!(d.states, StateChoice::Cycles(vec![0.0, 1e4]));
    }

    #[test]
    fn healthy_and_faulty_conditions_share_one_load_sharing_law() {
        // A record of identical teeth under Pedrero's law (paper eq. 7) beside records of
        // a cracked tooth shared by compression would label a change of law as the
        // fault's signature: with a per-tooth condition present, "auto" becomes
        // "stiffness" in every condition; without one the conditions keep "auto".
        use crate::config::case::LoadSharingModel;
        let two = "[[condition]]\nname = \"healthy\"\n[[condition]]\nname = \"crack\"\nfault = \"crack\"\nseverity = 1.0\n[[condition.case.fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 0\ncrack_depth_mm = 1.0\n";
        let d = parse_design(two, "d.toml", &no_file).unwrap();
        assert!(d.conditions[1].case.has_per_tooth_inputs());
        for c in &d.conditions {
            assert_eq!(
                c.case.contact.load_sharing,
                LoadSharingModel::Stiffness,
                "{}",
                c.name
            );
        }
        let d = parse_design("[[condition]]\nname = \"healthy\"\n", "d.toml", &no_file).unwrap();
        assert_eq!(
            d.conditions[0].case.contact.load_sharing,
            LoadSharingModel::Auto
        );
    }

    #[test]
    fn a_design_rebuilt_from_its_resolved_cases_is_the_design() {
        // A merge rebuilds a shard's design from its description (the base case file is
        // not kept): the design text, each condition's case as TOML, and the defaults
        // the base case gave. The rebuilt design must be the parsed one, field by field.
        let text = "case = \"base.toml\"\nset = [\"signals.snr_db=25\"]\n[run_to_failure]\nstates = 2\n[[condition]]\nname = \"healthy\"\n[[condition]]\nname = \"rough\"\n[condition.case.surface]\nroughness_table_rms_um = [0.42, 0.38, 0.30]\n";
        let base =
            |_: &str| Ok("[operating]\nload_torque_nm = 50\ninput_speed_hz = 25\n".to_owned());
        let d = parse_design(text, "d.toml", &base).unwrap();
        let cases: Vec<String> = d
            .conditions
            .iter()
            .map(|c| toml::to_string(&c.case).unwrap())
            .collect();
        let defaults = Defaults {
            max_cycles: d.max_cycles,
            speed_hz: d.speeds_hz[0],
            torque_nm: d.torques_nm[0],
        };
        let again = design_of_cases(text, "d.toml", &cases, defaults).unwrap();
        assert_eq!(again.torques_nm, vec![50.0]);
        assert_eq!(again.speeds_hz, vec![25.0]);
        assert_eq!(again.max_cycles, d.max_cycles);
        for (a, b) in again.conditions.iter().zip(&d.conditions) {
            assert_eq!(
                toml::to_string(&a.case).unwrap(),
                toml::to_string(&b.case).unwrap()
            );
            assert_eq!(
                (&a.name, &a.fault, a.severity),
                (&b.name, &b.fault, b.severity)
            );
        }
        // A case list of another length is refused, naming the count.
        let e = design_of_cases(text, "d.toml", &cases[..1], defaults).unwrap_err();
        assert!(e[0].contains("1 cases kept for 2 conditions"), "{e:?}");
    }

    #[test]
    fn bad_designs_name_the_key() {
        let e = parse_design(
            "[run_to_failure]\ncycles = [2, 1]\n[records]\nnoise_realisations = 0\n",
            "d.toml",
            &no_file,
        )
        .unwrap_err();
        assert!(
            e.iter().any(|m| m.contains("`run_to_failure.cycles`")),
            "{e:?}"
        );
        assert!(
            e.iter()
                .any(|m| m.contains("`records.noise_realisations` = 0")),
            "{e:?}"
        );
        let e = parse_design(
            "[[condition]]\nname = \"x\"\n[condition.case.gear]\nmodule_mm = -1\n",
            "d.toml",
            &no_file,
        )
        .unwrap_err();
        assert!(
            e[0].contains("condition 1") && e[0].contains("gear.module_mm"),
            "{e:?}"
        );
        let e = parse_design("sed = 1\n", "d.toml", &no_file).unwrap_err();
        assert!(e[0].contains("sed"), "{e:?}");
    }
}
