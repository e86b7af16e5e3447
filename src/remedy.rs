//! Problems with their remedies, in words that each front end finishes its own way.
//!
//! A library error says what is wrong and what to do about it. The remedy often concerns
//! an argument of the job rather than a case key: the output folder, resuming, a sweep
//! axis, the run budget. The command line spells those as flags (`--out`), Python as
//! keyword arguments (`out`), so a library message never spells one: it holds an
//! [`Arg`], and the front end renders the message with its own `Spelling`
//! ([`Words::render`], [`Problem::render`]). `Display` renders plain words ("the output
//! folder") for callers of the library itself, and is what `tests/no_flags.rs` checks
//! for flags.
//!
//! Case keys (`operating.input_speed_hz`) are the same in every front end and stay in the
//! text, in backticks.

use std::fmt;
use std::path::PathBuf;

/// An argument of a job that a message can name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Arg {
    /// A `section.key=value` override of the case.
    Override,
    /// The case file.
    CaseFile,
    /// The output folder.
    Out,
    /// Continue from the checkpoints (or finished cases) in the output folder.
    Resume,
    /// A varied key of a sweep and its values.
    Vary,
    /// One shard of a sweep or prediction.
    Shard,
    /// Following solution branches in a sweep.
    Continuation,
    /// What each case of a sweep runs.
    SweepRun,
    /// An external transmission error.
    TransmissionError,
    /// The observations of a calibration.
    Observations,
    /// The posterior samples of a prediction.
    Posterior,
    /// A number of samples.
    Samples,
    /// Walkers of the ensemble sampler.
    Walkers,
    /// Steps of the ensemble sampler.
    Steps,
    /// True wear runs to check a surrogate against.
    CheckRuns,
    /// Cycle counts of the fan charts.
    GridPoints,
    /// The wear limit of a prediction.
    LimitUm,
    /// The horizon of a prediction.
    Cycles,
    /// The scale of the run budget.
    BudgetScale,
    /// Running without the budget check.
    NoBudget,
    /// The inputs of a merge.
    Inputs,
    /// Replacing an output folder that holds another command's results.
    Replace,
    /// A measured load-time history.
    History,
    /// Torque classes of a load duration distribution.
    TorqueClasses,
    /// Speed classes of a load duration distribution.
    SpeedClasses,
    /// The longest interval of a history, in median intervals.
    GapFactor,
    /// The share of the revolutions below which a spectrum's bins are merged.
    MergeBelowShare,
    /// A transfer-path file of the signal chain.
    TransferPath,
    /// The study design of a dataset.
    Design,
    /// The load spectrum of a prediction's future duty.
    FutureSpectrum,
    /// The cycle count from which a prediction's future duty applies.
    FutureFromCycles,
    /// The formats figures are written in.
    FigureFormats,
    /// The size of the figures.
    FigureSize,
}

/// How a front end spells an argument in its messages.
pub(crate) type Spelling = fn(Arg) -> &'static str;

impl Arg {
    /// Every argument.
    pub const ALL: [Arg; 33] = [
        Arg::Override,
        Arg::CaseFile,
        Arg::Out,
        Arg::Resume,
        Arg::Vary,
        Arg::Shard,
        Arg::Continuation,
        Arg::SweepRun,
        Arg::TransmissionError,
        Arg::Observations,
        Arg::Posterior,
        Arg::Samples,
        Arg::Walkers,
        Arg::Steps,
        Arg::CheckRuns,
        Arg::GridPoints,
        Arg::LimitUm,
        Arg::Cycles,
        Arg::BudgetScale,
        Arg::NoBudget,
        Arg::Inputs,
        Arg::Replace,
        Arg::History,
        Arg::TorqueClasses,
        Arg::SpeedClasses,
        Arg::GapFactor,
        Arg::MergeBelowShare,
        Arg::TransferPath,
        Arg::Design,
        Arg::FutureSpectrum,
        Arg::FutureFromCycles,
        Arg::FigureFormats,
        Arg::FigureSize,
    ];

