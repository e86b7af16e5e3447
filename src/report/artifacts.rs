//! What a command produces, before it is written: the summary, the tables, the figures,
//! other documents, and the short text a user sees. Built by pure functions of the results
//! (`report::{stiffness, dynamics, wear, paper, sweep}`) that the command line and the
//! Python binding share; written by [`write_artifacts`] into an output set.

// The default size of a figure is figure_output's; re-exported where figures are written.
pub use super::figure_output::{plot_height, PLOT_H, PLOT_W};

use super::figure_output::FigureOutput;
use super::plot::{render_png, render_svg, Figure, PlotError};
use crate::io::{OutputDir, OutputError, Table};
use crate::store::RunMetadata;
use rayon::prelude::*;
use std::path::PathBuf;

/// A figure and the file it goes to.
pub struct FigureFile {
    /// Path relative to the output folder, ending in `.png`.
    pub path: String,
    /// The figure to render.
    pub figure: Figure,
    /// Image width, px.
    pub width_px: u32,
    /// Image height, px.
    pub height_px: u32,
    /// The table (its path in [`Artifacts::tables`]) that holds exactly the plotted
    /// numbers, each curve's x and y a column in the plotted unit.
    pub data: Option<String>,
    /// The files, when already rendered (a report embeds each figure, and the same bytes
    /// are written once).
    pub rendered: Option<Rendered>,
}

/// A figure rendered in the formats and size a job asked for.
#[derive(Debug, Clone, Default)]
pub struct Rendered {
    /// Width and height of the images, px.
    pub size_px: (u32, u32),
    /// PNG file bytes, when PNG was asked.
    pub png: Option<Vec<u8>>,
    /// SVG document, when SVG was asked.
    pub svg: Option<String>,
}

impl Rendered {
    /// `figure` rendered as `how` says, its default size being `default` (w, h) px.
    pub fn of(
        figure: &Figure,
        default: (u32, u32),
        how: FigureOutput,
        path: &str,
    ) -> Result<Self, WriteError> {
        let (w, h) = how.size_of(default);
        let plot = |source| WriteError::Plot {
            path: path.to_owned(),
            source,
        };
        let (png, svg) = rayon::join(
            || how.png.then(|| render_png(figure, w, h)).transpose(),
            || how.svg.then(|| render_svg(figure, w, h)).transpose(),
        );
        Ok(Self {
            size_px: (w, h),
            png: png.map_err(plot)?,
            svg: svg.map_err(plot)?,
        })
    }

    /// What a report embeds: the PNG, or the SVG when only SVG was asked, so a report
    /// never shows a format that was not written.
    pub fn block(&self, caption: String, csv_name: Option<String>) -> super::html::FigureBlock {
        super::html::FigureBlock {
            caption,
            png: self.png.clone().unwrap_or_default(),
            svg: self.svg.clone().filter(|_| self.png.is_none()),
            csv_name,
        }
    }
}

/// Everything one command writes.
#[derive(Default)]
pub struct Artifacts {
    /// The content of `summary.json` (the numbers a user or a script reads).
    pub summary: serde_json::Value,
    /// The file the summary is written to, when not `summary.json` (a sweep's
    /// `sweep.json`, a prediction shard's `predict_shard_I_of_N.json`).
    pub summary_file: Option<String>,
    /// CSV tables by relative path.
    pub tables: Vec<(String, Table)>,
    /// Figures with their file paths.
    pub figures: Vec<FigureFile>,
    /// Other files (e.g. `report.html`) by relative path.
    pub documents: Vec<(String, Vec<u8>)>,
    /// A few lines for standard output: the headline results.
    pub headline: String,
    /// The formats and size the figures are written in (PNG at the default size unless
    /// the job asks otherwise).
    pub figure_output: FigureOutput,
}

impl Artifacts {
    /// Add a table at `path` (`NAME.csv`); a long one (a hunting period's time series, a
    /// long wear history) goes to `NAME.parquet` instead (`decimate::long_table_path`).
    pub fn table(&mut self, path: impl Into<String>, t: Table) {
        let path = path.into();
        let path = match path.strip_suffix(".csv") {
            Some(stem) => super::decimate::long_table_path(stem, &t),
            None => path,
        };
        self.tables.push((path, t));
    }

