//! The part of the home page below the live arm: a tile for each in-browser page (a picture
//! its recipe's kernel draws at the defaults (`home_picture`), a label saying what it shows,
//! its title), one card per recipe (title, picture, description; behind one disclosure the
//! live page that pairs with it, its inputs with their defaults, the files it writes and the
//! `bsv` and `python` command lines; links to run it in the browser), then the seed's "Compare
//! the tools" table with the official links (outbound only). Drawing the pictures runs every
//! recipe's kernel, so this part is a wasm chunk of its own, fetched once the arm is live
//! (`home.rs`), and the learner's progress on the exercises at the foot (`home_progress`).
//! Everything about a recipe (labels, defaults, limits, the live page that pairs
//! with it) comes from its facts (`RecipeInfo`, `ArgSpec`).

use wasm_bindgen::prelude::*;
use web_sys::Element;

use super::home_picture;
use super::home_progress::{self, Keep};
use crate::args::ArgSpec;
use crate::recipes::{RecipeInfo, RECIPES};
use crate::ui::command_line::shell_word;
use crate::ui::ctx;
use crate::ui::dom::{append, el, el_class, el_i18n, el_text};
use crate::ui::page::{PageDef, ShellLink};
use crate::ui::router::{self, HOME_ID};

/// Builds the tiles, the recipe cards and the tools table into `root`, before `status` (the
/// line that stood in for them, removed once they are all in), one part per task so that no
/// task is long on a phone, then draws the pictures; the learner's progress comes last, at the
/// foot (`home_progress`), held by `keep`. Each part goes below the ones before it: nothing
/// shown moves.
pub fn build(
    root: &Element,
    status: &Element,
    shell: ShellLink,
    keep: &Keep,
) -> Result<(), JsValue> {
    let tiles = el_class("ul", "tile-grid")?;
    tiles.set_attribute("data-testid", "home-tiles")?;
    crate::ui::dom::set_i18n_attrs(&tiles, &[("aria-label", "home-tiles-label")])?;
    crate::ui::dom::mark_section(&tiles, "drills")?;
    for def in shell.pages.iter().filter(|d| d.id != HOME_ID) {
        let item = el("li")?;
        append(&item, &featured_card(def)?)?;
        append(&tiles, &item)?;
    }
    root.insert_before(&tiles, Some(status))?;
    let (root, status, keep) = (root.clone(), status.clone(), keep.clone());
    wasm_bindgen_futures::spawn_local(async move {
        if let Err(error) = build_rest(&root, &status, shell, &keep).await {
            web_sys::console::error_1(&error);
        }
    });
    Ok(())
}

/// The recipe cards (in two parts) and the tools table, each in a later task while the home
/// page stands (`status` still in `root`), then the pictures.
async fn build_rest(
    root: &Element,
    status: &Element,
    shell: ShellLink,
    keep: &Keep,
) -> Result<(), JsValue> {
    let here = || root.contains(Some(status));
    crate::ui::schedule::next_task().await;
    if !here() {
        return Ok(());
    }
    let recipes = el_class("section", "recipes")?;
    recipes.set_attribute("aria-labelledby", "recipes-heading")?;
    crate::ui::dom::mark_section(&recipes, "recipes")?;
    let heading = el_i18n("h2", "", "home-recipes-heading")?;
    heading.set_id("recipes-heading");
    append(&recipes, &heading)?;
    append(
        &recipes,
        &el_i18n("p", "section-intro", "home-recipes-intro")?,
    )?;
    let grid = el_class("ol", "recipe-grid")?;
    append(&recipes, &grid)?;
    let (first, second) = RECIPES.split_at(RECIPES.len() / 2);
    for recipe in first {
        append(&grid, &recipe_card(recipe.info, shell)?)?;
    }
    root.insert_before(&recipes, Some(status))?;
    crate::ui::schedule::next_task().await;
    if !here() {
        return Ok(());
    }
    for recipe in second {
        append(&grid, &recipe_card(recipe.info, shell)?)?;
    }
    crate::ui::schedule::next_task().await;
    if !here() {
        return Ok(());
    }
    let tools = tools_section()?;
    root.insert_before(&tools, Some(status))?;
    status.remove();
    home_picture::draw_all(root)?;
    home_progress::build(root, shell, keep);
    Ok(())
}

/// The seed's "Compare the tools" table: each tool's key (its Fluent ids are
/// `home-tool-<key>-{name,job,licence,difficulty,where}`) and its official address. The links
/// go out; the app fetches nothing from them.
const TOOLS: [(&str, &str); 7] = [
    ("mujoco", "https://mujoco.org/"),
    ("mujoco-docs", "https://mujoco.readthedocs.io/"),
    ("numpy", "https://numpy.org/"),
    ("isaac-lab", "https://isaac-sim.github.io/IsaacLab/"),
    ("isaac-teleop", "https://isaac-sim.github.io/IsaacLab/v2.3.0/source/overview/imitation-learning/teleop_imitation.html"),
    ("ros2", "https://docs.ros.org/"),
    ("robot-web-tools", "https://robotwebtools.github.io/"),
];

