//! The teaching steps: the stepper's model and options, and the step panel under the
//! stepper: the step's title, what it computes (with the numbers of this run where they
//! matter) and the small matrices it produces, from [`crate::view::umeyama_2d::shown_for`].
//! The matrices' tables are built when the step changes; a drag that only changes their
//! numbers rewrites the cells whose text changed.

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::kit::form::escape;
use crate::ui::kit::stepper::{default_speed_label, Length, Speed, StepModel, StepperOptions};
use crate::ui::{ctx, dom};
use crate::view::signal::sig;
use crate::view::umeyama_2d::{shown_for, umeyama_scale, Scene, Shown, Step, STEPS};

use super::markup::P;

/// The stepper's model: which teaching step is shown.
pub struct StepIndex {
    pub index: u64,
}

impl StepModel for StepIndex {
    fn length(&self) -> Length {
        Length::Finite(STEPS.len() as u64 - 1)
    }
    fn go_to(&mut self, index: u64) {
        self.index = index.min(STEPS.len() as u64 - 1);
    }
}

/// The stepper over the steps: its speeds, labelled in seconds per step.
pub fn stepper_options() -> StepperOptions {
    StepperOptions {
        speeds: [0.5, 1.0, 2.0].map(Speed::PerSecond).to_vec(),
        initial_speed: 1,
        speed_label: Box::new(|speed| match speed {
            Speed::PerSecond(rate) if rate > 0.0 => {
                ctx::t_args("umeyama-speed", &[("seconds", (1.0 / rate).into())])
            }
            other => default_speed_label(other),
        }),
        testid: "umeyama-2d-stepper",
    }
}

/// The panel component.
pub struct StepPanel {
    title: Element,
    text: Element,
    mats: Element,
    /// The title and text shown now (written only when they change).
    shown: RefCell<(String, String)>,
    /// The matrices' layout shown now (step, symbols, shapes) and their cells, each with the
    /// text and `data-value` it shows.
    cells: RefCell<(String, Vec<Cell>)>,
}

/// One number of a matrix: its `<td>`, text and exact value shown.
struct Cell {
    td: Element,
    text: String,
    value: String,
}

/// What fixes the matrices' markup: the step, each matrix's symbol and shape.
fn layout(key: &str, shown: &[Shown]) -> String {
    let mut out = key.to_string();
    for m in shown {
        out.push_str(&format!(
            "|{}:{}",
            m.symbol,
            m.rows
                .iter()
                .map(|r| r.len().to_string())
                .collect::<Vec<_>>()
                .join(",")
        ));
    }
    out
}

/// A matrix as an HTML table beside its symbol.
fn matrix_html(symbol: &str, rows: &[Vec<f64>]) -> String {
    let mut html = format!(
        "<span class=\"ume-mat\"><span class=\"ume-mat-symbol\">{} =</span><table><tbody>",
        escape(symbol)
    );
    for row in rows {
        html.push_str("<tr>");
        for v in row {
            html.push_str(&format!(
                "<td data-value=\"{}\">{}</td>",
                crate::pyfmt::py_float(*v),
                escape(&sig(*v, 4))
            ));
        }
        html.push_str("</tr>");
    }
    html.push_str("</tbody></table></span>");
    html
}

impl StepPanel {
    /// Finds the panel's elements under `root`.
    pub fn find(root: &Element) -> Result<StepPanel, JsValue> {
        let role = |name: &str| dom::find::<Element>(root, &format!("[data-{P}=\"{name}\"]"), P);
        Ok(StepPanel {
            title: role("step-title")?,
            text: role("step-text")?,
            mats: role("step-mats")?,
            shown: RefCell::new(Default::default()),
            cells: RefCell::new(Default::default()),
        })
    }

    /// Shows `step` of `scene` (in the current language).
    pub fn show(&self, scene: &Scene, step: Step) {
        let key = step.key();
        let title = ctx::t(&format!("umeyama-step-{key}-title"));
        let s = &scene.steps;
        let text = match step {
            Step::Reflection if s.reflection_fixed() => ctx::t("umeyama-step-reflection-fixed"),
            Step::Reflection => ctx::t("umeyama-step-reflection-none"),
            Step::Scale => match umeyama_scale(s) {
                Some(u) => ctx::t_strings(
                    "umeyama-step-scale-quirk",
                    &[("recipe", sig(s.scale, 4)), ("umeyama", sig(u, 4))],
                ),
                None => ctx::t("umeyama-step-scale-text"),
            },
            _ => ctx::t(&format!("umeyama-step-{key}-text")),
        };
        let mut shown = self.shown.borrow_mut();
        if shown.0 != title {
            self.title.set_text_content(Some(&title));
            shown.0 = title;
        }
        if shown.1 != text {
            self.text.set_text_content(Some(&text));
            shown.1 = text;
        }
        self.show_matrices(key, &shown_for(scene, step));
    }

    /// The matrices: built anew for another layout, else only the changed cells rewritten.
    fn show_matrices(&self, key: &str, matrices: &[Shown]) {
        let mut cells = self.cells.borrow_mut();
        let layout = layout(key, matrices);
        let values = matrices.iter().flat_map(|m| m.rows.iter().flatten());
        if cells.0 == layout {
            for (cell, v) in cells.1.iter_mut().zip(values) {
                let text = sig(*v, 4);
                if cell.text != text {
                    cell.td.set_text_content(Some(&text));
                    cell.text = text;
                }
                let value = crate::pyfmt::py_float(*v);
                if cell.value != value {
                    let _ = cell.td.set_attribute("data-value", &value);
                    cell.value = value;
                }
            }
            return;
        }
        let html: String = matrices
            .iter()
            .map(|m| matrix_html(m.symbol, &m.rows))
            .collect();
        self.mats.set_inner_html(&html);
        let _ = self.mats.set_attribute("data-step", key);
        let tds = dom::matching(&self.mats, "td").unwrap_or_default();
        let found = tds.len() == values.clone().count();
        cells.1 = tds
            .into_iter()
            .zip(values)
            .map(|(td, v)| Cell {
                td,
                text: sig(*v, 4),
                value: crate::pyfmt::py_float(*v),
            })
            .collect();
        // Cells not found as built: the next frame builds them again.
        cells.0 = if found { layout } else { String::new() };
    }
}
