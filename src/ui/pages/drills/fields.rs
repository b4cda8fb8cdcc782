//! The drill's form: one field per argument of the recipe's `INFO` (positional arguments in
//! command-line order, then the `--flag` options), each with its localized label
//! (`recipe-<id>-arg-<name>` / `-flag-<name>` in recipes.ftl), the recipe's default as initial
//! value and placeholder, a hint that states the kernel's limits (with the limits taken from
//! the kernels' constants), and a slot for the localized error message beside it.
//!
//! An empty field means the default (the placeholder shows it), as an argument left off the
//! command line does. traj-resample's path argument is a file picker instead of a text field.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement, HtmlSelectElement};

use super::texts::{escape, group, plain_number};
use crate::args::ArgSpec;
use crate::error::RecipeError;
use crate::i18n::FluentArg;
use crate::recipes::{
    cubic_path, ik_workspace, jacobian_2r, manip_grid, pendulum_energy, pid_step, rrt_2d,
    traj_resample, trapezoid_profile, umeyama_2d, RecipeInfo,
};
use crate::ui::ctx;

/// How a value is entered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A number that may be negative (a text keypad: phone decimal pads often lack a minus).
    Signed,
    /// A number that is never negative.
    Unsigned,
    /// A whole number.
    Whole,
    /// Several numbers separated by commas.
    List,
    /// One of a few words.
    Choice(&'static [&'static str]),
    /// An input file (traj-resample's CSV).
    File,
}

impl Kind {
    fn inputmode(self) -> &'static str {
        match self {
            Kind::Unsigned => "decimal",
            Kind::Whole => "numeric",
            _ => "text",
        }
    }
}

/// One field of the form.
#[derive(Debug, Clone, Copy)]
pub struct Field {
    pub spec: &'static ArgSpec,
    /// A `--flag` option (after the positional arguments).
    pub flag: bool,
    pub kind: Kind,
    /// Fluent id of the hint (limits).
    pub hint: &'static str,
}

impl Field {
    /// Fluent id of the label (recipes.ftl).
    pub fn label_id(&self, recipe: &str) -> String {
        let kind = if self.flag { "flag" } else { "arg" };
        format!("recipe-{recipe}-{kind}-{}", self.spec.name)
    }
}

/// The fields of a recipe: positional arguments, then flags.
pub fn fields(info: &RecipeInfo) -> Vec<Field> {
    let make = |spec: &'static ArgSpec, flag: bool| {
        let (kind, hint) = describe(info.id, spec.name);
        Field {
            spec,
            flag,
            kind,
            hint,
        }
    };
    info.args
        .iter()
        .map(|s| make(s, false))
        .chain(info.flags.iter().map(|s| make(s, true)))
        .collect()
}

/// How each argument is entered and which hint states its limits.
fn describe(recipe: &str, name: &str) -> (Kind, &'static str) {
    use Kind::*;
    match (recipe, name) {
        ("pendulum-energy", "duration_s") => (Unsigned, "drills-hint-pendulum-duration"),
        ("pendulum-energy", "damping") => (Unsigned, "drills-hint-pendulum-damping"),
        ("pendulum-energy", "angle-deg") => (Signed, "drills-hint-pendulum-angle"),
        ("pendulum-energy", "timestep") => (Unsigned, "drills-hint-pendulum-timestep"),
        ("pendulum-energy", "integrator") => {
            (Choice(&["euler", "rk4"]), "drills-hint-pendulum-integrator")
        }
        ("pendulum-energy", _) => (Unsigned, "drills-hint-positive"),
        ("ik-workspace" | "jacobian-2r" | "manip-grid", "L1" | "L2") => {
            (Unsigned, "drills-hint-link")
        }
        ("ik-workspace", "half_mm") => (Unsigned, "drills-hint-ik-half"),
        ("ik-workspace", "step_mm") => (Unsigned, "drills-hint-ik-step"),
        ("traj-resample", "csv_path") => (File, "drills-hint-traj-file"),
        ("traj-resample", "dt") => (Unsigned, "drills-hint-traj-dt"),
        ("dh-fk", _) => (List, "drills-hint-dh-angles"),
        ("jacobian-2r", "q1_stop") => (Signed, "drills-hint-jacobian-stop"),
        ("jacobian-2r", "q1_step") => (Unsigned, "drills-hint-jacobian-step"),
        ("jacobian-2r" | "cubic-path", "q1_start" | "q2" | "q0" | "q1") => {
            (Signed, "drills-hint-angle-range")
        }
        ("cubic-path", "T") => (Unsigned, "drills-hint-cubic-duration"),
        ("cubic-path" | "trapezoid-profile", "dt") => (Unsigned, "drills-hint-rows-dt"),
        ("se3-relative", "ax" | "ay" | "az" | "bx" | "by" | "bz") => {
            (Signed, "drills-hint-se3-position")
        }
        ("se3-relative", _) => (Signed, "drills-hint-se3-angle"),
        ("rrt-2d" | "umeyama-2d", "seed") => (Whole, "drills-hint-seed"),
        ("rrt-2d", "max_iter") => (Whole, "drills-hint-rrt-iterations"),
        ("rrt-2d", _) => (Unsigned, "drills-hint-rrt-goal"),
        ("pid-step", "tau") => (Unsigned, "drills-hint-pid-tau"),
        ("pid-step", "steps") => (Whole, "drills-hint-pid-steps"),
        ("pid-step", _) => (Signed, "drills-hint-pid-gain"),
        ("manip-grid", "n") => (Whole, "drills-hint-manip-n"),
        ("trapezoid-profile", "distance") => (Signed, "drills-hint-trapezoid-distance"),
        ("trapezoid-profile", _) => (Signed, "drills-hint-trapezoid-limit"),
        ("umeyama-2d", "sigma") => (Unsigned, "drills-hint-umeyama-sigma"),
        ("umeyama-2d", "n") => (Whole, "drills-hint-umeyama-n"),
        _ => (Signed, "drills-hint-number"),
    }
}

