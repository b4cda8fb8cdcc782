//! The pictures on the home page tiles of the two Robot Pilot pages, which have no recipe to
//! draw one: each page's scene at its start state, in the drawing model of the recipe cards
//! ([`crate::recipes::picture`]). The planar arm (`#/teleop`) is seen as its page shows it,
//! from the side: table, pedestal, links, open gripper, block and goal region of the
//! pick-and-place task. The SO-101 (`#/so101`) is seen from where its page's camera starts,
//! without the perspective: a patch of the table's grid, the green goal square, and the boxes
//! of the base, the links (as contact sees them) and the cube, each filled as its outline on
//! the screen, farthest first.

use glam::{DVec2, DVec3};

use crate::recipes::picture::{series, Mark, Picture, UnitFrame};
use crate::so101::model::BODIES;
use crate::so101::scene::{
    link_boxes, Obb, SceneConfig as So101Config, CUBE_HALF, GOAL_HALF, JAW_OPEN, TABLE_Z,
};
use crate::teleop::scene::{arm_capsules, Capsule, Layout, SceneConfig, OPEN_HALF_WIDTH};
use crate::view::so101::VIEW_AZIMUTH;

/// The pages with a scene picture.
pub const PAGES: [&str; 2] = ["teleop", "so101"];

/// The picture of page `page_id`'s scene at its start, for a canvas `aspect` (width / height)
/// wide (`None` for a page without one).
pub fn picture(page_id: &str, aspect: f64) -> Option<Picture> {
    match page_id {
        "teleop" => Some(planar_arm(aspect).0),
        "so101" => Some(so101(aspect).0),
        _ => None,
    }
}

/// Half the width of the pedestal the planar arm's base stands on, m.
const PEDESTAL_HALF_M: f64 = 0.015;
/// How far the table is drawn beyond the pedestal and the goal, m.
const TABLE_MARGIN_M: f64 = 0.04;

/// The four corners of a capsule's body (its axis widened by its radius on both sides).
fn capsule_outline(c: &Capsule) -> [DVec2; 4] {
    let s = &c.segment;
    let (a, b) = (DVec2::new(s.x0, s.z0), DVec2::new(s.x1, s.z1));
    let n = (b - a).perp().normalize_or_zero() * c.radius;
    [a + n, b + n, b - n, a - n]
}

/// The rectangle `(x0, z0)`–`(x1, z1)`, counter-clockwise from its bottom left.
fn rect(x0: f64, z0: f64, x1: f64, z1: f64) -> [DVec2; 4] {
    [
        DVec2::new(x0, z0),
        DVec2::new(x1, z0),
        DVec2::new(x1, z1),
        DVec2::new(x0, z1),
    ]
}

/// `points` mapped by `frame` onto the unit square.
fn on_frame(frame: &UnitFrame, points: &[DVec2]) -> Vec<DVec2> {
    points.iter().map(|p| frame.map(*p)).collect()
}

