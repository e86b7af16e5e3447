//! Dashed and dotted lines as separate straight pieces, in pixels.
//!
//! plotters draws a dash that runs across a vertex as one polyline, and a wide polyline's
//! miter join spikes far past the data where the line turns back on itself (a mesh-force
//! jump, Fig. 8). Cut into pieces that each lie on one segment of the line, a dashed line
//! has no join at all: every drawn piece stays between two plotted points.

/// Pixel coordinates (x, y) of the whole image.
pub type Px = (i32, i32);

/// The dashes of the line through `pts`: `on` px drawn, `off` px skipped, the pattern
/// running on across vertices (as plotters' own dashes do). A dash across a vertex is two
/// pieces, one on each segment. Pieces that round to a single pixel are left out (a
/// butt-capped stroke of zero length draws nothing).
pub fn dash_pieces(pts: &[Px], on: f64, off: f64) -> Vec<[Px; 2]> {
    let mut out = Vec::new();
    if !(on > 0.0 && off >= 0.0) {
        return out;
    }
    let (mut drawing, mut left) = (true, on);
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
        let d = dx.hypot(dy);
        let at = |s: f64| {
            let t = s / d;
            (
                (f64::from(a.0) + t * dx).round() as i32,
                (f64::from(a.1) + t * dy).round() as i32,
            )
        };
        let mut pos = 0.0;
        while pos < d {
            let step = left.min(d - pos);
            if drawing {
                let (p, q) = (at(pos), at(pos + step));
                if p != q {
                    out.push([p, q]);
                }
            }
            pos += step;
            left -= step;
            if left <= 0.0 {
                drawing = !drawing;
                left = if drawing { on } else { off };
                // A zero-length gap (off = 0) would otherwise stall on its own.
                if left <= 0.0 {
                    drawing = true;
                    left = on;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `p` lies on the segment a-b to within rounding (half a pixel each coordinate).
    fn on_segment(p: Px, a: Px, b: Px) -> bool {
        let (lo_x, hi_x) = (a.0.min(b.0), a.0.max(b.0));
        let (lo_y, hi_y) = (a.1.min(b.1), a.1.max(b.1));
        (lo_x..=hi_x).contains(&p.0) && (lo_y..=hi_y).contains(&p.1)
    }

    #[test]
    fn dashes_cover_their_share_and_stay_on_the_segments() {
        // A spike: up 100 px, back down 100 px, then 100 px right (a force jump's shape).
        let line = [(0, 200), (1, 100), (2, 200), (102, 200)];
        let pieces = dash_pieces(&line, 10.0, 6.0);
        for [p, q] in &pieces {
            // Each piece lies on one segment: no piece spans a vertex, so no join.
            let seg = line
                .windows(2)
                .find(|w| on_segment(*p, w[0], w[1]) && on_segment(*q, w[0], w[1]));
            assert!(seg.is_some(), "{p:?} {q:?}");
        }
        // Drawn length = 10/16 of the path (300 px) up to the last partial dash (< 10 px)
        // and the rounding of piece ends (< 1 px each end of each piece).
        let drawn: f64 = pieces
            .iter()
            .map(|[p, q]| f64::from(q.0 - p.0).hypot(f64::from(q.1 - p.1)))
            .sum();
        let path = 100.0_f64.hypot(1.0) * 2.0 + 100.0;
        let want = path * 10.0 / 16.0;
        assert!(
            (drawn - want).abs() < 10.0 + 2.0 * pieces.len() as f64,
            "{drawn} {want}"
        );
    }

    #[test]
    fn degenerate_inputs_give_no_pieces_or_a_solid_line() {
        assert!(dash_pieces(&[], 10.0, 6.0).is_empty());
        assert!(dash_pieces(&[(3, 3)], 10.0, 6.0).is_empty());
        assert!(dash_pieces(&[(3, 3), (3, 3)], 10.0, 6.0).is_empty());
        assert!(dash_pieces(&[(0, 0), (50, 0)], 0.0, 6.0).is_empty());
        // No gap: pieces of `on` px end to end along the whole line.
        let solid = dash_pieces(&[(0, 0), (50, 0)], 10.0, 0.0);
        assert_eq!(solid.first().map(|p| p[0]), Some((0, 0)));
        assert_eq!(solid.last().map(|p| p[1]), Some((50, 0)));
        assert_eq!(solid.len(), 5);
    }
}
