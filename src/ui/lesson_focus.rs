//! What a presented lesson step shows: its focus section (`data-section`, see
//! [`crate::view::sections`]; without one the page's main view) brought fully into view above
//! the presenter bar, and the bar kept off it. The page comes in its own time (its chunk, its
//! second stage), so the section is looked for, and moved back into view when the layout
//! shifts under it, every tenth of a second for five seconds after the step is shown,
//! until the user scrolls, touches or clicks. A section taller than the room above the bar
//! shrinks the bar to one line (`.lesson-bar-compact`). Once the section has stood in view for
//! three ticks the bar says so: `data-focus="<id>"`. That work is a wasm chunk of
//! its own, fetched when the first step is shown: no page needs it before its first frame.
//!
//! "+ Lesson" records the section nearest the middle of the viewport (`middle_section`).

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::ui::kit::exercise_link::{EXERCISES_SECTION, PRESENT_EXERCISE_ATTR};
use crate::ui::split_point::split_point;
use crate::ui::{dom, router, schedule};
use crate::view::sections;

/// How often the section is looked for and put back in view (ms).
const TICK_MS: i32 = 100;
/// How many ticks after a step is shown (5 s: a page's chunk and its second stage land).
const SETTLE_TICKS: u32 = 50;
/// How many ticks in a row the section stands in view before the bar says it is shown.
const STABLE_TICKS: u32 = 3;
/// Room kept between the section and the viewport's top or the bar (CSS px).
const MARGIN_PX: f64 = 8.0;
/// The class of the bar shrunk to one line.
const COMPACT: &str = "lesson-bar-compact";

thread_local! {
    /// Counts the steps shown: a tick of an older step (or after a scroll) does nothing.
    static SHOWN: Cell<u64> = const { Cell::new(0) };
    /// Wheel, touch and pointer listeners while presenting: the user takes over the scroll.
    static WATCH: RefCell<Vec<dom::Listener>> = const { RefCell::new(Vec::new()) };
}

/// Lets go of the step shown: its ticks stop.
fn let_go() -> u64 {
    SHOWN.with(|shown| {
        shown.set(shown.get() + 1);
        shown.get()
    })
}

/// Brings section `focus` of `page` (its main view when `None`, or when the page has no such
/// section) into view above `bar`, once the page is there.
pub(crate) fn show(bar: &Element, page: String, focus: Option<String>) {
    let generation = let_go();
    // Said again once this step's section is in view.
    let _ = bar.remove_attribute("data-focus");
    let bar = bar.clone();
    wasm_bindgen_futures::spawn_local(async move {
        if let Ok(follow) = follower().await {
            if let Err(error) = follow(bar, page, focus, generation) {
                web_sys::console::error_2(&"BSV Playground: lesson focus".into(), &error);
            }
        }
    });
}

/// What brings a step's section into view ([`follow`]).
type FollowFn = fn(Element, String, Option<String>, u64) -> Result<(), JsValue>;

// The chunk that brings a step's section into view.
split_point!(lesson_focus, fn follower() -> FollowFn = follow);

