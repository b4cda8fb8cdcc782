//! The step panel under the stepper: the step's title, what it computes (with the numbers of
//! this run where they matter) and the small matrices it produces, from
//! [`crate::view::umeyama_2d::shown_for`].

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::kit::form::escape;
use crate::ui::{ctx, dom};
use crate::view::signal::sig;
use crate::view::umeyama_2d::{shown_for, umeyama_scale, Scene, Step};

use super::P;

/// The panel component.
pub struct StepPanel {
    title: Element,
    text: Element,
    mats: Element,
    /// What the panel shows now (written only when it changes).
    shown: RefCell<(String, String, String)>,
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
        let html: String = shown_for(scene, step)
            .iter()
            .map(|m| matrix_html(m.symbol, &m.rows))
            .collect();
        let mut shown = self.shown.borrow_mut();
        if shown.0 != title {
            self.title.set_text_content(Some(&title));
            shown.0 = title;
        }
        if shown.1 != text {
            self.text.set_text_content(Some(&text));
            shown.1 = text;
        }
        if shown.2 != html {
            self.mats.set_inner_html(&html);
            let _ = self.mats.set_attribute("data-step", key);
            shown.2 = html;
        }
    }
}
