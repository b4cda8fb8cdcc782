//! A page built only once a wasm chunk it needs has come: a pilot page whose browser storage
//! holds a session needs the code that reads the session (in its files' chunk) before its
//! parts can be built. When nothing is stored the page is built at once and the chunk comes
//! later. Meanwhile the page's markup stands inert (`aria-busy`), its heading and lede over a
//! line saying what is loading (`role="status"`); if the chunk cannot be fetched, the line says
//! so with a Retry button (`role="alert"`), and the stored session stays stored.

use std::cell::RefCell;
use std::future::Future;
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::page::{MountCtx, ShellLink, ShellRequest, SplitLoaderError};
use crate::ui::{dom, page_frame};

/// The line's messages: while the chunk loads, and when it could not be fetched.
#[derive(Clone, Copy)]
pub struct LateTexts {
    pub loading: &'static str,
    pub failed: &'static str,
}

/// The page, once built.
pub struct LatePage<P: 'static> {
    built: Rc<RefCell<Option<P>>>,
    /// The page's root while it waits (its markup and line follow the language).
    waiting: Option<Element>,
}

/// Fetching the chunk and building the page with what it brings.
struct Job<F, L, B> {
    root: Element,
    shell: ShellLink,
    status: Element,
    texts: LateTexts,
    load: L,
    build: B,
    _fns: std::marker::PhantomData<F>,
}

impl<P: 'static> LatePage<P> {
    /// A page built at once.
    pub fn built(page: P) -> LatePage<P> {
        LatePage {
            built: Rc::new(RefCell::new(Some(page))),
            waiting: None,
        }
    }

    /// Mounts a page under `ctx.root`: built at once by `build(ctx, None)` when the chunk is
    /// not `needed` (fetching it is then the page's business), else with what `load` brings,
    /// the page's `markup()` standing inert meanwhile ([`LatePage::after`]).
    pub fn mount<F, L, Fut>(
        ctx: MountCtx,
        needed: bool,
        markup: fn() -> String,
        texts: LateTexts,
        load: L,
        build: fn(&MountCtx, Option<F>) -> Result<P, JsValue>,
    ) -> Result<LatePage<P>, JsValue>
    where
        F: 'static,
        L: Fn() -> Fut + 'static,
        Fut: Future<Output = Result<F, SplitLoaderError>> + 'static,
    {
        if !needed {
            return Ok(LatePage::built(build(&ctx, None)?));
        }
        let root = ctx.root.clone();
        page_frame::fill(&root, &markup())?;
        dom::relocalize(&root)?;
        LatePage::after(&root, ctx.shell, texts, load, move |fns| {
            build(&ctx, Some(fns))
        })
    }

    /// `root`'s markup shown inert under the loading line while `load` fetches the chunk;
    /// then the page is `build`t with what it brought (the line goes with the old markup),
    /// and the shell is told that the route is settled.
    pub fn after<F, L, Fut, B>(
        root: &Element,
        shell: ShellLink,
        texts: LateTexts,
        load: L,
        build: B,
    ) -> Result<LatePage<P>, JsValue>
    where
        F: 'static,
        L: Fn() -> Fut + 'static,
        Fut: Future<Output = Result<F, SplitLoaderError>> + 'static,
        B: Fn(F) -> Result<P, JsValue> + 'static,
    {
        let status = dom::el_class("p", "late-page")?;
        status.set_attribute("data-testid", "late-page")?;
        place_line(root, &status)?;
        inert_but(root, &status)?;
        root.set_attribute("aria-busy", "true")?;
        page_frame::show_part_loading(&status, texts.loading)?;
        let built = Rc::new(RefCell::new(None));
        let job = Rc::new(Job {
            root: root.clone(),
            shell,
            status,
            texts,
            load,
            build,
            _fns: std::marker::PhantomData,
        });
        start(job, Rc::downgrade(&built));
        Ok(LatePage {
            built,
            waiting: Some(root.clone()),
        })
    }

    /// Whether the page is built.
    pub fn is_built(&self) -> bool {
        self.built.borrow().is_some()
    }

    /// `f` of the page, if it is built.
    pub fn with<R>(&self, f: impl FnOnce(&P) -> R) -> Option<R> {
        self.built.borrow().as_ref().map(f)
    }

    /// The language changed: the page `relocalize`s itself if it is built; else the waiting
    /// markup and line are said again.
    pub fn relocalize(&self, relocalize: impl FnOnce(&P)) {
        if self.with(relocalize).is_none() {
            if let Some(root) = &self.waiting {
                let _ = dom::relocalize(root);
            }
        }
    }
}

/// Puts the line under the page's heading and its lede (where the page's frame had its loading
/// line), so that nothing painted moves; above the markup if it has no heading.
fn place_line(root: &Element, status: &Element) -> Result<(), JsValue> {
    match root.query_selector("h1")? {
        Some(heading) => page_frame::lede_of(&heading)
            .unwrap_or(heading)
            .after_with_node_1(status),
        None => root.prepend_with_node_1(status),
    }
}

/// Makes `root`'s markup inert but for `line` (its Retry is live) and the elements holding it.
fn inert_but(root: &Element, line: &Element) -> Result<(), JsValue> {
    let mut keep = line.clone();
    while let Some(parent) = keep.parent_element() {
        for part in dom::matching(&parent, ":scope > *")? {
            if !part.is_same_node(Some(&keep)) {
                part.set_attribute("inert", "")?;
            }
        }
        if parent.is_same_node(Some(root)) {
            break;
        }
        keep = parent;
    }
    Ok(())
}

/// Fetches the chunk; builds the page into `slot` (unless the page was left meanwhile), or
/// says that the chunk could not be fetched, with Retry.
fn start<P, F, L, Fut, B>(job: Rc<Job<F, L, B>>, slot: Weak<RefCell<Option<P>>>)
where
    P: 'static,
    F: 'static,
    L: Fn() -> Fut + 'static,
    Fut: Future<Output = Result<F, SplitLoaderError>> + 'static,
    B: Fn(F) -> Result<P, JsValue> + 'static,
{
    wasm_bindgen_futures::spawn_local(async move {
        let loaded = (job.load)().await;
        let Some(cell) = slot.upgrade() else {
            return;
        };
        let done = match loaded {
            Ok(fns) => {
                let _ = job.root.remove_attribute("aria-busy");
                (job.build)(fns).map(|page| *cell.borrow_mut() = Some(page))
            }
            Err(_) => {
                let again = job.clone();
                let slot = slot.clone();
                page_frame::show_part_failed(
                    &job.status,
                    job.texts.failed,
                    job.texts.loading,
                    move || start(again.clone(), slot.clone()),
                )
            }
        }
        .and_then(|()| (job.shell.request)(ShellRequest::Settled));
        if let Err(error) = done {
            web_sys::console::error_1(&error);
        }
    });
}
