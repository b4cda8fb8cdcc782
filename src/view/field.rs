//! One field of the parameter form, read from a recipe's facts ([`ArgSpec`]): the argument it
//! sets, its label id, group, keypad and width, and the text typed in it.

use crate::args::{ArgKind, ArgSpec, Bound};
use crate::recipes::RecipeInfo;

/// One field of the form.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldDef {
    /// The argument it sets (name, default, kind, unit, limits, hint id).
    pub spec: &'static ArgSpec,
    /// A `--flag` option (after the positional arguments on the command line).
    pub flag: bool,
    /// Fluent id of the label (`recipe-<id>-arg-<name>` / `-flag-<name>`).
    pub label_id: String,
    /// The fieldset it belongs to (an index into the form's groups).
    pub group: usize,
}

impl FieldDef {
    /// The argument's name (`data-field`, URL key, command-line flag).
    pub fn name(&self) -> &'static str {
        self.spec.name
    }

    /// The recipe's default, as the recipe writes it.
    pub fn default(&self) -> &'static str {
        self.spec.default
    }

    /// The field is traj-resample-style file input (a picker, not a text box).
    pub fn is_file(&self) -> bool {
        self.spec.kind == ArgKind::File
    }

    /// The phone keypad: `numeric` for whole numbers, `decimal` for numbers that are never
    /// negative, `text` where a minus sign or commas are needed (phone decimal pads often
    /// have no minus key).
    pub fn inputmode(&self) -> &'static str {
        match self.spec.kind {
            ArgKind::Integer | ArgKind::Seed => "numeric",
            ArgKind::Number if never_negative(self.spec.min) => "decimal",
            _ => "text",
        }
    }

    /// A wide field (a list, points or a file takes a whole row).
    pub fn is_wide(&self) -> bool {
        matches!(
            self.spec.kind,
            ArgKind::List { .. } | ArgKind::File | ArgKind::Points
        )
    }
}

fn never_negative(min: Bound) -> bool {
    min.value().is_some_and(|m| m >= 0.0)
}

/// The fields of a recipe: its positional arguments (group 0) then its options (group 1).
pub fn recipe_fields(info: &RecipeInfo) -> Vec<FieldDef> {
    info.all_args()
        .map(|(spec, flag)| FieldDef {
            spec,
            flag,
            label_id: spec.label_id(info.id, flag),
            group: usize::from(flag),
        })
        .collect()
}

/// The texts of a form of `fields`: the value `values` names for each field, `None` for the
/// fields it does not name.
pub fn texts_by_name(fields: &[FieldDef], values: &[(&str, &str)]) -> Vec<Option<String>> {
    fields
        .iter()
        .map(|f| {
            values
                .iter()
                .find(|(n, _)| *n == f.name())
                .map(|(_, v)| v.to_string())
        })
        .collect()
}

/// The text typed in each field, trimmed, `None` where it is blank (blank = the default).
pub fn typed(texts: &[Option<String>], index: usize) -> Option<&str> {
    texts
        .get(index)
        .and_then(|t| t.as_deref())
        .map(str::trim)
        .filter(|t| !t.is_empty())
}

/// The fields' label and hint ids that have no message in some language (`"ja: <id>"`).
#[cfg(test)]
pub(crate) fn missing_messages(fields: &[FieldDef]) -> Vec<String> {
    use crate::i18n::{I18n, Lang};
    let i18n = I18n::new();
    let mut missing = Vec::new();
    for field in fields {
        for lang in Lang::ALL {
            for id in [field.label_id.as_str(), field.spec.hint_id] {
                if !i18n.has_message(lang, id) {
                    missing.push(format!("{}: {id}", lang.code()));
                }
            }
        }
    }
    missing
}
