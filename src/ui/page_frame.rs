//! What `<main>` shows while a page's chunk is on its way: the page's frame, which is the page's
//! own head (its wrapper, heading and lede, from the page table's `head`, in the page's own
//! classes, so laid out as the page will be) with a "Loading this drill…" line and its progress;
//! and, if the chunk cannot be fetched (offline before it was cached, a missing file), a message
//! with a Retry button. Both are localized like the rest of the shell.
//!
//! When the page comes, it fills `<main>` through [`fill`], which keeps the frame's heading and
//! lede where they are and builds the rest of the page around them: what a phone painted first
//! stays the largest paint, and nothing that was shown moves.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{DocumentFragment, Element, HtmlTemplateElement, Node};

use crate::ui::dom;
use crate::ui::page::PageDef;

/// `data-testid` of the frame's outer element.
const FRAME_TESTID: &str = "page-frame";

/// The frame in `main`, if one stands there.
fn frame_in(main: &Element) -> Result<Option<Element>, JsValue> {
    main.query_selector(&format!(":scope > [data-testid=\"{FRAME_TESTID}\"]"))
}

/// Removes a frame left in `main` by a page that did not fill it through [`fill`].
pub fn remove_leftover(main: &Element) -> Result<(), JsValue> {
    if let Some(frame) = frame_in(main)? {
        frame.remove();
    }
    Ok(())
}

/// The frame of page `def` with its loading line, built into `main` (emptied first).
pub fn show_loading(main: &Element, def: &PageDef) -> Result<(), JsValue> {
    let frame = frame(main, def)?;
    let line = dom::el_class("p", "page-loading-line")?;
    line.set_attribute("role", "status")?;
    line.set_attribute("data-testid", "page-loading")?;
    dom::append(&line, &dom::el_i18n("span", "", "page-loading")?)?;
    let progress = dom::el_class("progress", "page-loading-progress")?;
    progress.set_attribute("data-testid", "page-loading-progress")?;
    progress.set_attribute("aria-hidden", "true")?;
    dom::append(&line, &progress)?;
    dom::append(&frame, &line)
}

/// Shows how much of the page's chunk has arrived (`loaded` of `total` bytes) on the loading
/// line, if it is shown.
pub fn show_progress(main: &Element, loaded: f64, total: f64) -> Result<(), JsValue> {
    if let Some(progress) = main.query_selector(".page-loading-progress")? {
        if total > 0.0 {
            progress.set_attribute("max", &format!("{total}"))?;
            progress.set_attribute("value", &format!("{}", loaded.min(total)))?;
        }
    }
    Ok(())
}

/// The frame of page `def` with the "could not be loaded" message and its Retry button
/// (`data-action="retry"`), built into `main`; returns the button. Without the page's strings
/// (`page_strings` false) the frame is only the page's title.
pub fn show_failed(main: &Element, def: &PageDef, page_strings: bool) -> Result<Element, JsValue> {
    let frame = if page_strings {
        frame(main, def)?
    } else {
        dom::clear(main);
        let frame = dom::el_class("section", "page-frame")?;
        frame.set_attribute("data-testid", FRAME_TESTID)?;
        frame.set_attribute("data-page", def.id)?;
        dom::append(&frame, &dom::el_i18n("h1", "", def.title_id)?)?;
        dom::append(main, &frame)?;
        frame
    };
    let alert = dom::el_class("div", "page-load-failed")?;
    alert.set_attribute("role", "alert")?;
    alert.set_attribute("data-testid", "page-load-failed")?;
    dom::append(&alert, &dom::el_i18n("p", "", "page-load-failed")?)?;
    let retry = retry_button()?;
    dom::append(&alert, &retry)?;
    dom::append(&frame, &alert)?;
    Ok(retry)
}

/// The Retry button of a part that could not be fetched (`data-action="retry"`).
pub fn retry_button() -> Result<Element, JsValue> {
    let retry = dom::el_i18n("button", "tool-button", "page-load-retry")?;
    retry.set_attribute("type", "button")?;
    retry.set_attribute("data-action", "retry")?;
    Ok(retry)
}

