//! The page's controls: elbow switch, workspace toggle and colour, Reset, the parameters
//! form (validate on input, apply what is valid, re-try fields that were waiting on another
//! value), the download buttons (CSV via the kernels, PNG of the arm view) and the copy buttons.

use std::rc::Weak;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::Element;

use super::canvas::Layer;
use super::frame::dirty;
use super::mount::role;
use super::state::{self, Field, Params, State, WsColor};
use super::{downloads, Page};
use crate::planar2r::Elbow;
use crate::ui::clipboard;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{self, show, Listener};

impl Page {
    /// Toolbar, form and download listeners.
    pub(super) fn install_controls(
        &self,
        weak: &Weak<Page>,
        out: &mut Vec<Listener>,
    ) -> Result<(), JsValue> {
        for (input, elbow) in [
            (&self.els.elbow_down, Elbow::Down),
            (&self.els.elbow_up, Elbow::Up),
        ] {
            out.push(Listener::for_page(input, "change", weak, move |p, _| {
                p.set_elbow(elbow)
            })?);
        }
        out.push(Listener::for_page(
            &self.els.ws_toggle,
            "change",
            weak,
            |p, _| {
                let on = p.els.ws_toggle.checked();
                p.set_workspace_visible(on);
            },
        )?);
        out.push(Listener::for_page(
            &self.els.ws_color,
            "change",
            weak,
            |p, _| {
                if let Some(c) = WsColor::from_key(&p.els.ws_color.value()) {
                    p.state.borrow_mut().ws_color = c;
                    p.refresh_workspace_image();
                    p.schedule_url();
                }
            },
        )?);
        let reset: Element = role(&self.root, "reset")?;
        out.push(Listener::for_page(&reset, "click", weak, |p, _| p.reset())?);
        let form: Element = role(&self.root, "form")?;
        out.push(Listener::for_page(&form, "input", weak, |p, e| {
            if let Some(key) = e
                .target()
                .and_then(|t| t.dyn_into::<Element>().ok())
                .and_then(|el| el.get_attribute("data-field"))
            {
                p.on_field_input(&key);
            }
        })?);
        out.push(Listener::for_page(&form, "submit", weak, |_, e| {
            e.prevent_default()
        })?);
        for button in dom::matching(&self.root, "[data-download]")? {
            let file = button.get_attribute("data-download").unwrap_or_default();
            out.push(Listener::for_page(&button, "click", weak, move |p, _| {
                p.download(&file)
            })?);
        }
        for button in dom::matching(&self.root, "[data-copy]")? {
            let key = button.get_attribute("data-copy").unwrap_or_default();
            out.push(Listener::for_page(&button, "click", weak, move |p, _| {
                p.copy_command(&key)
            })?);
        }
        Ok(())
    }

    /// A form field changed: validate it, apply it if valid, show or clear its message.
    pub(super) fn on_field_input(&self, key: &str) {
        let Some(field) = Field::ALL.into_iter().find(|f| f.key() == key) else {
            return;
        };
        let text = self.form.borrow().text(field).unwrap_or_default();
        let old = self.state.borrow().params;
        match state::validate(&old, field, &text) {
            Ok(next) => {
                self.form.borrow_mut().set_error(field, None);
                self.apply_params(old, next);
                self.revalidate_others(field);
            }
            Err(e) => self.form.borrow_mut().set_error(field, Some(e)),
        }
    }

    /// Fields still showing an error may have become valid with the new values (e.g. q1_start
    /// after q1_stop grew): try them again.
    pub(super) fn revalidate_others(&self, edited: Field) {
        for field in Field::ALL {
            if field == edited {
                continue;
            }
            let text = self.form.borrow().text(field).unwrap_or_default();
            let old = self.state.borrow().params;
            if field.text(&old) == text {
                self.form.borrow_mut().set_error(field, None);
                continue;
            }
            if let Ok(next) = state::validate(&old, field, &text) {
                self.form.borrow_mut().set_error(field, None);
                self.apply_params(old, next);
            }
        }
    }

