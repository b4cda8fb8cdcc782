//! Fluent bundles embedded from `locales/`, language choice and per-message fallback ja → en.
//!
//! Every `.ftl` file of both languages is compiled in with `include_str!` for the tests, the
//! CLI and Node; each language's files are one table ([`locale_files`]). The browser app
//! fetches the files it needs instead and adds them one by one ([`I18n::add_files`]): the
//! ones every page needs ([`FIRST_FILES`]) and each page's own when it is first shown. [`I18n::t`] formats a message from one language's bundle; a message missing in
//! Japanese falls back to English, a message missing in both shows its id, and each such gap
//! (and each formatting error) is noted once and handed out by [`I18n::take_warnings`], which
//! the browser logs with `console.warn`. Bidi isolation marks are off
//! (`set_use_isolating(false)`) because strings are also drawn on canvas, where U+2068/U+2069
//! would show as boxes. Japanese has only the plural category `other`, so its messages need
//! no `[one]` variants.
//!
//! No web-sys: this module compiles and is tested natively.

use std::cell::{Ref, RefCell};
use std::collections::BTreeSet;

use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};
use unic_langid::subtags::Language;
use unic_langid::LanguageIdentifier;

use crate::error::RecipeError;

/// A language of the UI.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Lang {
    En,
    Ja,
}

impl Lang {
    /// Both languages, English (the fallback) first.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Ja];

    /// The BCP 47 code: `"en"` or `"ja"` (used in `?lang=`, `<html lang>` and localStorage).
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Ja => "ja",
        }
    }

    /// The language of a tag such as `"ja"`, `"ja-JP"`, `"EN_us"`; `None` for any other
    /// language.
    pub fn parse(tag: &str) -> Option<Lang> {
        let primary = tag.trim().split(['-', '_']).next().unwrap_or("");
        if primary.eq_ignore_ascii_case("en") {
            Some(Lang::En)
        } else if primary.eq_ignore_ascii_case("ja") {
            Some(Lang::Ja)
        } else {
            None
        }
    }

    /// The other language (what the language switch offers).
    pub fn other(self) -> Lang {
        match self {
            Lang::En => Lang::Ja,
            Lang::Ja => Lang::En,
        }
    }

    /// The language's name in itself: `"English"`, `"日本語"`.
    pub fn native_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Ja => "日本語",
        }
    }
}

/// Both languages have the same files with the same message ids; [`locale_files`] names
/// each language's. They are two tables, so that a build that loads one language on demand
/// (the browser app) holds each language's text apart.
/// The Fluent files of English: file name, text.
#[rustfmt::skip]
pub const EN_FILES: &[(&str, &str)] = &[
    ("shell.ftl", include_str!("../locales/en/shell.ftl")),
    ("pages.ftl", include_str!("../locales/en/pages.ftl")),
    ("home.ftl", include_str!("../locales/en/home.ftl")),
    ("errors.ftl", include_str!("../locales/en/errors.ftl")),
    ("recipes.ftl", include_str!("../locales/en/recipes.ftl")),
    ("ik2r.ftl", include_str!("../locales/en/ik2r.ftl")),
    ("drills.ftl", include_str!("../locales/en/drills.ftl")),
    ("kit.ftl", include_str!("../locales/en/kit.ftl")),
    ("lesson.ftl", include_str!("../locales/en/lesson.ftl")),
    ("pendulum.ftl", include_str!("../locales/en/pendulum.ftl")),
    ("rrt.ftl", include_str!("../locales/en/rrt.ftl")),
    ("se3.ftl", include_str!("../locales/en/se3.ftl")),
    ("signals.ftl", include_str!("../locales/en/signals.ftl")),
    ("traj.ftl", include_str!("../locales/en/traj.ftl")),
    ("dh.ftl", include_str!("../locales/en/dh.ftl")),
    ("umeyama.ftl", include_str!("../locales/en/umeyama.ftl")),
    ("teleop.ftl", include_str!("../locales/en/teleop.ftl")),
    ("so101.ftl", include_str!("../locales/en/so101.ftl")),
    ("exercises.ftl", include_str!("../locales/en/exercises.ftl")),
    ("progress.ftl", include_str!("../locales/en/progress.ftl")),
];