/// The planar arm's picture and its frame (scene metres, x right, z up → unit square).
fn planar_arm(aspect: f64) -> (Picture, UnitFrame) {
    let config = SceneConfig::default();
    let layout = Layout::of(&config.task);
    let table_z = crate::teleop::scene::TABLE_Z;
    let half = crate::teleop::scene::BLOCK_HALF;
    let (bx, bz) = layout.block_start;
    let block = rect(bx - half, bz - half, bx + half, bz + half);
    // The pick-and-place task's goal region (a task without one: none drawn, under the block).
    let goal = layout.goal.map(|g| rect(g.x0, g.z0, g.x1, g.z1));
    // The three links and the two fingers.
    let arm =
        arm_capsules(&config.arm, &config.start_q, OPEN_HALF_WIDTH).map(|c| capsule_outline(&c));
    let pedestal = rect(-PEDESTAL_HALF_M, table_z, PEDESTAL_HALF_M, 0.0);

    // The table: from behind the pedestal to beyond the goal (or the block).
    let right = goal.map_or(bx + half, |g| g[1].x);
    let table = [
        DVec2::new(-PEDESTAL_HALF_M - TABLE_MARGIN_M, table_z),
        DVec2::new(right + TABLE_MARGIN_M, table_z),
    ];
    let mut things: Vec<DVec2> = Vec::with_capacity(34);
    things.extend_from_slice(arm.as_flattened());
    for shape in [block, goal.unwrap_or(block), pedestal] {
        things.extend_from_slice(&shape);
    }
    things.extend_from_slice(&table);
    let frame = UnitFrame::fit(things.iter().copied(), Some(aspect));

    let mut marks = vec![
        Mark::Line {
            series: series::GREY,
            points: on_frame(&frame, &table),
        },
        Mark::Fill {
            series: series::GREY,
            points: on_frame(&frame, &pedestal),
        },
    ];
    if let Some(goal) = goal {
        marks.push(Mark::Region {
            series: series::GREEN,
            points: on_frame(&frame, &goal),
        });
    }
    marks.push(Mark::Fill {
        series: series::ORANGE,
        points: on_frame(&frame, &block),
    });
    for shape in &arm {
        marks.push(Mark::Fill {
            series: series::BLUE,
            points: on_frame(&frame, shape),
        });
    }
    (Picture { marks }, frame)
}

/// The convex hull of `points`, counter-clockwise from the leftmost (gift wrapping: a box's
/// eight corners need no sort).
fn hull(points: &[DVec2]) -> Vec<DVec2> {
    let n = points.len();
    let Some(start) = (0..n).min_by(|&a, &b| {
        let (p, q) = (points[a], points[b]);
        p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
    }) else {
        return Vec::new();
    };
    let mut out = Vec::with_capacity(n);
    let mut at = start;
    loop {
        out.push(points[at]);
        let p = points[at];
        let mut next = (at + 1) % n;
        for (k, &r) in points.iter().enumerate() {
            let q = points[next];
            let turn = (q - p).perp_dot(r - p);
            // r is clockwise of p→q, or on that line and farther: wrap to r.
            if turn < 0.0 || (turn == 0.0 && p.distance_squared(r) > p.distance_squared(q)) {
                next = k;
            }
        }
        at = next;
        if at == start || out.len() >= n {
            return out;
        }
    }
}

/// The patch of the table's grid drawn, under the base, the cube and the goal: its corner of
/// least x and y, m …
const GRID_CORNER_M: [f64; 2] = [-0.05, -0.15];
/// … its cells each way …
const GRID_CELLS: usize = 7;
/// … and their side (the page's grid), m.
const GRID_CELL_M: f64 = crate::view::so101::TABLE_CELL_M;
/// How high the view looks down, rad (the page camera's iso preset: 35°).
const VIEW_ELEVATION: f64 = 35.0 * std::f64::consts::PI / 180.0;

/// The page camera's direction without its perspective: world point → (screen right, screen
/// up), and its depth (larger is farther).
struct View {
    right: DVec3,
    up: DVec3,
    forward: DVec3,
}

impl View {
    /// Looking at the scene from [`VIEW_AZIMUTH`] about z, [`VIEW_ELEVATION`] above the table.
    fn page() -> View {
        let (sa, ca) = crate::math::sincos(VIEW_AZIMUTH);
        let (se, ce) = crate::math::sincos(VIEW_ELEVATION);
        View {
            right: DVec3::new(-sa, ca, 0.0),
            up: DVec3::new(-se * ca, -se * sa, ce),
            forward: DVec3::new(-ce * ca, -ce * sa, -se),
        }
    }

    fn at(&self, p: [f64; 3]) -> DVec2 {
        let p = DVec3::from_array(p);
        DVec2::new(p.dot(self.right), p.dot(self.up))
    }

    fn depth(&self, p: [f64; 3]) -> f64 {
        DVec3::from_array(p).dot(self.forward)
    }
}

