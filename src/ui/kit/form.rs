//! The parameter form of a page, built from a recipe's facts ([`FieldDef`], see
//! [`crate::view::form`]): one field per argument with its localized label, the recipe's
//! default, a hint stating its limits, the phone keypad of its kind (a `<select>` for a
//! choice, a file picker for an input file), and a slot for the localized message beside it.
//!
//! Hooks: each control carries `data-field="<name>"` (the file picker `data-file-input`), its
//! wrapper `data-field-wrap="<name>"`, its message `data-field-error="<name>"`. Classes are
//! `kit-*` plus `<prefix>-*` (the page's own styles keep working).
//!
//! Messages use the field's label ("Number of steps: “abc” must be a whole number…"), not the
//! argument's internal name; every field an error involves gets `aria-invalid="true"`.
//!
//! A page can present more than one recipe's arguments, in its own fieldsets, and ask for
//! more with [`FormOptions`]. [`Form::focus_first_error`] and [`reveal`] bring a field or a
//! result into view clear of sticky bars (the phone's sticky Run bar, a sticky header).

use std::cell::Cell;

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlElement, HtmlInputElement, HtmlSelectElement};

use crate::args::ArgKind;
use crate::error::RecipeError;
use crate::ui::ctx;
use crate::view::form::{error_args, fluent_args, speaker, Checked, FieldDef};

/// A fieldset of the form: its legend and an optional note under it (Fluent ids).
#[derive(Debug, Clone, Copy)]
pub struct Group {
    pub legend_id: &'static str,
    pub note_id: Option<&'static str>,
}

/// The two groups of a recipe's form: arguments in command-line order, then options.
pub const RECIPE_GROUPS: [Group; 2] = [
    Group {
        legend_id: "kit-form-args",
        note_id: None,
    },
    Group {
        legend_id: "kit-form-options",
        note_id: Some("kit-form-options-note"),
    },
];

/// What a page asks of its form beyond the recipe facts (the default: nothing more): a unit
/// beside a field's box, and a note beside each field a cross-field limit involves ("part of
/// the same limit as Step"). The IK page asks for them: ik-workspace, jacobian-2r, manip-grid
/// and its own heatmap resolution, in its own fieldsets.
#[derive(Debug, Clone, Copy, Default)]
pub struct FormOptions<'a> {
    /// Fluent id of the unit shown beside a field's box, by field name.
    pub units: &'a [(&'a str, &'a str)],
    /// A field that a cross-field limit involves, when the message sits beside another field,
    /// says so (`kit-form-involved`) instead of only being marked invalid.
    pub involved_note: bool,
}

