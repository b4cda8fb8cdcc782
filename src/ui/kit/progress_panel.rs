//! The learner's progress file on a page (each exercises section, the home page): their name
//! (optional; it goes in the file a teacher collects), Export (`bsv_progress.json`,
//! [`crate::ui::kit::progress_store`]) and Import (merged into the record, then the page
//! redraws). What an import did, or why a file was not read, is said under the buttons as a
//! lesson import says it: the size refused before the file is read, bad JSON with its line
//! and column, another program's file named.

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement};

use crate::i18n::fluent_args;
use crate::ui::dom::{self, Listener};
use crate::ui::kit::input_file;
use crate::ui::kit::lang_follow::draw_texts;
use crate::ui::kit::progress_store::{self, FILE_NAME};
use crate::ui::kit::store::Refused;
use crate::ui::{ctx, download};
use crate::view::exercises;
use crate::view::learner_progress::{from_json, to_json, ProgressError, MAX_FILE_BYTES};

const MARKUP: &str = "<label class=\"progress-name\"><span data-l10n=\"progress-name-label\"></span>\
<input type=\"text\" data-field=\"learner-name\" maxlength=\"80\" autocomplete=\"off\"></label>\
<div class=\"progress-actions\">\
<button type=\"button\" class=\"tool-button\" data-download=\"bsv_progress.json\" data-l10n=\"progress-export\"></button>\
<label class=\"tool-button progress-import\"><span data-l10n=\"progress-import\"></span>\
<input type=\"file\" accept=\".json,application/json\" data-action=\"progress-import\" class=\"visually-hidden\"></label>\
</div><p class=\"progress-status\" data-testid=\"progress-status\" hidden></p>";

/// What the status line says: a message id, its arguments, and whether it is an error.
#[derive(Clone)]
struct Said {
    id: &'static str,
    args: Vec<(&'static str, String)>,
    error: bool,
}

/// The panel: its element and listeners, and what its line says.
pub struct ProgressPanel {
    element: Element,
    status: Element,
    name: HtmlInputElement,
    said: RefCell<Option<Said>>,
    listeners: RefCell<Vec<Listener>>,
}

impl ProgressPanel {
    /// A panel; `imported` runs after an import changed the record.
    pub fn new(imported: impl Fn() + 'static) -> Result<Rc<ProgressPanel>, JsValue> {
        let element = dom::el_class("div", "progress-panel")?;
        element.set_inner_html(MARKUP);
        draw_texts(&element)?;
        let status = dom::find(&element, ".progress-status", "progress")?;
        let name: HtmlInputElement =
            dom::find(&element, "[data-field=\"learner-name\"]", "progress")?;
        name.set_value(progress_store::load().learner.as_deref().unwrap_or(""));
        let panel = Rc::new(ProgressPanel {
            element,
            status,
            name,
            said: RefCell::new(None),
            listeners: RefCell::new(Vec::new()),
        });
        panel.listen(Rc::new(imported))?;
        Ok(panel)
    }

    /// The panel's element.
    pub fn element(&self) -> &Element {
        &self.element
    }

    /// Says the record could not be kept (`refused`), or nothing more.
    pub fn say_saved(&self, refused: Option<Refused>) {
        if let Some(refused) = refused {
            let id = match refused {
                Refused::Full => "progress-not-saved-full",
                Refused::Unavailable => "progress-not-saved",
            };
            self.say(Some(Said {
                id,
                args: Vec::new(),
                error: true,
            }));
        }
    }

    /// Draws the texts again in the current language (once its strings are in it).
    pub fn relocalize(&self) {
        let _ = draw_texts(&self.element);
        self.draw();
    }

    fn listen(self: &Rc<Self>, imported: Rc<dyn Fn()>) -> Result<(), JsValue> {
        let mut listeners = self.listeners.borrow_mut();
        let weak = Rc::downgrade(self);
        listeners.push(Listener::new(&self.name, "change", move |_| {
            if let Some(panel) = weak.upgrade() {
                panel.name_changed();
            }
        })?);
        let export: Element = dom::find(&self.element, "[data-download]", "progress")?;
        let weak = Rc::downgrade(self);
        listeners.push(Listener::new(&export, "click", move |_| {
            if let Some(panel) = weak.upgrade() {
                panel.export();
            }
        })?);
        let input: HtmlInputElement = dom::find(
            &self.element,
            "[data-action=\"progress-import\"]",
            "progress",
        )?;
        let weak = Rc::downgrade(self);
        let file_input = input.clone();
        listeners.push(Listener::new(&input, "change", move |_| {
            if let Some(picked) = input_file::chosen(&file_input) {
                import(&weak, picked, imported.clone());
            }
            file_input.set_value("");
        })?);
        Ok(())
    }