/// The Fluent files of Japanese: file name, text.
#[rustfmt::skip]
pub const JA_FILES: &[(&str, &str)] = &[
    ("shell.ftl", include_str!("../locales/ja/shell.ftl")),
    ("pages.ftl", include_str!("../locales/ja/pages.ftl")),
    ("home.ftl", include_str!("../locales/ja/home.ftl")),
    ("errors.ftl", include_str!("../locales/ja/errors.ftl")),
    ("recipes.ftl", include_str!("../locales/ja/recipes.ftl")),
    ("ik2r.ftl", include_str!("../locales/ja/ik2r.ftl")),
    ("drills.ftl", include_str!("../locales/ja/drills.ftl")),
    ("kit.ftl", include_str!("../locales/ja/kit.ftl")),
    ("lesson.ftl", include_str!("../locales/ja/lesson.ftl")),
    ("pendulum.ftl", include_str!("../locales/ja/pendulum.ftl")),
    ("rrt.ftl", include_str!("../locales/ja/rrt.ftl")),
    ("se3.ftl", include_str!("../locales/ja/se3.ftl")),
    ("signals.ftl", include_str!("../locales/ja/signals.ftl")),
    ("traj.ftl", include_str!("../locales/ja/traj.ftl")),
    ("dh.ftl", include_str!("../locales/ja/dh.ftl")),
    ("umeyama.ftl", include_str!("../locales/ja/umeyama.ftl")),
    ("teleop.ftl", include_str!("../locales/ja/teleop.ftl")),
    ("so101.ftl", include_str!("../locales/ja/so101.ftl")),
    ("exercises.ftl", include_str!("../locales/ja/exercises.ftl")),
    ("progress.ftl", include_str!("../locales/ja/progress.ftl")),
];

/// The name of every Fluent file (each language has the same files).
pub const FILE_NAMES: &[&str] = &[
    "shell.ftl",
    "pages.ftl",
    "home.ftl",
    "errors.ftl",
    "recipes.ftl",
    "ik2r.ftl",
    "drills.ftl",
    "kit.ftl",
    "lesson.ftl",
    "pendulum.ftl",
    "rrt.ftl",
    "se3.ftl",
    "signals.ftl",
    "traj.ftl",
    "dh.ftl",
    "umeyama.ftl",
    "teleop.ftl",
    "so101.ftl",
    "exercises.ftl",
    "progress.ftl",
];

/// The kernels' errors and warnings in both languages (what the Web Worker formats).
pub const ERROR_SOURCES: &[(Lang, &str, &str)] = &[
    (
        Lang::En,
        "errors.ftl",
        include_str!("../locales/en/errors.ftl"),
    ),
    (
        Lang::Ja,
        "errors.ftl",
        include_str!("../locales/ja/errors.ftl"),
    ),
];

/// The files every page needs before its first frame: the shell (with the lesson bar), the
/// page table's titles and descriptions, the kit and the kernels' errors. A page names the rest
/// it needs in its `page!` line (its own file, the signal pages' shared one, and the recipes'
/// texts on every page but the two pilot pages, which show none of them).
pub const FIRST_FILES: &[&str] = &["shell.ftl", "pages.ftl", "kit.ftl", "errors.ftl"];

/// The Fluent files of `lang`: file name, text.
pub fn locale_files(lang: Lang) -> &'static [(&'static str, &'static str)] {
    match lang {
        Lang::En => EN_FILES,
        Lang::Ja => JA_FILES,
    }
}

/// One argument of a message: text, or a number (numbers select plural variants such as
/// `[one]` in English and are printed without trailing zeros: `2`, `0.12`).
#[derive(Debug, Clone, PartialEq)]
pub enum FluentArg {
    Text(String),
    Number(f64),
}

impl From<&str> for FluentArg {
    fn from(text: &str) -> Self {
        FluentArg::Text(text.to_string())
    }
}

impl From<String> for FluentArg {
    fn from(text: String) -> Self {
        FluentArg::Text(text)
    }
}

impl From<&String> for FluentArg {
    fn from(text: &String) -> Self {
        FluentArg::Text(text.clone())
    }
}

macro_rules! number_arg {
    ($($t:ty),*) => {$(
        impl From<$t> for FluentArg {
            fn from(value: $t) -> Self {
                FluentArg::Number(value as f64)
            }
        }
    )*};
}
number_arg!(f64, f32, i32, i64, u32, u64, usize);

impl FluentArg {
    fn to_value(&self) -> FluentValue<'static> {
        match self {
            FluentArg::Text(text) => FluentValue::from(text.clone()),
            FluentArg::Number(value) => FluentValue::from(*value),
        }
    }
}

/// How many bytes of a Fluent file [`I18n::build_next`] parses at most in one call (a file is
/// cut into pieces of about this size where an entry starts; an entry is never cut): a few
/// milliseconds on a slow phone.
const PIECE_BYTES: usize = 4096;

/// `text` cut where a line starts an entry (a message or a term: an identifier at the start of
/// a line; what continues an entry is indented or closes a placeable), into pieces of at least
/// `max` bytes but the last. The pieces, parsed one after the other into one bundle, give the
/// messages and terms of the whole.
fn pieces(text: &str, max: usize) -> Vec<&str> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut at = 0;
    while let Some(newline) = text[at..].find('\n') {
        at += newline + 1;
        let starts_entry = match text.as_bytes()[at..] {
            [b'-', c, ..] | [c, ..] => c.is_ascii_alphabetic(),
            [] => false,
        };
        if at - start >= max && starts_entry {
            out.push(&text[start..at]);
            start = at;
        }
    }
    if start < text.len() || out.is_empty() {
        out.push(&text[start..]);
    }
    out
}

