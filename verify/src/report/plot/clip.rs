//! The data box of a plotting area: points outside are dropped, lines are cut at its edges
//! and broken at non-finite points, and positions are normalised to it (for legend placement).

use super::axis::Axis;
use super::range::is_finite_point;

/// The data-space box of a plotting area.
#[derive(Debug, Clone, Copy)]
pub(super) struct Bounds {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl Bounds {
    /// The box spanned by the ranges of the two axes.
    pub(super) fn of(xa: &Axis, ya: &Axis) -> Self {
        Self {
            x0: xa.lo,
            x1: xa.hi,
            y0: ya.lo,
            y1: ya.hi,
        }
    }

    /// Whether the point lies in the box (with a relative tolerance of 1e-9 of its size).
    pub(super) fn contains(&self, (x, y): (f64, f64)) -> bool {
        let ex = (self.x1 - self.x0) * 1e-9;
        let ey = (self.y1 - self.y0) * 1e-9;
        x >= self.x0 - ex && x <= self.x1 + ex && y >= self.y0 - ey && y <= self.y1 + ey
    }

    /// Normalises `p` to the box (`[0, 1]²` inside it).
    pub(super) fn normalised(&self, p: (f64, f64)) -> (f64, f64) {
        (
            (p.0 - self.x0) / (self.x1 - self.x0),
            (p.1 - self.y0) / (self.y1 - self.y0),
        )
    }

    /// Liang–Barsky clipping of the segment `a`–`b`; the ends that need no clipping are
    /// returned unchanged so that consecutive segments can be joined again.
    fn clip(&self, a: (f64, f64), b: (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let mut t0 = 0.0f64;
        let mut t1 = 1.0f64;
        let checks = [
            (-dx, a.0 - self.x0),
            (dx, self.x1 - a.0),
            (-dy, a.1 - self.y0),
            (dy, self.y1 - a.1),
        ];
        for (p, q) in checks {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
                if t0 > t1 {
                    return None;
                }
            }
        }
        let start = if t0 > 0.0 {
            (a.0 + t0 * dx, a.1 + t0 * dy)
        } else {
            a
        };
        let end = if t1 < 1.0 {
            (a.0 + t1 * dx, a.1 + t1 * dy)
        } else {
            b
        };
        Some((start, end))
    }

    /// The visible polylines of `points`: broken at non-finite points and at the box edges.
    pub(super) fn polylines(&self, points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
        let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
        let mut current: Vec<(f64, f64)> = Vec::new();
        for pair in points.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let clipped = if is_finite_point(&a) && is_finite_point(&b) {
                self.clip(a, b)
            } else {
                None
            };
            match clipped {
                Some((s, e)) => {
                    if current.last() != Some(&s) {
                        if current.len() > 1 {
                            out.push(std::mem::take(&mut current));
                        }
                        current.clear();
                        current.push(s);
                    }
                    current.push(e);
                }
                None => {
                    if current.len() > 1 {
                        out.push(std::mem::take(&mut current));
                    }
                    current.clear();
                }
            }
        }
        if current.len() > 1 {
            out.push(current);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_clipped_to_the_range() {
        let b = Bounds {
            x0: 0.0,
            x1: 1.0,
            y0: 0.0,
            y1: 1.0,
        };
        let lines = b.polylines(&[
            (-1.0, 0.5),
            (0.5, 0.5),
            (0.5, 2.0),
            (f64::NAN, 0.0),
            (0.2, 0.2),
            (0.3, 0.3),
        ]);
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], vec![(0.0, 0.5), (0.5, 0.5), (0.5, 1.0)]);
        assert_eq!(lines[1], vec![(0.2, 0.2), (0.3, 0.3)]);
        assert!(b.polylines(&[(2.0, 2.0), (3.0, 3.0)]).is_empty());
    }
}