    /// Add a per-point table of a run (its time series, its path of contact) at `path`
    /// (`NAME.csv`): as [`Artifacts::table`] when `full` or when short; a long one
    /// (over `decimate::MAX_CSV_CELLS` values) goes to `NAME.parquet` at every k-th row
    /// (`decimate::thinning_stride`). Returns, for a thinned table, what `summary.json`
    /// states of it: the file, the rows computed and written, and k.
    pub fn per_point_table(
        &mut self,
        path: &str,
        t: Table,
        full: bool,
    ) -> Option<serde_json::Value> {
        let k = super::decimate::thinning_stride(&t);
        if full || k == 1 {
            self.table(path, t);
            return None;
        }
        let stem = path.strip_suffix(".csv").unwrap_or(path);
        // The path of the whole table (Parquet, or CSV when a column is not finite).
        let file = super::decimate::long_table_path(stem, &t);
        let rows = t.rows();
        let thinned = super::decimate::thin_table(t, k);
        let note = serde_json::json!({
            "file": file,
            "rows_computed": rows,
            "rows_written": thinned.rows(),
            "every_kth_row": k,
        });
        self.tables.push((file, thinned));
        Some(note)
    }

    /// Add a figure of the default size for its number of panels.
    pub fn figure(&mut self, path: impl Into<String>, figure: Figure) {
        let h = plot_height(figure.panels.len());
        self.figure_sized(path, figure, PLOT_W, h);
    }

    /// Add a figure of `w` x `h` px.
    pub fn figure_sized(&mut self, path: impl Into<String>, figure: Figure, w: u32, h: u32) {
        self.figures.push(FigureFile {
            path: path.into(),
            figure,
            width_px: w,
            height_px: h,
            data: None,
            rendered: None,
        });
    }

    /// Add a figure of the default size and the table of its data, at `csv/STEM.csv` for a
    /// figure `STEM.png`. Long series (over `decimate::MAX_FIGURE_POINTS` points) are
    /// drawn and tabled by their extremes (`report::decimate`).
    pub fn figure_with_data(&mut self, path: impl Into<String>, figure: Figure, data: Table) {
        let (figure, data) = (
            super::decimate::decimate_figure(figure),
            super::decimate::decimate_table(data),
        );
        let path = path.into();
        let stem = path.trim_end_matches(".png");
        self.table(
            format!("csv/{}.csv", stem.rsplit('/').next().unwrap_or(stem)),
            data,
        );
        // The path the table took (CSV, or Parquet when long).
        let data_path = self.tables.last().map(|(p, _)| p.clone());
        self.figure(path.clone(), figure);
        if let Some(f) = self.figures.last_mut() {
            f.data = data_path;
        }
    }

    /// These artifacts with their figures written as `f` says.
    pub fn with_figure_output(mut self, f: FigureOutput) -> Self {
        self.figure_output = f;
        self
    }

    /// What these artifacts write, in words for the results line: "report, summary,
    /// 13 figures, 17 tables" (other documents by name, or counted when more than three).
    pub fn contents_words(&self) -> String {
        let mut parts = Vec::new();
        let (reports, others): (Vec<&str>, Vec<&str>) = self
            .documents
            .iter()
            .map(|(p, _)| p.as_str())
            .partition(|p| p.ends_with("report.html"));
        if !reports.is_empty() {
            parts.push("report".to_owned());
        }
        if !self.summary.is_null() {
            parts.push("summary".to_owned());
        }
        let count = |n: usize, one: &str, many: &str| match n {
            0 => None,
            1 => Some(format!("1 {one}")),
            n => Some(format!("{n} {many}")),
        };
        parts.extend(count(self.figures.len(), "figure", "figures"));
        parts.extend(count(self.tables.len(), "table", "tables"));
        if others.len() <= 3 {
            parts.extend(others.iter().map(|p| p.to_string()));
        } else {
            parts.extend(count(others.len(), "other file", "other files"));
        }
        parts.join(", ")
    }

    /// The table at `path`, if present.
    pub fn table_at(&self, path: &str) -> Option<&Table> {
        self.tables.iter().find(|(p, _)| p == path).map(|(_, t)| t)
    }

    /// Stamp the run's metadata on the summary as `metadata` (unless the builder already
    /// did, as `run` does for its report footer). The command line and the Python binding
    /// both call this, so they hand out the same summary.
    pub fn stamp_metadata(&mut self, meta: &RunMetadata) -> Result<(), serde_json::Error> {
        if self.summary.get("metadata").is_none() {
            self.summary["metadata"] = serde_json::to_value(meta)?;
        }
        Ok(())
    }
}

