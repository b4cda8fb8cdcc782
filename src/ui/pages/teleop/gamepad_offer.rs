//! The offer of a gamepad that sends input while the session uses another device
//! (`data-testid="gamepad-offer"`, over the arm view): "Use this gamepad"
//! (`data-action="use-gamepad"`) switches the session's device, "Not now"
//! (`data-action="dismiss-gamepad"`) hides it for that pad. Nothing switches by itself.

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::InputDevice;
use crate::ui::{ctx, dom};

use super::markup::{find, role};

/// The offer.
pub struct GamepadOffer {
    root: Element,
    text: Element,
    pub accept: Element,
    pub dismiss: Element,
    /// The pad offered now (`None`: hidden).
    offered: RefCell<Option<String>>,
    /// The pad the pilot said no to.
    declined: RefCell<Option<String>>,
}

impl GamepadOffer {
    /// Finds the offer under `root`.
    pub fn find(root: &Element) -> Result<GamepadOffer, JsValue> {
        Ok(GamepadOffer {
            root: find(root, "[data-testid=\"gamepad-offer\"]")?,
            text: role(root, "offer-text")?,
            accept: find(root, "[data-action=\"use-gamepad\"]")?,
            dismiss: find(root, "[data-action=\"dismiss-gamepad\"]")?,
            offered: RefCell::new(None),
            declined: RefCell::new(None),
        })
    }

    /// After a poll: the pad `pad_name` (if one is connected) sent input (`active`) while the
    /// session uses `device`. Shows the offer for a new pad in use, hides it once the session
    /// uses the gamepad or the pad is gone.
    pub fn polled(&self, device: InputDevice, pad_name: Option<&str>, active: bool) {
        let Some(name) = pad_name.filter(|_| device != InputDevice::Gamepad) else {
            self.hide();
            return;
        };
        let offered = self.offered.borrow().as_deref() == Some(name);
        let declined = self.declined.borrow().as_deref() == Some(name);
        if active && !offered && !declined {
            *self.offered.borrow_mut() = Some(name.to_string());
            self.render();
            dom::show(&self.root, true);
        }
    }

    /// "Not now": hidden until another pad sends input.
    pub fn decline(&self) {
        *self.declined.borrow_mut() = self.offered.borrow().clone();
        self.hide();
    }

    /// Hidden.
    pub fn hide(&self) {
        if self.offered.borrow_mut().take().is_some() {
            dom::show(&self.root, false);
        }
    }

    /// The text in the current language.
    pub fn render(&self) {
        if let Some(name) = self.offered.borrow().as_ref() {
            let text = ctx::t_strings("teleop-pad-offer", &[("name", name.clone())]);
            self.text.set_text_content(Some(&text));
        }
    }
}