    /// Applies new (valid) parameters: what depends on which value is redrawn or recomputed.
    pub(super) fn apply_params(&self, old: Params, next: Params) {
        if old == next {
            return;
        }
        self.state.borrow_mut().params = next;
        let show_ws = self.state.borrow().show_ws;
        let arm_changed = old.l1 != next.l1 || old.l2 != next.l2;
        let mut bits = dirty::FRAME | dirty::PLOT_FG;
        if arm_changed {
            bits |= dirty::LAYOUT | dirty::ARM_BG | dirty::PLOT_BG;
        }
        if arm_changed || old.heatmap_n != next.heatmap_n {
            self.heat_timer.schedule(120);
        }
        if arm_changed || old.half_mm != next.half_mm || old.step_mm != next.step_mm {
            if show_ws {
                self.ws_timer.schedule(200);
                bits |= dirty::LAYOUT | dirty::ARM_BG;
            } else {
                self.gfx.borrow_mut().ws_data = None;
            }
        }
        if (old.q1_start, old.q1_stop, old.q1_step) != (next.q1_start, next.q1_stop, next.q1_step) {
            bits |= dirty::PLOT_BG;
        }
        self.update_texts();
        self.update_commands();
        self.invalidate(bits);
        self.schedule_url();
    }

    /// Back to the defaults (key `r`, Reset button).
    pub(super) fn reset(&self) {
        let old = self.state.borrow().params;
        *self.state.borrow_mut() = State::default();
        {
            let mut ui = self.ui.borrow_mut();
            ui.ignored_url_keys.clear();
            ui.ghost = None;
            ui.pinned_pointer = None;
        }
        self.set_clamp_note(false);
        self.form.borrow_mut().fill(&State::default().params);
        self.sync_controls();
        let next = self.state.borrow().params;
        if old != next {
            self.heat_timer.schedule(0);
        }
        self.gfx.borrow_mut().ws_data = None;
        self.update_texts();
        self.update_commands();
        self.invalidate(dirty::ALL);
        self.write_url();
    }

    /// A download button: CSV from the kernels, or the arm view as PNG.
    pub(super) fn download(&self, file: &str) {
        let slot = self
            .root
            .query_selector(&format!("[data-dl-error=\"{file}\"]"))
            .ok()
            .flatten();
        let result = if file == downloads::ARM_PNG {
            self.arm_png()
        } else {
            let st = *self.state.borrow();
            match downloads::EXPORTS.iter().find(|e| e.file == file) {
                Some(export) => match downloads::csv(export, &st.params, st.q2) {
                    Ok(text) => crate::ui::download::download_text(file, &text, "text/csv"),
                    Err(e) => Err(JsValue::from_str(&ctx::error_text(&e))),
                },
                None => Ok(()),
            }
        };
        if let Some(slot) = slot {
            match result {
                Ok(()) => show(&slot, false),
                Err(e) => {
                    let msg = e.as_string().unwrap_or_else(|| format!("{e:?}"));
                    slot.set_text_content(Some(&t_strings("ik2r-dl-failed", &[("error", msg)])));
                    show(&slot, true);
                }
            }
        }
    }

    /// The arm view (background and arm layers) composed into one PNG.
    pub(super) fn arm_png(&self) -> Result<(), JsValue> {
        let gfx = self.gfx.borrow();
        let doc = dom::document()?;
        let out = Layer::offscreen(&doc)?;
        out.canvas.set_width(gfx.arm_bg.canvas.width());
        out.canvas.set_height(gfx.arm_bg.canvas.height());
        out.ctx
            .draw_image_with_html_canvas_element(&gfx.arm_bg.canvas, 0.0, 0.0)?;
        out.ctx
            .draw_image_with_html_canvas_element(&gfx.arm_fg.canvas, 0.0, 0.0)?;
        crate::ui::download::download_canvas_png(&out.canvas, downloads::ARM_PNG)
    }

    /// A copy button: the command line beside it to the clipboard.
    pub(super) fn copy_command(&self, key: &str) {
        let Ok(Some(code)) = self.root.query_selector(&format!("[data-cmd=\"{key}\"]")) else {
            return;
        };
        let text = code.text_content().unwrap_or_default();
        let element = self.els.copy_status.clone();
        let status = self.copy_status.clone();
        clipboard::copy_text(&text, move |ok| {
            let id = if ok {
                "ik2r-copied"
            } else {
                "ik2r-copy-failed"
            };
            status.set(Some(id));
            element.set_text_content(Some(&ctx::t(id)));
        });
    }
}