/// A figure of a report: its file stem, the figure, the table of exactly its data, and
/// its caption.
pub struct EmbeddedFigure {
    /// File stem (the figure goes to `STEM.png`/`STEM.svg`, its data to `csv/STEM.csv`).
    pub stem: String,
    /// The figure.
    pub figure: Figure,
    /// Exactly the plotted numbers.
    pub table: Table,
    /// Caption in the report (plain text).
    pub caption: String,
}

/// Render `figs` once (in parallel), in the formats and size of `a.figure_output`, and
/// add each to `a` as `STEM.png`/`STEM.svg` with its data at `csv/STEM.csv`; the blocks
/// that embed the same bytes in a report, in order (a figure that fails to render shows
/// as unavailable).
pub fn embed_figures(
    a: &mut Artifacts,
    figs: Vec<EmbeddedFigure>,
) -> Vec<super::html::FigureBlock> {
    let how = a.figure_output;
    let mut files: Vec<FigureFile> = figs
        .iter()
        .map(|f| FigureFile {
            path: format!("{}.png", f.stem),
            figure: f.figure.clone(),
            width_px: PLOT_W,
            height_px: plot_height(f.figure.panels.len()),
            data: Some(format!("csv/{}.csv", f.stem)),
            rendered: None,
        })
        .collect();
    files.par_iter_mut().for_each(|f| {
        f.rendered = Rendered::of(&f.figure, (f.width_px, f.height_px), how, &f.path).ok();
    });
    let mut blocks = Vec::new();
    for (f, file) in figs.into_iter().zip(&files) {
        let csv = format!("csv/{}.csv", f.stem);
        a.table(csv.clone(), f.table);
        let r = file.rendered.clone().unwrap_or_default();
        blocks.push(r.block(f.caption, Some(csv)));
    }
    a.figures.extend(files);
    blocks
}

/// Render one figure of default size `default` (w, h) px now, in the formats and size of
/// `a.figure_output`, add it to `a` at `path` (`NAME.png`; `NAME.svg` beside or instead)
/// and return the block a report embeds.
pub fn embed_figure(
    a: &mut Artifacts,
    path: &str,
    figure: Figure,
    default: (u32, u32),
    caption: &str,
    csv_name: Option<&str>,
) -> Result<super::html::FigureBlock, WriteError> {
    let r = Rendered::of(&figure, default, a.figure_output, path)?;
    let block = r.block(caption.to_owned(), csv_name.map(String::from));
    a.figures.push(FigureFile {
        path: path.to_owned(),
        figure,
        width_px: default.0,
        height_px: default.1,
        data: csv_name.map(String::from),
        rendered: Some(r),
    });
    Ok(block)
}

/// Why artifacts could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// Staging a file in the output folder failed.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// Drawing a figure failed.
    #[error("cannot draw {path}: {source}")]
    Plot {
        /// The figure's path in the output folder.
        path: String,
        /// What the plotting layer reported.
        source: PlotError,
    },
    /// Encoding a table (CSV or Parquet) failed.
    #[error("cannot format {path}: {reason}")]
    Format {
        /// The table's path in the output folder.
        path: String,
        /// What failed.
        reason: String,
    },
}

/// Stage every artifact into `out` (`summary.json`, tables, figures, documents). The
/// caller publishes the set.
pub fn write_artifacts(out: &mut OutputDir, a: &Artifacts) -> Result<(), WriteError> {
    let (name, text) = summary_file(a)?;
    out.stage(name, text.as_bytes())?;
    for (path, t) in &a.tables {
        let bytes = if path.ends_with(".parquet") {
            t.to_parquet().map_err(|e| WriteError::Format {
                path: path.clone(),
                reason: e.to_string(),
            })?
        } else {
            t.to_csv().map_err(|e| WriteError::Format {
                path: path.clone(),
                reason: e.to_string(),
            })?
        };
        out.stage(path, &bytes)?;
    }
    stage_figures(out, &a.figures, a.figure_output)?;
    for (path, bytes) in &a.documents {
        out.stage(path, bytes)?;
    }
    Ok(())
}

