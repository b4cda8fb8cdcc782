//! The module bar (`data-module`, `aria-current` on the current one, `aria-disabled` on those
//! not yet open, each of those with the line that says what opens it, shown under it and its
//! accessible description) with its help line and Next module, and the preflight under the
//! readouts:
//! the device choice (`data-device`, `aria-checked`), the checks (`data-check`, `data-state`
//! `todo|done|failed`) and the device status (the pad's name, or the hint of the device).

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::{InputDevice, Module, Session, RECORD_TARGET};
use crate::ui::{ctx, dom};

use super::markup::{bool_text, find, role};
use super::sessions::Sessions;

/// The bar and the preflight.
pub struct ModuleBar {
    pub modules: Vec<(Module, Element)>,
    /// Under each module: what opens it (shown while it is not open).
    unlocks: Vec<Element>,
    pub devices: Vec<(InputDevice, Element)>,
    pub next: Element,
    help: Element,
    preflight: Element,
    check_moved: Element,
    check_reset: Element,
    device_status: Element,
    /// The device status shown (`None`: to be written).
    shown_device: RefCell<Option<String>>,
}

impl ModuleBar {
    /// Finds the bar and the preflight under `root`.
    pub fn find(root: &Element) -> Result<ModuleBar, JsValue> {
        let modules = Module::ALL
            .iter()
            .map(|m| Ok((*m, find(root, &format!("[data-module=\"{}\"]", m.id()))?)))
            .collect::<Result<Vec<_>, JsValue>>()?;
        let devices = InputDevice::ALL
            .iter()
            .map(|d| Ok((*d, find(root, &format!("[data-device=\"{}\"]", d.id()))?)))
            .collect::<Result<Vec<_>, JsValue>>()?;
        let unlocks = Module::ALL
            .iter()
            .map(|m| find(root, &format!("#tele-why-{}", m.id())))
            .collect::<Result<Vec<_>, JsValue>>()?;
        Ok(ModuleBar {
            modules,
            unlocks,
            next: find(root, "[data-action=\"next-module\"]")?,
            help: role(root, "module-help")?,
            preflight: role(root, "preflight")?,
            devices,
            check_moved: find(root, "[data-check=\"moved\"]")?,
            check_reset: find(root, "[data-check=\"reset\"]")?,
            device_status: role(root, "device-status")?,
            shown_device: RefCell::new(None),
        })
    }

    /// The module bar, its help line, the preflight and its checks.
    pub fn render_modules(&self, sessions: &Sessions) {
        let current = sessions.module();
        for (m, el) in &self.modules {
            if *m == current {
                let _ = el.set_attribute("aria-current", "step");
            } else {
                let _ = el.remove_attribute("aria-current");
            }
        }
        let help = ctx::t_strings(
            &format!("teleop-help-{}", current.id()),
            &[("target", RECORD_TARGET.to_string())],
        );
        self.help.set_text_content(Some(&help));
        dom::show(&self.preflight, current == Module::Preflight);
        self.render_checks(sessions);
    }

    /// The preflight checks, the device chosen and which modules are open.
    pub fn render_checks(&self, sessions: &Sessions) {
        let s = sessions.current.borrow();
        let mark = |el: &Element, state: &str| {
            let _ = el.set_attribute("data-state", state);
        };
        mark(
            &self.check_moved,
            if s.preflight.moved { "done" } else { "todo" },
        );
        mark(
            &self.check_reset,
            match s.preflight.reset_verified {
                Some(true) => "done",
                Some(false) => "failed",
                None => "todo",
            },
        );
        for (d, el) in &self.devices {
            let _ = el.set_attribute("aria-checked", bool_text(*d == s.input_device));
        }
        drop(s);
        self.render_open(sessions);
    }

    /// Which modules are open, what opens the others (and Next module).
    pub fn render_open(&self, sessions: &Sessions) {
        let s = sessions.current.borrow();
        for ((m, el), why) in self.modules.iter().zip(&self.unlocks) {
            let open = sessions.allows(*m);
            let _ = el.set_attribute("aria-disabled", bool_text(!open));
            if open {
                let _ = el.remove_attribute("aria-describedby");
            } else {
                why.set_text_content(Some(&ctx::t(unlock_message(*m, &s))));
                let _ = el.set_attribute("aria-describedby", &why.id());
            }
            dom::show(why, !open);
        }
        let current = s.module;
        drop(s);
        let next = current.next();
        let next_ok = next != current && sessions.allows(next);
        let _ = self
            .next
            .set_attribute("aria-disabled", bool_text(!next_ok));
        if next_ok || next == current {
            let _ = self.next.remove_attribute("aria-describedby");
        } else {
            let _ = self
                .next
                .set_attribute("aria-describedby", &format!("tele-why-{}", next.id()));
        }
    }

    /// The device status: the pad's name or that none is connected, or the hint of the
    /// keyboard or the pointer (written only when it changes, unless `rewrite`).
    pub fn render_device(&self, device: InputDevice, pad_name: Option<String>, rewrite: bool) {
        if rewrite {
            *self.shown_device.borrow_mut() = None;
        }
        let text = match device {
            InputDevice::Gamepad => match pad_name {
                Some(name) => ctx::t_strings("teleop-pad-connected", &[("name", name)]),
                None => ctx::t("teleop-pad-none"),
            },
            InputDevice::Keyboard => ctx::t("teleop-keyboard-hint"),
            InputDevice::Pointer => ctx::t("teleop-pointer-hint"),
        };
        if self.shown_device.borrow().as_deref() != Some(&text) {
            self.device_status.set_text_content(Some(&text));
            *self.shown_device.borrow_mut() = Some(text);
        }
    }

    /// Whether the device status is still to be written.
    pub fn device_unwritten(&self) -> bool {
        self.shown_device.borrow().is_none()
    }
}

/// The Fluent id of what opens module `m` of `session` while it is closed.
fn unlock_message(m: Module, session: &Session) -> &'static str {
    match m {
        Module::RecordTen if session.preflight.moved => "teleop-unlock-record-ten-reset",
        Module::RecordTen => "teleop-unlock-record-ten",
        _ => "teleop-unlock-episode",
    }
}