    fn name_changed(&self) {
        let name = self.name.value();
        let mut refused_name = None;
        let (progress, refused) = progress_store::update(&mut |p| {
            refused_name = p.set_learner(&name).err();
        });
        self.name
            .set_value(progress.learner.as_deref().unwrap_or(""));
        match refused_name {
            Some(error) => self.say_error(&error),
            None => self.say_saved(refused),
        }
    }

    fn export(&self) {
        let mut progress = progress_store::load();
        progress.build = progress_store::BUILD.to_owned();
        if let Err(error) =
            download::download_text(FILE_NAME, &to_json(&progress), "application/json")
        {
            web_sys::console::error_2(&"BSV Playground: progress export".into(), &error);
        }
    }

    fn say_error(&self, error: &ProgressError) {
        let mut args = error.args();
        args.push(("file", String::new()));
        self.say(Some(Said {
            id: error.message_id(),
            args,
            error: true,
        }));
    }

    fn say(&self, said: Option<Said>) {
        *self.said.borrow_mut() = said;
        self.draw();
    }

    fn draw(&self) {
        let said = self.said.borrow();
        let Some(said) = said.as_ref() else {
            dom::show(&self.status, false);
            return;
        };
        let _ = self
            .status
            .set_attribute("role", if said.error { "alert" } else { "status" });
        let _ = self
            .status
            .set_attribute("data-state", if said.error { "error" } else { "ok" });
        let file = said
            .args
            .iter()
            .find(|(k, _)| *k == "file")
            .map(|(_, v)| v.as_str());
        let text = ctx::t_args(said.id, &fluent_args(said.args.clone()));
        let text = match file {
            Some(file) if said.error && !file.is_empty() => ctx::t_args(
                "progress-file-problem",
                &fluent_args(vec![("file", file.to_owned()), ("problem", text)]),
            ),
            _ => text,
        };
        self.status.set_text_content(Some(&text));
        dom::show(&self.status, true);
    }
}

/// Reads the picked file and merges it into the record (or says why not).
fn import(panel: &Weak<ProgressPanel>, picked: input_file::Picked, imported: Rc<dyn Fn()>) {
    let file = picked.name.clone();
    if picked.bytes > MAX_FILE_BYTES {
        if let Some(panel) = panel.upgrade() {
            panel.said_about(
                &file,
                Err(ProgressError::TooBig {
                    bytes: picked.bytes,
                }),
                &imported,
            );
        }
        return;
    }
    let panel = panel.clone();
    input_file::read_text(&picked.name, &picked.blob, move |text| {
        let Some(panel) = panel.upgrade() else { return };
        let read = text
            .map_err(|problem| match problem {
                input_file::ReadProblem::Browser(detail) => ProgressError::NotText { detail },
                input_file::ReadProblem::Decode(error) => ProgressError::Decode(error),
            })
            .and_then(|text| from_json(&text));
        panel.said_about(&file, read, &imported);
    });
}

impl ProgressPanel {
    /// What an import of `file` found: merged (and the page redrawn), or named with its problem.
    fn said_about(
        &self,
        file: &str,
        read: Result<crate::view::learner_progress::LearnerProgress, ProgressError>,
        imported: &Rc<dyn Fn()>,
    ) {
        match read {
            Ok(theirs) => {
                let known = theirs
                    .exercises
                    .keys()
                    .filter(|id| exercises::all_ids().any(|k| k == id.as_str()))
                    .count();
                let unknown = theirs.exercises.len() - known;
                let (progress, refused) = progress_store::update(&mut |p| p.merge(&theirs));
                self.name
                    .set_value(progress.learner.as_deref().unwrap_or(""));
                self.say(Some(Said {
                    id: if unknown > 0 {
                        "progress-imported-unknown"
                    } else {
                        "progress-imported"
                    },
                    args: vec![
                        ("file", file.to_owned()),
                        ("count", known.to_string()),
                        ("unknown", unknown.to_string()),
                    ],
                    error: false,
                }));
                self.say_saved(refused);
                imported();
            }
            Err(error) => {
                let mut args = error.args();
                args.push(("file", file.to_owned()));
                self.say(Some(Said {
                    id: error.message_id(),
                    args,
                    error: true,
                }));
            }
        }
    }
}