/// The Fluent arguments of a field's hint: the kernel's limits, formatted for reading.
fn hint_args(recipe: &str, name: &str) -> Vec<(&'static str, FluentArg)> {
    let count = |n: u64| FluentArg::from(group(n));
    let real = |x: f64| FluentArg::from(plain_number(x));
    match (recipe, name) {
        ("pendulum-energy", "duration_s") => {
            let step = pendulum_energy::PendulumParams::default().timestep_s;
            vec![
                ("max", count(pendulum_energy::MAX_STEPS)),
                ("seconds", real(step * pendulum_energy::MAX_STEPS as f64)),
            ]
        }
        ("pendulum-energy", "timestep") => vec![("max", count(pendulum_energy::MAX_STEPS))],
        (_, "L1" | "L2") => vec![
            ("min", real(ik_workspace::LINK_MIN_M)),
            ("max", real(ik_workspace::LINK_MAX_M)),
        ],
        ("ik-workspace", "half_mm") => vec![("max", real(ik_workspace::HALF_MAX_MM))],
        ("ik-workspace", "step_mm") => vec![("max", count(ik_workspace::MAX_AXIS_SAMPLES))],
        ("traj-resample", "csv_path") => vec![(
            "limit",
            FluentArg::from(super::texts::size_text(traj_resample::MAX_INPUT_BYTES)),
        )],
        ("traj-resample", "dt") => vec![("max", count(traj_resample::MAX_OUTPUT_CELLS))],
        ("jacobian-2r", "q1_start" | "q1_stop" | "q2") => {
            vec![("max", real(jacobian_2r::ANGLE_MAX_RAD))]
        }
        ("jacobian-2r", "q1_step") => vec![("max", count(jacobian_2r::MAX_SAMPLES))],
        ("cubic-path", "q0" | "q1") => vec![("max", real(cubic_path::ANGLE_MAX_RAD))],
        ("cubic-path", "T") => vec![
            ("min", real(cubic_path::DURATION_MIN_S)),
            ("max", real(cubic_path::DURATION_MAX_S)),
        ],
        ("cubic-path", "dt") => vec![("max", count(cubic_path::MAX_ROWS))],
        ("trapezoid-profile", "dt") => vec![("max", count(trapezoid_profile::MAX_ROWS))],
        ("rrt-2d", "max_iter") => vec![("max", count(rrt_2d::MAX_ITER_LIMIT as u64))],
        ("pid-step", "tau") => vec![("max", real(pid_step::TAU_MAX_S))],
        ("pid-step", "steps") => vec![
            ("max", count(pid_step::MAX_STEPS.unsigned_abs())),
            ("seconds", real(pid_step::MAX_STEPS as f64 * pid_step::DT_S)),
        ],
        ("manip-grid", "n") => {
            let n = manip_grid::MAX_N.unsigned_abs();
            vec![("max", count(n)), ("rows", count(n * n))]
        }
        ("trapezoid-profile", "distance") => {
            vec![("max", real(trapezoid_profile::MAGNITUDE_MAX))]
        }
        ("trapezoid-profile", _) => vec![
            ("min", real(trapezoid_profile::MAGNITUDE_MIN)),
            ("max", real(trapezoid_profile::MAGNITUDE_MAX)),
        ],
        ("umeyama-2d", "n") => vec![
            ("min", count(umeyama_2d::MIN_POINTS as u64)),
            ("max", count(umeyama_2d::MAX_POINTS as u64)),
        ],
        _ => Vec::new(),
    }
}

