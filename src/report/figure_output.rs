//! How a job writes its figures: PNG (the default), SVG (vector) or both, and the image
//! size. A job option, not a case key: an output choice must not change the case's
//! identity (paper-case detection, checkpoint and sweep-record matching). Parsed here from
//! the words every front end takes (the command line's flags, Python's keyword arguments),
//! so both validate alike; a problem names the argument as [`Arg`], which each front end
//! spells its own way.

use super::plot::MAX_SIDE_PX;
use crate::remedy::{Arg, Problem};

/// Default plot size, px (one panel).
pub const PLOT_W: u32 = 900;
/// Default plot height, px (one panel).
pub const PLOT_H: u32 = 420;

/// Height of a figure of `panels` stacked panels, px: [`PLOT_H`] for one, 300 px a panel
/// plus the title band for more.
pub fn plot_height(panels: usize) -> u32 {
    match u32::try_from(panels) {
        Ok(0 | 1) => PLOT_H,
        Ok(n) => 40 + 300 * n.min(20),
        Err(_) => PLOT_H,
    }
}

/// Accepted width of a one-panel figure, px: a 300 px plot area plus the axis labels and
/// a legend band beside it (`plot::draw`) below, and [`MAX_SIDE_PX`] (the RGB buffer's
/// bound) above.
pub const WIDTH_RANGE_PX: (u32, u32) = (400, MAX_SIDE_PX);

/// Accepted height of a one-panel figure, px: the title band plus the smallest titled
/// panel (`plot::min_size`, ~150 px) rounded up below; 4096 px above, so that the two- and
/// four-panel figures, scaled alike, stay within [`MAX_SIDE_PX`] (taller ones are capped).
pub const HEIGHT_RANGE_PX: (u32, u32) = (200, 4096);

/// The formats as given: "png", "svg", or both, comma-separated.
pub const FORMAT_WORDS: &str = "png, svg or png,svg";

/// The formats figures are written in, and their size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FigureOutput {
    /// Write PNG files.
    pub png: bool,
    /// Write SVG files.
    pub svg: bool,
    /// Width and height of a one-panel figure, px; `None`: the defaults
    /// ([`PLOT_W`] x [`PLOT_H`]). A figure of n panels keeps its default height ratio to a
    /// one-panel figure.
    pub size_px: Option<(u32, u32)>,
}

impl Default for FigureOutput {
    fn default() -> Self {
        Self {
            png: true,
            svg: false,
            size_px: None,
        }
    }
}

/// The figure options of a job as given, resolved (and checked) when the job starts.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FigureRequest {
    /// "png", "svg" or "png,svg"; `None`: PNG.
    pub formats: Option<String>,
    /// "WIDTHxHEIGHT" in pixels; `None`: the default size.
    pub size: Option<String>,
}

impl FigureRequest {
    /// The output these options ask for, or a problem naming the argument that is out of
    /// range or malformed.
    pub fn resolve(&self) -> Result<FigureOutput, Problem> {
        FigureOutput::parse(
            self.formats.as_deref().unwrap_or("png"),
            self.size.as_deref(),
        )
    }
}

impl FigureOutput {
    /// From the formats' words and the size ("WIDTHxHEIGHT", e.g. "1600x800"; `None` for
    /// the default size).
    pub fn parse(formats: &str, size: Option<&str>) -> Result<Self, Problem> {
        let mut out = Self {
            png: false,
            svg: false,
            size_px: None,
        };
        for f in formats.split(',').map(str::trim) {
            match f.to_ascii_lowercase().as_str() {
                "png" => out.png = true,
                "svg" => out.svg = true,
                _ => {
                    return Err(Problem::given(
                        Arg::FigureFormats,
                        formats,
                        format!("expected {FORMAT_WORDS}"),
                    ))
                }
            }
        }
        if let Some(s) = size {
            out.size_px = Some(parse_size(s)?);
        }
        Ok(out)
    }

    /// Width and height of a figure whose default size is `default` (w, h) px.
    pub fn size_of(&self, default: (u32, u32)) -> (u32, u32) {
        let Some((w, h)) = self.size_px else {
            return default;
        };
        let scaled = f64::from(default.1) * f64::from(h) / f64::from(PLOT_H);
        let width = (f64::from(default.0) * f64::from(w) / f64::from(PLOT_W)).round();
        (
            (width as u32).clamp(1, MAX_SIDE_PX),
            (scaled.round() as u32).clamp(1, MAX_SIDE_PX),
        )
    }
}

/// "WIDTHxHEIGHT" in pixels, each side within its range.
pub fn parse_size(text: &str) -> Result<(u32, u32), Problem> {
    let bad = |why: String| Problem::given(Arg::FigureSize, text, why);
    let range = format!(
        "WIDTHxHEIGHT in pixels, width in [{}, {}], height in [{}, {}]",
        WIDTH_RANGE_PX.0, WIDTH_RANGE_PX.1, HEIGHT_RANGE_PX.0, HEIGHT_RANGE_PX.1
    );
    let (w, h) = text
        .trim()
        .split_once(['x', 'X'])
        .ok_or_else(|| bad(format!("expected {range}")))?;
    let side = |s: &str, (lo, hi): (u32, u32)| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|v| (lo..=hi).contains(v))
            .ok_or_else(|| bad(format!("expected {range}")))
    };
    Ok((side(w, WIDTH_RANGE_PX)?, side(h, HEIGHT_RANGE_PX)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_and_sizes_parse_or_name_the_argument_and_range() {
        let f = FigureOutput::parse("png,svg", Some("1600x800")).unwrap();
        assert!(f.png && f.svg && f.size_px == Some((1600, 800)));
        assert_eq!(
            FigureOutput::parse("png", None).unwrap(),
            FigureOutput::default()
        );
        let svg = FigureOutput::parse("SVG", None).unwrap();
        assert!(svg.svg && !svg.png);
        let cases = [
            ("gif", None, Arg::FigureFormats),
            ("png,", None, Arg::FigureFormats),
            ("png", Some("1600"), Arg::FigureSize),
            ("png", Some("10x800"), Arg::FigureSize),
            ("png", Some("1600x9000"), Arg::FigureSize),
            ("png", Some("-5x300"), Arg::FigureSize),
        ];
        for (formats, size, arg) in cases {
            let e = FigureOutput::parse(formats, size).unwrap_err();
            let text = e.render(Arg::plain);
            assert_eq!(e.arg, Some(arg), "{text}");
            assert!(text.contains(size.unwrap_or(formats)), "{text}");
            if arg == Arg::FigureSize {
                assert!(text.contains("[400, 8192]") && text.contains("[200, 4096]"));
            }
        }
    }

    #[test]
    fn taller_figures_keep_their_ratio_and_stay_within_the_image_limit() {
        let f = FigureOutput::parse("png", Some("1800x840")).unwrap();
        assert_eq!(f.size_of((PLOT_W, PLOT_H)), (1800, 840));
        // Two panels (640 px by default): the height doubles with the one-panel height.
        assert_eq!(f.size_of((PLOT_W, 640)), (1800, 1280));
        let huge = FigureOutput::parse("png", Some("8192x4096")).unwrap();
        assert_eq!(huge.size_of((PLOT_W, 6040)).1, MAX_SIDE_PX);
        assert_eq!(
            FigureOutput::default().size_of((PLOT_W, 640)),
            (PLOT_W, 640)
        );
    }
}
