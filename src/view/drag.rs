//! Hit shapes of draggable handles (circles and capsules, in CSS pixels of a canvas) and the
//! boxes of the touch overlay elements that stand over them, so that a touch on a handle is
//! the page's (`touch-action: none`) and a touch anywhere else scrolls the page.

use glam::DVec2;

/// A handle's hit region, CSS pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HandleShape {
    /// A disc around a point (a tip, a joint, a marker).
    Circle { centre: DVec2, radius: f64 },
    /// All points within `radius` of the segment `a`–`b` (a link).
    Capsule { a: DVec2, b: DVec2, radius: f64 },
}

/// An axis-aligned box rotated by `angle_rad` about its centre: what an overlay element needs
/// (`left`, `top`, `width`, `height`, `transform: rotate(angle)`), CSS pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverlayBox {
    pub left: f64,
    pub top: f64,
    pub width: f64,
    pub height: f64,
    pub angle_rad: f64,
    /// `border-radius`: half the height makes a capsule or a disc.
    pub radius: f64,
}

/// Distance from `p` to the segment `a`–`b`.
pub fn dist_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - p).length()
}

impl HandleShape {
    /// Whether `p` is inside the shape.
    pub fn contains(&self, p: DVec2) -> bool {
        match *self {
            HandleShape::Circle { centre, radius } => p.distance(centre) <= radius,
            HandleShape::Capsule { a, b, radius } => dist_to_segment(p, a, b) <= radius,
        }
    }

    /// The overlay box covering exactly the shape (a rounded, rotated rectangle).
    pub fn overlay_box(&self) -> OverlayBox {
        match *self {
            HandleShape::Circle { centre, radius } => OverlayBox {
                left: centre.x - radius,
                top: centre.y - radius,
                width: 2.0 * radius,
                height: 2.0 * radius,
                angle_rad: 0.0,
                radius,
            },
            HandleShape::Capsule { a, b, radius } => {
                let mid = (a + b) / 2.0;
                let d = b - a;
                let width = d.length() + 2.0 * radius;
                OverlayBox {
                    left: mid.x - width / 2.0,
                    top: mid.y - radius,
                    width,
                    height: 2.0 * radius,
                    angle_rad: d.y.atan2(d.x),
                    radius,
                }
            }
        }
    }
}

/// Whether a press that went down at `down` and came up at `up` after `ms` milliseconds is a
/// tap (not a swipe nor a long press).
pub fn is_tap(down: DVec2, up: DVec2, ms: f64) -> bool {
    down.distance(up) <= TAP_SLOP_PX && ms <= TAP_MAX_MS
}

/// How far a finger may move during a tap, CSS px.
pub const TAP_SLOP_PX: f64 = 10.0;
/// The longest press that is still a tap, ms.
pub const TAP_MAX_MS: f64 = 600.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capsule_contains_points_near_the_segment_only() {
        let s = HandleShape::Capsule {
            a: DVec2::new(0.0, 0.0),
            b: DVec2::new(100.0, 0.0),
            radius: 10.0,
        };
        assert!(s.contains(DVec2::new(50.0, 9.9)));
        assert!(s.contains(DVec2::new(-9.0, 0.0)));
        assert!(!s.contains(DVec2::new(50.0, 10.1)));
        assert!(!s.contains(DVec2::new(111.0, 0.0)));
        assert_eq!(dist_to_segment(DVec2::new(103.0, 4.0), s_a(), s_b()), 5.0);
    }

    fn s_a() -> DVec2 {
        DVec2::new(0.0, 0.0)
    }
    fn s_b() -> DVec2 {
        DVec2::new(100.0, 0.0)
    }

    #[test]
    fn overlay_box_of_a_diagonal_capsule_is_centred_and_rotated() {
        let s = HandleShape::Capsule {
            a: DVec2::new(0.0, 0.0),
            b: DVec2::new(30.0, 40.0),
            radius: 5.0,
        };
        let b = s.overlay_box();
        assert_eq!(b.width, 60.0);
        assert_eq!(b.height, 10.0);
        assert_eq!(
            (b.left + b.width / 2.0, b.top + b.height / 2.0),
            (15.0, 20.0)
        );
        assert!((b.angle_rad - (40f64).atan2(30.0)).abs() < 1e-15);
        let c = HandleShape::Circle {
            centre: DVec2::new(10.0, 20.0),
            radius: 4.0,
        }
        .overlay_box();
        assert_eq!(
            (c.left, c.top, c.width, c.height, c.radius),
            (6.0, 16.0, 8.0, 8.0, 4.0)
        );
    }

    #[test]
    fn taps_are_short_and_still() {
        let p = DVec2::new(5.0, 5.0);
        assert!(is_tap(p, p + DVec2::new(6.0, 6.0), 200.0));
        assert!(!is_tap(p, p + DVec2::new(0.0, 30.0), 200.0));
        assert!(!is_tap(p, p, 900.0));
    }
}