/// The hint of a field in the current language.
pub fn hint_text(recipe: &str, field: &Field) -> String {
    ctx::t_args(field.hint, &hint_args(recipe, field.spec.name))
}

/// The markup of one field (`data-field="<name>"`, error slot `data-field-error="<name>"`).
fn field_markup(recipe: &str, field: &Field) -> String {
    let name = escape(field.spec.name);
    let default = escape(field.spec.default);
    let label = field.label_id(recipe);
    let flag = if field.flag {
        format!(" <code class=\"drills-flag\">--{name}</code>")
    } else {
        String::new()
    };
    let described = format!("drills-h-{name} drills-e-{name}");
    let control = match field.kind {
        Kind::File => format!(
            "<div class=\"drills-file-row\">\
             <label class=\"button drills-file-pick\">\
             <input type=\"file\" accept=\".csv,text/csv\" class=\"drills-visually-hidden\" \
             id=\"drills-f-{name}\" data-file-input data-testid=\"drills-file\" \
             aria-describedby=\"drills-file-status {described}\">\
             <span data-i18n=\"drills-file-open\"></span></label>\
             <button type=\"button\" class=\"button\" data-use-sample data-testid=\"drills-use-sample\" \
             data-i18n=\"drills-file-sample\"></button></div>\
             <p class=\"drills-file-status\" id=\"drills-file-status\" data-file-status \
             data-testid=\"drills-file-status\" role=\"status\"></p>"
        ),
        Kind::Choice(choices) => {
            let mut html = format!(
                "<select id=\"drills-f-{name}\" data-field=\"{name}\" aria-describedby=\"{described}\">"
            );
            for choice in choices {
                let c = escape(choice);
                html.push_str(&format!("<option value=\"{c}\">{c}</option>"));
            }
            html.push_str("</select>");
            html
        }
        kind => format!(
            "<input id=\"drills-f-{name}\" type=\"text\" inputmode=\"{mode}\" autocomplete=\"off\" \
             autocapitalize=\"off\" spellcheck=\"false\" enterkeyhint=\"go\" data-field=\"{name}\" \
             placeholder=\"{default}\" aria-describedby=\"{described}\">",
            mode = kind.inputmode()
        ),
    };
    let default_note = if field.spec.default.is_empty() || matches!(field.kind, Kind::File) {
        String::new()
    } else {
        format!(
            "<span class=\"drills-default\"><span data-i18n=\"drills-default\"></span> \
             <code>{default}</code></span> "
        )
    };
    let label_open = if matches!(field.kind, Kind::File) {
        format!("<span class=\"drills-label\" id=\"drills-l-{name}\">")
    } else {
        format!("<label class=\"drills-label\" for=\"drills-f-{name}\">")
    };
    let label_close = if matches!(field.kind, Kind::File) {
        "</span>"
    } else {
        "</label>"
    };
    format!(
        "<div class=\"drills-field{wide}\" data-field-wrap=\"{name}\">\
         {label_open}<span data-i18n=\"{label}\"></span>{flag}{label_close}\
         {control}\
         <small class=\"drills-hint\" id=\"drills-h-{name}\">{default_note}<span data-hint></span></small>\
         <p class=\"drills-error\" id=\"drills-e-{name}\" data-field-error=\"{name}\" role=\"alert\" hidden></p>\
         </div>",
        wide = if matches!(field.kind, Kind::File | Kind::List) {
            " drills-field-wide"
        } else {
            ""
        },
    )
}

/// The whole form of a recipe: a fieldset of arguments and, if any, one of options.
pub fn markup(info: &RecipeInfo, fields: &[Field]) -> String {
    let mut html = String::new();
    for (flags, legend) in [(false, "drills-args-legend"), (true, "drills-flags-legend")] {
        let mut group = fields.iter().filter(|f| f.flag == flags).peekable();
        if group.peek().is_none() {
            continue;
        }
        html.push_str(&format!(
            "<fieldset class=\"drills-fieldset\"><legend data-i18n=\"{legend}\"></legend>"
        ));
        if flags {
            html.push_str(
                "<p class=\"drills-hint drills-legend-note\" data-i18n=\"drills-flags-note\"></p>",
            );
        }
        for field in group {
            html.push_str(&field_markup(info.id, field));
        }
        html.push_str("</fieldset>");
    }
    html
}