/// The Fluent bundles of the languages added so far, plus the notes about missing messages
/// and formatting errors not yet handed out.
pub struct I18n {
    /// Each language's bundle, built from its files on the language's first use (and grown
    /// by the files added after), so that a page in one language never parses the other's
    /// files (about half of the app's start).
    en: RefCell<Option<FluentBundle<FluentResource>>>,
    ja: RefCell<Option<FluentBundle<FluentResource>>>,
    /// The files (language, name, text) added and not in their bundle yet.
    sources: RefCell<Vec<(Lang, String, String)>>,
    /// The files (language, name) added: a message is looked up only in languages with one.
    added: RefCell<BTreeSet<(Lang, String)>>,
    /// Every note ever made (so each is made once).
    noted: RefCell<BTreeSet<String>>,
    /// Notes not yet taken by [`I18n::take_warnings`].
    pending: RefCell<Vec<String>>,
}

impl Default for I18n {
    fn default() -> Self {
        I18n::new()
    }
}

impl I18n {
    /// The bundles of both languages' files ([`locale_files`]), each built on its language's
    /// first use.
    pub fn new() -> I18n {
        let i18n = I18n::empty();
        for lang in Lang::ALL {
            i18n.add_files(lang, locale_files(lang));
        }
        i18n
    }

    /// No language yet: every message shows its id until a language is added.
    pub fn empty() -> I18n {
        I18n {
            en: RefCell::new(None),
            ja: RefCell::new(None),
            sources: RefCell::new(Vec::new()),
            added: RefCell::new(BTreeSet::new()),
            noted: RefCell::new(BTreeSet::new()),
            pending: RefCell::new(Vec::new()),
        }
    }

    /// Bundles of the given `(language, file name, text)` sources, each built on its
    /// language's first use.
    pub fn from_sources(sources: &[(Lang, &str, &str)]) -> I18n {
        let i18n = I18n::empty();
        for lang in Lang::ALL {
            let files: Vec<(&str, &str)> = sources
                .iter()
                .filter(|(l, _, _)| *l == lang)
                .map(|(_, file, text)| (*file, *text))
                .collect();
            i18n.add_files(lang, &files);
        }
        i18n
    }

    /// Adds `lang`'s files (file name, text) to its bundle, on the bundle's next use. A file
    /// added twice keeps its first text.
    pub fn add_files(&self, lang: Lang, files: &[(&str, &str)]) {
        let (Ok(mut added), Ok(mut sources)) =
            (self.added.try_borrow_mut(), self.sources.try_borrow_mut())
        else {
            return;
        };
        for (file, text) in files {
            if added.insert((lang, file.to_string())) {
                for piece in pieces(text, PIECE_BYTES) {
                    sources.push((lang, file.to_string(), piece.to_string()));
                }
            }
        }
    }

    /// Whether any of `lang`'s files was added.
    pub fn has_language(&self, lang: Lang) -> bool {
        self.added
            .try_borrow()
            .is_ok_and(|added| added.iter().any(|(l, _)| *l == lang))
    }

    /// Whether `lang`'s file `name` was added.
    pub fn has_file(&self, lang: Lang, name: &str) -> bool {
        self.added
            .try_borrow()
            .is_ok_and(|added| added.contains(&(lang, name.to_string())))
    }

    /// Builds `lang`'s bundle now if it is not built yet (its syntax errors and duplicate ids
    /// become warnings then).
    pub fn preload(&self, lang: Lang) {
        self.bundle(lang);
    }

    /// Parses one piece (about `PIECE_BYTES`, 4 KB) of `lang`'s added files that is not in its
    /// bundle yet, if there is one, and says whether there are more: a caller that parses
    /// files ahead of their use (in the browser's idle time) takes them a piece at a time.
    pub fn build_next(&self, lang: Lang) -> bool {
        if !self.has_language(lang) {
            return false;
        }
        let cell = self.cell(lang);
        if let Ok(mut bundle) = cell.try_borrow_mut() {
            self.build(lang, bundle.get_or_insert_with(|| new_bundle(lang)), 1);
        }
        self.sources
            .try_borrow()
            .is_ok_and(|sources| sources.iter().any(|(l, _, _)| *l == lang))
    }

    fn cell(&self, lang: Lang) -> &RefCell<Option<FluentBundle<FluentResource>>> {
        match lang {
            Lang::En => &self.en,
            Lang::Ja => &self.ja,
        }
    }