/// A message beside a field.
#[derive(Debug, Clone, PartialEq)]
pub enum Message {
    /// A kernel's (or the argument parser's) error; arguments are named by their labels.
    Recipe(RecipeError),
    /// A page's own message: Fluent id and text arguments.
    Text {
        id: &'static str,
        args: Vec<(&'static str, String)>,
    },
}

/// A field's control.
enum Control {
    Input(HtmlInputElement),
    Select(HtmlSelectElement),
    /// A file picker (its value is the page's opened file, not text).
    File(HtmlInputElement),
}

impl Control {
    fn element(&self) -> &Element {
        match self {
            Control::Input(i) | Control::File(i) => i,
            Control::Select(s) => s,
        }
    }
}

/// Escapes `& < > " '` for HTML text and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

fn field_markup(p: &str, field: &FieldDef, unit_id: Option<&str>) -> String {
    let name = escape(field.name());
    let default = escape(field.default());
    let label = escape(&field.label_id);
    let hint = escape(field.spec.hint_id);
    let flag = if field.flag {
        format!(" <code class=\"kit-flag {p}-flag\">--{name}</code>")
    } else {
        String::new()
    };
    let described = format!("{p}-h-{name} {p}-e-{name}");
    let control = match field.spec.kind {
        ArgKind::File => format!(
            "<div class=\"kit-file-row {p}-file-row\">\
             <label class=\"button kit-file-pick {p}-file-pick\">\
             <input type=\"file\" accept=\".csv,text/csv\" class=\"kit-visually-hidden\" \
             id=\"{p}-f-{name}\" data-file-input data-testid=\"{p}-file\" \
             aria-describedby=\"{p}-file-status {described}\">\
             <span data-i18n=\"kit-form-file-open\"></span></label>\
             <button type=\"button\" class=\"button\" data-use-sample data-testid=\"{p}-use-sample\" \
             data-i18n=\"kit-form-file-sample\"></button></div>\
             <p class=\"kit-file-status {p}-file-status\" id=\"{p}-file-status\" data-file-status \
             data-testid=\"{p}-file-status\" role=\"status\"></p>"
        ),
        ArgKind::Choice(choices) => {
            let mut html = format!(
                "<select id=\"{p}-f-{name}\" data-field=\"{name}\" aria-describedby=\"{described}\">"
            );
            for choice in choices {
                let c = escape(choice);
                html.push_str(&format!("<option value=\"{c}\">{c}</option>"));
            }
            html.push_str("</select>");
            html
        }
        _ => {
            let input = format!(
                "<input id=\"{p}-f-{name}\" type=\"text\" inputmode=\"{mode}\" autocomplete=\"off\" \
                 autocapitalize=\"off\" spellcheck=\"false\" enterkeyhint=\"go\" data-field=\"{name}\" \
                 placeholder=\"{default}\" aria-describedby=\"{described}\"{unit}>",
                mode = field.inputmode(),
                unit = field
                    .spec
                    .unit
                    .map(|u| format!(" data-unit=\"{}\"", escape(u)))
                    .unwrap_or_default(),
            );
            match unit_id {
                Some(unit) => format!(
                    "<div class=\"kit-input-row {p}-input-row\">{input}\
                     <span class=\"kit-unit {p}-unit\" data-i18n=\"{}\"></span></div>",
                    escape(unit)
                ),
                None => input,
            }
        }
    };
    let default_note = if field.default().is_empty() || field.is_file() {
        String::new()
    } else {
        format!(
            "<span class=\"kit-default {p}-default\"><span data-i18n=\"kit-form-default\"></span> \
             <code>{default}</code></span> "
        )
    };
    let (label_open, label_close) = if field.is_file() {
        (
            format!("<span class=\"kit-label {p}-label\" id=\"{p}-l-{name}\">"),
            "</span>",
        )
    } else {
        (
            format!("<label class=\"kit-label {p}-label\" for=\"{p}-f-{name}\">"),
            "</label>",
        )
    };
    let wide = if field.is_wide() {
        format!(" kit-field-wide {p}-field-wide")
    } else {
        String::new()
    };
    format!(
        "<div class=\"kit-field {p}-field{wide}\" data-field-wrap=\"{name}\">\
         {label_open}<span data-i18n=\"{label}\"></span>{flag}{label_close}\
         {control}\
         <small class=\"kit-hint {p}-hint\" id=\"{p}-h-{name}\">{default_note}<span data-hint data-i18n=\"{hint}\"></span></small>\
         <p class=\"kit-error {p}-error\" id=\"{p}-e-{name}\" data-field-error=\"{name}\" role=\"alert\" hidden></p>\
         </div>"
    )
}

/// The form's markup: one fieldset per group that has fields.
pub fn markup(prefix: &str, groups: &[Group], fields: &[FieldDef]) -> String {
    markup_with(prefix, groups, fields, &FormOptions::default())
}

/// [`markup`] with a page's [`FormOptions`].
pub fn markup_with(
    prefix: &str,
    groups: &[Group],
    fields: &[FieldDef],
    options: &FormOptions,
) -> String {
    let p = escape(prefix);
    let mut html = String::new();
    for (index, group) in groups.iter().enumerate() {
        let mut members = fields.iter().filter(|f| f.group == index).peekable();
        if members.peek().is_none() {
            continue;
        }
        html.push_str(&format!(
            "<fieldset class=\"kit-fieldset {p}-fieldset\"><legend data-i18n=\"{}\"></legend>",
            group.legend_id
        ));
        if let Some(note) = group.note_id {
            html.push_str(&format!(
                "<p class=\"kit-hint {p}-hint kit-legend-note {p}-legend-note\" data-i18n=\"{note}\"></p>"
            ));
        }
        for field in members {
            let unit = options
                .units
                .iter()
                .find(|(name, _)| *name == field.name())
                .map(|(_, unit)| *unit);
            html.push_str(&field_markup(&p, field, unit));
        }
        html.push_str("</fieldset>");
    }
    html
}

/// The form's controls and message slots, found after [`markup`] is in place.
pub struct Form {
    pub fields: Vec<FieldDef>,
    controls: Vec<Control>,
    errors: Vec<Option<Element>>,
    /// The file picker's status line (a form with a file field only).
    pub file_status: Option<Element>,
    /// Messages shown beside fields and the fields marked (re-rendered on a language switch).
    shown: Vec<(usize, Message)>,
    marked: Vec<usize>,
    involved_note: bool,
    /// The field the user edited last (cross-field messages go there).
    changed: Cell<Option<usize>>,
}

/// Writes `value` into `control` of `field` (a choice the select does not offer is the
/// default; a file picker is left alone).
fn write(field: &FieldDef, control: &Control, value: &str) {
    match control {
        Control::Input(input) => input.set_value(value),
        Control::Select(select) => {
            let value = value.trim().to_ascii_lowercase();
            let known = matches!(field.spec.kind,
                ArgKind::Choice(c) if c.contains(&value.as_str()));
            select.set_value(if known { &value } else { field.default() });
        }
        Control::File(_) => {}
    }
}

fn query<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    crate::ui::dom::find(root, selector, "form")
}