/// A message beside a field.
#[derive(Debug, Clone, PartialEq)]
pub enum Message {
    /// A kernel's (or the argument parser's) error.
    Recipe(RecipeError),
    /// A chosen file over the kernel's input limit, refused before reading.
    FileTooLarge {
        name: String,
        bytes: u64,
        limit: u64,
    },
    /// The browser could not read the chosen file.
    FileUnreadable { name: String, reason: String },
}

impl Message {
    /// The message in the current language.
    pub fn text(&self) -> String {
        match self {
            Message::Recipe(e) => ctx::error_text(e),
            Message::FileTooLarge { name, bytes, limit } => ctx::t_args(
                "drills-file-too-large",
                &[
                    ("name", FluentArg::from(name)),
                    ("size", FluentArg::from(super::texts::size_text(*bytes))),
                    ("limit", FluentArg::from(super::texts::size_text(*limit))),
                ],
            ),
            Message::FileUnreadable { name, reason } => ctx::t_args(
                "drills-file-unreadable",
                &[
                    ("name", FluentArg::from(name)),
                    ("reason", FluentArg::from(reason)),
                ],
            ),
        }
    }
}

/// A field's control.
pub enum Control {
    Input(HtmlInputElement),
    Select(HtmlSelectElement),
    /// traj-resample's file picker (its value is the page's input file, not text).
    File(HtmlInputElement),
}

/// The form's controls, hints and error slots, found after [`markup`] is in place.
pub struct Form {
    pub recipe: &'static str,
    pub fields: Vec<Field>,
    controls: Vec<Control>,
    hints: Vec<Option<Element>>,
    errors: Vec<Option<Element>>,
    /// The file picker's status line (traj-resample only).
    pub file_status: Option<Element>,
    /// The error shown beside each field, by field index (re-rendered on a language switch).
    shown: Vec<(usize, Message)>,
}

fn query<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    root.query_selector(selector)?
        .ok_or_else(|| JsValue::from_str(&format!("drills: missing {selector}")))?
        .dyn_into::<T>()
        .map_err(|_| JsValue::from_str(&format!("drills: wrong element type for {selector}")))
}

impl Form {
    /// Builds the form of `info` into `container` and fills it with `values`.
    pub fn build(
        container: &Element,
        info: &'static RecipeInfo,
        values: &[String],
    ) -> Result<Form, JsValue> {
        let fields = fields(info);
        container.set_inner_html(&markup(info, &fields));
        crate::ui::dom::relocalize(container)?;
        let mut controls = Vec::new();
        let mut hints = Vec::new();
        let mut errors = Vec::new();
        for field in &fields {
            let name = field.spec.name;
            let wrap: Element = query(container, &format!("[data-field-wrap=\"{name}\"]"))?;
            controls.push(match field.kind {
                Kind::File => Control::File(query(&wrap, "[data-file-input]")?),
                Kind::Choice(_) => Control::Select(query(&wrap, "[data-field]")?),
                _ => Control::Input(query(&wrap, "[data-field]")?),
            });
            hints.push(wrap.query_selector("[data-hint]")?);
            errors.push(wrap.query_selector("[data-field-error]")?);
        }
        let file_status = container.query_selector("[data-file-status]")?;
        let form = Form {
            recipe: info.id,
            fields,
            controls,
            hints,
            errors,
            file_status,
            shown: Vec::new(),
        };
        form.fill(values);
        form.relocalize();
        Ok(form)
    }

    /// Writes `values` into the controls (a missing value is the default).
    pub fn fill(&self, values: &[String]) {
        for (index, (field, control)) in self.fields.iter().zip(&self.controls).enumerate() {
            let value = values
                .get(index)
                .map(String::as_str)
                .unwrap_or(field.spec.default);
            match control {
                Control::Input(input) => input.set_value(value),
                Control::Select(select) => {
                    let value = value.trim().to_ascii_lowercase();
                    let known =
                        matches!(field.kind, Kind::Choice(c) if c.contains(&value.as_str()));
                    select.set_value(if known { &value } else { field.spec.default });
                }
                Control::File(_) => {}
            }
        }
    }

    /// The text now in each field (`None` for the file picker).
    pub fn texts(&self) -> Vec<Option<String>> {
        self.controls
            .iter()
            .map(|c| match c {
                Control::Input(i) => Some(i.value()),
                Control::Select(s) => Some(s.value()),
                Control::File(_) => None,
            })
            .collect()
    }

