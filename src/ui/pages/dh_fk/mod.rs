//! DH forward kinematics in 3D (`#/dh-fk`): the recipe's 3R chain drawn in an orbit view
//! (links, joint axes, every frame's axes, a ground grid), posed by three joint sliders or the
//! recipe's `angles` field; the modified-DH table with the current θ, every frame's pose as the
//! CSV writes it, the tip's readouts; "show one row" walks a row through its four elementary
//! transforms with the stepper, the moving frame animated from one to the next. The CSV is the
//! recipe's run with the page's `angles`, byte for byte what `bsv dh-fk` writes.
//!
//! Components, one file each: `chain_view` (the kit's orbit view and the scene), `tables` (the
//! DH and pose tables), `walk` (the row walk: stepper, steps, matrices) and `markup`; the
//! form, URL notice and exports are the kit's [`RecipeControls`], the readouts the kit's. The
//! numbers come from the kernel and the pure `crate::view::dh_fk`.

mod chain_view;
mod markup;
mod tables;
mod walk;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement, KeyboardEvent};

use crate::recipes::dh_fk::{self, params_from_args, run, DhParams, CSV_NAME, JOINTS};
use crate::recipes::PageRecipe;
use crate::ui::kit::canvas::{Ink, LayeredCanvas};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::frame;
use crate::ui::kit::keymap;
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::recipe_controls::RecipeControls;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::stepper::Command;
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::camera3d::{Camera, Preset};
use crate::view::dh_fk::{
    cell, csv_rows, draw_frames, set_joint_text, DrawFrame, PageQuery, RowWalk, OWN_KEYS,
    WALK_STEPS,
};
use crate::view::exercises::dh_fk::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::scene3d::AxisPalette;
use markup::P;

/// Quiet time after which the tip's new position is announced, ms.
const ANNOUNCE_QUIET_MS: f64 = 600.0;
/// How long the moving frame takes from one step to the next, ms.
const TWEEN_MS: f64 = 550.0;

/// The page's keys besides the stepper's and the view's.
const ROW_KEYS: Shortcut = keymap::key("1  2  3", "dh-key-row");

/// The chain as last validly posed.
struct Posed {
    params: DhParams,
    frames: Vec<DrawFrame>,
    /// The CSV's data rows (cells as written).
    rows: Vec<Vec<String>>,
}

impl Posed {
    fn new(params: DhParams) -> Posed {
        let rows = run(&params)
            .ok()
            .and_then(|out| out.file(CSV_NAME).map(csv_rows))
            .unwrap_or_default();
        Posed {
            frames: draw_frames(&params.q),
            params,
            rows,
        }
    }
}

/// A step animation: from step, to step, start time (ms).
type Tween = (usize, usize, f64);

/// The mounted page.
pub struct DhPage {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    controls: RecipeControls<DhParams>,
    posed: RefCell<Posed>,
    query: Cell<PageQuery>,
    view: RefCell<Option<chain_view::ChainView>>,
    walk: RefCell<Option<walk::WalkPanel>>,
    tween: Cell<Option<Tween>>,
    /// Steps animate (not while the page restores its URL state).
    animate: Cell<bool>,
    dh_table: tables::DhTable,
    pose_table: tables::PoseTable,
    readouts: Readouts,
    sliders: Vec<(HtmlInputElement, Element)>,
    cb_axes: HtmlInputElement,
    legend: Element,
    url: RefCell<Option<UrlWriter>>,
    scope: RefCell<Scope>,
}