/// The tools table, with a caption and column headers for screen readers.
fn tools_section() -> Result<Element, JsValue> {
    let section = el_class("section", "tools")?;
    section.set_attribute("aria-labelledby", "tools-heading")?;
    section.set_attribute("data-testid", "tools")?;
    crate::ui::dom::mark_section(&section, "tools")?;
    let heading = el_i18n("h2", "", "home-tools-title")?;
    heading.set_id("tools-heading");
    append(&section, &heading)?;
    append(
        &section,
        &el_i18n("p", "section-intro", "home-tools-intro")?,
    )?;
    let wrap = el_class("div", "tools-wrap")?;
    let table = el_class("table", "tools-table")?;
    append(&table, &el_i18n("caption", "", "home-tools-caption")?)?;
    let head = el("thead")?;
    let row = el("tr")?;
    for col in ["tool", "job", "licence", "difficulty", "where"] {
        let th = el_i18n("th", "", &format!("home-tools-col-{col}"))?;
        th.set_attribute("scope", "col")?;
        append(&row, &th)?;
    }
    append(&head, &row)?;
    append(&table, &head)?;
    let body = el("tbody")?;
    for (key, href) in TOOLS {
        let row = el("tr")?;
        row.set_attribute("data-tool", key)?;
        let th = el("th")?;
        th.set_attribute("scope", "row")?;
        let link = el_i18n("a", "", &format!("home-tool-{key}-name"))?;
        link.set_attribute("href", href)?;
        link.set_attribute("rel", "noopener noreferrer")?;
        link.set_attribute("target", "_blank")?;
        append(&th, &link)?;
        let note = el_i18n("span", "visually-hidden", "home-tools-external")?;
        append(&link, &note)?;
        append(&row, &th)?;
        for col in ["job", "licence", "difficulty", "where"] {
            append(&row, &el_i18n("td", "", &format!("home-tool-{key}-{col}"))?)?;
        }
        append(&body, &row)?;
    }
    append(&table, &body)?;
    append(&wrap, &table)?;
    append(&section, &wrap)?;
    Ok(section)
}

/// The tile of an in-browser page: the picture its (first) recipe draws (the Robot Pilot
/// pages: their scenes at the start), a label saying what the page shows
/// (`home-featured-label-<page id>`, where the page has one), its title with an arrow.
fn featured_card(def: &PageDef) -> Result<Element, JsValue> {
    let card = el_class("a", "featured-card")?;
    card.set_attribute("href", &router::build_hash(def.id, &[]))?;
    card.set_attribute("data-testid", &format!("featured-{}", def.id))?;
    let recipe = RECIPES.iter().find(|r| r.info.page == Some(def.id));
    if recipe.is_some() || home_picture::has_scene(def.id) {
        let recipe_id = recipe.map(|r| r.info.id);
        append(&card, &home_picture::tile_canvas(def.id, recipe_id)?)?;
    }
    let label_id = format!("home-featured-label-{}", def.id);
    if ctx::has_message(&label_id) {
        append(&card, &el_i18n("span", "featured-label", &label_id)?)?;
    }
    let title = el_class("span", "featured-title")?;
    append(&title, &el_i18n("span", "", def.title_id)?)?;
    let arrow = el_text("span", "arrow", "\u{a0}→")?;
    arrow.set_attribute("aria-hidden", "true")?;
    append(&title, &arrow)?;
    append(&card, &title)?;
    Ok(card)
}

