//! The small picture on each recipe card of the home page, drawn from what the recipe's kernel
//! computes at its defaults. Each recipe draws its own (`RecipeInfo::picture`, beside its
//! kernel); the drawing model is [`crate::recipes::picture`].

pub use crate::recipes::picture::{series, Mark, Picture};
use crate::recipes::{self, RecipeOutput};

/// The picture of recipe `id` from its output at the defaults (`None` for an unknown id or an
/// output without the expected columns).
pub fn picture(id: &str, output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    (recipes::find(id)?.picture)(output, aspect)
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

    #[test]
    fn every_recipe_has_a_picture_inside_the_unit_square() {
        for recipe in recipes::RECIPES.iter() {
            let id = recipe.info.id;
            let picture = default_picture(id, 2.8).unwrap_or_else(|| panic!("{id}: no picture"));
            assert!(!picture.marks.is_empty(), "{id}");
            for p in picture.points() {
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