    /// `lang`'s bundle with every file added so far, `None` while none is.
    fn bundle(&self, lang: Lang) -> Option<Ref<'_, FluentBundle<FluentResource>>> {
        if !self.has_language(lang) {
            return None;
        }
        let cell = self.cell(lang);
        if let Ok(mut bundle) = cell.try_borrow_mut() {
            self.build(
                lang,
                bundle.get_or_insert_with(|| new_bundle(lang)),
                usize::MAX,
            );
        }
        Ref::filter_map(cell.try_borrow().ok()?, Option::as_ref).ok()
    }

    /// Adds up to `most` of `lang`'s files not in its bundle yet (taken out of `sources`, in
    /// the order they were added). A syntax error or a duplicate id does not stop the app: the
    /// rest of the file loads and the problem becomes a warning.
    fn build(&self, lang: Lang, bundle: &mut FluentBundle<FluentResource>, most: usize) {
        let files: Vec<(Lang, String, String)> = match self.sources.try_borrow_mut() {
            Ok(mut sources) => {
                let mut taken = 0;
                let (mine, rest) =
                    std::mem::take(&mut *sources)
                        .into_iter()
                        .partition(|(l, _, _)| {
                            let take = *l == lang && taken < most;
                            taken += usize::from(take);
                            take
                        });
                *sources = rest;
                mine
            }
            Err(_) => Vec::new(),
        };
        for (_, file, text) in files {
            let resource = match FluentResource::try_new(text) {
                Ok(resource) => resource,
                Err((resource, errors)) => {
                    for error in errors {
                        self.note(format!("{}/{file}: syntax error: {error}", lang.code()));
                    }
                    resource
                }
            };
            if let Err(errors) = bundle.add_resource(resource) {
                for error in errors {
                    self.note(format!("{}/{file}: {error}", lang.code()));
                }
            }
        }
    }

    /// Whether `lang`'s own bundle has message `id` with a value (no fallback).
    pub fn has_message(&self, lang: Lang, id: &str) -> bool {
        self.bundle(lang)
            .is_some_and(|bundle| bundle.get_message(id).and_then(|m| m.value()).is_some())
    }

    /// Message `id` in `lang`, without arguments.
    pub fn t(&self, lang: Lang, id: &str) -> String {
        self.t_args(lang, id, &[])
    }

    /// Message `id` in `lang` with arguments. Falls back to English per message; a message
    /// missing everywhere shows its id. Never panics.
    pub fn t_args(&self, lang: Lang, id: &str, args: &[(&str, FluentArg)]) -> String {
        let fluent_args = if args.is_empty() {
            None
        } else {
            let mut fluent_args = FluentArgs::with_capacity(args.len());
            for (name, value) in args {
                fluent_args.set(name.to_string(), value.to_value());
            }
            Some(fluent_args)
        };
        let chain: &[Lang] = match lang {
            Lang::En => &[Lang::En],
            Lang::Ja => &[Lang::Ja, Lang::En],
        };
        for &source in chain {
            let Some(bundle) = self.bundle(source) else {
                continue;
            };
            let Some(pattern) = bundle.get_message(id).and_then(|m| m.value()) else {
                continue;
            };
            if source != lang {
                self.note(format!(
                    "{}: message '{id}' is missing; showing the {} text",
                    lang.code(),
                    source.code()
                ));
            }
            let mut errors = Vec::new();
            let text = bundle.format_pattern(pattern, fluent_args.as_ref(), &mut errors);
            for error in errors {
                self.note(format!("{}: message '{id}': {error}", source.code()));
            }
            return text.into_owned();
        }
        self.note(format!("message '{id}' is missing in every language"));
        id.to_string()
    }

    /// The message of a kernel error in `lang`, with its arguments (whole numbers such as
    /// counts are passed as numbers so that plural variants work).
    pub fn recipe_error(&self, lang: Lang, error: &RecipeError) -> String {
        self.t_args(lang, error.message_id(), &fluent_args(error.message_args()))
    }

    /// The notes (missing messages, formatting and loading errors) made since the last call;
    /// each distinct note is made only once.
    pub fn take_warnings(&self) -> Vec<String> {
        match self.pending.try_borrow_mut() {
            Ok(mut pending) => std::mem::take(&mut *pending),
            Err(_) => Vec::new(),
        }
    }

    fn note(&self, text: String) {
        let (Ok(mut noted), Ok(mut pending)) =
            (self.noted.try_borrow_mut(), self.pending.try_borrow_mut())
        else {
            return;
        };
        if noted.insert(text.clone()) {
            pending.push(text);
        }
    }
}

fn new_bundle(lang: Lang) -> FluentBundle<FluentResource> {
    // Built from its language subtag, not parsed: the tag parser (and its sorting of variants)
    // would be in every first load for two fixed tags.
    let language = Language::from_bytes(lang.code().as_bytes()).unwrap_or_default();
    let langid = LanguageIdentifier::from_raw_parts_unchecked(language, None, None, None);
    let mut bundle = FluentBundle::new(vec![langid]);
    bundle.set_use_isolating(false);
    bundle
}

/// The UI language for the browser's preferred languages (`navigator.languages`, best
/// first): the first one we have (`"ja-JP"` → Japanese), else English.
pub fn negotiate(preferred: &[String]) -> Lang {
    preferred
        .iter()
        .find_map(|tag| Lang::parse(tag))
        .unwrap_or(Lang::En)
}

