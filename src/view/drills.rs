//! The drills page's URL state: `#/drills?recipe=pid-step&Kp=2&steps=120`. The keys are the
//! recipe's argument names (`ArgSpec::name`, options too: `integrator=rk4`, `goal-x=0.5`);
//! only values that differ from the defaults are written, as typed. traj-resample writes the
//! name of the opened file as `csv_path` (the file itself never leaves the computer: reopening
//! the link asks for it again).
//!
//! Reading is forgiving: an unknown recipe falls back to the first one, keys the recipe does
//! not take are reported as [`IgnoredKey::unknown`], and values are put in their fields as
//! they are, where validation flags the bad ones (the page reports those as
//! [`IgnoredKey::flagged`]).

use crate::recipes::{self, RecipeInfo, INFOS};
use crate::view::form::FieldDef;
use crate::view::url::{IgnoredKey, UrlState};

/// The query key of the recipe id.
pub const RECIPE_KEY: &str = "recipe";

/// What a drills URL holds.
#[derive(Clone)]
pub struct DrillsQuery {
    pub recipe: &'static RecipeInfo,
    /// `(name, value)` for the recipe's fields, in URL order.
    pub values: Vec<(String, String)>,
    /// The recipe id of the URL when no recipe has it.
    pub unknown_recipe: Option<String>,
}

impl DrillsQuery {
    /// The query of a recipe and the texts of its fields: every field whose text is not blank
    /// and differs from its default.
    pub fn from_form(
        recipe: &'static RecipeInfo,
        fields: &[FieldDef],
        texts: &[Option<String>],
    ) -> DrillsQuery {
        let mut values = Vec::new();
        for (field, text) in fields.iter().zip(texts) {
            let Some(text) = text.as_deref().map(str::trim) else {
                continue;
            };
            if !text.is_empty() && text != field.default() {
                values.push((field.name().to_string(), text.to_string()));
            }
        }
        DrillsQuery {
            recipe,
            values,
            unknown_recipe: None,
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

impl UrlState for DrillsQuery {
    /// Reads the decoded query of `#/drills?...` (`lang` already removed by the router).
    fn read(query: &[(String, String)]) -> (DrillsQuery, Vec<IgnoredKey>) {
        let asked = query
            .iter()
            .find(|(k, _)| k == RECIPE_KEY)
            .map(|(_, v)| v.trim());
        let found = asked.and_then(recipes::find_info);
        let recipe = found.unwrap_or(INFOS[0]);
        let unknown_recipe = match (asked, found) {
            (Some(id), None) => Some(id.to_string()),
            _ => None,
        };
        let info = recipe;
        let mut values: Vec<(String, String)> = Vec::new();
        let mut ignored: Vec<IgnoredKey> = Vec::new();
        for (key, value) in query {
            if key == RECIPE_KEY {
                continue;
            }
            let known = info.args.iter().chain(info.flags).any(|s| s.name == key);
            if known && unknown_recipe.is_none() {
                values.retain(|(k, _)| k != key);
                values.push((key.clone(), value.clone()));
            } else if !ignored.iter().any(|k| &k.key == key) {
                ignored.push(IgnoredKey::unknown(key.clone()));
            }
        }
        let query = DrillsQuery {
            recipe,
            values,
            unknown_recipe,
        };
        (query, ignored)
    }

    /// `recipe` first, then the values.
    fn write(&self) -> Vec<(String, String)> {
        let id = self
            .unknown_recipe
            .clone()
            .unwrap_or_else(|| self.recipe.id.to_string());
        std::iter::once((RECIPE_KEY.to_string(), id))
            .chain(self.values.iter().cloned())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::form::recipe_fields as fields;
    use crate::view::url::{parse_hash, query as pairs};

    /// The query the page is handed for `#/drills?<query>` (decoded by the router).
    fn q(query: &str) -> Vec<(String, String)> {
        parse_hash(&format!("#/drills?{query}")).page_query()
    }

    #[test]
    fn a_url_round_trips_through_the_fields() {
        let (url, ignored) = DrillsQuery::read(&q("recipe=pid-step&Kp=2&steps=120"));
        assert_eq!(url.recipe.id, "pid-step");
        assert!(url.unknown_recipe.is_none() && ignored.is_empty());
        let fields = fields(url.recipe);
        let texts = url.texts(&fields);
        assert_eq!(texts[0].as_deref(), Some("2"));
        assert_eq!(texts[1], None);
        assert_eq!(texts[4].as_deref(), Some("120"));
        let written = DrillsQuery::from_form(url.recipe, &fields, &texts).write();
        assert_eq!(
            written,
            pairs(&[("recipe", "pid-step"), ("Kp", "2"), ("steps", "120")])
        );
        // Defaults and blanks are not written; a text equal to the default after trimming
        // neither.
        let mut texts = texts;
        texts[0] = Some(" 1.2 ".into());
        texts[1] = Some("  ".into());
        let written = DrillsQuery::from_form(url.recipe, &fields, &texts).write();
        assert_eq!(written, pairs(&[("recipe", "pid-step"), ("steps", "120")]));
        let (back, ignored) = DrillsQuery::read(&written);
        assert!(ignored.is_empty());
        assert_eq!(back.values, pairs(&[("steps", "120")]));
    }

    #[test]
    fn options_bad_values_unknown_keys_and_recipes() {
        let (url, ignored) = DrillsQuery::read(&q(
            "recipe=pendulum-energy&integrator=rk4&duration_s=abc&Kp=3&Kp=4",
        ));
        // Bad values go to their field as typed (validation flags them there).
        assert_eq!(
            url.values,
            pairs(&[("integrator", "rk4"), ("duration_s", "abc")])
        );
        assert_eq!(ignored, vec![IgnoredKey::unknown("Kp")]);
        let (url, ignored) = DrillsQuery::read(&q("recipe=nope&Kp=3"));
        assert_eq!(url.recipe.id, INFOS[0].id);
        assert_eq!(url.unknown_recipe.as_deref(), Some("nope"));
        assert!(url.values.is_empty());
        assert_eq!(ignored, vec![IgnoredKey::unknown("Kp")]);
        let (url, ignored) = DrillsQuery::read(&[]);
        assert_eq!(url.recipe.id, INFOS[0].id);
        assert!(url.unknown_recipe.is_none() && ignored.is_empty());
    }
}
