//! "Show one row": the kit stepper over the four elementary transforms of the row picked
//! (Rx(α), Tx(a), Rz(θ), Tz(d), in that order), the list of the four with the current one
//! marked, the current elementary matrix and the product so far (from frame i−1 to the moving
//! frame; after the fourth step it is the row's link transform).

use std::cell::RefCell;
use std::rc::Rc;

use glam::DMat4;
use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::i18n::FluentArg;
use crate::ui::kit::stepper::{Length, Speed, StepModel, StepperOptions, StepperWidget};
use crate::ui::{ctx, dom};
use crate::view::dh_fk::{cell, Elementary, RowWalk, WALK_STEPS};

/// The stepper's model: the steps done in the row (0..=4).
#[derive(Debug, Default)]
pub struct WalkModel {
    pub step: u64,
}

impl StepModel for WalkModel {
    fn length(&self) -> Length {
        Length::Finite(WALK_STEPS as u64)
    }
    fn go_to(&mut self, index: u64) {
        self.step = index.min(WALK_STEPS as u64);
    }
}

/// Steps per second offered while playing (the first is the default).
const SPEEDS: [f64; 3] = [1.0, 0.5, 2.0];

/// The panel.
pub struct WalkPanel {
    pub model: Rc<RefCell<WalkModel>>,
    pub stepper: StepperWidget<WalkModel>,
    /// Per step: the list item, its symbol and its text.
    steps: Vec<(Element, Element, Element)>,
    where_text: Element,
    elementary: (Element, Vec<Element>),
    product: (Element, Vec<Element>),
}

fn matrix_cells(root: &Element, name: &str) -> Result<(Element, Vec<Element>), JsValue> {
    let caption = dom::find(root, &format!("[data-dh=\"{name}-caption\"]"), "dh")?;
    let table: Element = dom::find(root, &format!("[data-testid=\"dh-fk-{name}\"]"), "dh")?;
    let mut cells = Vec::new();
    for r in 0..4 {
        for c in 0..4 {
            cells.push(dom::find(&table, &format!("[data-rc=\"{r}{c}\"]"), "dh")?);
        }
    }
    Ok((caption, cells))
}

fn show_matrix(cells: &[Element], m: &DMat4) {
    for r in 0..4 {
        for c in 0..4 {
            let text = cell(m.col(c)[r]);
            let el = &cells[r * 4 + c];
            if el.text_content().as_deref() != Some(text.as_str()) {
                el.set_text_content(Some(&text));
            }
        }
    }
}

impl WalkPanel {
    /// Finds the panel under `root`, the stepper built in its slot; `on_change(step)` runs
    /// after every move.
    pub fn new(root: &Element, on_change: impl Fn(u64) + 'static) -> Result<WalkPanel, JsValue> {
        let slot: Element = dom::find(root, "[data-dh=\"stepper\"]", "dh")?;
        let model = Rc::new(RefCell::new(WalkModel::default()));
        let stepper = StepperWidget::new(
            &slot,
            model.clone(),
            StepperOptions {
                speeds: SPEEDS.iter().map(|&r| Speed::PerSecond(r)).collect(),
                initial_speed: 0,
                speed_label: Box::new(crate::ui::kit::stepper::default_speed_label),
                testid: "dh-fk-stepper",
            },
            on_change,
        )?;
        let mut steps = Vec::new();
        for k in 1..=WALK_STEPS {
            let li: Element = dom::find(root, &format!("[data-step=\"{k}\"]"), "dh")?;
            let symbol = dom::find(&li, ".dh-step-symbol", "dh")?;
            let text = dom::find(&li, ".dh-step-text", "dh")?;
            steps.push((li, symbol, text));
        }
        Ok(WalkPanel {
            model,
            stepper,
            steps,
            where_text: dom::find(root, "[data-dh=\"walk-where\"]", "dh")?,
            elementary: matrix_cells(root, "elementary")?,
            product: matrix_cells(root, "product")?,
        })
    }

    /// The steps done.
    pub fn step(&self) -> usize {
        self.model.try_borrow().map_or(0, |m| m.step as usize)
    }

    /// Shows `walk` after `step` steps, in the current language. The steps' descriptions
    /// depend only on the row and the language: `describe` rewrites them (a new row, a
    /// language switch), else only the numbers change.
    pub fn show(&self, walk: &RowWalk, step: usize, describe: bool) {
        let row = walk.row;
        let prev = row - 1;
        let num = |x: usize| FluentArg::Number(x as f64);
        for (k, (li, symbol, text)) in self.steps.iter().enumerate() {
            let kind = Elementary::ALL[k];
            let amount = walk.amount(k + 1);
            let unit = if kind.is_rotation() { "rad" } else { "m" };
            let shown = format!("{} = {} {unit}", kind.symbol(row), cell(amount));
            if symbol.text_content().as_deref() != Some(shown.as_str()) {
                symbol.set_text_content(Some(&shown));
            }
            if describe {
                text.set_text_content(Some(&ctx::t_args(
                    &format!("dh-step-{}", kind.id()),
                    &[("prev", num(prev)), ("row", num(row))],
                )));
            }
            let state = if k + 1 == step {
                "current"
            } else if k + 1 < step {
                "done"
            } else {
                "todo"
            };
            let _ = li.set_attribute("data-state", state);
            if k + 1 == step {
                let _ = li.set_attribute("aria-current", "step");
            } else {
                let _ = li.remove_attribute("aria-current");
            }
        }
        if describe {
            self.show_where(row, step);
        }
        let (caption, cells) = &self.elementary;
        if step == 0 {
            if describe {
                caption.set_text_content(Some(&ctx::t("dh-elementary-none")));
            }
            show_matrix(cells, &DMat4::IDENTITY);
        } else {
            let k = step.min(WALK_STEPS);
            if describe {
                caption.set_text_content(Some(&ctx::t_strings(
                    "dh-elementary-caption",
                    &[
                        ("k", k.to_string()),
                        ("symbol", Elementary::ALL[k - 1].symbol(row)),
                    ],
                )));
            }
            show_matrix(cells, &walk.elementary(k));
        }
        let (caption, cells) = &self.product;
        if describe {
            caption.set_text_content(Some(&ctx::t_args(
                if step >= WALK_STEPS {
                    "dh-product-done"
                } else {
                    "dh-product-caption"
                },
                &[("prev", num(prev)), ("row", num(row))],
            )));
        }
        show_matrix(cells, &walk.local(step));
    }

    /// Where the walk is, in words.
    fn show_where(&self, row: usize, step: usize) {
        let prev = row - 1;
        let num = |x: usize| FluentArg::Number(x as f64);
        let where_text = match step {
            0 => ctx::t_args(
                "dh-walk-at-start",
                &[("prev", num(prev)), ("row", num(row))],
            ),
            s if s >= WALK_STEPS => ctx::t_args("dh-walk-at-end", &[("row", num(row))]),
            s => ctx::t_strings(
                "dh-walk-at-step",
                &[
                    ("k", s.to_string()),
                    ("symbol", Elementary::ALL[s - 1].symbol(row)),
                ],
            ),
        };
        self.where_text.set_text_content(Some(&where_text));
    }

    /// The stepper's labels in the current language.
    pub fn relocalize(&self) {
        self.stepper.relocalize();
    }
}
