//! The live arm's buttons (`data-action` `engage`, `gripper`, `reset`, `end-episode`), their
//! texts and pressed states, and the line that says how an episode ended
//! (`data-tele="ended"`). They hide in the failure review.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::Outcome;
use crate::ui::{ctx, dom};

use super::markup::{bool_text, find, role};

/// The buttons.
pub struct Controls {
    pub engage: Element,
    pub gripper: Element,
    pub reset: Element,
    pub end: Element,
    ended: Element,
}

impl Controls {
    /// Finds the buttons under `root`.
    pub fn find(root: &Element) -> Result<Controls, JsValue> {
        Ok(Controls {
            engage: find(root, "[data-action=\"engage\"]")?,
            gripper: find(root, "[data-action=\"gripper\"]")?,
            reset: find(root, "[data-action=\"reset\"]")?,
            end: find(root, "[data-action=\"end-episode\"]")?,
            ended: role(root, "ended")?,
        })
    }

    /// The engage and gripper buttons' texts and pressed states.
    pub fn render(&self, engaged: bool, gripper_closed: bool) {
        self.engage.set_text_content(Some(&ctx::t(if engaged {
            "teleop-pause"
        } else {
            "teleop-engage"
        })));
        let _ = self
            .engage
            .set_attribute("aria-pressed", bool_text(engaged));
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

    /// How the episode ended (`outcome`; `None`: ended by the pilot), at `t_s`.
    pub fn show_ended(&self, outcome: Option<Outcome>, t_s: f64) {
        let text = match outcome {
            Some(Outcome::Success) => {
                ctx::t_strings("teleop-ended-success", &[("t", format!("{t_s:.2}"))])
            }
            Some(Outcome::Timeout) => ctx::t("teleop-ended-timeout"),
            None => ctx::t("teleop-ended-pilot"),
        };
        self.ended.set_text_content(Some(&text));
        dom::show(&self.ended, true);
    }

    /// The ended line hidden.
    pub fn hide_ended(&self) {
        dom::show(&self.ended, false);
    }
}