/// [`show`] for step `generation`, once its chunk is here: looks for the section every tick
/// and keeps it in view.
fn follow(
    bar: Element,
    page: String,
    focus: Option<String>,
    generation: u64,
) -> Result<(), JsValue> {
    if SHOWN.with(Cell::get) != generation {
        return Ok(());
    }
    bar.class_list().remove_1(COMPACT)?;
    let wanted = match focus.filter(|f| sections::has(&page, f)) {
        Some(focus) => focus,
        None => match sections::main_view(&page) {
            Some(main) => main.to_owned(),
            None => return Ok(()),
        },
    };
    if WATCH.with_borrow(Vec::is_empty) {
        let window = dom::window()?;
        let listeners = ["wheel", "touchstart", "pointerdown"]
            .into_iter()
            .map(|event| {
                dom::Listener::new(&window, event, |_| {
                    let_go();
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        WATCH.with_borrow_mut(|watch| *watch = listeners);
    }
    wasm_bindgen_futures::spawn_local(async move {
        let mut stable = 0;
        for _ in 0..SETTLE_TICKS {
            schedule::sleep_ms(TICK_MS).await;
            if SHOWN.with(Cell::get) != generation {
                return;
            }
            let section = (router::current_route().page == page)
                .then(|| find(&wanted))
                .flatten();
            let in_view = section.is_some_and(|s| bring_into_view(&s, &bar).unwrap_or(false));
            stable = if in_view { stable + 1 } else { 0 };
            if stable == STABLE_TICKS {
                let _ = bar.set_attribute("data-focus", &wanted);
            }
        }
    });
    Ok(())
}

/// Presenting ended: no more ticks, no more listeners.
pub(crate) fn stop() {
    let_go();
    WATCH.with_borrow_mut(Vec::clear);
}

/// The shown section `id` of the page (`None` while it is absent or hidden); for the exercises
/// section of a step about one exercise, that exercise's card once it is there.
fn find(id: &str) -> Option<Element> {
    let document = dom::document().ok()?;
    let shown = |selector: String| {
        document
            .query_selector(&selector)
            .ok()
            .flatten()
            .filter(|e| e.get_bounding_client_rect().height() > 0.0)
    };
    let presented = document
        .document_element()
        .and_then(|root| root.get_attribute(PRESENT_EXERCISE_ATTR))
        .filter(|_| id == EXERCISES_SECTION);
    presented
        .and_then(|exercise| shown(format!("#app-main [data-exercise=\"{exercise}\"]")))
        .or_else(|| shown(format!("#app-main [data-section=\"{id}\"]")))
}

/// Scrolls `section` into the room between the viewport's top and `bar` (the least that
/// does it), shrinking the bar first when the section is taller than the room; whether it was
/// in view already.
fn bring_into_view(section: &Element, bar: &Element) -> Result<bool, JsValue> {
    let window = dom::window()?;
    let height = window.inner_height()?.as_f64().unwrap_or(0.0);
    let rect = section.get_bounding_client_rect();
    let mut bar_height = bar.get_bounding_client_rect().height();
    let classes = bar.class_list();
    if !classes.contains(COMPACT) && rect.height() > height - bar_height - 2.0 * MARGIN_PX {
        classes.add_1(COMPACT)?;
        bar_height = bar.get_bounding_client_rect().height();
    }
    // Where the bar stands once stuck to the viewport's foot (higher on a short page).
    let bar_top = height - bar_height;
    let shown_bar_top = bar.get_bounding_client_rect().top().min(bar_top);
    let in_view = rect.top() >= 0.0 && rect.bottom() <= shown_bar_top;
    let below = rect.bottom() - (bar_top - MARGIN_PX);
    let above = rect.top() - MARGIN_PX;
    let scroll = if below > 0.0 {
        below.min(above)
    } else if above < 0.0 {
        above
    } else {
        0.0
    };
    if !in_view && scroll.abs() >= 1.0 {
        window.scroll_by_with_x_and_y(0.0, scroll);
    }
    Ok(in_view)
}

/// The page's section nearest the middle of the viewport: of those across its middle line (else
/// the nearest to it), the one whose centre is nearest the middle, then the nearest sideways;
/// what "+ Lesson" records as the step's focus.
pub(crate) fn middle_section() -> Option<String> {
    let window = dom::window().ok()?;
    let x = window.inner_width().ok()?.as_f64()? / 2.0;
    let y = window.inner_height().ok()?.as_f64()? / 2.0;
    let root = dom::document().ok()?.get_element_by_id("app-main")?;
    dom::matching(&root, "[data-section]")
        .ok()?
        .into_iter()
        .filter_map(|section| {
            let r = section.get_bounding_client_rect();
            if r.width() <= 0.0 || r.height() <= 0.0 {
                return None;
            }
            let dx = (r.left() - x).max(x - r.right()).max(0.0);
            let dy = (r.top() - y).max(y - r.bottom()).max(0.0);
            let centre = ((r.top() + r.bottom()) / 2.0 - y).abs();
            let id = section.get_attribute("data-section")?;
            Some(([dy, centre, dx], id))
        })
        .min_by(|(a, _), (b, _)| {
            a.iter()
                .zip(b)
                .map(|(a, b)| a.total_cmp(b))
                .find(|o| o.is_ne())
                .unwrap_or(std::cmp::Ordering::Equal)
        })
        .map(|(_, id)| id)
}
