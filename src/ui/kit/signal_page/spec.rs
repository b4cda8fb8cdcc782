//! What a signal page is, as data: its recipe and kernel, sliders, readouts, keys, overlays
//! and explanation ([`SignalSpec`]), and the markup the kit builds from it.
//!
//! Fluent ids it reads: `<prefix>-title`, `<prefix>-plots-title`, `<prefix>-canvas-label`,
//! `<prefix>-explain-<section>` and `<prefix>-explain-<section>-title`,
//! `<prefix>-overlay-<overlay>`, `recipe-<recipe id>-blurb`, the recipe's quirks id and the
//! `signals-*` card titles. Hooks: `data-testid="<recipe id>-canvas"` on the top canvas,
//! `data-testid="<recipe id>-computing"`, `data-<prefix>="stage"`, `data-overlay="<overlay>"`.

use web_sys::KeyboardEvent;

use super::sliced::Rows;
use super::thinned::ThinRow;
use crate::recipes::{RecipeInfo, RunRaw};
use crate::ui::kit::readouts;
use crate::ui::kit::recipe_controls::{self, Parse};
use crate::ui::page::Shortcut;
use crate::view::signal::{snap, Slider};

/// What a signal page is, as the kit needs it: arguments `P`, kernel rows `R`.
pub struct SignalSpec<P: 'static, R: 'static> {
    /// Prefix of its Fluent ids, classes and `data-<prefix>` roles (`cubic`).
    pub prefix: &'static str,
    /// The recipe it runs, its parse + validate, and its kernel's rows of valid arguments
    /// (`None` when the kernel refuses them).
    pub info: &'static RecipeInfo,
    /// Its kernel's run from command-line words (the CSV downloads).
    pub run: RunRaw,
    pub parse: Parse<P>,
    pub kernel: fn(&P) -> Option<Rows<R>>,
    /// The page's thinning hook: a row's time and plotted values pushed into the thinner
    /// (one column a value, [`crate::ui::kit::signal_page::Run::thinned`] gives them back).
    pub thin: ThinRow<R>,
    /// The file the PNG button saves.
    pub png: &'static str,
    /// Canvases in the stage: 3 (axes, data, cursor) or 4 (axes, data, marks, cursor).
    pub layers: usize,
    pub sliders: &'static [Slider],
    /// `(data-readout, label id)`, before the cursor's (`<prefix>-ro-<key>`).
    pub readouts: &'static [(&'static str, &'static str)],
    /// The explanation's sections (`<prefix>-explain-<section>`), before the quirks.
    pub explain: &'static [&'static str],
    /// The arrow keys that step an argument (`r` resets, on every page).
    pub nudges: &'static [Nudge<P>],
    /// Checkboxes over the plot, URL key = name (`1` when on), off by default.
    pub overlays: &'static [&'static str],
    /// Markup under the stage, in the plot card (notes, warnings), after the overlays.
    pub under_plot: &'static str,
    /// Markup under the readouts.
    pub under_readouts: &'static str,
}

/// Which arrows step an argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arrows {
    /// ↑ adds a step, ↓ takes one.
    UpDown,
    /// → adds a step, ← takes one.
    LeftRight,
}

impl Arrows {
    /// These arrows stepping `field` by `step` from `read`, not below `floor`; the keys'
    /// Fluent id `message_id`.
    pub const fn nudge<P>(
        self,
        message_id: &'static str,
        field: &'static str,
        read: fn(&P) -> f64,
        step: f64,
        floor: f64,
    ) -> Nudge<P> {
        Nudge {
            arrows: self,
            message_id,
            field,
            read,
            step,
            floor,
        }
    }
}

/// Two arrow keys that step argument `field` by `step` (Shift: ten steps), snapped to
/// `step`, never below `floor` (`f64::NEG_INFINITY`: no floor); `read` is its value in the
/// arguments.
pub struct Nudge<P> {
    pub arrows: Arrows,
    /// What the keys do, for the `?` overlay.
    pub message_id: &'static str,
    pub field: &'static str,
    pub read: fn(&P) -> f64,
    pub step: f64,
    pub floor: f64,
}

