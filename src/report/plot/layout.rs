//! Where things go on a panel, in pixels: the rectangles of the plot area, the legend, the
//! colour bar and the marker labels, and the pixels the data cover. Pure geometry: the
//! renderer (`draw.rs`) computes a [`PanelLayout`] from the chart it is about to draw and
//! draws exactly there, and [`super::layout()`] hands the same layout to tests.

/// An axis-aligned rectangle in pixels of the whole image, half-open: x in [x0, x1),
/// y in [y0, y1) (y grows downwards).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rect {
    /// Left edge (inclusive), px.
    pub x0: i32,
    /// Top edge (inclusive), px.
    pub y0: i32,
    /// Right edge (exclusive), px.
    pub x1: i32,
    /// Bottom edge (exclusive), px.
    pub y1: i32,
}

impl Rect {
    /// The rectangle of width `w` and height `h` with its top-left corner at (x, y).
    pub fn at(x: i32, y: i32, w: u32, h: u32) -> Self {
        let (w, h) = (
            i32::try_from(w).unwrap_or(i32::MAX),
            i32::try_from(h).unwrap_or(0),
        );
        Self {
            x0: x,
            y0: y,
            x1: x.saturating_add(w),
            y1: y.saturating_add(h),
        }
    }

    /// Width, px.
    pub fn width(&self) -> i32 {
        self.x1 - self.x0
    }

    /// Height, px.
    pub fn height(&self) -> i32 {
        self.y1 - self.y0
    }

    /// Whether pixel (x, y) lies inside.
    pub fn contains(&self, (x, y): (i32, i32)) -> bool {
        (self.x0..self.x1).contains(&x) && (self.y0..self.y1).contains(&y)
    }

    /// Whether the two rectangles share a pixel.
    pub fn intersects(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Grown by `d` pixels on every side.
    pub fn inflate(&self, d: i32) -> Rect {
        Rect {
            x0: self.x0 - d,
            y0: self.y0 - d,
            x1: self.x1 + d,
            y1: self.y1 + d,
        }
    }
}

/// What the renderer placed on one panel, in pixels of the whole image.
#[derive(Debug, Clone, Default)]
pub struct PanelLayout {
    /// The plotting area inside the axes.
    pub plot: Rect,
    /// The legend box, when the panel has one (two or more named series).
    pub legend: Option<Rect>,
    /// The colour bar with its label and tick labels, when the panel has one.
    pub color_bar: Option<Rect>,
    /// The labels of the vertical markers.
    pub labels: Vec<Rect>,
    /// Pixels covered by data: every plotted point, and samples at most
    /// [`MARK_STEP_PX`] apart along every line or stem drawn between points.
    pub marks: Vec<(i32, i32)>,
}

/// Largest distance between two samples of a drawn line in [`PanelLayout::marks`], px.
pub const MARK_STEP_PX: f64 = 2.0;

/// Clearance kept between a legend and any data pixel, px: half the 2 px line width plus
/// the 4 px radius of the largest marker, rounded up.
pub const CLEARANCE_PX: i32 = 5;

/// Inset of a legend from the plot area's corner, px.
const INSET_PX: i32 = 6;

/// Append the pixels of the polyline through `pts` to `out`, sampled at most
/// [`MARK_STEP_PX`] apart.
pub fn sample_polyline(pts: &[(i32, i32)], out: &mut Vec<(i32, i32)>) {
    out.extend(pts.first());
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
        let n = ((dx.hypot(dy) / MARK_STEP_PX).ceil() as usize).max(1);
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let x = f64::from(a.0) + t * dx;
            let y = f64::from(a.1) + t * dy;
            out.push((x.round() as i32, y.round() as i32));
        }
    }
}

