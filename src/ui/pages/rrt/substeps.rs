//! The sub-step panel: the current iteration written out (sample → nearest → steer → check →
//! outcome, each line from `crate::view::rrt::sub_text`) and the pseudocode with the line that
//! decided the outcome (or, in sub-step mode, the line of the sub-step shown) highlighted.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::i18n::FluentArg;
use crate::recipes::rrt_2d::RrtIteration;
use crate::ui::{ctx, dom};
use crate::view::rrt::{phase_line, phases, sub_text, Phase};

/// The panel component.
pub struct SubSteps {
    list: Element,
    none: Element,
    lines: Vec<Element>,
}

impl SubSteps {
    /// Finds the panel's elements under `root`.
    pub fn find(root: &Element) -> Result<SubSteps, JsValue> {
        let lines = dom::matching(root, "[data-code-line]")?;
        Ok(SubSteps {
            list: dom::find(root, "[data-rrt=\"subs\"]", "rrt")?,
            none: dom::find(root, "[data-rrt=\"sub-none\"]", "rrt")?,
            lines,
        })
    }

    /// Shows iteration `record` up to sub-step `upto` (`None`: all of it); at iteration 0,
    /// the note that nothing ran yet.
    pub fn show(&self, record: Option<&RrtIteration>, upto: Option<Phase>) {
        dom::clear(&self.list);
        dom::show(&self.none, record.is_none());
        let mut current = None;
        if let Some(r) = record {
            let all = phases(r);
            let upto = upto.unwrap_or(Phase::Outcome);
            for phase in all.iter().copied().filter(|p| (*p as u8) <= (upto as u8)) {
                let text = sub_text(r, phase);
                let args: Vec<(&str, FluentArg)> = text
                    .args
                    .iter()
                    .map(|(k, v)| (*k, FluentArg::Text(v.clone())))
                    .collect();
                let mut line = ctx::t_args(text.id, &args);
                if phase == Phase::Sample {
                    line = format!(
                        "{} {}",
                        ctx::t_args(
                            "rrt-sub-iteration",
                            &[("n", FluentArg::Number(r.iteration as f64))]
                        ),
                        line
                    );
                }
                if let Ok(li) = dom::el_text("li", "rrt-step-line", &line) {
                    let _ = li.set_attribute("data-phase", phase_name(phase));
                    if phase == Phase::Outcome {
                        let _ = li.set_attribute("data-outcome", r.outcome.name());
                    }
                    let _ = dom::append(&self.list, &li);
                }
                current = Some(phase_line(r, phase));
            }
        }
        for (k, line) in self.lines.iter().enumerate() {
            let on = current == Some(k + 1);
            let _ = if on {
                line.set_attribute("data-current", "true")
            } else {
                line.remove_attribute("data-current")
            };
        }
    }
}

fn phase_name(phase: Phase) -> &'static str {
    match phase {
        Phase::Sample => "sample",
        Phase::Nearest => "nearest",
        Phase::Steer => "steer",
        Phase::Check => "check",
        Phase::Outcome => "outcome",
    }
}