impl Page for DhPage {
    fn mount(ctx: MountCtx) -> Result<DhPage, JsValue> {
        let exercises_root = ctx.root.clone();
        let root = PageRoot::fill(&ctx.root, &markup::page(), P, P)?;
        let controls = RecipeControls::mount(
            &root,
            P,
            PageRecipe::of::<dh_fk::Entry>(),
            &[],
            &ctx.query,
            &OWN_KEYS,
            params_from_args,
        )?;
        let (query, bad) = PageQuery::read(&ctx.query);
        controls.note_ignored(bad);
        let posed = Posed::new(controls.value());
        let mut sliders = Vec::new();
        for i in 1..=JOINTS {
            sliders.push((
                root.find(&format!("[data-slider=\"q{i}\"]"))?,
                root.role(&format!("q{i}-value"))?,
            ));
        }
        let cb_axes: HtmlInputElement = root.find("[data-option=\"cb-axes\"]")?;
        cb_axes.set_checked(query.palette == AxisPalette::ColorBlindSafe);
        let legend = root.role("legend")?;
        let dh_table = tables::DhTable::find(&root)?;
        let pose_table = tables::PoseTable::find(&root)?;
        let readouts = Readouts::find(&root)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::url_pairs);
            Inner {
                me: me.clone(),
                root: root.clone(),
                controls,
                posed: RefCell::new(posed),
                query: Cell::new(query),
                view: RefCell::new(None),
                walk: RefCell::new(None),
                tween: Cell::new(None),
                animate: Cell::new(false),
                dh_table,
                pose_table,
                readouts,
                sliders,
                cb_axes,
                legend,
                url: RefCell::new(Some(url)),
                scope: RefCell::new(scope),
            }
        });
        inner.build(query.view)?;
        inner.install()?;
        inner.show_palette();
        inner.show_pose(false);
        if query.step > 0 {
            inner.command(Command::Seek(query.step as u64));
        } else {
            inner.show_walk(true);
        }
        inner.animate.set(true);
        inner.redraw_now();
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(DhPage {
            inner,
            _exercises: exercises,
        })
    }

    fn relocalize(&self) {
        let p = &self.inner;
        p.controls.relocalize();
        if let Some(v) = p.view.borrow().as_ref() {
            v.orbit.relocalize();
        }
        if let Some(w) = p.walk.borrow().as_ref() {
            w.relocalize();
        }
        p.show_walk(true);
        p.show_pose(false);
    }

    fn set_projector(&self, _on: bool) {
        if let Some(v) = self.inner.view.borrow().as_ref() {
            v.orbit.relayout();
        }
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        let mut keys = crate::ui::kit::orbit::KEYS.to_vec();
        keys.push(ROW_KEYS);
        keys.extend_from_slice(keymap::STEPPER);
        keys
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = &self.inner;
        if p.view
            .borrow()
            .as_ref()
            .is_some_and(|v| v.orbit.on_key(event))
        {
            return true;
        }
        if let Ok(row) = event.key().parse::<usize>() {
            if (1..=JOINTS).contains(&row) {
                p.pick_row(row);
                return true;
            }
        }
        p.walk
            .borrow()
            .as_ref()
            .is_some_and(|w| w.stepper.on_key(event))
    }
}

impl Inner {
    /// The URL: the recipe's `angles` (when not the default), then the page's own keys.
    fn url_pairs(&self) -> Vec<(String, String)> {
        let mut pairs = self.controls.url_pairs();
        let mut q = self.query.get();
        if let Ok(walk) = self.walk.try_borrow() {
            if let Some(w) = walk.as_ref() {
                q.step = w.step();
            }
        }
        pairs.extend(q.write());
        pairs
    }

