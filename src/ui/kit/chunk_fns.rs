//! Functions from a wasm chunk that a page fetches once it is mounted and uses on demand (a
//! pilot page's session files): kept once they have come; if a fetch fails, the next use
//! fetches again. The page says a failure only when someone waited for the functions.

use std::cell::Cell;
use std::future::Future;
use std::rc::Weak;

use crate::ui::page::SplitLoaderError;

/// The chunk's functions once they are here, and whether the page says that the last fetch
/// someone waited for failed.
pub struct ChunkFns<F: Copy> {
    fns: Cell<Option<F>>,
    said_failed: Cell<bool>,
}

impl<F: Copy> Default for ChunkFns<F> {
    fn default() -> Self {
        ChunkFns {
            fns: Cell::new(None),
            said_failed: Cell::new(false),
        }
    }
}

impl<F: Copy + 'static> ChunkFns<F> {
    /// Functions already here (the page was built once their chunk had come).
    pub fn ready(fns: F) -> Self {
        ChunkFns {
            fns: Cell::new(Some(fns)),
            said_failed: Cell::new(false),
        }
    }

    /// Runs `then` on `page` with the functions: at once if they are here, else once `load`
    /// has brought them, if the page (`me`) is still there. If the fetch fails and `say` is
    /// set, `show_failed(page, true)`; once functions come after such a failure,
    /// `show_failed(page, false)`.
    pub fn with<P: 'static, L>(
        page: &P,
        me: &Weak<P>,
        of: fn(&P) -> &ChunkFns<F>,
        load: impl FnOnce() -> L + 'static,
        say: bool,
        show_failed: fn(&P, bool),
        then: impl FnOnce(&P, F) + 'static,
    ) where
        L: Future<Output = Result<F, SplitLoaderError>>,
    {
        if let Some(f) = of(page).fns.get() {
            then(page, f);
            return;
        }
        let me = me.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let loaded = load().await;
            let Some(page) = me.upgrade() else {
                return;
            };
            let cell = of(&page);
            match loaded {
                Ok(f) => {
                    cell.fns.set(Some(f));
                    if cell.said_failed.replace(false) {
                        show_failed(&page, false);
                    }
                    then(&page, f);
                }
                Err(_) if say => {
                    cell.said_failed.set(true);
                    show_failed(&page, true);
                }
                Err(_) => {}
            }
        });
    }
}