/// The recipe's errors a check found, as messages beside their fields.
pub fn recipe_messages<T>(checked: &Checked<T>) -> Vec<(usize, Message)> {
    checked
        .messages
        .iter()
        .map(|(i, e)| (*i, Message::Recipe(e.clone())))
        .collect()
}

impl Form {
    /// Builds the form of `fields` into `container` (classes `<prefix>-*`) and fills it with
    /// `values` (a missing value is the default).
    pub fn build(
        container: &Element,
        prefix: &str,
        groups: &[Group],
        fields: Vec<FieldDef>,
        values: &[String],
    ) -> Result<Form, JsValue> {
        Form::build_with(
            container,
            prefix,
            groups,
            fields,
            values,
            &FormOptions::default(),
        )
    }

    /// [`Form::build`] with a page's [`FormOptions`].
    pub fn build_with(
        container: &Element,
        prefix: &str,
        groups: &[Group],
        fields: Vec<FieldDef>,
        values: &[String],
        options: &FormOptions,
    ) -> Result<Form, JsValue> {
        container.set_inner_html(&markup_with(prefix, groups, &fields, options));
        crate::ui::dom::relocalize(container)?;
        let mut controls = Vec::new();
        let mut errors = Vec::new();
        for field in &fields {
            let name = field.name();
            let wrap: Element = query(container, &format!("[data-field-wrap=\"{name}\"]"))?;
            controls.push(match field.spec.kind {
                ArgKind::File => Control::File(query(&wrap, "[data-file-input]")?),
                ArgKind::Choice(_) => Control::Select(query(&wrap, "[data-field]")?),
                _ => Control::Input(query(&wrap, "[data-field]")?),
            });
            errors.push(wrap.query_selector("[data-field-error]")?);
        }
        let file_status = container.query_selector("[data-file-status]")?;
        let form = Form {
            fields,
            controls,
            errors,
            file_status,
            shown: Vec::new(),
            marked: Vec::new(),
            involved_note: options.involved_note,
            changed: Cell::new(None),
        };
        form.fill(values);
        Ok(form)
    }

    /// Writes `values` into the controls (a missing value, or a choice the select does not
    /// offer, is the default).
    pub fn fill(&self, values: &[String]) {
        for (index, (field, control)) in self.fields.iter().zip(&self.controls).enumerate() {
            let value = values
                .get(index)
                .map(String::as_str)
                .unwrap_or(field.default());
            write(field, control, value);
        }
    }

    /// Writes `value` into field `index` alone, as [`Form::fill`] would, and returns the text
    /// the field now holds (what [`Form::texts`] reads for it; `None` for a file picker or no
    /// such field). A drag that moves one argument writes one box instead of all of them.
    pub fn set_value(&self, index: usize, value: &str) -> Option<String> {
        let (field, control) = self.fields.get(index).zip(self.controls.get(index))?;
        write(field, control, value);
        match control {
            // A text box's value sanitization only drops line breaks.
            Control::Input(_) if !value.contains(['\r', '\n']) => Some(value.to_string()),
            Control::Input(i) => Some(i.value()),
            Control::Select(s) => Some(s.value()),
            Control::File(_) => None,
        }
    }

