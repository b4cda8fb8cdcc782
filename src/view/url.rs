//! The URL codec of the app: `#/<page-id>?k=v&...` parsed into a [`Route`] and built back, with
//! the percent-encoding and the `lang` rules. Plain Rust (no web-sys), so `cargo test` and the
//! property tests cover it; `crate::ui::router` adds only the browser side (`hashchange`,
//! `history.replaceState`).
//!
//! - `#`, `#/` and an empty hash are the home page ([`HOME_ID`]); a trailing `/` is dropped.
//! - Percent-encoding: keys and values are encoded as in `encodeURIComponent` (except that `,`
//!   stays readable); decoding also accepts `+` for a space, and invalid escapes stay as typed.
//! - `lang`: the shell's, not the page's. [`Route::page_query`] removes it from the query a page
//!   sees; [`with_shell_keys`] writes it (last) when the URL should carry it. `embed=1`
//!   ([`EMBED_KEY`]) is the shell's too, and written before it.

use crate::i18n::Lang;

/// Route id of the home page (`#/`, `#/home`).
pub const HOME_ID: &str = "home";

/// The query key the shell uses for the language.
pub const LANG_KEY: &str = "lang";

/// The query key that shows a page embedded (`embed=1`): no site chrome, the page's main view
/// filling the frame, the postMessage API (`crate::view::embed`). Like `lang`, the shell's.
pub const EMBED_KEY: &str = "embed";

/// A parsed hash route.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Route {
    /// The page id ([`HOME_ID`] for an empty route).
    pub page: String,
    /// The decoded query, in order, `lang` included.
    pub query: Vec<(String, String)>,
}

impl Route {
    /// The language named by `?lang=`, if any and known.
    pub fn lang(&self) -> Option<Lang> {
        self.query
            .iter()
            .find(|(k, _)| k == LANG_KEY)
            .and_then(|(_, v)| Lang::parse(v))
    }

    /// Whether the query asks for the page embedded (`embed=1`).
    pub fn embedded(&self) -> bool {
        self.query.iter().any(|(k, v)| k == EMBED_KEY && v == "1")
    }

    /// The query without the shell's keys (`lang`, `embed`).
    pub fn page_query(&self) -> Vec<(String, String)> {
        self.query
            .iter()
            .filter(|(k, _)| k != LANG_KEY && k != EMBED_KEY)
            .cloned()
            .collect()
    }
}

/// Parses a location hash (`"#/ik-2r?L1=0.12&lang=ja"`, `"#/"`, `""`).
pub fn parse_hash(hash: &str) -> Route {
    let body = hash.strip_prefix('#').unwrap_or(hash);
    let body = body.strip_prefix('/').unwrap_or(body);
    let (path, query) = body.split_once('?').unwrap_or((body, ""));
    let page = percent_decode(path.trim_end_matches('/'));
    let page = if page.is_empty() {
        HOME_ID.to_string()
    } else {
        page
    };
    Route {
        page,
        query: parse_query(query),
    }
}

/// Decodes `k=v&k2=v2` (no leading `?`) in order; empty pairs are skipped, a key without `=`
/// has the empty value.
pub fn parse_query(query: &str) -> Vec<(String, String)> {
    query
        .split('&')
        .filter(|pair| !pair.is_empty())
        .map(|pair| {
            let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
            (percent_decode(k), percent_decode(v))
        })
        .collect()
}

/// The hash for a page and query (`"#/ik-2r?L1=0.12"`; `"#/"` for home without a query).
pub fn build_hash(page: &str, query: &[(String, String)]) -> String {
    let path = if page == HOME_ID {
        String::new()
    } else {
        percent_encode(page)
    };
    let mut hash = format!("#/{path}");
    for (index, (key, value)) in query.iter().enumerate() {
        hash.push(if index == 0 { '?' } else { '&' });
        hash.push_str(&percent_encode(key));
        hash.push('=');
        hash.push_str(&percent_encode(value));
    }
    hash
}