/// Text arguments as Fluent arguments, whole-number texts (counts) as numbers so that plural
/// variants work.
pub fn fluent_args(args: Vec<(&'static str, String)>) -> Vec<(&'static str, FluentArg)> {
    args.into_iter()
        .map(|(name, value)| {
            let is_count = !value.is_empty() && value.bytes().all(|b| b.is_ascii_digit());
            let arg = match value.parse::<u64>() {
                Ok(count) if is_count => FluentArg::Number(count as f64),
                _ => FluentArg::Text(value),
            };
            (name, arg)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn the_file_lists_name_every_file_of_both_languages() {
        for lang in Lang::ALL {
            let names: Vec<&str> = locale_files(lang).iter().map(|(name, _)| *name).collect();
            assert_eq!(names, FILE_NAMES, "{}", lang.code());
        }
        assert!(FIRST_FILES.iter().all(|f| FILE_NAMES.contains(f)));
        for (lang, name, text) in ERROR_SOURCES {
            assert!(locale_files(*lang).contains(&(*name, *text)));
        }
    }

    #[test]
    fn files_added_one_by_one_grow_the_bundle() {
        let i18n = I18n::empty();
        let files = locale_files(Lang::Ja);
        let shell = files.iter().find(|(n, _)| *n == "shell.ftl").unwrap();
        let rrt = files.iter().find(|(n, _)| *n == "rrt.ftl").unwrap();
        i18n.add_files(Lang::Ja, &[*shell]);
        assert!(i18n.has_file(Lang::Ja, "shell.ftl") && !i18n.has_file(Lang::Ja, "rrt.ftl"));
        assert!(i18n.has_language(Lang::Ja) && !i18n.has_language(Lang::En));
        assert!(!i18n.has_message(Lang::Ja, "rrt-lede"));
        i18n.add_files(Lang::Ja, &[*rrt, *shell]);
        assert!(i18n.has_message(Lang::Ja, "rrt-lede"));
        // A file added twice is added once: no duplicate-id warning.
        assert!(i18n.take_warnings().is_empty());
    }

    #[test]
    fn files_cut_into_pieces_keep_every_entry() {
        let shown = |bundle: &FluentBundle<FluentResource>, id: &str| -> Option<Vec<String>> {
            let message = bundle.get_message(id)?;
            let mut errors = Vec::new();
            let mut out: Vec<String> = message
                .value()
                .map(|v| bundle.format_pattern(v, None, &mut errors).to_string())
                .into_iter()
                .collect();
            for attribute in message.attributes() {
                let text = bundle.format_pattern(attribute.value(), None, &mut errors);
                out.push(format!("{}={text}", attribute.id()));
            }
            Some(out)
        };
        for lang in Lang::ALL {
            for (name, text) in locale_files(lang) {
                let cut = pieces(text, PIECE_BYTES);
                assert_eq!(cut.concat(), *text, "{name}: the pieces are the file");
                for piece in &cut[..cut.len() - 1] {
                    assert!(
                        piece.len() >= PIECE_BYTES,
                        "{name}: a short piece before the last"
                    );
                }
                let mut whole = new_bundle(lang);
                let _ = whole.add_resource(FluentResource::try_new(text.to_string()).unwrap());
                let mut parts = new_bundle(lang);
                for piece in &cut {
                    let _ = parts.add_resource(FluentResource::try_new(piece.to_string()).unwrap());
                }
                let ids = text.lines().filter_map(|line| {
                    let id = line.split('=').next()?.trim_end();
                    let ok = line.starts_with(|c: char| c.is_ascii_alphabetic())
                        && line.contains('=')
                        && id
                            .chars()
                            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
                    ok.then_some(id)
                });
                let mut count = 0;
                for id in ids {
                    let expected = shown(&whole, id);
                    assert!(expected.is_some(), "{}/{name}: {id}", lang.code());
                    assert_eq!(shown(&parts, id), expected, "{}/{name}: {id}", lang.code());
                    count += 1;
                }
                assert!(count > 0, "{}/{name}: messages", lang.code());
            }
        }
        let select =
            "a = { $n ->\n    [one] one\n   *[other] many\n}\nb = B\n-t = T\n    .x = X\nc = C\n";
        assert_eq!(
            pieces(select, 1),
            [
                "a = { $n ->\n    [one] one\n   *[other] many\n}\n",
                "b = B\n",
                "-t = T\n    .x = X\n",
                "c = C\n"
            ]
        );
        assert_eq!(pieces("", 8), [""]);
    }

    #[test]
    fn added_files_are_parsed_one_at_a_time_ahead_of_their_use() {
        let i18n = I18n::empty();
        assert!(
            !i18n.build_next(Lang::Ja),
            "nothing added: nothing to parse"
        );
        let files = locale_files(Lang::Ja);
        let pick = |name: &str| *files.iter().find(|(n, _)| *n == name).unwrap();
        i18n.add_files(Lang::En, &[*locale_files(Lang::En).first().unwrap()]);
        i18n.add_files(
            Lang::Ja,
            &[pick("shell.ftl"), pick("rrt.ftl"), pick("pages.ftl")],
        );
        let waiting = |lang: Lang| {
            i18n.sources
                .borrow()
                .iter()
                .filter(|(l, _, _)| *l == lang)
                .count()
        };
        let english = waiting(Lang::En);
        assert!(english > 0);
        let japanese = waiting(Lang::Ja);
        assert!(
            japanese > 3,
            "shell.ftl in Japanese is more than one piece: {japanese}"
        );
        for parsed in 1..japanese {
            assert!(i18n.build_next(Lang::Ja));
            assert_eq!(waiting(Lang::Ja), japanese - parsed);
        }
        assert!(
            !i18n.build_next(Lang::Ja),
            "the last piece parsed: none waits"
        );
        assert_eq!(waiting(Lang::Ja), 0);
        assert_eq!(
            waiting(Lang::En),
            english,
            "the other language's file is left to its own use"
        );
        assert!(i18n.has_message(Lang::Ja, "rrt-lede"));
        assert!(i18n.take_warnings().is_empty());
    }

    /// Message id → its whole text block (id line plus indented continuation lines), read
    /// straight from the `.ftl` source: terms (`-x`) and comments are skipped.
    fn message_blocks(source: &str) -> Vec<(String, String)> {
        let mut blocks: Vec<(String, String)> = Vec::new();
        let mut current: Option<(String, String)> = None;
        for line in source.lines() {
            let starts_entry = line.starts_with(|c: char| c.is_ascii_alphabetic());
            let ends_entry = starts_entry || line.starts_with('#') || line.starts_with('-');
            if ends_entry {
                if let Some(done) = current.take() {
                    blocks.push(done);
                }
            }
            if starts_entry {
                if let Some((id, _)) = line.split_once('=') {
                    current = Some((id.trim().to_string(), line.to_string()));
                }
            } else if let Some((_, text)) = current.as_mut() {
                text.push('\n');
                text.push_str(line);
            }
        }
        if let Some(done) = current.take() {
            blocks.push(done);
        }
        blocks
    }

    /// Every variable name (`$name`) in a block.
    fn variables(block: &str) -> BTreeSet<String> {
        let mut names = BTreeSet::new();
        let mut rest = block;
        while let Some(pos) = rest.find('$') {
            let after = &rest[pos + 1..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
                .collect();
            if !name.is_empty() {
                names.insert(name);
            }
            rest = after;
        }
        names
    }

    fn all_files() -> Vec<(Lang, &'static str, &'static str)> {
        Lang::ALL
            .iter()
            .flat_map(|&lang| locale_files(lang).iter().map(move |(f, t)| (lang, *f, *t)))
            .collect()
    }

    fn ids_by_lang() -> BTreeMap<Lang, BTreeMap<String, (String, String)>> {
        let mut map: BTreeMap<Lang, BTreeMap<String, (String, String)>> = BTreeMap::new();
        for (lang, file, text) in all_files() {
            for (id, block) in message_blocks(text) {
                map.entry(lang)
                    .or_default()
                    .insert(id, (file.to_string(), block));
            }
        }
        map
    }

    #[test]
    fn every_file_loads_without_syntax_errors_or_duplicates() {
        let i18n = I18n::new();
        i18n.preload(Lang::En);
        i18n.preload(Lang::Ja);
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn both_languages_have_the_same_message_ids_in_the_same_files() {
        let map = ids_by_lang();
        let en = &map[&Lang::En];
        let ja = &map[&Lang::Ja];
        assert!(en.len() > 100, "only {} English messages found", en.len());
        let only_en: Vec<_> = en.keys().filter(|id| !ja.contains_key(*id)).collect();
        let only_ja: Vec<_> = ja.keys().filter(|id| !en.contains_key(*id)).collect();
        assert!(only_en.is_empty(), "missing in Japanese: {only_en:?}");
        assert!(only_ja.is_empty(), "missing in English: {only_ja:?}");
        for (id, (file, _)) in en {
            assert_eq!(&ja[id].0, file, "{id} lives in different files");
        }
    }

    #[test]
    fn every_message_formats_without_errors_in_both_languages() {
        let i18n = I18n::new();
        for (lang, messages) in ids_by_lang() {
            for (id, (file, block)) in messages {
                let vars = variables(&block);
                assert!(
                    i18n.has_message(lang, &id),
                    "{lang:?} {file}: {id} has no value"
                );
                let samples = [FluentArg::Number(1.0), FluentArg::Number(2.5), "x".into()];
                for sample in samples {
                    let args: Vec<(&str, FluentArg)> =
                        vars.iter().map(|v| (v.as_str(), sample.clone())).collect();
                    let text = i18n.t_args(lang, &id, &args);
                    assert!(!text.trim().is_empty(), "{lang:?} {id} is empty");
                    assert!(!text.contains("{$"), "{lang:?} {id}: {text}");
                }
                // Attributes too.
                let bundle = i18n.bundle(lang).expect("both languages are added");
                if let Some(message) = bundle.get_message(&id) {
                    let mut args = FluentArgs::new();
                    for v in &vars {
                        args.set(v.clone(), FluentValue::from(2.0));
                    }
                    for attr in message.attributes() {
                        let mut errors = Vec::new();
                        bundle.format_pattern(attr.value(), Some(&args), &mut errors);
                        assert!(errors.is_empty(), "{lang:?} {id}.{}: {errors:?}", attr.id());
                    }
                }
            }
        }
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn japanese_uses_only_the_other_plural_category() {
        for (lang, file, text) in all_files() {
            if lang != Lang::Ja {
                continue;
            }
            for line in text.lines() {
                let key = line.trim_start().trim_start_matches('*');
                for category in ["[zero]", "[one]", "[two]", "[few]", "[many]"] {
                    assert!(!key.starts_with(category), "ja/{file}: {line}");
                }
            }
        }
        // A count selects `other` in Japanese and still reads correctly for 1.
        let i18n = I18n::new();
        let error = RecipeError::CsvTooFewRows { rows: 1, min: 2 };
        let ja = i18n.recipe_error(Lang::Ja, &error);
        assert!(ja.contains('1') && ja.contains('2'), "{ja}");
        let en = i18n.recipe_error(Lang::En, &error);
        assert!(
            en.contains("1 data row;") || en.contains("1 data row "),
            "{en}"
        );
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    /// Does not compile when `RecipeError` gains a variant: add it to [`one_of_each_error`]
    /// and give it a message in both `errors.ftl` files.
    #[allow(dead_code)]
    fn every_variant_is_listed(error: &RecipeError) {
        use RecipeError::*;
        match error {
            UnknownRecipe { .. }
            | UnknownFlag { .. }
            | MissingFlagValue { .. }
            | TooManyArgs { .. }
            | NotANumber { .. }
            | NotAnInteger { .. }
            | NotFinite { .. }
            | NotPositive { .. }
            | OutOfRange { .. }
            | TooLarge { .. }
            | WrongCount { .. }
            | BadChoice { .. }
            | InputTooLarge { .. }
            | CsvMissingColumn { .. }
            | CsvNoJointColumns
            | CsvTooFewRows { .. }
            | CsvRagged { .. }
            | CsvBadCell { .. }
            | CsvTimeNotIncreasing { .. }
            | CsvUnterminatedQuote { .. }
            | InputMissing { .. }
            | InputNotUtf8 { .. }
            | InputUtf16 { .. }
            | InputBinary { .. }
            | CsvTooManyColumns { .. }
            | PointInObstacle { .. }
            | BoxInverted { .. }
            | TooManyValues { .. } => {}
        }
    }

    fn one_of_each_error() -> Vec<RecipeError> {
        use RecipeError::*;
        let p = || "step_mm".to_string();
        vec![
            UnknownRecipe { id: "foo".into() },
            UnknownFlag {
                flag: "--foo".into(),
            },
            MissingFlagValue {
                flag: "--integrator".into(),
            },
            TooManyArgs { max: 4, got: 5 },
            NotANumber {
                param: p(),
                value: "abc".into(),
            },
            NotAnInteger {
                param: p(),
                value: "1.5".into(),
            },
            NotFinite { param: p() },
            NotPositive {
                param: p(),
                value: -1.0,
            },
            OutOfRange {
                param: p(),
                value: 9.0,
                min: 0.5,
                max: 5.0,
            },
            TooLarge {
                param: p(),
                count: 4_000_000,
                limit: 1_000_000,
                also: vec![],
                square: false,
            },
            WrongCount {
                param: "angles".into(),
                expected: 3,
                got: 2,
            },
            BadChoice {
                param: "integrator".into(),
                value: "rk5".into(),
                choices: "euler, rk4".into(),
            },
            InputTooLarge {
                bytes: 9_000_000,
                limit: 5_000_000,
            },
            CsvMissingColumn {
                column: "t_s".into(),
            },
            CsvNoJointColumns,
            CsvTooFewRows { rows: 1, min: 2 },
            CsvRagged {
                row: 3,
                expected: 4,
                got: 3,
            },
            CsvBadCell {
                row: 3,
                column: "q1".into(),
                value: "zz".into(),
            },
            CsvTimeNotIncreasing { row: 4 },
            CsvUnterminatedQuote { row: 2 },
            CsvTooManyColumns {
                count: 1_000_000,
                limit: 1000,
            },
            InputUtf16 {
                name: "walk.csv".into(),
            },
            InputBinary {
                name: "walk.png".into(),
                line: 3,
                column: 2,
            },
            InputMissing {
                name: "my_traj.csv".into(),
            },
            InputNotUtf8 {
                name: "latin1.csv".into(),
                offset: 1234,
            },
            PointInObstacle {
                param: "start".into(),
                x: 0.5,
                y: 0.4,
                index: 2,
            },
            BoxInverted {
                param: "obstacle".into(),
                index: 3,
                corners: [0.6, 0.2, 0.4, 0.3],
            },
            TooManyValues {
                param: "obstacle".into(),
                count: 40,
                limit: 32,
            },
        ]
    }

    #[test]
    fn every_recipe_error_has_a_message_with_its_arguments_in_both_languages() {
        let i18n = I18n::new();
        let errors = one_of_each_error();
        let ids: BTreeSet<_> = errors.iter().map(|e| e.message_id()).collect();
        assert_eq!(ids.len(), errors.len(), "one variant per message id");
        for error in &errors {
            for lang in Lang::ALL {
                assert!(
                    i18n.has_message(lang, error.message_id()),
                    "{lang:?}: no {}",
                    error.message_id()
                );
                let text = i18n.recipe_error(lang, error);
                for (name, value) in error.message_args() {
                    assert!(
                        text.contains(&value),
                        "{lang:?} {}: ${name} = {value} not shown in {text:?}",
                        error.message_id()
                    );
                }
            }
        }
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn a_message_missing_in_japanese_falls_back_to_english_and_is_noted_once() {
        let i18n = I18n::from_sources(&[
            (
                Lang::En,
                "t.ftl",
                "greet = Hello\nonly-en = Only { $n } here\n",
            ),
            (Lang::Ja, "t.ftl", "greet = こんにちは\n"),
        ]);
        assert_eq!(i18n.t(Lang::Ja, "greet"), "こんにちは");
        let args = [("n", FluentArg::from(3))];
        assert_eq!(i18n.t_args(Lang::Ja, "only-en", &args), "Only 3 here");
        assert_eq!(i18n.t_args(Lang::Ja, "only-en", &args), "Only 3 here");
        let warnings = i18n.take_warnings();
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert!(warnings[0].contains("only-en"), "{warnings:?}");
        assert!(i18n.take_warnings().is_empty());
        // Missing everywhere: the id itself, noted once.
        assert_eq!(i18n.t(Lang::En, "no-such-id"), "no-such-id");
        assert_eq!(i18n.t(Lang::Ja, "no-such-id"), "no-such-id");
        assert_eq!(i18n.take_warnings().len(), 1);
    }

    #[test]
    fn numbers_print_plainly_and_no_isolation_marks_are_added() {
        let i18n = I18n::from_sources(&[(Lang::En, "t.ftl", "v = { $a } and { $b } m\n")]);
        let text = i18n.t_args(
            Lang::En,
            "v",
            &[
                ("a", FluentArg::from(0.12)),
                ("b", FluentArg::from(200usize)),
            ],
        );
        assert_eq!(text, "0.12 and 200 m");
        assert!(!text.contains('\u{2068}') && !text.contains('\u{2069}'));
    }

    #[test]
    fn plural_categories_follow_each_language() {
        let source = "n = { $n ->\n    [one] one\n    [few] few\n   *[other] other\n}\n";
        let i18n = I18n::from_sources(&[(Lang::En, "t.ftl", source), (Lang::Ja, "t.ftl", source)]);
        let said = |lang, n: usize| i18n.t_args(lang, "n", &[("n", FluentArg::from(n))]);
        assert_eq!(said(Lang::En, 1), "one");
        assert_eq!(said(Lang::En, 2), "other");
        assert_eq!(said(Lang::En, 0), "other");
        // Japanese has one category: every number is "other".
        assert_eq!(said(Lang::Ja, 1), "other");
        assert_eq!(said(Lang::Ja, 3), "other");
    }

    #[test]
    fn a_broken_file_still_loads_its_good_messages_and_warns() {
        let i18n = I18n::from_sources(&[(Lang::En, "t.ftl", "good = Good\nbad = { oops\n")]);
        assert_eq!(i18n.t(Lang::En, "good"), "Good");
        assert!(!i18n.take_warnings().is_empty());
    }

    #[test]
    fn languages_parse_from_tags_and_negotiate_from_browser_preferences() {
        assert_eq!(Lang::parse("ja"), Some(Lang::Ja));
        assert_eq!(Lang::parse("ja-JP"), Some(Lang::Ja));
        assert_eq!(Lang::parse("EN_us"), Some(Lang::En));
        assert_eq!(Lang::parse("fr"), None);
        assert_eq!(Lang::parse(""), None);
        let prefs = |tags: &[&str]| tags.iter().map(|t| t.to_string()).collect::<Vec<_>>();
        assert_eq!(negotiate(&prefs(&["ja-JP", "en-US"])), Lang::Ja);
        assert_eq!(negotiate(&prefs(&["en-US", "ja"])), Lang::En);
        assert_eq!(negotiate(&prefs(&["fr-FR", "ja"])), Lang::Ja);
        assert_eq!(negotiate(&prefs(&["de", "fr"])), Lang::En);
        assert_eq!(negotiate(&[]), Lang::En);
        for lang in Lang::ALL {
            assert_eq!(Lang::parse(lang.code()), Some(lang));
            assert_eq!(lang.other().other(), lang);
        }
    }
}