/// The SO-101's picture, with its view (world → a plane across the view) and the frame (that
/// plane → unit square) for the tests.
fn so101(aspect: f64) -> (Picture, UnitFrame, View) {
    let config = So101Config::default_for(false);
    let chain = crate::so101::kinematics::chain(&config.start_q, JAW_OPEN);
    let view = View::page();

    // The base, the links and the cube: the depth of their centres, their series, their
    // corners.
    let [cx, cy] = config.cube_start;
    let cube = Obb::aligned([cx, cy, TABLE_Z + CUBE_HALF], [CUBE_HALF; 3]);
    let base = &BODIES[0];
    let [l1, l2, l3, l4, l5, l6] = link_boxes(&chain);
    let solids = [
        (
            series::GREY,
            Obb::of(&chain.bodies[0], &base.box_centre, &base.box_half),
        ),
        (series::BLUE, l1),
        (series::BLUE, l2),
        (series::BLUE, l3),
        (series::BLUE, l4),
        (series::BLUE, l5),
        (series::BLUE, l6),
        (series::ORANGE, cube),
    ]
    .map(|(series, b)| {
        (
            view.depth(b.centre),
            series,
            b.corners().map(|c| view.at(c)),
        )
    });
    // Farthest first (insertion: a handful of boxes).
    let mut order: [usize; 8] = std::array::from_fn(|i| i);
    for i in 1..order.len() {
        let mut j = i;
        while j > 0 && solids[order[j - 1]].0 < solids[order[j]].0 {
            order.swap(j - 1, j);
            j -= 1;
        }
    }
    let [gx, gy] = config.goal;
    let goal = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .map(|(sx, sy)| view.at([gx + sx * GOAL_HALF, gy + sy * GOAL_HALF, TABLE_Z]));

    let span = GRID_CELL_M * GRID_CELLS as f64;
    let [x0, y0] = GRID_CORNER_M;
    let mut grid = [DVec2::ZERO; 4 * (GRID_CELLS + 1)];
    for k in 0..=GRID_CELLS {
        let t = k as f64 * GRID_CELL_M;
        grid[4 * k] = view.at([x0 + t, y0, TABLE_Z]);
        grid[4 * k + 1] = view.at([x0 + t, y0 + span, TABLE_Z]);
        grid[4 * k + 2] = view.at([x0, y0 + t, TABLE_Z]);
        grid[4 * k + 3] = view.at([x0 + span, y0 + t, TABLE_Z]);
    }

    // The frame fits it all.
    let mut fitted: Vec<DVec2> = Vec::with_capacity(goal.len() + grid.len() + 8 * solids.len());
    fitted.extend_from_slice(&goal);
    fitted.extend_from_slice(&grid);
    for (_, _, corners) in &solids {
        fitted.extend_from_slice(corners);
    }
    let frame = UnitFrame::fit(fitted.iter().copied(), Some(aspect));
    let grid = on_frame(&frame, &grid);
    let mut marks = vec![
        Mark::Segments {
            series: series::GREY,
            pairs: grid.chunks_exact(2).map(|ab| (ab[0], ab[1])).collect(),
        },
        Mark::Region {
            series: series::GREEN,
            points: on_frame(&frame, &goal),
        },
    ];
    for (_, series, corners) in order.map(|i| &solids[i]) {
        marks.push(Mark::Fill {
            series: *series,
            points: hull(&on_frame(&frame, corners)),
        });
    }
    (Picture { marks }, frame, view)
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::teleop::arm::fk;

    /// The tile's canvas: about 250 × 88 CSS px.
    const TILE_ASPECT: f64 = 2.8;

    fn fills(p: &Picture, wanted: u8) -> Vec<&Vec<DVec2>> {
        p.marks
            .iter()
            .filter_map(|m| match m {
                Mark::Fill { series, points } | Mark::Region { series, points }
                    if *series == wanted =>
                {
                    Some(points)
                }
                _ => None,
            })
            .collect()
    }

    fn centroid(points: &[DVec2]) -> DVec2 {
        points.iter().copied().sum::<DVec2>() / points.len() as f64
    }

    fn inside_unit_square(p: &Picture) -> bool {
        p.points().iter().all(|q| {
            q.is_finite()
                && (-1e-9..=1.0 + 1e-9).contains(&q.x)
                && (-1e-9..=1.0 + 1e-9).contains(&q.y)
        })
    }

    #[test]
    fn the_planar_arm_tile_shows_the_block_where_the_scene_puts_it() {
        let (picture, frame) = planar_arm(TILE_ASPECT);
        assert!(inside_unit_square(&picture));
        let blocks = fills(&picture, series::ORANGE);
        assert_eq!(blocks.len(), 1);
        let (bx, bz) = Layout::of(&SceneConfig::default().task).block_start;
        let at = frame.map(DVec2::new(bx, bz));
        assert!((centroid(blocks[0]) - at).length() < 1e-12, "{at:?}");
        // On the table, between the arm's base and the goal region.
        let goal = centroid(fills(&picture, series::GREEN)[0]);
        let base = frame.map(DVec2::ZERO);
        assert!(base.x < at.x && at.x < goal.x, "{base:?} {at:?} {goal:?}");
        // Three links and two fingers; the gripper hangs above the block.
        let arm = fills(&picture, series::BLUE);
        assert_eq!(arm.len(), 5);
        let tip = fk(&SceneConfig::default().arm, &SceneConfig::default().start_q);
        assert!(frame.map(DVec2::new(tip.x, tip.z)).y > at.y);
    }

    #[test]
    fn the_so101_tile_shows_the_cube_and_the_goal_apart_under_the_arm() {
        let (picture, frame, view) = so101(TILE_ASPECT);
        assert!(inside_unit_square(&picture));
        let config = So101Config::default_for(false);
        let cubes = fills(&picture, series::ORANGE);
        assert_eq!(cubes.len(), 1);
        let [cx, cy] = config.cube_start;
        let at = frame.map(view.at([cx, cy, TABLE_Z + CUBE_HALF]));
        // Seen without perspective, a box's outline is symmetric about its centre.
        assert!((centroid(cubes[0]) - at).length() < 1e-9, "{at:?}");
        assert_eq!(
            cubes[0].len(),
            6,
            "a cube seen from above a corner: a hexagon"
        );
        let goal = fills(&picture, series::GREEN)[0];
        assert_eq!(goal.len(), 4);
        let (lo, hi) = goal.iter().fold((DVec2::ONE, DVec2::ZERO), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
        assert!(
            !(lo.x..=hi.x).contains(&at.x) || !(lo.y..=hi.y).contains(&at.y),
            "the cube starts outside the goal square"
        );
        // The base and the six moving boxes (shoulder … gripper, the moving jaw); the arm
        // stands above the goal.
        assert_eq!(fills(&picture, series::GREY).len(), 1);
        assert_eq!(fills(&picture, series::BLUE).len(), 6);
        let top = fills(&picture, series::BLUE)
            .iter()
            .flat_map(|s| s.iter())
            .fold(0.0f64, |m, p| m.max(p.y));
        assert!(top > hi.y);
    }

    #[test]
    fn only_the_pilot_pages_have_a_scene_picture() {
        for id in PAGES {
            assert!(
                picture(id, 1.0).is_some_and(|p| !p.marks.is_empty()),
                "{id}"
            );
        }
        assert_eq!(picture("ik-2r", 1.0), None);
    }

    #[test]
    fn the_hull_of_a_square_and_its_centre_is_the_square() {
        let square = rect(0.0, 0.0, 1.0, 1.0);
        let mut points = vec![DVec2::splat(0.5), DVec2::new(0.5, 0.0)];
        points.extend(square.iter().rev());
        points.push(DVec2::ZERO);
        assert_eq!(hull(&points), square);
    }
}
