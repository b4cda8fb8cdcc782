//! The session's part of the page: the module bar and device buttons (`aria-pressed`), the
//! preflight checks, the label panel, the episodes table (label, category, duration,
//! collisions, a replay and a download button per episode), the session's summary, the
//! repeatability table (the first session beside this one), the session line, the file
//! opener's problem, the status line and the storage warning (the kit's
//! `pilot_session`).

use std::cell::{Cell, RefCell};

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::practice::Practice;
use crate::so101::episode::Episode;
use crate::teleop::session::{Module, PracticeEpisode, SessionError};
use crate::ui::kit::form::escape;
use crate::ui::kit::pilot_session::{open_error_text, render_comparison, StorageWarning};
use crate::ui::{ctx, dom};

/// The elements the session writes to.
pub struct SessionView {
    modules: Vec<(Module, Element)>,
    devices: Vec<Element>,
    help: Element,
    /// The preflight's checklist (`li[data-check]`), shown in the preflight only.
    preflight: Element,
    checks: Vec<Element>,
    device_row: Element,
    summary_block: Element,
    repeat: Element,
    pub label_panel: Element,
    label_title: Element,
    label_proposal: Element,
    labels: Vec<Element>,
    categories: Vec<Element>,
    pub note: web_sys::HtmlInputElement,
    episodes: Element,
    summary: Element,
    compare: Element,
    session_line: Element,
    /// The file opener (`data-so101="open"`).
    pub open: Element,
    open_error: Element,
    status: Element,
    storage: StorageWarning,
    /// What the opener last refused (shown until a good set of files is opened).
    pub open_problem: RefCell<Option<OpenProblem>>,
    /// The status line's message.
    pub status_id: Cell<Option<&'static str>>,
    /// The browser refused to store the session, the first session.
    pub unsaved: Cell<(bool, bool)>,
}

/// Why opened files did not become the session.
#[derive(Debug, Clone, PartialEq)]
pub enum OpenProblem {
    /// The browser could not read this file as text.
    Unreadable(String),
    /// The files do not make a session.
    Session(SessionError),
    /// The part of the page that writes and reads the files could not be fetched.
    Unloaded,
}

fn find<T: wasm_bindgen::JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    dom::find(root, selector, "so101")
}

impl SessionView {
    /// Finds its parts under `root`.
    pub fn find(root: &Element) -> Result<SessionView, JsValue> {
        let mut modules = Vec::new();
        for m in Module::ALL {
            modules.push((m, find(root, &format!("[data-module=\"{}\"]", m.id()))?));
        }
        Ok(SessionView {
            modules,
            devices: dom::matching(root, "[data-device]")?,
            help: find(root, "[data-so101=\"module-help\"]")?,
            preflight: find(root, "[data-so101=\"preflight\"]")?,
            checks: dom::matching(root, "[data-so101=\"preflight\"] li[data-check]")?,
            device_row: find(root, "[data-so101=\"devices\"]")?,
            summary_block: find(root, "[data-so101=\"summary-block\"]")?,
            repeat: find(root, "[data-so101=\"repeat\"]")?,
            label_panel: find(root, "[data-so101=\"label-panel\"]")?,
            label_title: find(root, "[data-so101=\"label-title\"]")?,
            label_proposal: find(root, "[data-so101=\"label-proposal\"]")?,
            labels: dom::matching(root, "[data-label]")?,
            categories: dom::matching(root, "[data-category]")?,
            note: find(root, "[data-field=\"note\"]")?,
            episodes: find(root, "[data-so101=\"episodes\"]")?,
            summary: find(root, "[data-so101=\"summary\"]")?,
            compare: find(root, "[data-so101=\"compare\"] tbody")?,
            session_line: find(root, "[data-so101=\"session-line\"]")?,
            open: find(root, "[data-so101=\"open\"]")?,
            open_error: find(root, "[data-so101=\"open-error\"]")?,
            status: find(root, "[data-so101=\"status\"]")?,
            storage: StorageWarning::find(root, &Episode::episodes_name())?,
            open_problem: RefCell::new(None),
            status_id: Cell::new(None),
            unsaved: Cell::new((false, false)),
        })
    }

    /// Everything from the practice state.
    pub fn show(&self, p: &Practice) {
        let s = &p.session;
        for (m, el) in &self.modules {
            let _ = el.set_attribute(
                "aria-pressed",
                if *m == s.module { "true" } else { "false" },
            );
        }
        for el in &self.devices {
            let on = el.get_attribute("data-device").as_deref() == Some(s.input_device.id());
            let _ = el.set_attribute("aria-pressed", if on { "true" } else { "false" });
        }
        let help = match s.module {
            Module::RecordTen => {
                ctx::t_strings("teleop-help-record-ten", &[("target", "10".into())])
            }
            m => ctx::t(&format!("teleop-help-{}", m.id())),
        };
        self.help.set_text_content(Some(&help));
        // Each module's panels under its own tab only: the checklist in the preflight, the
        // device choice wherever the arm is live, the summary and the second session in
        // repeatability.
        dom::show(&self.preflight, s.module == Module::Preflight);
        dom::show(&self.device_row, s.module != Module::FailureReview);
        dom::show(&self.summary_block, s.module == Module::Repeatability);
        dom::show(&self.repeat, s.module == Module::Repeatability);
        for li in &self.checks {
            let done = match li.get_attribute("data-check").as_deref() {
                Some("moved") => s.preflight.moved,
                _ => s.preflight.reset_verified == Some(true),
            };
            let state = if done { "done" } else { "todo" };
            if li.get_attribute("data-state").as_deref() != Some(state) {
                let _ = li.set_attribute("data-state", state);
            }
        }
        self.show_labels(p);
        self.show_table(p);
        self.show_summary(p);
        let first = p.first.as_ref().map(|f| f.summary());
        let current = p.session.summary();
        if let Err(e) = render_comparison(&self.compare, first.as_ref(), &current) {
            web_sys::console::warn_1(&e);
        }
        self.show_notes();
        let (a, b) = self.unsaved.get();
        self.storage.render(a || b, s.episodes.len());
    }

