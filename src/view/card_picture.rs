//! The small picture on each recipe card of the home page, drawn from what the recipe's kernel
//! computes at its defaults: the pendulum's energy curves, the IK workspace's reachable
//! points, the resampled joints, the DH chain, the Jacobian sweep's tip arc, the cubic path, the
//! two SE(3) frames, the RRT tree and its path, the PID response, the manipulability grid,
//! the trapezoid's velocity and the Umeyama alignment.
//!
//! Everything is in unit coordinates (x right, y up, both in [0, 1]) so the page only scales
//! to its canvas; series are indices into the page's palette.

use glam::{DVec2, DVec3};

use crate::recipes::{self, se3_relative, umeyama_2d, RecipeOutput};
use crate::view::camera3d::{Camera, Preset};

/// One mark of a picture.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A polyline.
    Line { series: u8, points: Vec<DVec2> },
    /// Dots.
    Dots { series: u8, points: Vec<DVec2> },
    /// Separate segments (tree edges, frame axes).
    Segments {
        series: u8,
        pairs: Vec<(DVec2, DVec2)>,
    },
    /// A grid of cells, row-major from the bottom-left, values in [0, 1].
    Cells {
        cols: usize,
        rows: usize,
        values: Vec<f64>,
    },
}

/// A recipe card's picture.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    pub marks: Vec<Mark>,
}

/// Palette slots the page maps to colours (Okabe–Ito, safe for colour-blind readers).
pub mod series {
    pub const BLUE: u8 = 0;
    pub const ORANGE: u8 = 1;
    pub const GREEN: u8 = 2;
    pub const GREY: u8 = 3;
    pub const RED: u8 = 4;
}

/// A CSV file of an output as columns by header name.
struct Table<'a> {
    header: Vec<&'a str>,
    rows: Vec<Vec<f64>>,
}

impl<'a> Table<'a> {
    fn of(output: &'a RecipeOutput, name: &str) -> Option<Table<'a>> {
        let text = &output.files.iter().find(|f| f.name == name)?.text;
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next()?.split(',').collect();
        let rows = lines
            .map(|line| {
                line.split(',')
                    .map(|cell| cell.trim().parse::<f64>().unwrap_or(f64::NAN))
                    .collect()
            })
            .collect();
        Some(Table { header, rows })
    }

    fn col(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.header.iter().position(|h| *h == name)?;
        Some(
            self.rows
                .iter()
                .map(|r| r.get(i).copied().unwrap_or(f64::NAN))
                .collect(),
        )
    }
}

/// Maps data boxes onto the unit square with a margin.
#[derive(Debug, Clone, Copy)]
struct Frame {
    min: DVec2,
    scale: DVec2,
    offset: DVec2,
}

impl Frame {
    const MARGIN: f64 = 0.06;