/// A page's pairs as the URL writes them: any `lang` or `embed` the page passed is dropped,
/// then `embed=1` is appended when `embedded` (the tab is embedded) and `lang=<code>` when
/// `lang` is `Some` (the URL carries the language).
pub fn with_shell_keys<K: AsRef<str>>(
    pairs: &[(K, String)],
    embedded: bool,
    lang: Option<Lang>,
) -> Vec<(String, String)> {
    let mut query: Vec<(String, String)> = pairs
        .iter()
        .filter(|(k, _)| k.as_ref() != LANG_KEY && k.as_ref() != EMBED_KEY)
        .map(|(k, v)| (k.as_ref().to_string(), v.clone()))
        .collect();
    if embedded {
        query.push((EMBED_KEY.to_string(), "1".to_string()));
    }
    if let Some(lang) = lang {
        query.push((LANG_KEY.to_string(), lang.code().to_string()));
    }
    query
}

/// Why a key of the URL was not used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IgnoredReason {
    /// The page has no such key.
    Unknown,
    /// The page has the key but could not use its value (the default stays).
    Invalid,
    /// The page put the value in its field, where a message beside it says why it is not
    /// valid (a form page keeps what the link typed).
    Flagged,
    /// The key names an input file (its value the file's name) that the link cannot carry:
    /// the user has to open it again.
    File,
}

/// A key of the URL the page did not use, for the notice that says so.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IgnoredKey {
    pub key: String,
    pub reason: IgnoredReason,
}

impl IgnoredKey {
    /// A key the page does not know.
    pub fn unknown(key: impl Into<String>) -> IgnoredKey {
        IgnoredKey {
            key: key.into(),
            reason: IgnoredReason::Unknown,
        }
    }

    /// A key whose value the page could not use.
    pub fn invalid(key: impl Into<String>) -> IgnoredKey {
        IgnoredKey {
            key: key.into(),
            reason: IgnoredReason::Invalid,
        }
    }

    /// A key whose value stays in its field, flagged there as not valid.
    pub fn flagged(key: impl Into<String>) -> IgnoredKey {
        IgnoredKey {
            key: key.into(),
            reason: IgnoredReason::Flagged,
        }
    }

    /// The name of an input file the link used (`key` holds the file's name, not the query
    /// key), to be opened again.
    pub fn file(name: impl Into<String>) -> IgnoredKey {
        IgnoredKey {
            key: name.into(),
            reason: IgnoredReason::File,
        }
    }
}

/// A page's state as it lives in the URL query. `read` never fails: what it cannot use keeps
/// its default and is reported; `write` lists the pairs in a fixed order (usually only values
/// that differ from the defaults), so that `read(write(s))` gives `s` back.
pub trait UrlState: Sized {
    /// The state the decoded query (without `lang`) asks for, and the keys it could not use.
    fn read(query: &[(String, String)]) -> (Self, Vec<IgnoredKey>);
    /// The query pairs for this state, in order.
    fn write(&self) -> Vec<(String, String)>;
}