/// `status` as the line that stands in for a part of the page while its chunk loads
/// (`role="status"`, `data-state="loading"`, the message `loading_id`).
pub fn show_part_loading(status: &Element, loading_id: &str) -> Result<(), JsValue> {
    dom::clear(status);
    status.set_attribute("data-state", "loading")?;
    status.set_attribute("role", "status")?;
    dom::set_i18n(status, loading_id)
}

/// `status` says that the part could not be fetched (`role="alert"`, `data-state="failed"`,
/// the message `failed_id`) with a Retry button, which shows the loading line
/// (`loading_id`) again and calls `retry`.
pub fn show_part_failed(
    status: &Element,
    failed_id: &str,
    loading_id: &'static str,
    retry: impl Fn() + 'static,
) -> Result<(), JsValue> {
    dom::clear(status);
    status.remove_attribute("data-i18n")?;
    status.set_attribute("data-state", "failed")?;
    status.set_attribute("role", "alert")?;
    dom::append(status, &dom::el_i18n("span", "", failed_id)?)?;
    dom::append(status, &dom::el_text("span", "", " ")?)?;
    let button = retry_button()?;
    dom::append(status, &button)?;
    let again = status.clone();
    dom::Listener::new(&button, "click", move |_| {
        if show_part_loading(&again, loading_id).is_ok() {
            retry();
        }
    })?
    .forever();
    Ok(())
}

/// The page's head (`def.head`) as the frame, in `main` (emptied first), localized; returns its
/// outer element (`data-testid="page-frame"`, `data-page`).
fn frame(main: &Element, def: &PageDef) -> Result<Element, JsValue> {
    main.set_inner_html(def.head);
    let outer = main
        .first_element_child()
        .ok_or_else(|| JsValue::from_str("the page's head has no element"))?;
    outer.set_attribute("data-testid", FRAME_TESTID)?;
    outer.set_attribute("data-page", def.id)?;
    dom::relocalize(main)?;
    Ok(outer)
}

/// Fills the page root `root` with `html`: around the frame's heading and lede if the frame
/// stands there and has the page's shape ([`fill_with`]), else in place of what it holds.
pub fn fill(root: &Element, html: &str) -> Result<(), JsValue> {
    let template: HtmlTemplateElement = dom::el("template")?.dyn_into()?;
    template.set_inner_html(html);
    fill_with(root, &template.content())
}

/// Fills the page root `root` with the nodes of `content`. If `root` holds the page's frame
/// and the frame's path to its heading has the same elements as the page's (`<div>` in `<div>`
/// and so on), the frame's elements on that path, its heading and its lede (the paragraph after
/// the heading) stay in the document: they take the page's attributes and text, and the page's
/// other nodes go around them. Otherwise `root` is emptied and `content` appended.
pub fn fill_with(root: &Element, content: &DocumentFragment) -> Result<(), JsValue> {
    if let Some(frame) = frame_in(root)? {
        if adopt(root, &frame, content)? {
            return Ok(());
        }
    }
    dom::clear(root);
    root.append_child(content)?;
    Ok(())
}

/// The elements from the child of `top` down to `leaf`, top first; `None` if `leaf` is not
/// under `top`.
fn path_from(top: &Node, leaf: &Element) -> Option<Vec<Element>> {
    let mut path = vec![leaf.clone()];
    let mut at: Node = leaf.parent_node()?;
    while !at.is_same_node(Some(top)) {
        path.push(at.clone().dyn_into().ok()?);
        at = at.parent_node()?;
    }
    path.reverse();
    Some(path)
}

/// The element after `element` among its siblings, if it is a `<p>`: a head's lede.
pub fn lede_of(element: &Element) -> Option<Element> {
    element
        .next_element_sibling()
        .filter(|next| next.tag_name().eq_ignore_ascii_case("p"))
}