    /// Fits the points' box; with `aspect` (canvas width / height) set, one data unit is as
    /// long across as up on the canvas (a square stays square), else each axis fills.
    fn fit(points: impl Iterator<Item = DVec2>, aspect: Option<f64>) -> Frame {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for p in points.filter(|p| p.is_finite()) {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        if !lo.is_finite() || !hi.is_finite() {
            lo = DVec2::ZERO;
            hi = DVec2::ONE;
        }
        let span = (hi - lo).max(DVec2::splat(1e-12));
        let inner = 1.0 - 2.0 * Self::MARGIN;
        match aspect.filter(|a| a.is_finite() && *a > 0.0) {
            None => Frame {
                min: lo,
                scale: DVec2::splat(inner) / span,
                offset: DVec2::splat(Self::MARGIN),
            },
            Some(aspect) => {
                // Pixels of a canvas `aspect` wide and 1 high.
                let s = (inner * aspect / span.x).min(inner / span.y);
                let scale = DVec2::new(s / aspect, s);
                let used = span * scale;
                Frame {
                    min: lo,
                    scale,
                    offset: (DVec2::ONE - used) / 2.0,
                }
            }
        }
    }

    fn map(&self, p: DVec2) -> DVec2 {
        self.offset + (p - self.min) * self.scale
    }
}

fn pairs(x: &[f64], y: &[f64]) -> Vec<DVec2> {
    x.iter().zip(y).map(|(a, b)| DVec2::new(*a, *b)).collect()
}

/// Lines of `ys` over `x`, one frame for all.
fn lines(x: &[f64], ys: &[(&[f64], u8)]) -> Picture {
    let all: Vec<Vec<DVec2>> = ys.iter().map(|(y, _)| pairs(x, y)).collect();
    let frame = Frame::fit(all.iter().flatten().copied(), None);
    Picture {
        marks: all
            .into_iter()
            .zip(ys)
            .map(|(pts, (_, series))| Mark::Line {
                series: *series,
                points: pts.into_iter().map(|p| frame.map(p)).collect(),
            })
            .collect(),
    }
}

/// The picture of recipe `id` from its output at the defaults (`None` for an unknown id or an
/// output without the expected columns).
pub fn picture(id: &str, output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    use series::*;
    match id {
        "pendulum-energy" => {
            let t = Table::of(output, "pendulum_energy.csv")?;
            let x = t.col("t_s")?;
            Some(lines(
                &x,
                &[
                    (&t.col("ke_j")?, ORANGE),
                    (&t.col("pe_j")?, GREEN),
                    (&t.col("total_j")?, BLUE),
                ],
            ))
        }
        "ik-workspace" => {
            let t = Table::of(output, "ik_workspace.csv")?;
            let pts = pairs(&t.col("x_mm")?, &t.col("y_mm")?);
            let reach = t.col("reachable")?;
            let frame = Frame::fit(pts.iter().copied(), Some(aspect));
            let (mut yes, mut no) = (Vec::new(), Vec::new());
            for (p, r) in pts.iter().zip(&reach) {
                if *r > 0.5 { &mut yes } else { &mut no }.push(frame.map(*p));
            }
            Some(Picture {
                marks: vec![
                    Mark::Dots {
                        series: GREY,
                        points: no,
                    },
                    Mark::Dots {
                        series: BLUE,
                        points: yes,
                    },
                ],
            })
        }
        "traj-resample" => {
            let t = Table::of(output, "traj_resampled.csv")?;
            let raw = Table::of(output, "traj_sample_labeled.csv")?;
            let x = t.col("t_s")?;
            let (q1, q2) = (t.col("q1")?, t.col("q2")?);
            let (rx, r1, r2) = (raw.col("t_s")?, raw.col("q1")?, raw.col("q2")?);
            let frame = Frame::fit(
                pairs(&x, &q1)
                    .into_iter()
                    .chain(pairs(&x, &q2))
                    .chain(pairs(&rx, &r1))
                    .chain(pairs(&rx, &r2)),
                None,
            );
            let m = |v: Vec<DVec2>| v.into_iter().map(|p| frame.map(p)).collect::<Vec<_>>();
            Some(Picture {
                marks: vec![
                    Mark::Line {
                        series: BLUE,
                        points: m(pairs(&x, &q1)),
                    },
                    Mark::Line {
                        series: ORANGE,
                        points: m(pairs(&x, &q2)),
                    },
                    Mark::Dots {
                        series: BLUE,
                        points: m(pairs(&rx, &r1)),
                    },
                    Mark::Dots {
                        series: ORANGE,
                        points: m(pairs(&rx, &r2)),
                    },
                ],
            })
        }
        "dh-fk" => {
            let t = Table::of(output, "dh_fk.csv")?;
            let (x, y, z) = (t.col("x_m")?, t.col("y_m")?, t.col("z_m")?);
            let chain: Vec<DVec3> = (0..x.len()).map(|i| DVec3::new(x[i], y[i], z[i])).collect();
            let cam = Camera::framing(DVec3::new(0.0, 0.0, 0.15), 0.3, Preset::Iso, 1.0, 1.0);
            let grid: Vec<(DVec3, DVec3)> = crate::view::camera3d::ground_grid(4, 0.1);
            let project = |p: DVec3| cam.project(p).map(|q| DVec2::new(q.at.x, 1.0 - q.at.y));
            let grid2: Vec<(DVec2, DVec2)> = grid
                .into_iter()
                .filter_map(|(a, b)| Some((project(a)?, project(b)?)))
                .collect();
            let chain2: Vec<DVec2> = chain.into_iter().filter_map(project).collect();
            let frame = Frame::fit(
                chain2
                    .iter()
                    .copied()
                    .chain(grid2.iter().flat_map(|(a, b)| [*a, *b])),
                Some(aspect),
            );
            Some(Picture {
                marks: vec![
                    Mark::Segments {
                        series: GREY,
                        pairs: grid2
                            .iter()
                            .map(|(a, b)| (frame.map(*a), frame.map(*b)))
                            .collect(),
                    },
                    Mark::Line {
                        series: BLUE,
                        points: chain2.iter().map(|p| frame.map(*p)).collect(),
                    },
                    Mark::Dots {
                        series: ORANGE,
                        points: chain2.iter().map(|p| frame.map(*p)).collect(),
                    },
                ],
            })
        }
        "jacobian-2r" => {
            // The sweep turns q1 at a fixed q2: the tip's arc, with the arm's reach to it.
            let t = Table::of(output, "jacobian_2r.csv")?;
            let tips = pairs(&t.col("x_m")?, &t.col("y_m")?);
            let frame = Frame::fit(tips.iter().copied().chain([DVec2::ZERO]), Some(aspect));
            Some(Picture {
                marks: vec![
                    Mark::Segments {
                        series: GREY,
                        pairs: tips
                            .iter()
                            .map(|p| (frame.map(DVec2::ZERO), frame.map(*p)))
                            .collect(),
                    },
                    Mark::Line {
                        series: BLUE,
                        points: tips.iter().map(|p| frame.map(*p)).collect(),
                    },
                    Mark::Dots {
                        series: ORANGE,
                        points: tips.iter().map(|p| frame.map(*p)).collect(),
                    },
                ],
            })
        }
        "cubic-path" => {
            let t = Table::of(output, "cubic_path.csv")?;
            Some(lines(
                &t.col("t_s")?,
                &[(&t.col("q")?, BLUE), (&t.col("qd")?, ORANGE)],
            ))
        }
        "se3-relative" => Some(se3_picture(aspect)),
        "rrt-2d" => {
            let nodes = Table::of(output, "rrt_nodes.csv")?;
            let path = Table::of(output, "rrt_path.csv")?;
            let pts = pairs(&nodes.col("x")?, &nodes.col("y")?);
            let parent = nodes.col("parent")?;
            let frame = Frame::fit([DVec2::ZERO, DVec2::ONE].into_iter(), Some(aspect));
            let edges = pts
                .iter()
                .zip(&parent)
                .filter(|(_, p)| **p >= 0.0)
                .filter_map(|(c, p)| Some((frame.map(*c), frame.map(*pts.get(*p as usize)?))))
                .collect();
            Some(Picture {
                marks: vec![
                    Mark::Segments {
                        series: GREY,
                        pairs: edges,
                    },
                    Mark::Line {
                        series: ORANGE,
                        points: pairs(&path.col("x")?, &path.col("y")?)
                            .into_iter()
                            .map(|p| frame.map(p))
                            .collect(),
                    },
                ],
            })
        }
        "pid-step" => {
            let t = Table::of(output, "pid_step.csv")?;
            Some(lines(
                &t.col("t")?,
                &[(&t.col("r")?, ORANGE), (&t.col("y")?, BLUE)],
            ))
        }
        "manip-grid" => {
            let t = Table::of(output, "manip_ellipse.csv")?;
            let (q1, q2, m) = (t.col("q1")?, t.col("q2")?, t.col("manip")?);
            let distinct = |v: &[f64]| {
                let mut s: Vec<f64> = v.to_vec();
                s.sort_by(f64::total_cmp);
                s.dedup();
                s
            };
            let (xs, ys) = (distinct(&q1), distinct(&q2));
            let top = m
                .iter()
                .copied()
                .filter(|v| v.is_finite())
                .fold(0.0, f64::max);
            let mut values = vec![0.0; xs.len() * ys.len()];
            for i in 0..m.len() {
                let cx = xs.binary_search_by(|v| v.total_cmp(&q1[i])).ok()?;
                let cy = ys.binary_search_by(|v| v.total_cmp(&q2[i])).ok()?;
                values[cy * xs.len() + cx] = if top > 0.0 { m[i] / top } else { 0.0 };
            }
            Some(Picture {
                marks: vec![Mark::Cells {
                    cols: xs.len(),
                    rows: ys.len(),
                    values,
                }],
            })
        }
        "trapezoid-profile" => {
            let t = Table::of(output, "trap_profile.csv")?;
            Some(lines(&t.col("t")?, &[(&t.col("v")?, BLUE)]))
        }
        "umeyama-2d" => Some(umeyama_picture(aspect)),
        _ => None,
    }
}

/// World and the recipe's frames A and B as triads in an iso view, with the arrow A → B.
fn se3_picture(aspect: f64) -> Picture {
    let params = se3_relative::Se3Params::default();
    let cam = Camera::framing(DVec3::new(0.05, 0.025, 0.01), 0.12, Preset::Iso, 1.0, 1.0);
    let project = |p: DVec3| cam.project(p).map(|q| DVec2::new(q.at.x, 1.0 - q.at.y));
    let triad = |t: nalgebra::Matrix4<f64>, len: f64| -> Vec<(u8, DVec2, DVec2)> {
        let o = DVec3::new(t[(0, 3)], t[(1, 3)], t[(2, 3)]);
        (0..3)
            .filter_map(|k| {
                let axis = DVec3::new(t[(0, k)], t[(1, k)], t[(2, k)]);
                Some((k as u8, project(o)?, project(o + axis * len)?))
            })
            .collect()
    };
    let mut axes = triad(params.a.to_matrix(), 0.05);
    axes.extend(triad(params.b.to_matrix(), 0.05));
    let arrow: Vec<DVec2> = [params.a, params.b]
        .iter()
        .filter_map(|p| project(DVec3::new(p.x, p.y, p.z)))
        .collect();
    let frame = Frame::fit(
        axes.iter()
            .flat_map(|(_, a, b)| [*a, *b])
            .chain(arrow.iter().copied()),
        Some(aspect),
    );
    let colour = |k: u8| match k {
        0 => series::RED,
        1 => series::GREEN,
        _ => series::BLUE,
    };
    let mut marks: Vec<Mark> = (0..3u8)
        .map(|k| Mark::Segments {
            series: colour(k),
            pairs: axes
                .iter()
                .filter(|(axis, _, _)| *axis == k)
                .map(|(_, a, b)| (frame.map(*a), frame.map(*b)))
                .collect(),
        })
        .collect();
    marks.push(Mark::Line {
        series: series::ORANGE,
        points: arrow.iter().map(|p| frame.map(*p)).collect(),
    });
    Picture { marks }
}

/// The recipe's noisy targets Y and the aligned source points s R X + t, with residuals.
fn umeyama_picture(aspect: f64) -> Picture {
    let params = umeyama_2d::UmeyamaParams::default();
    let (x, y) = umeyama_2d::sample_points(&params);
    let fit = umeyama_2d::umeyama(&x, &y);
    let (s, c) = fit.rotation_deg.to_radians().sin_cos();
    let aligned: Vec<DVec2> = x
        .iter()
        .map(|p| {
            DVec2::new(
                fit.scale * (c * p[0] - s * p[1]) + fit.tx,
                fit.scale * (s * p[0] + c * p[1]) + fit.ty,
            )
        })
        .collect();
    let source: Vec<DVec2> = x.iter().map(|p| DVec2::new(p[0], p[1])).collect();
    let target: Vec<DVec2> = y.iter().map(|p| DVec2::new(p[0], p[1])).collect();
    let frame = Frame::fit(
        source.iter().chain(&target).chain(&aligned).copied(),
        Some(aspect),
    );
    let m = |v: &[DVec2]| v.iter().map(|p| frame.map(*p)).collect::<Vec<_>>();
    Picture {
        marks: vec![
            Mark::Segments {
                series: series::GREY,
                pairs: target
                    .iter()
                    .zip(&aligned)
                    .map(|(a, b)| (frame.map(*a), frame.map(*b)))
                    .collect(),
            },
            Mark::Dots {
                series: series::GREY,
                points: m(&source),
            },
            Mark::Dots {
                series: series::ORANGE,
                points: m(&target),
            },
            Mark::Dots {
                series: series::BLUE,
                points: m(&aligned),
            },
        ],
    }
}

/// The picture of a recipe at its defaults, running its kernel, for a canvas `aspect` (width
/// / height) wide.
pub fn default_picture(id: &str, aspect: f64) -> Option<Picture> {
    let output = recipes::run(id, &[]).ok()?;
    picture(id, &output, aspect)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(p: &Picture) -> Vec<DVec2> {
        p.marks
            .iter()
            .flat_map(|m| match m {
                Mark::Line { points, .. } | Mark::Dots { points, .. } => points.clone(),
                Mark::Segments { pairs, .. } => pairs.iter().flat_map(|(a, b)| [*a, *b]).collect(),
                Mark::Cells { .. } => Vec::new(),
            })
            .collect()
    }

    #[test]
    fn every_recipe_has_a_picture_inside_the_unit_square() {
        for recipe in recipes::RECIPES.iter() {
            let id = recipe.info.id;
            let picture = default_picture(id, 2.8).unwrap_or_else(|| panic!("{id}: no picture"));
            assert!(!picture.marks.is_empty(), "{id}");
            for p in points(&picture) {
                assert!(
                    p.is_finite()
                        && (-1e-9..=1.0 + 1e-9).contains(&p.x)
                        && (-1e-9..=1.0 + 1e-9).contains(&p.y),
                    "{id}: {p:?}"
                );
            }
        }
    }

    #[test]
    fn the_rrt_picture_has_one_edge_per_node_but_the_root_and_the_path() {
        let picture = default_picture("rrt-2d", 1.0).unwrap();
        let Mark::Segments { pairs, .. } = &picture.marks[0] else {
            panic!("edges first")
        };
        // The recipe's default run: 91 nodes, a 33-point path.
        assert_eq!(pairs.len(), 90);
        let Mark::Line { points, .. } = &picture.marks[1] else {
            panic!("path second")
        };
        assert_eq!(points.len(), 33);
    }

    #[test]
    fn equal_aspect_keeps_squares_square_on_a_wide_canvas() {
        let aspect = 3.0;
        let frame = Frame::fit([DVec2::ZERO, DVec2::ONE].into_iter(), Some(aspect));
        let (a, b) = (frame.map(DVec2::ZERO), frame.map(DVec2::ONE));
        // Canvas pixels: x scaled by the aspect.
        let w = (b.x - a.x) * aspect;
        let h = b.y - a.y;
        assert!((w - h).abs() < 1e-12 && h > 0.8 && a.x > 0.0 && b.x < 1.0);
    }

    #[test]
    fn the_manipulability_grid_fills_every_cell_and_peaks_at_one() {
        let picture = default_picture("manip-grid", 2.0).unwrap();
        let Mark::Cells { cols, rows, values } = &picture.marks[0] else {
            panic!("cells")
        };
        assert_eq!(cols * rows, 576);
        assert!(values.iter().all(|v| (0.0..=1.0).contains(v)));
        assert_eq!(values.iter().copied().fold(0.0, f64::max), 1.0);
    }

    #[test]
    fn the_pendulum_picture_draws_three_energies_over_time() {
        let picture = default_picture("pendulum-energy", 3.0).unwrap();
        assert_eq!(picture.marks.len(), 3);
        let Mark::Line { points, .. } = &picture.marks[2] else {
            panic!()
        };
        assert_eq!(points.len(), 2500);
        assert!(points.windows(2).all(|w| w[1].x > w[0].x));
    }

    #[test]
    fn an_output_without_the_columns_gives_no_picture() {
        let output = RecipeOutput::single("pid_step.csv", "a,b\n1,2\n".into(), String::new());
        assert_eq!(picture("pid-step", &output, 1.0), None);
        assert_eq!(picture("nope", &output, 1.0), None);
    }
}