    /// Plain words for the argument, naming no front end's syntax.
    pub fn plain(self) -> &'static str {
        match self {
            Arg::Override => "override",
            Arg::CaseFile => "the case file",
            Arg::Out => "the output folder",
            Arg::Resume => "resuming",
            Arg::Vary => "sweep axis",
            Arg::Shard => "shard",
            Arg::Continuation => "continuation",
            Arg::SweepRun => "sweep run",
            Arg::TransmissionError => "transmission error",
            Arg::Observations => "observations",
            Arg::Posterior => "posterior samples",
            Arg::Samples => "samples",
            Arg::Walkers => "walkers",
            Arg::Steps => "sampler steps",
            Arg::CheckRuns => "check runs",
            Arg::GridPoints => "fan grid points",
            Arg::LimitUm => "wear limit (µm)",
            Arg::Cycles => "horizon (cycles)",
            Arg::BudgetScale => "a budget scale",
            Arg::NoBudget => "no budget check",
            Arg::Inputs => "inputs",
            Arg::Replace => "replacing another command's results",
            Arg::History => "the load-time history",
            Arg::TorqueClasses => "torque classes",
            Arg::SpeedClasses => "speed classes",
            Arg::GapFactor => "the gap limit",
            Arg::MergeBelowShare => "the share below which bins are merged",
            Arg::TransferPath => "the transfer-path file",
            Arg::Design => "the dataset design",
            Arg::FutureSpectrum => "the future load spectrum",
            Arg::FutureFromCycles => "the cycles the future duty starts at",
            Arg::FigureFormats => "the figure formats",
            Arg::FigureSize => "the figure size",
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Piece {
    Text(String),
    Arg(Arg),
}

/// Text that may name job arguments (see the module docs).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Words(Vec<Piece>);

impl Words {
    /// Empty text.
    pub fn new() -> Self {
        Self::default()
    }

    /// Append text.
    pub fn text(mut self, t: impl Into<String>) -> Self {
        self.0.push(Piece::Text(t.into()));
        self
    }

    /// Append an argument, spelled by the renderer.
    pub fn arg(mut self, a: Arg) -> Self {
        self.0.push(Piece::Arg(a));
        self
    }

    /// The text with every argument spelled by `spell`.
    pub fn render(&self, spell: Spelling) -> String {
        self.0
            .iter()
            .map(|p| match p {
                Piece::Text(t) => t.as_str(),
                Piece::Arg(a) => spell(*a),
            })
            .collect()
    }

    /// The arguments the text names.
    pub fn args(&self) -> Vec<Arg> {
        self.0
            .iter()
            .filter_map(|p| match p {
                Piece::Arg(a) => Some(*a),
                Piece::Text(_) => None,
            })
            .collect()
    }

    /// Whether the text is empty.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl From<String> for Words {
    fn from(s: String) -> Self {
        Words::new().text(s)
    }
}

impl From<&str> for Words {
    fn from(s: &str) -> Self {
        Words::new().text(s)
    }
}

impl fmt::Display for Words {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Arg::plain))
    }
}

/// What to do about a problem: the action in words, and, where the action concerns one,
/// the case key to change and the file or folder concerned.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Remedy {
    /// What to do, in words that may name job arguments.
    pub action: Words,
    /// The case key to change, dotted (`section.key`), when the action concerns one.
    pub key: Option<String>,
    /// The file or folder concerned, when the action concerns one.
    pub path: Option<PathBuf>,
}

impl Remedy {
    /// A remedy that is the action `action` alone.
    pub fn new(action: impl Into<Words>) -> Self {
        Self {
            action: action.into(),
            ..Default::default()
        }
    }

    /// `action`, done through argument `arg`: "choose a folder you can write to (--out)".
    pub(crate) fn via(action: &str, arg: Arg) -> Self {
        Self::new(Words::new().text(format!("{action} (")).arg(arg).text(")"))
    }

    /// Name the case key `key` the action concerns.
    pub fn key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }

    /// Name the file or folder `path` the action concerns.
    pub fn path(mut self, path: impl Into<PathBuf>) -> Self {
        self.path = Some(path.into());
        self
    }

    /// An action on the output folder: "choose a folder you can write to (--out)".
    pub fn output(action: &str) -> Self {
        Self::via(action, Arg::Out)
    }

    /// Start afresh instead of resuming: "rerun without --resume".
    pub(crate) fn start_afresh() -> Self {
        Self::new(Words::new().text("rerun without ").arg(Arg::Resume))
    }
}