/// The summary file of `a`: its name (`summary.json` unless `a` names another) and text.
fn summary_file(a: &Artifacts) -> Result<(&str, String), WriteError> {
    let name = a.summary_file.as_deref().unwrap_or("summary.json");
    let text = serde_json::to_string_pretty(&a.summary).map_err(|e| WriteError::Format {
        path: name.into(),
        reason: e.to_string(),
    })?;
    Ok((name, text))
}

/// Move `sub` (another job's artifacts) into the folder `dir` of `into`: its summary,
/// stamped with `meta`, as `dir/summary.json` (or its own summary file), its tables,
/// figures and documents under `dir/`, each the bytes `sub` published alone would write
/// (the run job on a gear train holds each study's outputs so). Returns `sub`'s summary.
pub fn nest(
    into: &mut Artifacts,
    dir: &str,
    mut sub: Artifacts,
    meta: &RunMetadata,
) -> Result<serde_json::Value, WriteError> {
    sub.stamp_metadata(meta).map_err(|e| WriteError::Format {
        path: format!("{dir}/summary.json"),
        reason: e.to_string(),
    })?;
    let at = |p: &str| format!("{dir}/{p}");
    let (name, text) = summary_file(&sub)?;
    into.documents.push((at(name), text.into_bytes()));
    into.tables
        .extend(sub.tables.into_iter().map(|(p, t)| (at(&p), t)));
    for mut f in sub.figures {
        f.path = at(&f.path);
        f.data = f.data.as_deref().map(at);
        into.figures.push(f);
    }
    into.documents
        .extend(sub.documents.into_iter().map(|(p, b)| (at(&p), b)));
    Ok(sub.summary)
}

/// Render the figure of `a` at `path` now (in `a`'s formats and size), keep the rendering
/// (so the file and a report show the same bytes) and return the block a report embeds;
/// `None` when `a` has no such figure or it cannot be drawn.
pub fn embed_existing(
    a: &mut Artifacts,
    path: &str,
    caption: String,
) -> Option<super::html::FigureBlock> {
    let how = a.figure_output;
    let f = a.figures.iter_mut().find(|f| f.path == path)?;
    let r = Rendered::of(&f.figure, (f.width_px, f.height_px), how, path).ok()?;
    f.rendered = Some(r.clone());
    Some(r.block(caption, f.data.clone()))
}

/// Stage every artifact into `out` and publish the set; returns the folder.
pub fn publish_artifacts(mut out: OutputDir, a: &Artifacts) -> Result<PathBuf, WriteError> {
    write_artifacts(&mut out, a)?;
    let root = out.root().to_path_buf();
    out.publish()?;
    Ok(root)
}

/// Render (in parallel) and stage figures into `out` in the formats and size of `how`:
/// `NAME.png` and/or `NAME.svg`. Files rendered before are reused at their size.
pub fn stage_figures(
    out: &mut OutputDir,
    figures: &[FigureFile],
    how: FigureOutput,
) -> Result<(), WriteError> {
    let rendered: Vec<Rendered> = figures
        .par_iter()
        .map(|f| {
            let default = (f.width_px, f.height_px);
            let size = how.size_of(default);
            let mut r = f
                .rendered
                .clone()
                .filter(|r| r.size_px == size)
                .unwrap_or_default();
            let missing = FigureOutput {
                png: how.png && r.png.is_none(),
                svg: how.svg && r.svg.is_none(),
                ..how
            };
            if missing.png || missing.svg {
                let new = Rendered::of(&f.figure, default, missing, &f.path)?;
                r.png = r.png.or(new.png);
                r.svg = r.svg.or(new.svg);
            }
            Ok(r)
        })
        .collect::<Result<_, WriteError>>()?;
    for (f, r) in figures.iter().zip(rendered) {
        if let (true, Some(png)) = (how.png, &r.png) {
            out.stage(&f.path, png)?;
        }
        if let (true, Some(svg)) = (how.svg, &r.svg) {
            out.stage(&svg_path(&f.path), svg.as_bytes())?;
        }
    }
    Ok(())
}

/// The SVG file of the figure at `png_path` (`NAME.png` -> `NAME.svg`).
pub fn svg_path(png_path: &str) -> String {
    format!("{}.svg", png_path.trim_end_matches(".png"))
}

/// Metres to micrometres.
pub fn um(v: &[f64]) -> Vec<f64> {
    v.iter().map(|x| x * 1e6).collect()
}