/// The first corner of `plot` (upper right, upper left, lower right, lower left) where a
/// box of `size` (w, h) keeps [`CLEARANCE_PX`] from every mark and touches no obstacle.
pub fn free_corner(
    plot: Rect,
    size: (u32, u32),
    marks: &[(i32, i32)],
    obstacles: &[Rect],
) -> Option<Rect> {
    let (w, h) = (size.0 as i32, size.1 as i32);
    let (left, right) = (plot.x0 + INSET_PX, plot.x1 - INSET_PX - w);
    let (top, bottom) = (plot.y0 + INSET_PX, plot.y1 - INSET_PX - h);
    if right < left || bottom < top {
        return None;
    }
    let corners = [(right, top), (left, top), (right, bottom), (left, bottom)];
    corners
        .into_iter()
        .map(|(x, y)| Rect::at(x, y, size.0, size.1))
        .find(|r| {
            let grown = r.inflate(CLEARANCE_PX);
            !marks.iter().any(|m| grown.contains(*m)) && !obstacles.iter().any(|o| o.intersects(r))
        })
}

/// Boxes for marker labels of `sizes` (w, h) anchored at pixel columns `xs`, along the
/// top of `plot`, with `lines` the columns of every marker line: each label sits just
/// right of its marker, or left of it when the right side would leave the plot or cross
/// more of the other lines (a line through a label makes it unreadable: "frequency|3x");
/// then in the first row down where it overlaps no earlier label.
pub fn stack_labels(xs: &[i32], sizes: &[(u32, u32)], lines: &[i32], plot: Rect) -> Vec<Rect> {
    const GAP: i32 = 3;
    let mut order: Vec<usize> = (0..xs.len()).collect();
    order.sort_by_key(|&i| xs[i]);
    let mut placed: Vec<Option<Rect>> = vec![None; xs.len()];
    let mut done: Vec<Rect> = Vec::new();
    for i in order {
        let (w, h) = sizes[i];
        let crossed = |x0: i32| {
            let x1 = x0 + w as i32;
            lines
                .iter()
                .filter(|l| **l != xs[i] && (x0 - 1..=x1 + 1).contains(*l))
                .count()
        };
        let (right, left) = (xs[i] + GAP, xs[i] - GAP - w as i32);
        let right_fits = right + w as i32 <= plot.x1;
        let left_fits = left >= plot.x0;
        let x = match (right_fits, left_fits) {
            (true, true) if crossed(left) < crossed(right) => left,
            (true, _) => right,
            _ => left,
        };
        let mut row = 0;
        let rect = loop {
            let r = Rect::at(x, plot.y0 + GAP + row * (h as i32 + 2), w, h);
            if !done.iter().any(|d| d.inflate(3).intersects(&r)) || row > 64 {
                break r;
            }
            row += 1;
        };
        done.push(rect);
        placed[i] = Some(rect);
    }
    placed.into_iter().flatten().collect()
}