fn recipe_card(info: &RecipeInfo, shell: ShellLink) -> Result<Element, JsValue> {
    let id = info.id;
    let item = el_class("li", "recipe-card")?;
    item.set_attribute("data-testid", &format!("recipe-card-{id}"))?;
    item.set_attribute("data-recipe", id)?;
    append(&item, &el_i18n("h3", "", &info.title_id())?)?;
    append(&item, &home_picture::canvas(id)?)?;
    let blurb = el_i18n("p", "blurb", &info.blurb_id())?;
    // The picture's text alternative (`aria-describedby` of its canvas).
    blurb.set_id(&home_picture::blurb_id(id));
    append(&item, &blurb)?;
    // The rest (the live page it pairs with, inputs, options, files, command lines) behind
    // one disclosure.
    let more = el_class("details", "recipe-more")?;
    more.set_attribute("data-testid", &format!("recipe-more-{id}"))?;
    append(&more, &el_i18n("summary", "", "home-card-more")?)?;
    // The live page that runs it (from the recipe's facts): "Pairs with … →", linked.
    let live_page = info.page.and_then(|id| shell.find(id));
    if let Some(def) = live_page {
        let pairs = el_class("p", "recipe-pairs")?;
        append(
            &pairs,
            &el_i18n("span", "label", &format!("home-card-pairs-{}", def.id))?,
        )?;
        append(&pairs, &el_text("span", "", " ")?)?;
        append(
            &pairs,
            &card_link(
                &router::build_hash(def.id, &[]),
                def.title_id,
                &format!("recipe-pairs-{id}"),
            )?,
        )?;
        append(&more, &pairs)?;
    }

    if !info.args.is_empty() {
        append(&more, &el_i18n("h4", "", "home-card-inputs")?)?;
        append(&more, &arg_list(id, info.args, false)?)?;
    }
    if !info.flags.is_empty() {
        let details = el_class("details", "recipe-options")?;
        append(&details, &el_i18n("summary", "", "home-card-options")?)?;
        append(&details, &arg_list(id, info.flags, true)?)?;
        append(&more, &details)?;
    }
    if !info.writes.is_empty() {
        let writes = el_class("p", "recipe-writes")?;
        append(&writes, &el_i18n("span", "label", "home-card-writes")?)?;
        for file in info.writes {
            append(&writes, &el_text("code", "", file)?)?;
        }
        append(&more, &writes)?;
    }

    let commands = el_class("div", "commands")?;
    let args = default_command_args(info.args);
    append(
        &commands,
        &command_line("home-card-cli", &format!("bsv {id}"), &args, "cli")?,
    )?;
    append(
        &commands,
        &command_line(
            "home-card-python",
            &format!("python {}", info.python),
            &args,
            "python",
        )?,
    )?;
    append(&more, &commands)?;
    append(&item, &more)?;

    let links = el_class("p", "card-link")?;
    append(&links, &el_i18n("span", "label", "home-card-in-browser")?)?;
    append(&links, &drill_link(id)?)?;
    if let Some(def) = live_page {
        append(&links, &el_text("span", "sep", " · ")?)?;
        append(
            &links,
            &card_link(
                &router::build_hash(def.id, &[]),
                def.title_id,
                &format!("recipe-link-{id}"),
            )?,
        )?;
    }
    append(&item, &links)?;
    Ok(item)
}

/// "Run this drill", with the recipe's title for screen readers (whose list of links would
/// otherwise hold twelve identical "Run this drill" entries).
fn drill_link(id: &str) -> Result<Element, JsValue> {
    let link = card_link(
        &router::drill_hash(id),
        "home-card-drill",
        &format!("recipe-drill-{id}"),
    )?;
    let which = el_class("span", "visually-hidden")?;
    append(&which, &el_text("span", "", ": ")?)?;
    append(&which, &el_i18n("span", "", &format!("recipe-{id}-title"))?)?;
    if let Some(arrow) = link.last_element_child() {
        link.insert_before(&which, Some(&arrow))?;
    }
    Ok(link)
}

/// One link at the foot of a recipe card: its title and an arrow.
fn card_link(href: &str, title_id: &str, test_id: &str) -> Result<Element, JsValue> {
    let link = el("a")?;
    link.set_attribute("href", href)?;
    link.set_attribute("data-testid", test_id)?;
    append(&link, &el_i18n("span", "title", title_id)?)?;
    let arrow = el_text("span", "arrow", "\u{a0}→")?;
    arrow.set_attribute("aria-hidden", "true")?;
    append(&link, &arrow)?;
    Ok(link)
}

/// `<dl>`: the localized label of each argument (or `--flag`), its default and, from the
/// recipe's facts, the hint that states its limits.
fn arg_list(recipe_id: &str, specs: &[ArgSpec], flags: bool) -> Result<Element, JsValue> {
    let list = el_class("dl", "recipe-args")?;
    for spec in specs {
        let term = el("dt")?;
        if flags {
            append(&term, &el_text("code", "", &format!("--{} ", spec.name))?)?;
        }
        append(
            &term,
            &el_i18n("span", "", &spec.label_id(recipe_id, flags))?,
        )?;
        append(&list, &term)?;
        let value = el("dd")?;
        let shown = if spec.default.is_empty() {
            "—"
        } else {
            spec.default
        };
        append(&value, &el_text("code", "", shown)?)?;
        if !spec.hint_id.is_empty() {
            append(&value, &el_text("span", "", " ")?)?;
            append(&value, &el_i18n("small", "arg-hint", spec.hint_id)?)?;
        }
        append(&list, &value)?;
    }
    Ok(list)
}

/// The defaults as command-line words, up to the first argument without a default (it cannot
/// be skipped positionally).
fn default_command_args(specs: &[ArgSpec]) -> Vec<String> {
    specs
        .iter()
        .take_while(|spec| !spec.default.is_empty())
        .map(|spec| shell_word(spec.default))
        .collect()
}

/// A labelled command line: "Command line  `bsv ik-workspace 0.12 0.10 200 10`".
fn command_line(
    label_id: &str,
    program: &str,
    args: &[String],
    kind: &str,
) -> Result<Element, JsValue> {
    let row = el_class("div", "command")?;
    row.set_attribute("data-command", kind)?;
    append(&row, &el_i18n("span", "label", label_id)?)?;
    let mut text = program.to_string();
    for arg in args {
        text.push(' ');
        text.push_str(arg);
    }
    let code = el_text("code", "", &text)?;
    append(&row, &code)?;
    Ok(row)
}
