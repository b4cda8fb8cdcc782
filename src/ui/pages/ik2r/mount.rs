//! Mounting and unmounting the page: building it from its markup and the URL, wiring its
//! timers, animation-frame callback, resize observer, listeners and bench hooks, and taking
//! all of them down again.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, ResizeObserver};

use super::canvas::Layer;
use super::frame::dirty;
use super::heatmap::{self, HeatGrid, HeatLayout};
use super::plots::PlotSpec;
use super::state::State;
use super::view::ViewXf;
use super::{bench, form, markup, pointer, readouts, Els, Gfx, Handle, Page, Ui};
use crate::ui::dom;
use crate::ui::page::{MountCtx, PageHandle};
use crate::ui::schedule::Timer;

/// Builds the page into the shell's main element.
pub(super) fn mount(ctx: MountCtx) -> Result<Box<dyn PageHandle>, JsValue> {
    let page = Page::build(ctx)?;
    Ok(Box::new(Handle(page)))
}

/// The page's element `[data-ik2r="name"]`.
pub(super) fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    dom::find(root, &format!("[data-ik2r=\"{name}\"]"), "ik-2r")
}

impl Page {
    fn build(mount: MountCtx) -> Result<Rc<Page>, JsValue> {
        let root = mount.root.clone();
        root.set_inner_html(&markup::page());
        let doc = dom::document()?;
        let els = Els {
            arm_stage: role(&root, "arm-stage")?,
            heat_stage: role(&root, "heat-stage")?,
            plot_stage: role(&root, "plot-stage")?,
            arm_canvas: role(&root, "arm-fg")?,
            heat_canvas: role(&root, "heat-fg")?,
            clamp_note: role(&root, "clamp-note")?,
            url_notice: role(&root, "url-notice")?,
            view_notes: role(&root, "view-notes")?,
            ws_summary: role(&root, "ws-summary")?,
            heat_hover: role(&root, "heat-hover")?,
            copy_status: role(&root, "copy-status")?,
            elbow_down: role(&root, "elbow-down")?,
            elbow_up: role(&root, "elbow-up")?,
            ws_toggle: role(&root, "ws-toggle")?,
            ws_color: role(&root, "ws-color")?,
        };
        let gfx = Gfx {
            arm_bg: Layer::new(role(&root, "arm-bg")?)?,
            arm_fg: Layer::new(els.arm_canvas.clone())?,
            heat_bg: Layer::new(role(&root, "heat-bg")?)?,
            heat_fg: Layer::new(els.heat_canvas.clone())?,
            plot_bg: Layer::new(role(&root, "plot-bg")?)?,
            plot_fg: Layer::new(role(&root, "plot-fg")?)?,
            heat_img: Layer::offscreen(&doc)?,
            heat_grid: HeatGrid {
                n: 0,
                values: Vec::new(),
                scale_max: 1.0,
            },
            heat_painted: false,
            ws_data: None,
            ws_img: None,
            ws_img_colour: None,
            xf: ViewXf::fit(100.0, 100.0, 1.0),
            heat_layout: HeatLayout::new(100.0, 100.0, 1.0),
            plot_spec: PlotSpec::new(0.0, 1.0, 0.1, 0.1),
            sweep: Vec::new(),
            sweep_key: None,
            commands_shown: Vec::new(),
        };
        let (state, ignored) = State::from_query(&mount.query);
        let form = form::Form::find(&root)?;
        let readouts = readouts::Readouts::find(&root)?;
        let page = Rc::new(Page {
            root: root.clone(),
            els,
            state: RefCell::new(state),
            ui: RefCell::new(Ui {
                ignored_url_keys: ignored,
                ..Ui::default()
            }),
            gfx: RefCell::new(gfx),
            form: RefCell::new(form),
            readouts: RefCell::new(readouts),
            listeners: RefCell::new(Vec::new()),
            lut: heatmap::colour_lut(),
            dirty: Cell::new(0),
            raf_id: Cell::new(None),
            raf_callback: RefCell::new(None),
            resize: RefCell::new(None),
            heat_timer: Timer::default(),
            ws_timer: Timer::default(),
            url_timer: Timer::default(),
            timings: bench::Timings::install(),
            copy_status: Rc::new(Cell::new(None)),
        });
        dom::relocalize(&root)?;
        page.install(&page)?;
        page.sync_controls();
        page.form.borrow_mut().fill(&state.params);
        page.update_texts();
        page.recompute_heatmap();
        if state.show_ws {
            page.recompute_workspace();
        }
        page.update_commands();
        page.invalidate(dirty::ALL);
        Ok(page)
    }

    /// Wires listeners, timers, the animation-frame callback and the resize observer.
    fn install(&self, rc: &Rc<Page>) -> Result<(), JsValue> {
        let weak = Rc::downgrade(rc);
        {
            let w = weak.clone();
            *self.raf_callback.borrow_mut() = Some(Closure::new(move |_t: f64| {
                if let Some(page) = w.upgrade() {
                    page.raf_id.set(None);
                    page.frame();
                }
            }));
        }
        self.heat_timer.set_callback(&weak, Page::recompute_heatmap);
        self.ws_timer.set_callback(&weak, Page::recompute_workspace);
        self.url_timer.set_callback(&weak, Page::write_url);

        // Resize: every stage.
        let w = weak.clone();
        let resize_cb = Closure::<dyn FnMut(JsValue)>::new(move |_entries: JsValue| {
            if let Some(page) = w.upgrade() {
                page.invalidate(dirty::ALL);
            }
        });
        let observer = ResizeObserver::new(resize_cb.as_ref().unchecked_ref())?;
        observer.observe(&self.els.arm_stage);
        observer.observe(&self.els.heat_stage);
        observer.observe(&self.els.plot_stage);
        *self.resize.borrow_mut() = Some((observer, resize_cb));

        let mut listeners = Vec::new();
        pointer::install(self, &weak, &mut listeners)?;
        self.install_controls(&weak, &mut listeners)?;
        *self.listeners.borrow_mut() = listeners;
        bench::install_hooks(&weak)?;
        Ok(())
    }

    pub(super) fn relocalize(&self) {
        self.form.borrow().relocalize();
        self.update_texts();
        self.invalidate(dirty::ARM_BG | dirty::HEAT_BG | dirty::PLOT_BG | dirty::PLOT_FG);
    }

    pub(super) fn unmount(&self) {
        if let (Some(id), Some(window)) = (self.raf_id.take(), web_sys::window()) {
            let _ = window.cancel_animation_frame(id);
        }
        self.heat_timer.cancel();
        self.ws_timer.cancel();
        self.url_timer.cancel();
        if let Some((observer, _)) = self.resize.borrow_mut().take() {
            observer.disconnect();
        }
        self.listeners.borrow_mut().clear();
        bench::remove_hooks();
    }
}