    /// The opener's problem and the status line in the current language.
    fn show_notes(&self) {
        let problem = self.open_problem.borrow();
        let text = problem.as_ref().map(|p| match p {
            OpenProblem::Unreadable(name) => {
                ctx::t_strings("teleop-open-unreadable", &[("name", name.clone())])
            }
            OpenProblem::Session(e) => open_error_text(e, &Episode::episodes_name()),
            OpenProblem::Unloaded => ctx::t("so101-files-unloaded"),
        });
        self.open_error
            .set_text_content(Some(text.as_deref().unwrap_or("")));
        dom::show(&self.open_error, text.is_some());
        let status = self.status_id.get().map(ctx::t).unwrap_or_default();
        self.status.set_text_content(Some(&status));
    }

    fn show_labels(&self, p: &Practice) {
        dom::show(&self.label_panel, p.labelling.is_some());
        let Some(n) = p.labelling else {
            return;
        };
        self.label_title.set_text_content(Some(&ctx::t_strings(
            "so101-label-title",
            &[("n", n.to_string())],
        )));
        if let Some(e) = p.session.episodes.get(n - 1) {
            let (label, category) = e.proposal();
            let cat = category.map_or(String::new(), |c| ctx::t(&format!("teleop-cat-{}", c.id())));
            self.label_proposal.set_text_content(Some(&ctx::t_strings(
                "so101-label-proposal",
                &[
                    (
                        "label",
                        ctx::t(&format!("teleop-label-{}", label.id().to_ascii_lowercase())),
                    ),
                    ("category", cat),
                ],
            )));
        }
        let (label, category) = p.choice;
        for el in &self.labels {
            let on =
                label.is_some_and(|l| el.get_attribute("data-label").as_deref() == Some(l.id()));
            let _ = el.set_attribute("aria-pressed", if on { "true" } else { "false" });
        }
        for el in &self.categories {
            let on = category
                .is_some_and(|c| el.get_attribute("data-category").as_deref() == Some(c.id()));
            let _ = el.set_attribute("aria-pressed", if on { "true" } else { "false" });
        }
    }

    fn show_table(&self, p: &Practice) {
        let mut html = String::new();
        for e in &p.session.episodes {
            let label = e.label.map_or_else(
                || ctx::t("teleop-unlabelled"),
                |l| ctx::t(&format!("teleop-label-{}", l.id().to_ascii_lowercase())),
            );
            let category = e
                .category
                .map_or(String::new(), |c| ctx::t(&format!("teleop-cat-{}", c.id())));
            let file = Episode::episode_file_name(e.number);
            html.push_str(&format!(
                "<tr data-episode=\"{n}\"><th scope=\"row\">{n}</th><td>{label}</td><td>{category}</td>\
                 <td>{dur:.2}</td><td>{col}</td><td>\
                 <button type=\"button\" class=\"tool-button\" data-action=\"replay\" data-episode=\"{n}\">{replay}</button> \
                 <button type=\"button\" class=\"tool-button\" data-action=\"relabel\" data-episode=\"{n}\">{relabel}</button> \
                 <button type=\"button\" class=\"tool-button\" data-download=\"{file}\">{file}</button></td></tr>",
                n = e.number,
                label = escape(&label),
                category = escape(&category),
                dur = e.metrics.duration_s,
                col = e.metrics.collisions,
                replay = escape(&ctx::t("teleop-replay")),
                relabel = escape(&ctx::t("teleop-relabel")),
            ));
        }
        self.episodes.set_inner_html(&html);
        let s = p.session.summary();
        self.session_line.set_text_content(Some(&ctx::t_args(
            "so101-session-line",
            &[
                ("pilot", p.session.pilot_id.clone().into()),
                ("count", s.attempted.into()),
                ("unlabelled", s.unlabelled.into()),
            ],
        )));
    }

    fn show_summary(&self, p: &Practice) {
        let s = p.session.summary();
        let pct = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{:.0} %", v * 100.0));
        let secs = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{v:.2} s"));
        let mut rows = vec![
            ("teleop-cmp-attempted", s.attempted.to_string()),
            ("teleop-cmp-success-rate", pct(s.success_rate)),
            ("teleop-cmp-mean-time", secs(s.mean_duration_s)),
            ("teleop-cmp-efficiency", pct(s.mean_efficiency)),
            ("teleop-cmp-collisions", s.collisions.to_string()),
        ];
        let worst = p
            .session
            .episodes
            .iter()
            .map(|e| e.metrics.min_manipulability)
            .fold(f64::INFINITY, f64::min);
        if worst.is_finite() {
            rows.push((
                "so101-ro-manipulability",
                crate::view::so101::manipulability_text(worst),
            ));
        }
        for (c, n) in s.by_category.iter().filter(|(_, n)| *n > 0) {
            let id = format!("teleop-cat-{}", c.id());
            rows.push(("", format!("{}: {n}", ctx::t(&id))));
        }
        let html: String = rows
            .iter()
            .map(|(id, v)| {
                let label = if id.is_empty() {
                    String::new()
                } else {
                    ctx::t(id)
                };
                format!(
                    "<div><dt>{}</dt><dd>{}</dd></div>",
                    escape(&label),
                    escape(v)
                )
            })
            .collect();
        self.summary.set_inner_html(&html);
    }
}
