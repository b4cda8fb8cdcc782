//! The live arm's buttons (`data-action` `engage`, `gripper`, `reset`, `end-episode`), their
//! texts and pressed states, and the episode's outcome over the arm view (`data-tele="ended"`,
//! `data-testid="episode-outcome"`, `data-outcome` `success|timeout|ended`): how it ended and,
//! in Record ten, under which number it was recorded. They hide in the failure review.

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::InputDevice;
use crate::teleop::Outcome;
use crate::ui::{ctx, dom};

use super::markup::{bool_text, find, role};

/// The buttons.
pub struct Controls {
    pub engage: Element,
    /// The control state shown over the view ([`crate::ui::kit::pilot_control`]).
    control: Element,
    pub gripper: Element,
    pub reset: Element,
    pub end: Element,
    ended: Element,
    /// The outcome shown (rewritten in a new language).
    shown: RefCell<Option<Ended>>,
}

/// How an episode ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ended {
    /// `None`: ended by the pilot.
    pub outcome: Option<Outcome>,
    /// The episode's time, s.
    pub t_s: f64,
    /// Its number in the session, if it was recorded.
    pub recorded: Option<usize>,
    /// It was recorded labelled SUCCESS.
    pub counted_success: bool,
}

impl Controls {
    /// Finds the buttons under `root`.
    pub fn find(root: &Element) -> Result<Controls, JsValue> {
        Ok(Controls {
            engage: find(root, "[data-action=\"engage\"]")?,
            control: role(root, "control")?,
            gripper: find(root, "[data-action=\"gripper\"]")?,
            reset: find(root, "[data-action=\"reset\"]")?,
            end: find(root, "[data-action=\"end-episode\"]")?,
            ended: role(root, "ended")?,
            shown: RefCell::new(None),
        })
    }

    /// The engage and gripper buttons' texts and pressed states, and the control state shown
    /// over the view (in the words of `device`).
    pub fn render(&self, engaged: bool, gripper_closed: bool, device: InputDevice) {
        self.engage.set_text_content(Some(&ctx::t(if engaged {
            "teleop-pause"
        } else {
            "teleop-engage"
        })));
        let _ = self
            .engage
            .set_attribute("aria-pressed", bool_text(engaged));
        let _ = crate::ui::kit::pilot_control::show(&self.control, engaged, device);
        let _ = self
            .gripper
            .set_attribute("aria-disabled", bool_text(!engaged));
        self.gripper
            .set_text_content(Some(&ctx::t(if gripper_closed {
                "teleop-gripper-open-button"
            } else {
                "teleop-gripper-close-button"
            })));
        let _ = self
            .gripper
            .set_attribute("aria-pressed", bool_text(gripper_closed));
    }

    /// The live arm's buttons shown (`live`) or hidden with the ended line.
    pub fn show_live(&self, live: bool) {
        for el in [&self.engage, &self.gripper, &self.end, &self.reset] {
            dom::show(el, live);
        }
        if !live {
            dom::show(&self.ended, false);
        }
    }

    /// How the episode ended, over the arm view.
    pub fn show_ended(&self, ended: Ended) {
        *self.shown.borrow_mut() = Some(ended);
        self.render_ended();
        dom::show(&self.ended, true);
    }

    /// The outcome's text in the current language.
    pub fn render_ended(&self) {
        let Some(e) = *self.shown.borrow() else {
            return;
        };
        let (outcome, kind) = match e.outcome {
            Some(Outcome::Success) => (
                ctx::t_strings("teleop-ended-success", &[("t", format!("{:.2}", e.t_s))]),
                "success",
            ),
            Some(Outcome::Timeout) => (ctx::t("teleop-ended-timeout"), "timeout"),
            None => (ctx::t("teleop-ended-pilot"), "ended"),
        };
        let _ = self.ended.set_attribute("data-outcome", kind);
        let text = match e.recorded {
            Some(n) => {
                let id = if e.counted_success {
                    "teleop-ended-recorded-success"
                } else {
                    "teleop-ended-recorded"
                };
                ctx::t_args(id, &[("outcome", outcome.into()), ("n", n.into())])
            }
            None => outcome,
        };
        self.ended.set_text_content(Some(&text));
    }

    /// The outcome hidden.
    pub fn hide_ended(&self) {
        *self.shown.borrow_mut() = None;
        dom::show(&self.ended, false);
    }
}