/// Builds the page of `content` around the frame's path to its heading (see [`fill_with`]);
/// `false` (nothing changed) if the shapes differ.
fn adopt(root: &Element, frame: &Element, content: &DocumentFragment) -> Result<bool, JsValue> {
    let (Some(old_h1), Some(new_h1)) = (frame.query_selector("h1")?, content.query_selector("h1")?)
    else {
        return Ok(false);
    };
    let (Some(old_path), Some(new_path)) = (path_from(root, &old_h1), path_from(content, &new_h1))
    else {
        return Ok(false);
    };
    let same_shape = old_path.len() == new_path.len()
        && old_path
            .iter()
            .zip(&new_path)
            .all(|(a, b)| a.tag_name() == b.tag_name());
    if !same_shape {
        return Ok(false);
    }
    // The lede is kept where both have one.
    let ledes = match (lede_of(&old_h1), lede_of(&new_h1)) {
        (Some(old), Some(new)) => Some((old, new)),
        _ => None,
    };
    // The top level: `root`'s other nodes go, `content`'s other nodes come around the path.
    let old_top: Node = old_path[0].clone().into();
    let new_top: Node = new_path[0].clone().into();
    rebuild_around(root, content, &old_top, &new_top, None)?;
    for depth in 0..old_path.len() {
        let (old, new) = (&old_path[depth], &new_path[depth]);
        take_attributes(old, new)?;
        if let (Some(old_child), Some(new_child)) =
            (old_path.get(depth + 1), new_path.get(depth + 1))
        {
            let lede = ledes.as_ref().filter(|(old_lede, _)| {
                old_lede
                    .parent_node()
                    .is_some_and(|p| p.is_same_node(Some(old)))
            });
            rebuild_around(old, new, old_child, new_child, lede)?;
        }
    }
    // The heading's and the lede's own text and children are the page's.
    replace_children(&old_h1, &new_h1)?;
    if let Some((old_lede, new_lede)) = &ledes {
        take_attributes(old_lede, new_lede)?;
        replace_children(old_lede, new_lede)?;
    }
    dom::relocalize(root)?;
    Ok(true)
}

/// In `old`, keeps `old_child` (and, right after it, the kept lede of `lede`) and puts `new`'s
/// other child nodes around it as they stand around `new_child` in `new`.
fn rebuild_around(
    old: &Node,
    new: &Node,
    old_child: &Node,
    new_child: &Node,
    lede: Option<&(Element, Element)>,
) -> Result<(), JsValue> {
    let kept_lede: Option<Node> = lede.map(|(old_lede, _)| old_lede.clone().into());
    let new_lede: Option<Node> = lede.map(|(_, new_lede)| new_lede.clone().into());
    for node in children(old) {
        let kept = node.is_same_node(Some(old_child))
            || kept_lede
                .as_ref()
                .is_some_and(|k| node.is_same_node(Some(k)));
        if !kept {
            old.remove_child(&node)?;
        }
    }
    let mut before = true;
    for node in children(new) {
        if node.is_same_node(Some(new_child)) {
            before = false;
        } else if new_lede
            .as_ref()
            .is_some_and(|l| node.is_same_node(Some(l)))
        {
            continue;
        } else if before {
            old.insert_before(&node, Some(old_child))?;
        } else {
            old.append_child(&node)?;
        }
    }
    Ok(())
}

/// The child nodes of `node`, as they are now.
fn children(node: &Node) -> Vec<Node> {
    let list = node.child_nodes();
    (0..list.length()).filter_map(|i| list.item(i)).collect()
}

/// `old` gets exactly `new`'s attributes.
fn take_attributes(old: &Element, new: &Element) -> Result<(), JsValue> {
    for name in old
        .get_attribute_names()
        .iter()
        .filter_map(|n| n.as_string())
    {
        if !new.has_attribute(&name) {
            old.remove_attribute(&name)?;
        }
    }
    for name in new
        .get_attribute_names()
        .iter()
        .filter_map(|n| n.as_string())
    {
        let value = new.get_attribute(&name).unwrap_or_default();
        if old.get_attribute(&name).as_deref() != Some(value.as_str()) {
            old.set_attribute(&name, &value)?;
        }
    }
    Ok(())
}

/// `old`'s children are `new`'s; an empty `new` (text the page localizes from `data-i18n`)
/// leaves `old`'s text, which [`dom::relocalize`] keeps when it is the same.
fn replace_children(old: &Element, new: &Element) -> Result<(), JsValue> {
    if !new.has_child_nodes() {
        return Ok(());
    }
    dom::clear(old);
    for node in children(new) {
        old.append_child(&node)?;
    }
    Ok(())
}