/// Percent-encodes everything but `A–Z a–z 0–9 - _ . ~ ,` (UTF-8 bytes for other text).
pub fn percent_encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for byte in text.bytes() {
        if byte.is_ascii_alphanumeric() || matches!(byte, b'-' | b'_' | b'.' | b'~' | b',') {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

/// Decodes `%XX` escapes (as UTF-8, invalid sequences replaced) and `+` as a space; a `%` not
/// followed by two hex digits stays as it is.
pub fn percent_decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut index = 0;
    while index < bytes.len() {
        let byte = bytes[index];
        let escaped = if byte == b'%' {
            bytes
                .get(index + 1..index + 3)
                .and_then(|hex| std::str::from_utf8(hex).ok())
                .filter(|hex| hex.bytes().all(|b| b.is_ascii_hexdigit()))
                .and_then(|hex| u8::from_str_radix(hex, 16).ok())
        } else {
            None
        };
        match (byte, escaped) {
            (_, Some(decoded)) => {
                out.push(decoded);
                index += 3;
            }
            (b'+', None) => {
                out.push(b' ');
                index += 1;
            }
            (_, None) => {
                out.push(byte);
                index += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Query pairs from string slices, as the pages' tests write their URLs.
#[cfg(test)]
pub(crate) fn query(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
    pairs
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::query as q;
    use super::*;

    #[test]
    fn empty_and_root_hashes_are_home() {
        for hash in ["", "#", "#/", "/", "#/?"] {
            let route = parse_hash(hash);
            assert_eq!(route.page, HOME_ID, "{hash:?}");
            assert!(route.query.is_empty(), "{hash:?}");
        }
    }

    #[test]
    fn page_and_query_are_split_and_decoded_in_order() {
        let route = parse_hash("#/ik-2r?L1=0.12&note=a%20b+c&lang=ja&flag");
        assert_eq!(route.page, "ik-2r");
        assert_eq!(
            route.query,
            q(&[
                ("L1", "0.12"),
                ("note", "a b c"),
                ("lang", "ja"),
                ("flag", "")
            ])
        );
        assert_eq!(route.lang(), Some(Lang::Ja));
        assert_eq!(
            route.page_query(),
            q(&[("L1", "0.12"), ("note", "a b c"), ("flag", "")])
        );
        assert_eq!(parse_hash("#/ik-2r/").page, "ik-2r");
        assert_eq!(parse_hash("#/x?lang=fr").lang(), None);
        assert_eq!(
            parse_hash("#/x?a=1&&b=2=3").query,
            q(&[("a", "1"), ("b", "2=3")])
        );
    }

    #[test]
    fn encoding_round_trips_any_text() {
        for text in [
            "0.2,0.4,-0.3",
            "a b&c=d?e#f/g",
            "日本語",
            "100%",
            "+1e-3",
            "",
        ] {
            assert_eq!(percent_decode(&percent_encode(text)), text);
        }
        for (text, encoded) in [
            ("a b&c", "a%20b%26c"),
            ("日", "%E6%97%A5"),
            ("+1", "%2B1"),
            ("0.2,0.4", "0.2,0.4"),
        ] {
            assert_eq!(percent_encode(text), encoded);
        }
    }

    #[test]
    fn broken_escapes_do_not_panic_and_stay_as_typed() {
        for (typed, read) in [
            ("100%", "100%"),
            ("%zz%4", "%zz%4"),
            ("%E6%97", "\u{FFFD}"),
            ("%", "%"),
            // `from_str_radix` would accept a sign: "%+1" is not an escape.
            ("%+1", "% 1"),
        ] {
            assert_eq!(percent_decode(typed), read, "{typed}");
        }
    }

    #[test]
    fn built_hashes_parse_back() {
        let query = q(&[("L1", "0.12"), ("q", "a&b"), ("lang", "ja")]);
        let hash = build_hash("ik-2r", &query);
        assert_eq!(hash, "#/ik-2r?L1=0.12&q=a%26b&lang=ja");
        assert_eq!(
            parse_hash(&hash),
            Route {
                page: "ik-2r".into(),
                query
            }
        );
        assert_eq!(build_hash(HOME_ID, &[]), "#/");
        assert_eq!(build_hash(HOME_ID, &q(&[("a", "1")])), "#/?a=1");
    }

    /// A two-field state, as a page would write it.
    #[derive(Debug, PartialEq)]
    struct Demo {
        steps: u32,
        label: String,
    }

    impl UrlState for Demo {
        fn read(query: &[(String, String)]) -> (Demo, Vec<IgnoredKey>) {
            let mut demo = Demo {
                steps: 10,
                label: String::new(),
            };
            let mut ignored = Vec::new();
            for (key, value) in query {
                match key.as_str() {
                    "steps" => match value.parse() {
                        Ok(n) => demo.steps = n,
                        Err(_) => ignored.push(IgnoredKey::invalid(key.clone())),
                    },
                    "label" => demo.label = value.clone(),
                    _ => ignored.push(IgnoredKey::unknown(key.clone())),
                }
            }
            (demo, ignored)
        }
        fn write(&self) -> Vec<(String, String)> {
            vec![
                ("steps".into(), self.steps.to_string()),
                ("label".into(), self.label.clone()),
            ]
        }
    }

    #[test]
    fn a_url_state_round_trips_and_reports_what_it_ignored() {
        let demo = Demo {
            steps: 42,
            label: "a&b c".into(),
        };
        let hash = build_hash(
            "demo",
            &with_shell_keys(&demo.write(), false, Some(Lang::En)),
        );
        let (back, ignored) = Demo::read(&parse_hash(&hash).page_query());
        assert_eq!(back, demo);
        assert!(ignored.is_empty());
        let (bad, ignored) = Demo::read(&parse_hash("#/demo?steps=x&zoom=2").page_query());
        assert_eq!(bad.steps, 10);
        assert_eq!(
            ignored,
            vec![IgnoredKey::invalid("steps"), IgnoredKey::unknown("zoom")]
        );
    }

    #[test]
    fn lang_is_written_last_and_only_once() {
        let pairs = vec![("lang", "en".to_string()), ("L1", "0.2".to_string())];
        assert_eq!(with_shell_keys(&pairs, false, None), q(&[("L1", "0.2")]));
        assert_eq!(
            with_shell_keys(&pairs, false, Some(Lang::Ja)),
            q(&[("L1", "0.2"), ("lang", "ja")])
        );
        let hash = build_hash("drills", &with_shell_keys(&pairs, false, Some(Lang::Ja)));
        assert_eq!(parse_hash(&hash).page_query(), q(&[("L1", "0.2")]));
        assert_eq!(parse_hash(&hash).lang(), Some(Lang::Ja));
    }

    #[test]
    fn embed_is_the_shells_and_written_before_lang() {
        let pairs = vec![("embed", "0".to_string()), ("q1", "0.5".to_string())];
        let query = with_shell_keys(&pairs, true, Some(Lang::Ja));
        assert_eq!(query, q(&[("q1", "0.5"), ("embed", "1"), ("lang", "ja")]));
        let route = parse_hash(&build_hash("ik-2r", &query));
        assert!(route.embedded());
        assert_eq!(route.page_query(), q(&[("q1", "0.5")]));
        assert_eq!(with_shell_keys(&pairs, false, None), q(&[("q1", "0.5")]));
        assert!(!parse_hash("#/ik-2r?embed=0").embedded());
        assert!(!parse_hash("#/ik-2r").embedded());
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod properties {
    use super::*;
    use proptest::prelude::*;

    fn key() -> impl Strategy<Value = String> {
        // Any text but `lang` and `embed`, which the router takes out of a page's query.
        any::<String>().prop_filter("not the shell's", |k| k != LANG_KEY && k != EMBED_KEY)
    }

    proptest! {
        #[test]
        fn any_text_round_trips(text in any::<String>()) {
            prop_assert_eq!(percent_decode(&percent_encode(&text)), text);
        }

        #[test]
        fn encoded_text_has_no_separator(text in any::<String>()) {
            let encoded = percent_encode(&text);
            prop_assert!(!encoded.contains(['&', '=', '?', '#', '/', ' ', '+']));
            prop_assert!(encoded.is_ascii());
        }

        #[test]
        fn any_route_round_trips(
            page in "[a-z0-9][a-z0-9-]{0,12}",
            query in proptest::collection::vec((key(), any::<String>()), 0..6),
            lang in proptest::option::of(prop_oneof![Just(Lang::En), Just(Lang::Ja)]),
        ) {
            let written = with_shell_keys(&query, false, lang);
            let route = parse_hash(&build_hash(&page, &written));
            prop_assert_eq!(&route.page, &page);
            prop_assert_eq!(route.page_query(), query);
            prop_assert_eq!(route.lang(), lang);
        }

        #[test]
        fn decoding_never_panics(text in any::<String>()) {
            let _ = parse_hash(&text);
        }
    }
}