    /// Writes every field's default (and forgets the file picker's choice).
    pub fn reset(&self) {
        let defaults: Vec<String> = self
            .fields
            .iter()
            .map(|f| f.default().to_string())
            .collect();
        self.fill(&defaults);
        if let Some(input) = self.file_input() {
            input.set_value("");
        }
    }

    /// The text now in each field (`None` for a file picker).
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
        self.fields.iter().position(|f| f.name() == name)
    }

    /// The index of the file field, if any.
    pub fn file_index(&self) -> Option<usize> {
        self.fields.iter().position(FieldDef::is_file)
    }

    /// The file picker, if the form has one.
    pub fn file_input(&self) -> Option<&HtmlInputElement> {
        self.controls.iter().find_map(|c| match c {
            Control::File(input) => Some(input),
            _ => None,
        })
    }

    /// Notes that the user edited the field holding `element` (call from the input event).
    pub fn note_edit(&self, element: &Element) {
        if let Some(name) = element.get_attribute("data-field") {
            self.changed.set(self.index_of(&name));
        }
    }

    /// Notes that field `index` was edited last ([`Form::note_edit`] without the element).
    pub fn note_changed(&self, index: usize) {
        if index < self.fields.len() {
            self.changed.set(Some(index));
        }
    }

    /// The field the user edited last.
    pub fn changed(&self) -> Option<usize> {
        self.changed.get()
    }

    /// The localized label of the argument called `name` (the name itself if the form has no
    /// such field).
    pub fn label(&self, name: &str) -> String {
        match self.fields.iter().find(|f| f.name() == name) {
            Some(field) => ctx::t(&field.label_id),
            None => name.to_string(),
        }
    }

    /// `message` in the current language, arguments named by their labels.
    pub fn message_text(&self, message: &Message) -> String {
        self.message_at(None, message)
    }

    /// `message` as shown beside field `at`: a cross-field limit shown beside another field it
    /// involves (the one the user changed) speaks in that field's name.
    fn message_at(&self, at: Option<usize>, message: &Message) -> String {
        match message {
            Message::Recipe(error) => {
                let here = at.and_then(|i| self.fields.get(i)).map(FieldDef::name);
                let label = |name: &str| self.label(speaker(error, here, name));
                ctx::t_args(error.message_id(), &error_args(error, &label))
            }
            Message::Text { id, args } => ctx::t_args(id, &fluent_args(args.clone())),
        }
    }

    /// Shows exactly `messages` (field index → message), marks `marked` fields (and the ones
    /// with a message) invalid, and clears every other field.
    pub fn show(&mut self, messages: &[(usize, Message)], marked: &[usize]) {
        self.shown = messages.to_vec();
        self.marked = marked.to_vec();
        self.render();
    }

    /// Shows what a check of the form's texts found (its errors beside their fields, the
    /// fields marked); returns the messages shown.
    pub fn show_checked<T>(&mut self, checked: &Checked<T>) -> Vec<(usize, Message)> {
        let messages = recipe_messages(checked);
        self.show(&messages, &checked.marked);
        messages
    }

    /// The note beside field `index` that a cross-field limit shown beside another field
    /// involves: "part of the same limit as <that field>".
    fn involved_text(&self, index: usize) -> Option<String> {
        let name = self.fields.get(index)?.name();
        let (by, _) = self.shown.iter().find(|(at, m)| {
            *at != index && matches!(m, Message::Recipe(e) if e.params().contains(&name))
        })?;
        let label = ctx::t(&self.fields.get(*by)?.label_id);
        Some(ctx::t_args(
            "kit-form-involved",
            &fluent_args(vec![("field", label)]),
        ))
    }

    fn render(&self) {
        for index in 0..self.fields.len() {
            let message = self.shown.iter().find(|(i, _)| *i == index).map(|(_, m)| m);
            let marked = self.marked.contains(&index);
            let text = match message {
                Some(m) => Some(self.message_at(Some(index), m)),
                None if marked && self.involved_note => self.involved_text(index),
                None => None,
            };
            if let Some(Some(slot)) = self.errors.get(index) {
                match &text {
                    Some(t) => {
                        if slot.text_content().as_deref() != Some(t) {
                            slot.set_text_content(Some(t));
                        }
                        let _ = slot.remove_attribute("hidden");
                    }
                    None => {
                        slot.set_text_content(None);
                        let _ = slot.set_attribute("hidden", "");
                    }
                }
            }
            let invalid = message.is_some() || marked;
            if let Some(control) = self.controls.get(index) {
                let _ = control
                    .element()
                    .set_attribute("aria-invalid", if invalid { "true" } else { "false" });
            }
        }
    }

    /// Focuses the first field showing a message and brings it into view clear of sticky
    /// bars.
    pub fn focus_first_error(&self) {
        let Some(index) = self.shown.iter().map(|(i, _)| *i).min() else {
            return;
        };
        let Some(control) = self.controls.get(index) else {
            return;
        };
        let element = control.element();
        if let Some(html) = element.dyn_ref::<HtmlElement>() {
            let options = js_sys::Object::new();
            let _ = js_sys::Reflect::set(&options, &"preventScroll".into(), &true.into());
            let focus = js_sys::Reflect::get(html, &"focus".into())
                .ok()
                .and_then(|f| f.dyn_into::<js_sys::Function>().ok());
            match focus {
                Some(f) => {
                    let _ = f.call1(html, &options);
                }
                None => crate::ui::dom::focus(element),
            }
        }
        // The whole field (label to message), not just the box, should be readable.
        let wrap = element
            .closest("[data-field-wrap]")
            .ok()
            .flatten()
            .unwrap_or_else(|| element.clone());
        reveal(&wrap, Reveal::Nearest);
    }

    /// Re-renders shown messages in the current language (labels, hints and legends follow
    /// their `data-i18n` ids).
    pub fn relocalize(&self) {
        self.render();
    }
}