/// A perceptually ordered colour for t in [0, 1] (0 dark purple, 1 yellow): the viridis
/// map of matplotlib (van der Walt & Smith, 2015), linear between nine of its samples.
/// Values outside [0, 1] are clamped; NaN gives the t = 0 colour.
pub fn sequential_color(t: f64) -> [u8; 3] {
    #[rustfmt::skip]
    const VIRIDIS: [[f64; 3]; 9] = [
        [68.0, 1.0, 84.0], [71.0, 44.0, 122.0], [59.0, 81.0, 139.0],
        [44.0, 113.0, 142.0], [33.0, 144.0, 141.0], [39.0, 173.0, 129.0],
        [92.0, 200.0, 99.0], [170.0, 220.0, 50.0], [253.0, 231.0, 37.0],
    ];
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let s = t * (VIRIDIS.len() - 1) as f64;
    let i = (s.floor() as usize).min(VIRIDIS.len() - 2);
    let f = s - i as f64;
    let mix = |k: usize| (VIRIDIS[i][k] + f * (VIRIDIS[i + 1][k] - VIRIDIS[i][k])).round() as u8;
    [mix(0), mix(1), mix(2)]
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLOT: Rect = Rect {
        x0: 0,
        y0: 0,
        x1: 200,
        y1: 100,
    };

    #[test]
    fn polyline_samples_are_close_and_end_on_the_points() {
        let mut out = Vec::new();
        sample_polyline(&[(0, 0), (10, 0), (10, 7)], &mut out);
        assert_eq!(out.first(), Some(&(0, 0)));
        assert_eq!(out.last(), Some(&(10, 7)));
        assert!(out.contains(&(10, 0)));
        // Neighbouring samples are within the step (rounding adds at most 1 px).
        for w in out.windows(2) {
            let d = f64::from(w[1].0 - w[0].0).hypot(f64::from(w[1].1 - w[0].1));
            assert!(d <= MARK_STEP_PX + 1.0, "{w:?}");
        }
    }

    #[test]
    fn a_legend_avoids_data_and_obstacles() {
        // Data along the top edge: both upper corners are taken, lower right is free.
        let mut marks = Vec::new();
        sample_polyline(&[(0, 10), (200, 10)], &mut marks);
        let r = free_corner(PLOT, (50, 20), &marks, &[]).unwrap();
        assert_eq!((r.x1, r.y1), (200 - 6, 100 - 6));
        // An obstacle over the lower right leaves the lower left.
        let block = Rect::at(150, 60, 50, 40);
        let r = free_corner(PLOT, (50, 20), &marks, &[block]).unwrap();
        assert_eq!((r.x0, r.y1), (6, 94));
        // Data everywhere: no corner.
        let mut full = Vec::new();
        for y in (0..100).step_by(4) {
            sample_polyline(&[(0, y), (200, y)], &mut full);
        }
        assert!(free_corner(PLOT, (50, 20), &full, &[]).is_none());
        // A box larger than the plot never fits.
        assert!(free_corner(PLOT, (300, 20), &[], &[]).is_none());
    }

    #[test]
    fn close_labels_go_to_separate_rows() {
        let xs = [50, 60, 70, 150, 198];
        let r = stack_labels(&xs, &[(40, 12); 5], &xs, PLOT);
        assert_eq!(r.len(), 5);
        for (i, a) in r.iter().enumerate() {
            for b in &r[i + 1..] {
                assert!(!a.intersects(b), "{a:?} {b:?}");
            }
        }
        // 50: its right side would cross 60 and 70, its left none: left, first row.
        assert_eq!((r[0].x1, r[0].y0), (47, 3));
        // 60: a line crossed either side: right; 70 right of it, 10 px on: second row.
        assert_eq!((r[1].x0, r[1].y0), (63, 3));
        assert!(r[2].x0 == 73 && r[2].y0 > r[1].y0);
        assert_eq!(r[3].y0, r[0].y0); // far apart: first row
        assert!(r[4].x1 <= PLOT.x1); // near the right edge: left of its marker
    }

    #[test]
    fn a_label_goes_to_the_side_no_other_line_crosses() {
        // Line 110 would cross the label of 100 on its right (103..143): it goes left.
        let r = stack_labels(&[100], &[(40, 12)], &[100, 110], PLOT);
        assert_eq!((r[0].x0, r[0].x1), (100 - 3 - 40, 100 - 3));
        // Lines on both sides, one each: right, as usual.
        let r = stack_labels(&[100], &[(40, 12)], &[80, 100, 110], PLOT);
        assert_eq!(r[0].x0, 103);
        // No line near: right.
        let r = stack_labels(&[100], &[(40, 12)], &[100, 190], PLOT);
        assert_eq!(r[0].x0, 103);
    }

    #[test]
    fn viridis_ends_and_clamps() {
        assert_eq!(sequential_color(0.0), [68, 1, 84]);
        assert_eq!(sequential_color(1.0), [253, 231, 37]);
        assert_eq!(sequential_color(-1.0), sequential_color(0.0));
        assert_eq!(sequential_color(f64::NAN), sequential_color(0.0));
        assert_eq!(sequential_color(0.5), [33, 144, 141]); // the middle sample
    }
}
