//! The page's URL state: `#/drills?recipe=pid-step&Kp=2&steps=120`. The keys are the recipe's
//! argument names (`ArgSpec::name`, options too: `integrator=rk4`, `goal-x=0.5`); only values
//! that differ from the defaults are written, as typed. traj-resample writes the name of the
//! opened file as `csv_path` (the file itself never leaves the computer: reopening the link
//! asks for it again).
//!
//! Reading is forgiving: an unknown recipe falls back to the first one, keys the recipe does
//! not take are ignored, and values are put in their fields as they are, where validation
//! flags the bad ones; the page lists all of this in a notice.

use crate::recipes::{self, Recipe, RECIPES};
use crate::view::form::FieldDef;

/// The query key of the recipe id.
pub const RECIPE_KEY: &str = "recipe";

/// What a URL asks for.
#[derive(Clone)]
pub struct UrlState {
    pub recipe: &'static Recipe,
    /// `(name, value)` for the recipe's fields, in URL order.
    pub values: Vec<(String, String)>,
    /// The recipe id of the URL when no recipe has it.
    pub unknown_recipe: Option<String>,
    /// Keys that are not arguments of the recipe.
    pub ignored: Vec<String>,
}

impl UrlState {
    /// Reads the decoded query of `#/drills?...` (`lang` already removed by the router).
    pub fn parse(query: &[(String, String)]) -> UrlState {
        let asked = query
            .iter()
            .find(|(k, _)| k == RECIPE_KEY)
            .map(|(_, v)| v.trim());
        let found = asked.and_then(recipes::find);
        let recipe = found.unwrap_or(&RECIPES[0]);
        let unknown_recipe = match (asked, found) {
            (Some(id), None) => Some(id.to_string()),
            _ => None,
        };
        let info = recipe.info;
        let mut values = Vec::new();
        let mut ignored = Vec::new();
        for (key, value) in query {
            if key == RECIPE_KEY {
                continue;
            }
            let known = info.args.iter().chain(info.flags).any(|s| s.name == key);
            if known && unknown_recipe.is_none() {
                values.retain(|(k, _)| k != key);
                values.push((key.clone(), value.clone()));
            } else if !ignored.contains(key) {
                ignored.push(key.clone());
            }
        }
        UrlState {
            recipe,
            values,
            unknown_recipe,
            ignored,
        }
    }

    /// The URL's text for each field (`None` where the URL has none).
    pub fn texts(&self, fields: &[FieldDef]) -> Vec<Option<String>> {
        fields
            .iter()
            .map(|f| {
                self.values
                    .iter()
                    .find(|(k, _)| k == f.name())
                    .map(|(_, v)| v.clone())
            })
            .collect()
    }
}

/// The query for a recipe and the texts of its fields: `recipe` first, then every field whose
/// text is not blank and differs from its default.
pub fn pairs(
    recipe: &'static str,
    fields: &[FieldDef],
    texts: &[Option<String>],
) -> Vec<(&'static str, String)> {
    let mut out = vec![(RECIPE_KEY, recipe.to_string())];
    for (field, text) in fields.iter().zip(texts) {
        let Some(text) = text.as_deref().map(str::trim) else {
            continue;
        };
        if !text.is_empty() && text != field.default() {
            out.push((field.name(), text.to_string()));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::router;
    use crate::view::form::recipe_fields as fields;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    /// The query the page is handed for `#/drills?<query>` (decoded by the router).
    fn q(query: &str) -> Vec<(String, String)> {
        router::parse_hash(&format!("#/drills?{query}")).page_query()
    }

    #[test]
    fn a_url_round_trips_through_the_fields() {
        let url = UrlState::parse(&q("recipe=pid-step&Kp=2&steps=120"));
        assert_eq!(url.recipe.info.id, "pid-step");
        assert!(url.unknown_recipe.is_none() && url.ignored.is_empty());
        let fields = fields(url.recipe.info);
        let texts = url.texts(&fields);
        assert_eq!(texts[0].as_deref(), Some("2"));
        assert_eq!(texts[1], None);
        assert_eq!(texts[4].as_deref(), Some("120"));
        let written = pairs("pid-step", &fields, &texts);
        assert_eq!(
            written,
            vec![
                ("recipe", "pid-step".to_string()),
                ("Kp", "2".to_string()),
                ("steps", "120".to_string())
            ]
        );
    }

    #[test]
    fn options_bad_values_unknown_keys_and_recipes() {
        let url = UrlState::parse(&q(
            "recipe=pendulum-energy&integrator=rk4&duration_s=abc&Kp=3",
        ));
        assert_eq!(url.values.len(), 2);
        assert_eq!(url.ignored, vec!["Kp".to_string()]);
        let url = UrlState::parse(&q("recipe=nope&Kp=3"));
        assert_eq!(url.recipe.info.id, RECIPES[0].info.id);
        assert_eq!(url.unknown_recipe.as_deref(), Some("nope"));
        assert!(url.values.is_empty());
        let url = UrlState::parse(&[]);
        assert_eq!(url.recipe.info.id, RECIPES[0].info.id);
        assert!(url.unknown_recipe.is_none());
    }
}