    /// The index of the field called `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.fields.iter().position(|f| f.spec.name == name)
    }

    /// The file picker, if the recipe has one.
    pub fn file_input(&self) -> Option<&HtmlInputElement> {
        self.controls.iter().find_map(|c| match c {
            Control::File(input) => Some(input),
            _ => None,
        })
    }

    /// Shows exactly `errors` (field index → error) and clears every other field's message.
    pub fn show_errors(&mut self, errors: &[(usize, Message)]) {
        self.shown = errors.to_vec();
        for index in 0..self.fields.len() {
            let error = errors.iter().find(|(i, _)| *i == index).map(|(_, e)| e);
            if let Some(Some(slot)) = self.errors.get(index) {
                match error {
                    Some(e) => {
                        slot.set_text_content(Some(&e.text()));
                        let _ = slot.remove_attribute("hidden");
                    }
                    None => {
                        slot.set_text_content(None);
                        let _ = slot.set_attribute("hidden", "");
                    }
                }
            }
            let invalid = if error.is_some() { "true" } else { "false" };
            let element: Option<&Element> = match self.controls.get(index) {
                Some(Control::Input(i)) => Some(i),
                Some(Control::Select(s)) => Some(s),
                Some(Control::File(f)) => Some(f),
                None => None,
            };
            if let Some(element) = element {
                let _ = element.set_attribute("aria-invalid", invalid);
            }
        }
    }

    /// Focuses the first field showing an error.
    pub fn focus_first_error(&self) {
        let Some(index) = self.shown.iter().map(|(i, _)| *i).min() else {
            return;
        };
        let element: Option<&Element> = match self.controls.get(index) {
            Some(Control::Input(i)) => Some(i),
            Some(Control::Select(s)) => Some(s),
            Some(Control::File(f)) => Some(f),
            None => None,
        };
        if let Some(element) = element {
            crate::ui::dom::focus(element);
        }
    }

    /// Re-renders hints and shown errors in the current language.
    pub fn relocalize(&self) {
        for (field, hint) in self.fields.iter().zip(&self.hints) {
            if let Some(hint) = hint {
                hint.set_text_content(Some(&hint_text(self.recipe, field)));
            }
        }
        for (index, error) in &self.shown {
            if let Some(Some(slot)) = self.errors.get(*index) {
                slot.set_text_content(Some(&error.text()));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{I18n, Lang};
    use crate::recipes::RECIPES;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn every_field_has_a_specific_hint_in_both_languages_with_its_limits() {
        let i18n = I18n::new();
        for recipe in RECIPES {
            let info = recipe.info;
            for field in fields(info) {
                assert_ne!(
                    field.hint, "drills-hint-number",
                    "{} {}",
                    info.id, field.spec.name
                );
                for lang in Lang::ALL {
                    assert!(
                        i18n.has_message(lang, field.hint),
                        "{lang:?} {}",
                        field.hint
                    );
                    let text = i18n.t_args(lang, field.hint, &hint_args(info.id, field.spec.name));
                    assert!(!text.contains("{$"), "{text}");
                }
            }
        }
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
        let en = |id: &str, name: &str| {
            let field = fields(crate::recipes::find(id).unwrap().info)
                .into_iter()
                .find(|f| f.spec.name == name)
                .unwrap();
            i18n.t_args(Lang::En, field.hint, &hint_args(id, name))
        };
        assert!(en("rrt-2d", "max_iter").contains("50,000"));
        assert!(en("manip-grid", "n").contains("1,024"));
        assert!(en("pendulum-energy", "duration_s").contains("1,000,000"));
        assert!(en("ik-workspace", "step_mm").contains("1,001"));
        assert!(en("traj-resample", "csv_path").contains("128 MiB"));
    }

    #[test]
    fn fields_follow_the_command_line_order_and_choices_are_the_kernels() {
        let pendulum = fields(&pendulum_energy::INFO);
        assert_eq!(pendulum[0].spec.name, "duration_s");
        assert!(!pendulum[0].flag && pendulum[1].flag);
        let integrator = pendulum
            .iter()
            .find(|f| f.spec.name == "integrator")
            .unwrap();
        let Kind::Choice(choices) = integrator.kind else {
            panic!("integrator is a choice");
        };
        assert_eq!(
            choices.join(", "),
            pendulum_energy::Integrator::CHOICES,
            "the select offers what the kernel accepts"
        );
        assert_eq!(fields(&traj_resample::INFO)[0].kind, Kind::File);
    }
}
