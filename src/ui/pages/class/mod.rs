//! The class page (`#/class`): a teacher opens many learners' `bsv_progress.json` files at
//! once (the file picker, several at a time, or dropped on the page) and sees the class
//! summary ([`crate::view::class_summary`]): a table of learners by exercises (right at the
//! first try, right later, not yet), each exercise's success rate with the hardest first, and
//! `class_summary.csv`. Nothing leaves the browser.
//!
//! Files add up across picks and drops until "Clear". A file is refused as a lesson import
//! refuses one: over the size limit from its size alone, unread; not text, bad JSON (its line
//! and column), another program's file, a learner's second file; each is named beside the
//! picker with its problem, and the table keeps the good ones. The table itself is drawn by
//! [`table`]; the page's style (`class.late.css`) is linked when the page opens.

mod table;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, Event, HtmlInputElement};

use crate::i18n::fluent_args;
use crate::ui::dom::{self, Listener};
use crate::ui::kit::input_file::{self, Picked, ReadProblem};
use crate::ui::kit::late_style;
use crate::ui::page::{MountCtx, Page, ShellLink};
use crate::ui::{ctx, download, page_frame};
use crate::view::class_summary::{summarize, ClassSummary, FileProblem, RejectedFile, CSV_NAME};
use crate::view::exercises;
use crate::view::learner_progress::{ProgressError, MAX_FILE_BYTES};

/// The page's markup: head, the picker and its drop zone, what was refused, the table.
const MARKUP: &str = "<div class=\"lesson class-page\"><h1 data-i18n=\"class-title\"></h1>\
<p class=\"lesson-intro\" data-i18n=\"class-lede\"></p>\
<section class=\"lesson-card class-drop\" data-class=\"drop\" aria-labelledby=\"class-files-heading\">\
<h2 id=\"class-files-heading\" data-i18n=\"class-files-label\"></h2>\
<div class=\"lesson-actions\"><label class=\"tool-button lesson-import\"><span data-i18n=\"class-pick\"></span>\
<input type=\"file\" multiple accept=\".json,application/json\" data-field=\"class-files\" class=\"visually-hidden\"></label>\
<button type=\"button\" class=\"tool-button\" data-action=\"class-clear\" data-i18n=\"class-clear\"></button></div>\
<p class=\"class-drop-hint\" data-i18n=\"class-drop\"></p>\
<p class=\"class-counts\" data-class=\"counts\" role=\"status\"></p>\
<div class=\"class-rejected\" data-class=\"rejected\" hidden><h3 data-i18n=\"class-rejected-heading\"></h3>\
<ul data-testid=\"class-rejected\"></ul></div></section>\
<section class=\"lesson-card\" data-class=\"summary\" aria-labelledby=\"class-table-heading\" hidden>\
<h2 id=\"class-table-heading\" data-i18n=\"class-table-heading\"></h2>\
<p class=\"class-caption-note\" data-i18n=\"class-table-caption\"></p>\
<div class=\"class-scroll\" data-class=\"table\" tabindex=\"0\" role=\"region\" aria-labelledby=\"class-table-heading\"></div>\
<button type=\"button\" class=\"tool-button\" data-download=\"class_summary.csv\" data-i18n=\"class-download\"></button>\
<h2 data-i18n=\"class-rates-heading\"></h2><div class=\"class-scroll\" data-class=\"rates\"></div></section></div>";

/// A file the teacher gave: its text, or why it gave none.
enum Given {
    Text(String, String),
    Unread(String, ProgressError),
}

/// The page: the files given so far and the summary of them.
struct Inner {
    me: Weak<Inner>,
    root: Element,
    shell: ShellLink,
    files: RefCell<Vec<Given>>,
    summary: RefCell<Option<ClassSummary>>,
    /// Reads still under way.
    reading: std::cell::Cell<usize>,
    listeners: RefCell<Vec<Listener>>,
}

/// The class page.
pub struct ClassPage(Rc<Inner>);

impl Page for ClassPage {
    fn mount(ctx: MountCtx) -> Result<ClassPage, JsValue> {
        let root = ctx.root.clone();
        page_frame::fill(&root, MARKUP)?;
        dom::relocalize(&root)?;
        let inner = Rc::new_cyclic(|me| Inner {
            me: me.clone(),
            root,
            shell: ctx.shell,
            files: RefCell::new(Vec::new()),
            summary: RefCell::new(None),
            reading: std::cell::Cell::new(0),
            listeners: RefCell::new(Vec::new()),
        });
        inner.listen(&Rc::downgrade(&inner))?;
        inner.draw();
        wasm_bindgen_futures::spawn_local(late_style::linked("class"));
        Ok(ClassPage(inner))
    }

    fn relocalize(&self) {
        self.0.draw();
    }
}

impl Inner {
    fn part(&self, name: &str) -> Result<Element, JsValue> {
        dom::find(&self.root, &format!("[data-class=\"{name}\"]"), "class")
    }