/// A problem with the input of a job: the argument at fault (with its value as given), what
/// is wrong, and what to do.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Problem {
    /// The job argument at fault, if the problem concerns one.
    pub arg: Option<Arg>,
    /// The argument's value as given, quoted after it.
    pub given: Option<String>,
    /// What is wrong, in words that may name job arguments.
    pub what: Words,
    /// Boxed: most problems have none, and errors stay small.
    pub remedy: Option<Box<Remedy>>,
}

impl Problem {
    /// A problem that concerns no argument (a case key named in the text, a file).
    pub fn new(what: impl Into<Words>) -> Self {
        Self {
            what: what.into(),
            ..Default::default()
        }
    }

    /// A problem with argument `arg`.
    pub fn of(arg: Arg, what: impl Into<Words>) -> Self {
        Self {
            arg: Some(arg),
            ..Self::new(what)
        }
    }

    /// A problem with the value `given` of argument `arg`.
    pub fn given(arg: Arg, given: impl Into<String>, what: impl Into<Words>) -> Self {
        Self {
            given: Some(given.into()),
            ..Self::of(arg, what)
        }
    }

    /// Attach what to do about the problem.
    pub fn remedy(mut self, r: Remedy) -> Self {
        self.remedy = Some(Box::new(r));
        self
    }

    /// The message: `ARG GIVEN: what; remedy`, arguments spelled by `spell`.
    pub fn render(&self, spell: Spelling) -> String {
        let mut s = match (self.arg, &self.given) {
            (Some(a), Some(g)) => format!("{} {g}: ", spell(a)),
            (Some(a), None) => format!("{}: ", spell(a)),
            _ => String::new(),
        };
        s.push_str(&self.what.render(spell));
        if let Some(r) = &self.remedy {
            s.push_str("; ");
            s.push_str(&r.action.render(spell));
        }
        s
    }

    /// The same problem with `context` put before what is wrong ("case 3 (...): ").
    pub(crate) fn in_context(mut self, context: &str) -> Self {
        let mut w = Words::new().text(context.to_owned());
        w.0.extend(self.what.0);
        self.what = w;
        self
    }
}

impl From<String> for Problem {
    fn from(s: String) -> Self {
        Problem::new(s)
    }
}

impl From<&str> for Problem {
    fn from(s: &str) -> Self {
        Problem::new(s)
    }
}

impl From<Words> for Problem {
    fn from(w: Words) -> Self {
        Problem::new(w)
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Arg::plain))
    }
}

impl std::error::Error for Problem {}

/// Every problem a check of one input found (a file's rows, a table's keys), in the order
/// found: the error of a library function that reports all it finds rather than the first.
/// The application edge takes them as they are (`JobError::Input`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Problems(pub Vec<Problem>);

impl Problems {
    /// The messages in plain words, one per problem.
    pub fn messages(&self) -> Vec<String> {
        self.0.iter().map(Problem::to_string).collect()
    }
}

impl From<Vec<String>> for Problems {
    fn from(messages: Vec<String>) -> Self {
        Problems(messages.into_iter().map(Problem::from).collect())
    }
}

impl From<Problem> for Problems {
    fn from(p: Problem) -> Self {
        Problems(vec![p])
    }
}

impl fmt::Display for Problems {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.messages().join("\n"))
    }
}

impl std::error::Error for Problems {}

#[cfg(test)]
mod tests {
    use super::*;

    fn flags(a: Arg) -> &'static str {
        match a {
            Arg::Out => "--out",
            Arg::Vary => "--vary",
            _ => "--x",
        }
    }

    #[test]
    fn each_front_end_spells_the_arguments() {
        let p = Problem::given(Arg::Vary, "a.b=1:0:1", "empty range")
            .remedy(Remedy::output("choose a folder you can write to"));
        assert_eq!(
            p.render(flags),
            "--vary a.b=1:0:1: empty range; choose a folder you can write to (--out)"
        );
        assert_eq!(
            p.to_string(),
            "sweep axis a.b=1:0:1: empty range; choose a folder you can write to (the output folder)"
        );
        assert_eq!(p.what.args(), Vec::<Arg>::new());
        assert_eq!(p.remedy.unwrap().action.args(), vec![Arg::Out]);
    }
}
