//! The progress panel of a long run: a bar (`role="progressbar"` with `aria-valuemin`,
//! `aria-valuemax` = total rows and `aria-valuenow` = rows done), "rows done of total" with
//! digit grouping, the time taken and an estimate of the time left, and a Cancel button
//! (`data-action="cancel"`). The numbers come from [`crate::view::progress`]; the styles from
//! `progress.css` beside this file (bundled into `www/app.css`; the bar's width is set through
//! CSSOM, which the strict CSP allows).

use std::cell::Cell;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlElement};

use crate::i18n::FluentArg;
use crate::ui::ctx;
use crate::ui::dom::{self, show, Listener};
use crate::ui::schedule::now_ms;
use crate::view::progress::{progress_view, Clock, ProgressView};

/// The panel. Put [`element`](ProgressPanel::element) where it belongs; it is hidden until
/// [`start`](ProgressPanel::start).
pub struct ProgressPanel {
    root: Element,
    bar: Element,
    fill: HtmlElement,
    rows: Element,
    time: Element,
    started_ms: Cell<f64>,
    last: Cell<(u64, u64)>,
    _cancel: Listener,
}

/// "1 min 5 s" / "1 分 5 秒".
fn clock_text(clock: Clock) -> String {
    let args = [
        ("min", FluentArg::from(clock.minutes as usize)),
        ("s", FluentArg::from(clock.seconds as usize)),
    ];
    if clock.minutes == 0 {
        ctx::t_args("kit-progress-seconds", &args)
    } else {
        ctx::t_args("kit-progress-minutes", &args)
    }
}

fn rows_text(view: &ProgressView) -> String {
    if view.total == 0 {
        return ctx::t("kit-progress-starting");
    }
    ctx::t_args(
        "kit-progress-rows",
        &[
            ("done", FluentArg::from(view.done_text.clone())),
            ("total", FluentArg::from(view.total_text.clone())),
            ("percent", FluentArg::from(format!("{:.1}", view.percent))),
        ],
    )
}

fn time_text(view: &ProgressView) -> String {
    let elapsed = clock_text(view.elapsed);
    match view.remaining {
        Some(left) => ctx::t_strings(
            "kit-progress-time-left",
            &[("elapsed", elapsed), ("left", clock_text(left))],
        ),
        None => ctx::t_strings("kit-progress-time", &[("elapsed", elapsed)]),
    }
}

impl ProgressPanel {
    /// A hidden panel whose Cancel button calls `on_cancel`.
    pub fn new(on_cancel: impl Fn() + 'static) -> Result<ProgressPanel, JsValue> {
        let root = dom::el_class("div", "kit-progress")?;
        root.set_attribute("data-testid", "progress")?;
        let bar = dom::el_class("div", "kit-progress-bar")?;
        bar.set_attribute("role", "progressbar")?;
        bar.set_attribute("aria-valuemin", "0")?;
        bar.set_attribute("aria-valuemax", "0")?;
        bar.set_attribute("aria-valuenow", "0")?;
        bar.set_attribute("data-testid", "progress-bar")?;
        dom::set_i18n_attrs(&bar, &[("aria-label", "kit-progress-label")])?;
        let fill = dom::el_class("div", "kit-progress-fill")?.dyn_into::<HtmlElement>()?;
        dom::append(&bar, &fill)?;
        let line = dom::el_class("div", "kit-progress-line")?;
        let texts = dom::el_class("p", "kit-progress-text")?;
        let rows = dom::el_class("span", "kit-progress-rows")?;
        rows.set_attribute("data-testid", "progress-rows")?;
        let time = dom::el_class("span", "kit-progress-time")?;
        time.set_attribute("data-testid", "progress-time")?;
        dom::append(&texts, &rows)?;
        dom::append(&texts, &time)?;
        let cancel = dom::el_i18n(
            "button",
            "button kit-progress-cancel",
            "kit-progress-cancel",
        )?;
        cancel.set_attribute("type", "button")?;
        cancel.set_attribute("data-action", "cancel")?;
        cancel.set_attribute("data-testid", "progress-cancel")?;
        dom::append(&line, &texts)?;
        dom::append(&line, &cancel)?;
        dom::append(&root, &bar)?;
        dom::append(&root, &line)?;
        let listener = Listener::new(&cancel, "click", move |_| on_cancel())?;
        show(&root, false);
        Ok(ProgressPanel {
            root,
            bar,
            fill,
            rows,
            time,
            started_ms: Cell::new(0.0),
            last: Cell::new((0, 0)),
            _cancel: listener,
        })
    }

    /// The panel's element.
    pub fn element(&self) -> &Element {
        &self.root
    }

    /// Shows the panel at 0 for a run starting now (total not yet known).
    pub fn start(&self) {
        self.started_ms.set(now_ms());
        self.set(0, 0);
        show(&self.root, true);
    }

    /// `done` of `total` rows now.
    pub fn set(&self, done: u64, total: u64) {
        self.last.set((done, total));
        let view = progress_view(done, total, now_ms() - self.started_ms.get());
        let _ = self
            .bar
            .set_attribute("aria-valuemax", &view.total.to_string());
        let _ = self
            .bar
            .set_attribute("aria-valuenow", &view.done.to_string());
        let rows = rows_text(&view);
        let time = time_text(&view);
        let _ = self
            .bar
            .set_attribute("aria-valuetext", &format!("{rows} {time}"));
        let _ = self
            .fill
            .style()
            .set_property("width", &format!("{}%", view.percent));
        self.rows.set_text_content(Some(&rows));
        self.time.set_text_content(Some(&time));
    }

    /// Hides the panel (the run ended or was cancelled).
    pub fn hide(&self) {
        show(&self.root, false);
    }

    /// Whether the panel is showing a run.
    pub fn is_shown(&self) -> bool {
        !self.root.has_attribute("hidden")
    }

    /// Re-renders the texts in the current language.
    pub fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        let (done, total) = self.last.get();
        self.set(done, total);
    }
}

/// The one-line progress of a file written in slices: message `message_id` (with `$file`,
/// `$done` and `$total`, grouped digits) while `shown` is `Some((file, (done, total)))`;
/// hidden with `None`. `data-state` is `writing` or `idle` (test hooks).
pub fn show_writing_line(line: &Element, message_id: &str, shown: Option<(&str, (usize, usize))>) {
    let text = shown.map(|(file, (done, total))| {
        ctx::t_args(
            message_id,
            &[
                ("file", FluentArg::Text(file.to_string())),
                (
                    "done",
                    FluentArg::Text(crate::pyfmt::group_u64(done as u64)),
                ),
                (
                    "total",
                    FluentArg::Text(crate::pyfmt::group_u64(total as u64)),
                ),
            ],
        )
    });
    line.set_text_content(text.as_deref());
    show(line, text.is_some());
    let _ = line.set_attribute(
        "data-state",
        if text.is_some() { "writing" } else { "idle" },
    );
}