/// How [`reveal`] scrolls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reveal {
    /// As little as needed to show the whole element (or its top, if it is taller).
    Nearest,
    /// The element's top just below any sticky bar, unless its top is already well in view.
    Start,
}

/// The height of sticky or fixed bars covering the top and the bottom of the viewport now.
fn sticky_insets(window: &web_sys::Window) -> (f64, f64) {
    let Some(document) = window.document() else {
        return (0.0, 0.0);
    };
    let width = window
        .inner_width()
        .ok()
        .and_then(|w| w.as_f64())
        .unwrap_or(0.0);
    let height = window
        .inner_height()
        .ok()
        .and_then(|h| h.as_f64())
        .unwrap_or(0.0);
    let bar_at = |y: f64| -> Option<web_sys::DomRect> {
        let mut el = document.element_from_point((width / 2.0) as f32, y as f32);
        while let Some(e) = el {
            let position = window
                .get_computed_style(&e)
                .ok()
                .flatten()
                .and_then(|s| s.get_property_value("position").ok())
                .unwrap_or_default();
            if position == "sticky" || position == "fixed" {
                return Some(e.get_bounding_client_rect());
            }
            el = e.parent_element();
        }
        None
    };
    let top = bar_at(1.0).map_or(0.0, |r| r.bottom().clamp(0.0, height / 2.0));
    let bottom = bar_at(height - 2.0).map_or(0.0, |r| (height - r.top()).clamp(0.0, height / 2.0));
    (top, bottom)
}

/// Scrolls the page so that `element` is in view clear of sticky bars (the phone's sticky
/// Run bar, a sticky header), with a small margin.
pub fn reveal(element: &Element, how: Reveal) {
    const MARGIN_PX: f64 = 12.0;
    let Some(window) = web_sys::window() else {
        return;
    };
    let height = window
        .inner_height()
        .ok()
        .and_then(|h| h.as_f64())
        .unwrap_or(0.0);
    let (top_bar, bottom_bar) = sticky_insets(&window);
    let low = top_bar + MARGIN_PX;
    let high = height - bottom_bar - MARGIN_PX;
    let rect = element.get_bounding_client_rect();
    let dy = match how {
        Reveal::Nearest if rect.top() < low || rect.height() > high - low => rect.top() - low,
        Reveal::Nearest if rect.bottom() > high => rect.bottom() - high,
        Reveal::Nearest => 0.0,
        // A result whose top shows in the upper part of the free area is in view already.
        Reveal::Start if rect.top() >= low && rect.top() <= low + (high - low) * 0.5 => 0.0,
        Reveal::Start => rect.top() - low,
    };
    if dy.abs() >= 1.0 {
        window.scroll_by_with_x_and_y(0.0, dy);
    }
}