    fn listen(&self, me: &Weak<Inner>) -> Result<(), JsValue> {
        let mut listeners = self.listeners.borrow_mut();
        let input: HtmlInputElement =
            dom::find(&self.root, "[data-field=\"class-files\"]", "class")?;
        let picked = input.clone();
        listeners.push(Listener::for_page(&input, "change", me, move |page, _| {
            page.add(input_file::all_chosen(&picked));
            picked.set_value("");
        })?);
        let drop = self.part("drop")?;
        listeners.push(Listener::for_page(
            &drop,
            "dragover",
            me,
            |_, event: &Event| {
                if input_file::drags_files(event) {
                    event.prevent_default();
                }
            },
        )?);
        listeners.push(Listener::for_page(
            &drop,
            "drop",
            me,
            |page, event: &Event| {
                event.prevent_default();
                page.add(input_file::all_dropped(event));
            },
        )?);
        listeners.push(Listener::for_page(
            &self.root,
            "click",
            me,
            |page, event| {
                let Some(target) = event
                    .target()
                    .and_then(|t| wasm_bindgen::JsCast::dyn_into::<Element>(t).ok())
                else {
                    return;
                };
                if target
                    .closest("[data-action=\"class-clear\"]")
                    .ok()
                    .flatten()
                    .is_some()
                {
                    page.files.borrow_mut().clear();
                    page.summarize();
                } else if target.closest("[data-download]").ok().flatten().is_some() {
                    page.download();
                }
            },
        )?);
        Ok(())
    }

    /// Reads `picked` (each refused unread when too big) and adds them to the files given.
    fn add(&self, picked: Vec<Picked>) {
        for file in picked {
            if file.bytes > MAX_FILE_BYTES {
                let error = ProgressError::TooBig { bytes: file.bytes };
                self.files
                    .borrow_mut()
                    .push(Given::Unread(file.name, error));
                continue;
            }
            self.reading.set(self.reading.get() + 1);
            let weak = self.me.clone();
            let name = file.name.clone();
            input_file::read_text(&file.name, &file.blob, move |text| {
                let Some(page) = weak.upgrade() else { return };
                let given = match text {
                    Ok(text) => Given::Text(name, text),
                    Err(ReadProblem::Browser(detail)) => {
                        Given::Unread(name, ProgressError::NotText { detail })
                    }
                    Err(ReadProblem::Decode(error)) => {
                        Given::Unread(name, ProgressError::Decode(error))
                    }
                };
                page.files.borrow_mut().push(given);
                page.reading.set(page.reading.get().saturating_sub(1));
                if page.reading.get() == 0 {
                    page.summarize();
                }
            });
        }
        if self.reading.get() == 0 {
            self.summarize();
        }
    }

    /// The summary of the files given (those left unread named with them, in the order given).
    fn summarize(&self) {
        let files = self.files.borrow();
        let texts: Vec<(String, String)> = files
            .iter()
            .filter_map(|f| match f {
                Given::Text(name, text) => Some((name.clone(), text.clone())),
                Given::Unread(..) => None,
            })
            .collect();
        let ids: Vec<&str> = exercises::all_ids().collect();
        let mut summary = summarize(&texts, &ids);
        let order = |name: &str| {
            files.iter().position(|f| match f {
                Given::Text(n, _) | Given::Unread(n, _) => n == name,
            })
        };
        summary
            .rejected
            .extend(files.iter().filter_map(|f| match f {
                Given::Unread(file, error) => Some(RejectedFile {
                    file: file.clone(),
                    problem: FileProblem::Unreadable(error.clone()),
                }),
                Given::Text(..) => None,
            }));
        summary.rejected.sort_by_key(|r| order(&r.file));
        let empty = files.is_empty();
        drop(files);
        *self.summary.borrow_mut() = (!empty).then_some(summary);
        self.draw();
    }

    fn download(&self) {
        if let Some(summary) = self.summary.borrow().as_ref() {
            if let Err(error) = download::download_text(CSV_NAME, &summary.to_csv(), "text/csv") {
                web_sys::console::error_2(&"BSV Playground: class summary".into(), &error);
            }
        }
    }

    /// Everything in the current language.
    fn draw(&self) {
        if let Err(error) = self.try_draw() {
            web_sys::console::error_2(&"BSV Playground: class".into(), &error);
        }
    }

    fn try_draw(&self) -> Result<(), JsValue> {
        let summary = self.summary.borrow();
        let counts = self.part("counts")?;
        let rejected = self.part("rejected")?;
        let list = dom::find::<Element>(&rejected, "ul", "class")?;
        dom::clear(&list);
        let Some(summary) = summary.as_ref() else {
            counts.set_text_content(Some(&ctx::t("class-empty")));
            dom::show(&rejected, false);
            dom::show(&self.part("summary")?, false);
            return Ok(());
        };
        counts.set_text_content(Some(&ctx::t_args(
            "class-counts",
            &fluent_args(vec![
                ("learners", summary.learners.len().to_string()),
                ("files", summary.rejected.len().to_string()),
            ]),
        )));
        for r in &summary.rejected {
            let item = dom::el("li")?;
            item.set_attribute("data-file", &r.file)?;
            let problem = ctx::t_args(r.problem.message_id(), &fluent_args(r.problem.args()));
            item.set_text_content(Some(&ctx::t_args(
                "progress-file-problem",
                &fluent_args(vec![("file", r.file.clone()), ("problem", problem)]),
            )));
            dom::append(&list, &item)?;
        }
        dom::show(&rejected, !summary.rejected.is_empty());
        dom::show(&self.part("summary")?, true);
        table::draw_learners(&self.part("table")?, summary)?;
        table::draw_rates(&self.part("rates")?, summary, self.shell)?;
        Ok(())
    }
}
