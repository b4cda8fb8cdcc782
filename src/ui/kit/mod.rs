//! The page kit: what every page is built from. Each widget owns its elements, state and
//! listeners; pure parts (codecs, state machines, view models) live in [`crate::view`].
//!
//! - [`message_line`]: a line of text said from a value, hidden without one.
//! - [`page_root`]: a page's root, filled with its markup and localized; its parts by role.
//! - [`scope`]: listeners, timers, the frame loop and observers of a page, removed on drop.
//! - [`url_state`]: a page's state in the URL (read, debounced write, notice of ignored keys).
//! - [`keymap`]: the app's one keymap and the focus rule for page keys.
//! - [`stepper`]: step / back / play / scrub toolbar over a page's model; [`review`]: the
//!   Robot Pilot pages' failure review (a replayed episode under the stepper, its timeline).
//! - [`png`]: PNG export of any canvas.
//! - [`canvas`]: HiDPI layered canvases, resize watch, projector ink (line/type scale).
//! - [`frame`]: the one animation-frame loop (dirty flags, requests, animation), made by the
//!   scope; pages and the stepper run on it.
//! - [`drag`]: pointer drags (mouse, pen, touch) that leave the page scrollable.
//! - [`plot`]: line/scatter plots: panels sharing x, legend, cursor, incremental append.
//! - [`heatmap`]: colour-map heatmap with a legend.
//! - [`form`]: the ArgSpec-driven parameter form (one or several recipes' arguments);
//!   [`exports`]: downloads and command lines (one run or several); [`readouts`]:
//!   `data-readout` values and a paced `aria-live` summary.
//! - [`recipe_controls`]: form + sliders + URL + exports of a page that runs one recipe live;
//!   [`signal_page`]: the shell of such a page that plots the recipe's table (markup, mount,
//!   language/projector/resize, the plot with its drags, cursor and PNG).
//! - [`pilot_session`]: the Robot Pilot pages' repeatability table, storage-full warning and
//!   saved-files opener; [`chunk_fns`]: functions of a wasm chunk a page fetches once mounted
//!   and uses on demand (their session files); [`late_page`]: a page built only once a chunk
//!   it needs has come (a pilot page whose stored session needs the code that reads it).
//! - [`store`]: a page's work in localStorage: unreadable text moved aside, refused saves
//!   reported.
//! - [`input_file`]: a file the user opens or drops (or several), decoded as the CLI decodes it.
//! - [`exercise_slot`]: a page's exercises section, whose list is a chunk of its own
//!   ([`crate::ui::exercises`]) it shares [`exercise_link`] with; the learner's progress in
//!   the browser ([`progress_store`]) and its file's panel ([`progress_panel`]); a part with
//!   Fluent files of its own that follows the language ([`lang_follow`]); a chunk's own
//!   stylesheet, linked on first use ([`late_style`]).
//! - [`worker`]: long recipe runs in a Web Worker (same wasm), with progress and cancel.
//! - [`progress`]: the progress panel of such a run (bar, rows, time left, Cancel).
//! - [`orbit`]: a 3D view: orbit by drag, zoom by wheel/pinch/keys, preset views, a page's
//!   claimed drags, and the painter of [`crate::view::scene3d`] marks.

pub mod bench_log;
pub mod canvas;
pub mod chunk_fns;
pub mod drag;
pub mod exercise_link;
pub mod exercise_slot;
pub mod exports;
pub mod form;
pub mod frame;
pub mod heatmap;
pub mod input_file;
pub mod keymap;
pub mod lang_follow;
pub mod late_page;
pub mod late_style;
pub mod message_line;
pub mod orbit;
pub mod page_root;
pub mod pilot_control;
pub mod pilot_session;
pub mod plot;
pub mod png;
pub mod progress;
pub mod progress_panel;
pub mod progress_store;
pub mod readouts;
pub mod recipe_controls;
pub mod review;
pub mod scope;
pub mod signal_page;
pub mod stepper;
pub mod store;
pub mod url_state;
pub mod worker;