impl<P> Nudge<P> {
    /// The text of `field` after key `event` (of value `params`), if the key is one of its
    /// two.
    pub fn text(&self, event: &KeyboardEvent, params: &P) -> Option<String> {
        let sign = match (self.arrows, event.key().as_str()) {
            (Arrows::UpDown, "ArrowUp") | (Arrows::LeftRight, "ArrowRight") => 1.0,
            (Arrows::UpDown, "ArrowDown") | (Arrows::LeftRight, "ArrowLeft") => -1.0,
            _ => return None,
        };
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let value = (self.read)(params) + sign * (self.step * k);
        Some(snap(value.max(self.floor), self.step))
    }
}

/// The page's keys for the `?` overlay: its nudges, then reset.
pub fn shortcuts<P, R>(spec: &SignalSpec<P, R>) -> Vec<Shortcut> {
    let nudges = spec.nudges.iter().map(|n| Shortcut {
        keys: match n.arrows {
            Arrows::UpDown => "↑ ↓",
            Arrows::LeftRight => "← →",
        },
        message_id: n.message_id,
    });
    nudges
        .chain([Shortcut {
            keys: "r",
            message_id: "signals-key-reset",
        }])
        .collect()
}

/// The page's markup: head (title, blurb, URL notice), the plot card (stage, progress line,
/// overlays, notes), beside it the parameters (their sliders next to the curves they change)
/// and the readouts (the page's, then the `cursor` keys), then exports and explanation.
pub fn markup<P, R>(spec: &SignalSpec<P, R>, cursor: [&str; 4]) -> String {
    let (p, id) = (spec.prefix, spec.info.id);
    let (form, notice, exports) = recipe_controls::markup(p, spec.info, spec.png, "signals-png");
    let explain: String = spec
        .explain
        .iter()
        .map(|k| {
            format!(
                "<h3 data-i18n=\"{p}-explain-{k}-title\"></h3><p data-i18n=\"{p}-explain-{k}\"></p>"
            )
        })
        .collect();
    let cursor_labels = cursor.map(|key| format!("{p}-ro-{key}"));
    let ro: Vec<(&str, &str)> = (spec.readouts.iter().copied())
        .chain(
            cursor
                .into_iter()
                .zip(cursor_labels.iter().map(String::as_str)),
        )
        .collect();
    let under = "<canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>"
        .repeat(spec.layers.saturating_sub(1));
    let overlays = if spec.overlays.is_empty() {
        String::new()
    } else {
        let checks: String = spec
            .overlays
            .iter()
            .map(|o| format!("<label class=\"sig-check\"><input type=\"checkbox\" data-overlay=\"{o}\"><span data-i18n=\"{p}-overlay-{o}\"></span></label>"))
            .collect();
        format!("<div class=\"sig-checks\">{checks}</div>")
    };
    format!(
        "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"{p}-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"recipe-{id}-blurb\"></p>{notice}</header>\
         <div class=\"sig-top\"><section class=\"sig-card sig-plot-card\"><h2 data-i18n=\"{p}-plots-title\"></h2>\
         <div class=\"sig-stage\" data-{p}=\"stage\" data-section=\"plot\">{under}<canvas class=\"sig-layer\" \
         data-testid=\"{id}-canvas\" role=\"img\" tabindex=\"0\" data-i18n-attr=\"aria-label={p}-canvas-label\" \
         aria-describedby=\"{p}-readouts\"></canvas></div>\
         <p class=\"sig-computing\" data-{p}=\"computing\" data-testid=\"{id}-computing\" hidden></p>\
         {overlays}{under_plot}</section>\
         <div class=\"sig-side\"><section class=\"sig-card\" data-section=\"form\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section>\
         <section class=\"sig-card\" data-section=\"readouts\"><h2 data-i18n=\"signals-readouts-title\"></h2>{ro}{live}{under_readouts}</section></div></div>\
         <section class=\"sig-card\" data-section=\"exports\"><h2 data-i18n=\"signals-exports-title\"></h2>{exports}</section>\
         <section class=\"sig-card sig-explain\" data-section=\"explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"{quirks}\"></p></section></div>",
        under_plot = spec.under_plot,
        ro = readouts::markup(p, &ro),
        live = readouts::live_markup(p),
        under_readouts = spec.under_readouts,
        quirks = spec.info.quirks_id,
    )
}