    fn write_url(&self) {
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// The view and the row walk (their callbacks hold the page weakly).
    fn build(&self, preset: Preset) -> Result<(), JsValue> {
        let slot: Element = self.root.role("view")?;
        let (me_draw, me_view) = (self.me.clone(), self.me.clone());
        let view = chain_view::ChainView::new(
            &slot,
            preset,
            move |canvas, camera, ink| {
                if let Some(p) = me_draw.upgrade() {
                    p.draw(canvas, camera, ink);
                }
            },
            move |preset| {
                if let Some(p) = me_view.upgrade() {
                    p.view_changed(preset);
                }
            },
        )?;
        *self.view.borrow_mut() = Some(view);
        let me = self.me.clone();
        let walk = walk::WalkPanel::new(&self.root, move |step| {
            if let Some(p) = me.upgrade() {
                p.walk_moved(step as usize);
            }
        })?;
        *self.walk.borrow_mut() = Some(walk);
        Ok(())
    }

    /// Listeners: the form and exports (the kit's), sliders, row buttons, the colour switch.
    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        self.controls.attach(
            &mut scope,
            me,
            |p| &p.controls,
            Inner::changed,
            |p| {
                if let Some(v) = p.view.borrow().as_ref() {
                    v.orbit.png(markup::PNG);
                }
            },
        )?;
        for (joint, (slider, _)) in self.sliders.iter().enumerate() {
            scope.listen_for(slider, "input", me, move |p, _| p.slide(joint))?;
        }
        for button in dom::matching(&self.root, "[data-row]")? {
            let row = button
                .get_attribute("data-row")
                .and_then(|r| r.parse::<usize>().ok())
                .unwrap_or(1);
            scope.listen_for(&button, "click", me, move |p, _| p.pick_row(row))?;
        }
        scope.listen_for(&self.cb_axes, "change", me, |p, _| {
            let mut q = p.query.get();
            q.palette = if p.cb_axes.checked() {
                AxisPalette::ColorBlindSafe
            } else {
                AxisPalette::Classic
            };
            p.query.set(q);
            p.show_palette();
            p.request_redraw();
            p.write_url();
        })?;
        Ok(())
    }

    fn command(&self, command: Command) {
        if let Some(w) = self.walk.borrow().as_ref() {
            w.stepper.apply(command);
        }
    }

    fn request_redraw(&self) {
        if let Some(v) = self.view.borrow().as_ref() {
            v.orbit.request_redraw();
        }
    }

    fn redraw_now(&self) {
        if let Some(v) = self.view.borrow().as_ref() {
            v.orbit.redraw_now();
        }
    }

    /// Slider `joint` moved: its item of `angles` is replaced and the form checked.
    fn slide(&self, joint: usize) {
        let Some((slider, _)) = self.sliders.get(joint) else {
            return;
        };
        let text = set_joint_text(
            &self.controls.text("angles"),
            &self.controls.value().q,
            joint,
            &slider.value(),
        );
        if let Some(params) = self.controls.set_text("angles", &text, false) {
            self.changed(params);
        }
    }

    /// New valid angles: pose, tables, readouts, the walk, the view (next frame), the URL.
    fn changed(&self, params: DhParams) {
        let started = now_ms();
        *self.posed.borrow_mut() = Posed::new(params);
        self.show_pose(true);
        self.show_walk(false);
        self.request_redraw();
        self.write_url();
        bench_record("__dhChangeMs", now_ms() - started);
    }

    /// The sliders, the tables and the readouts of the current pose; `announce`: say the tip's
    /// new place (not for what the page opened with, nor a language switch).
    fn show_pose(&self, announce: bool) {
        let posed = self.posed.borrow();
        let q = posed.params.q;
        for ((slider, output), qi) in self.sliders.iter().zip(q) {
            if slider.value_as_number() != qi {
                slider.set_value_as_number(qi);
            }
            output.set_text_content(Some(&format!("{} rad", cell(qi))));
        }
        self.dh_table.show(&q, self.query.get().row);
        self.pose_table.show(&posed.rows);
        // The tip is frame 3: the CSV's last row (frame, x, y, z, roll, pitch, yaw).
        let Some(tip) = posed.rows.last() else {
            return;
        };
        for (k, key) in ["x", "y", "z", "roll", "pitch", "yaw"].iter().enumerate() {
            let exact = tip.get(k + 1).map_or("", String::as_str);
            let shown = exact.parse::<f64>().map_or(String::new(), cell);
            self.readouts.set_with_value(key, &shown, exact);
        }
        if !announce {
            return;
        }
        // Said once a drag settles, formatted only then.
        let f = |k: usize| {
            tip.get(k)
                .and_then(|t| t.parse::<f64>().ok())
                .map_or(String::new(), cell)
        };
        let (x, y, z) = (f(1), f(2), f(3));
        self.readouts.announce_settled(ANNOUNCE_QUIET_MS, move || {
            ctx::t_strings("dh-live", &[("x", x), ("y", y), ("z", z)])
        });
    }

    /// The walk of the current row at the pose.
    fn row_walk(&self) -> RowWalk {
        RowWalk::new(&self.posed.borrow().params.q, self.query.get().row)
    }

    /// The walk panel; `describe` also rewrites the steps' descriptions (row or language).
    fn show_walk(&self, describe: bool) {
        let walk = self.row_walk();
        if let Some(w) = self.walk.borrow().as_ref() {
            w.show(&walk, w.step(), describe);
        }
    }

    /// Row `row` picked: its walk from the start.
    fn pick_row(&self, row: usize) {
        let mut q = self.query.get();
        q.row = row.clamp(1, JOINTS);
        self.query.set(q);
        self.tween.set(None);
        self.dh_table.show(&self.posed.borrow().params.q, q.row);
        // Reset takes the stepper to 0 and always reports it (walk_moved redraws).
        self.command(Command::Reset);
    }

    /// The stepper moved to `step`.
    fn walk_moved(&self, step: usize) {
        let from = self.tween.get().map_or_else(
            || {
                let q = self.query.get();
                q.step
            },
            |(_, to, _)| to,
        );
        let mut q = self.query.get();
        q.step = step;
        self.query.set(q);
        let adjacent = step + 1 == from || from + 1 == step;
        if self.animate.get() && adjacent && !frame::reduced_motion() {
            self.tween.set(Some((from, step, now_ms())));
        } else {
            self.tween.set(None);
        }
        self.show_walk(true);
        self.request_redraw();
        self.write_url();
    }

    fn view_changed(&self, preset: Option<Preset>) {
        if let Some(p) = preset {
            let mut q = self.query.get();
            q.view = p;
            self.query.set(q);
        }
        self.write_url();
    }

    fn show_palette(&self) {
        let _ = self
            .legend
            .set_attribute("data-palette", self.query.get().palette.id());
    }

    /// One frame of the view.
    fn draw(&self, canvas: &LayeredCanvas, camera: &Camera, ink: Ink) {
        let started = now_ms();
        let q = self.query.get();
        let walk = self.row_walk();
        let moving = match self.tween.get() {
            Some((from, to, t0)) => {
                let s = (now_ms() - t0) / TWEEN_MS;
                if s >= 1.0 {
                    self.tween.set(None);
                    Some(walk.at(to))
                } else if to == from + 1 {
                    Some(walk.between(to, s))
                } else {
                    Some(walk.between(from, 1.0 - s))
                }
            }
            None if q.step > 0 => Some(walk.at(q.step)),
            None => None,
        };
        let moving = moving.map(|pose| {
            let mut trail: Vec<_> = (0..=q.step.min(WALK_STEPS))
                .map(|k| walk.at(k).w_axis.truncate())
                .collect();
            trail.push(pose.w_axis.truncate());
            chain_view::Moving { pose, trail }
        });
        let posed = self.posed.borrow();
        let look = chain_view::Look {
            frames: &posed.frames,
            palette: q.palette,
            moving,
        };
        if let Some(v) = self.view.borrow().as_ref() {
            v.paint(canvas, camera, ink, &look);
            if self.tween.get().is_some() {
                v.orbit.request_redraw();
            }
        }
        bench_record("__dhFrameMs", now_ms() - started);
    }
}

/// Bench builds keep each draw's and each recompute's duration, ms, in `window.<name>`
/// (`__dhFrameMs`, `__dhChangeMs`; `tests/bench/dh_fk.bench.mjs` reads them).
fn bench_record(name: &str, ms: f64) {
    crate::ui::kit::bench_log::push_ms(name, ms, crate::ui::kit::bench_log::KEEP_ALL);
}

/// The page's model for its exercises.
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    lend(&PageModel::DhFk(&inner.posed.borrow().params))
}
