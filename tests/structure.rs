//! The shape of `src/`, checked as text: the layers in one direction, no import circle between
//! its files, no function over 150 lines outside tests, no `.rs` file over 1,200 lines.
//!
//! The layers, bottom up: the kernels and the pieces they share (every module but `view` and
//! `ui`), the view models (`view`), the browser's code (`ui`), in which the kit (`ui::kit`) sits
//! below the pages (`ui::pages`). A kernel names no view or ui module, a view model no ui module,
//! the kit no page.
//!
//! The import graph has a node per `.rs` file of `src/` (the command line in `src/bin` aside)
//! and an edge from A to B when code in A (comments left out, test modules included) names
//! something in B: through `crate::…`, `super::…` or `self::…`, or a parent naming its child
//! module (`child::Item`). A child that uses its parent's items while the parent uses the child
//! is a circle too; a module's own `mod tests` reaching it by `super::` is not.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

const FUNCTION_LIMIT: usize = 150;
const FILE_LIMIT: usize = 1200;

type Module = Vec<String>;

/// The `.rs` files under `dir`, recursively, in a stable order.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|ext| ext == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a file: `src/ui/kit/mod.rs` is `ui::kit`, `src/lib.rs` is the root.
fn module_of(src: &Path, file: &Path) -> Module {
    let rel = file.strip_prefix(src).expect("under src");
    let mut parts: Module = rel
        .with_extension("")
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The text with comments, string literals and char literals blanked out (newlines kept), so
/// that braces and paths are only those of code.
fn code_only(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let blank = |out: &mut String, s: &[u8]| {
        for &b in s {
            out.push(if b == b'\n' { '\n' } else { ' ' });
        }
    };
    while i < bytes.len() {
        let rest = &bytes[i..];
        if rest.starts_with(b"//") {
            let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
            blank(&mut out, &rest[..end]);
            i += end;
        } else if rest.starts_with(b"/*") {
            let mut depth = 0;
            let mut j = 0;
            while j < rest.len() {
                if rest[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if rest[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            blank(&mut out, &rest[..j]);
            i += j;
        } else if let Some(len) = raw_string_len(bytes, i) {
            blank(&mut out, &bytes[i..i + len]);
            i += len;
        } else if bytes[i] == b'"' {
            let mut j = 1;
            while j < rest.len() && rest[j] != b'"' {
                j += if rest[j] == b'\\' { 2 } else { 1 };
            }
            let end = (j + 1).min(rest.len());
            blank(&mut out, &rest[..end]);
            i += end;
        } else if bytes[i] == b'\'' {
            // A char literal ('x', '\n', '\u{1F600}'), not a lifetime ('a).
            let len = if rest.get(1) == Some(&b'\\') {
                rest.iter().skip(3).position(|&b| b == b'\'').map(|p| p + 4)
            } else {
                let ch_len = text[i + 1..].chars().next().map_or(1, char::len_utf8);
                (rest.get(1 + ch_len) == Some(&b'\'')).then_some(2 + ch_len)
            };
            match len {
                Some(len) => {
                    blank(&mut out, &rest[..len]);
                    i += len;
                }
                None => {
                    out.push('\'');
                    i += 1;
                }
            }
        } else {
            let ch = text[i..].chars().next().expect("char");
            out.push(ch);
            i += ch.len_utf8();
        }
    }
    out
}

/// The length of a raw string literal (`r"…"`, `r#"…"#`, `br"…"`) starting at `i`.
fn raw_string_len(bytes: &[u8], i: usize) -> Option<usize> {
    if i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_') {
        return None;
    }
    let mut j = i;
    if bytes.get(j) == Some(&b'b') {
        j += 1;
    }
    if bytes.get(j) != Some(&b'r') {
        return None;
    }
    j += 1;
    let hashes = bytes[j..].iter().take_while(|&&b| b == b'#').count();
    j += hashes;
    if bytes.get(j) != Some(&b'"') {
        return None;
    }
    j += 1;
    let closing: Vec<u8> = std::iter::once(b'"')
        .chain(std::iter::repeat_n(b'#', hashes))
        .collect();
    let end = bytes[j..]
        .windows(closing.len())
        .position(|w| w == closing.as_slice())?;
    Some(j + end + closing.len() - i)
}

/// Where the file's own test module starts (`#[cfg(test)] mod tests {` or `mod tests;`).
fn test_module_start(code: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(at) = code[from..].find("#[cfg(test)]") {
        let start = from + at;
        let after = code[start + "#[cfg(test)]".len()..].trim_start();
        let after = after.strip_prefix("pub ").unwrap_or(after).trim_start();
        if after.starts_with("mod tests") {
            return Some(start);
        }
        from = start + 1;
    }
    None
}

fn is_ident(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Every path the code names, as its segments (`crate::ui::dom::el` gives
/// `["crate", "ui", "dom", "el"]`); `use` trees are expanded (`use a::{b, c::d}`).
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if !is_ident(bytes[i]) || (i > 0 && (is_ident(bytes[i - 1]) || bytes[i - 1] == b':')) {
            i += 1;
            continue;
        }
        let start = i;
        while i < bytes.len() && is_ident(bytes[i]) {
            i += 1;
        }
        let word = &code[start..i];
        if word == "use" {
            let end = code[i..].find(';').map_or(code.len(), |e| i + e);
            expand_use(&code[i..end], &mut Vec::new(), &mut out);
            i = end;
            continue;
        }
        let mut segments = vec![word.to_string()];
        while code[i..].starts_with("::") {
            let s = i + 2;
            let mut e = s;
            while e < bytes.len() && is_ident(bytes[e]) {
                e += 1;
            }
            if e == s {
                break;
            }
            segments.push(code[s..e].to_string());
            i = e;
        }
        if segments.len() > 1 {
            out.push(segments);
        }
    }
    out
}

/// Expands a `use` tree (`a::{b, c::{d, e as f}}`) under `prefix`.
fn expand_use(tree: &str, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let mut depth = 0;
    let mut part = String::new();
    let mut parts = Vec::new();
    for ch in tree.chars() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if ch == ',' && depth == 0 {
            parts.push(std::mem::take(&mut part));
        } else {
            part.push(ch);
        }
    }
    parts.push(part);
    for part in parts.iter().filter(|p| !p.is_empty()) {
        if let Some(open) = part.find('{') {
            let head = part[..open].trim_end_matches("::");
            let inner = &part[open + 1..part.rfind('}').unwrap_or(part.len())];
            let depth = prefix.len();
            prefix.extend(head.split("::").filter(|s| !s.is_empty()).map(String::from));
            expand_use(inner, prefix, out);
            prefix.truncate(depth);
        } else {
            let path = part.split("as").next().unwrap_or(part);
            let mut full = prefix.clone();
            full.extend(path.split("::").filter(|s| !s.is_empty()).map(String::from));
            out.push(full);
        }
    }
}

/// The module a path names from module `from` (`in_tests`: inside `from`'s test module), if
/// it is a module of the crate: the longest prefix of the resolved path that is one.
fn target(
    path: &[String],
    from: &Module,
    in_tests: bool,
    modules: &BTreeSet<Module>,
) -> Option<Module> {
    let mut resolved: Module = match path[0].as_str() {
        "crate" => Vec::new(),
        "self" => from.clone(),
        "super" => {
            let mut base = from.clone();
            if !in_tests {
                base.pop();
            }
            base
        }
        first => {
            let mut child = from.clone();
            child.push(first.to_string());
            if !modules.contains(&child) {
                return None;
            }
            from.clone()
        }
    };
    let mut rest = &path[usize::from(matches!(path[0].as_str(), "crate" | "self" | "super"))..];
    while rest.first().is_some_and(|s| s == "super") {
        resolved.pop();
        rest = &rest[1..];
    }
    resolved.extend(rest.iter().cloned());
    (1..=resolved.len())
        .rev()
        .map(|n| resolved[..n].to_vec())
        .find(|m| modules.contains(m))
}

struct Source {
    module: Module,
    name: String,
    code: String,
}

fn sources() -> Vec<Source> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files
        .into_iter()
        .filter(|f| !f.starts_with(src.join("bin")))
        .map(|f| Source {
            module: module_of(&src, &f),
            name: f
                .strip_prefix(&src)
                .expect("under src")
                .display()
                .to_string(),
            code: code_only(&fs::read_to_string(&f).expect("readable source")),
        })
        .collect()
}

fn import_graph(sources: &[Source]) -> BTreeMap<Module, BTreeSet<Module>> {
    let modules: BTreeSet<Module> = sources.iter().map(|s| s.module.clone()).collect();
    let mut graph = BTreeMap::new();
    for source in sources {
        let split = test_module_start(&source.code).unwrap_or(source.code.len());
        let mut edges = BTreeSet::new();
        for (part, in_tests) in [
            (&source.code[..split], false),
            (&source.code[split..], true),
        ] {
            for path in paths(part) {
                if let Some(to) = target(&path, &source.module, in_tests, &modules) {
                    if to != source.module {
                        edges.insert(to);
                    }
                }
            }
        }
        graph.insert(source.module.clone(), edges);
    }
    graph
}

/// The strongly connected components of more than one node (Tarjan).
fn circles(graph: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<Vec<Module>> {
    struct Walk<'g> {
        graph: &'g BTreeMap<Module, BTreeSet<Module>>,
        index: BTreeMap<&'g Module, usize>,
        low: BTreeMap<&'g Module, usize>,
        stack: Vec<&'g Module>,
        found: Vec<Vec<Module>>,
    }
    fn visit<'g>(w: &mut Walk<'g>, v: &'g Module) {
        let n = w.index.len();
        w.index.insert(v, n);
        w.low.insert(v, n);
        w.stack.push(v);
        for to in &w.graph[v] {
            if !w.index.contains_key(to) {
                visit(w, to);
                let low = w.low[v].min(w.low[to]);
                w.low.insert(v, low);
            } else if w.stack.contains(&to) {
                let low = w.low[v].min(w.index[to]);
                w.low.insert(v, low);
            }
        }
        if w.low[v] == w.index[v] {
            let mut component = Vec::new();
            while let Some(top) = w.stack.pop() {
                component.push(top.clone());
                if top == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                w.found.push(component);
            }
        }
    }
    let mut walk = Walk {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in graph.keys() {
        if !walk.index.contains_key(v) {
            visit(&mut walk, v);
        }
    }
    walk.found
}

fn show(module: &Module) -> String {
    if module.is_empty() {
        "crate".to_string()
    } else {
        module.join("::")
    }
}

/// A module's layer (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Layer {
    Kernel,
    View,
    Kit,
    Pages,
    /// The rest of `ui`: the shell, the router, the DOM helpers (above view, beside the kit).
    Ui,
}

fn layer(module: &Module) -> Layer {
    match (
        module.first().map(String::as_str),
        module.get(1).map(String::as_str),
    ) {
        (Some("view"), _) => Layer::View,
        (Some("ui"), Some("kit")) => Layer::Kit,
        (Some("ui"), Some("pages")) => Layer::Pages,
        (Some("ui"), _) => Layer::Ui,
        _ => Layer::Kernel,
    }
}

/// Whether code of layer `from` may name a module of layer `to`.
fn may_name(from: Layer, to: Layer) -> bool {
    match from {
        Layer::Kernel => to == Layer::Kernel,
        Layer::View => matches!(to, Layer::Kernel | Layer::View),
        Layer::Kit => to != Layer::Pages,
        Layer::Pages | Layer::Ui => true,
    }
}

/// Every edge of the graph that names a layer above its own, as `from -> to`.
fn layer_breaches(graph: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<String> {
    let mut out = Vec::new();
    for (from, edges) in graph {
        for to in edges {
            if !may_name(layer(from), layer(to)) {
                out.push(format!(
                    "{} ({:?}) -> {} ({:?})",
                    show(from),
                    layer(from),
                    show(to),
                    layer(to)
                ));
            }
        }
    }
    out
}

#[test]
fn layers_point_one_way() {
    let breaches = layer_breaches(&import_graph(&sources()));
    assert!(
        breaches.is_empty(),
        "a module names a layer above its own:\n    {}",
        breaches.join("\n    ")
    );
}

/// A fixture's module path, `a::b`.
fn module(m: &str) -> Module {
    m.split("::").map(String::from).collect()
}

/// A fixture's source file: module `m` holding `code`.
fn source(m: &str, code: &str) -> Source {
    Source {
        module: module(m),
        name: m.to_string(),
        code: code_only(code),
    }
}

#[test]
fn the_checker_sees_a_layer_breach() {
    let sources = [
        source("teleop", "use crate::view::keys::Held;\n"),
        source(
            "view::keys",
            "use crate::teleop::Command;\n// crate::ui::dom\n",
        ),
        source("view::plot", "fn f() { crate::ui::dom::el(); }\n"),
        source("ui::dom", "use crate::view::plot;\n"),
        source("ui::kit::form", "use crate::ui::pages::home;\n"),
        source("ui::pages::home", "use crate::ui::kit::form;\n"),
        source("ui::shell", "use crate::ui::pages::home;\n"),
    ];
    let breaches = layer_breaches(&import_graph(&sources));
    assert_eq!(
        breaches,
        [
            "teleop (Kernel) -> view::keys (View)",
            "ui::kit::form (Kit) -> ui::pages::home (Pages)",
            "view::plot (View) -> ui::dom (Ui)",
        ]
    );
}

#[test]
fn no_import_circle_in_src() {
    let graph = import_graph(&sources());
    let found = circles(&graph);
    let report: Vec<String> = found
        .iter()
        .map(|component| {
            let members: BTreeSet<&Module> = component.iter().collect();
            let edges: Vec<String> = component
                .iter()
                .map(|m| {
                    let to: Vec<String> = graph[m]
                        .iter()
                        .filter(|t| members.contains(t))
                        .map(show)
                        .collect();
                    format!("    {} -> {}", show(m), to.join(", "))
                })
                .collect();
            format!("circle of {}:\n{}", component.len(), edges.join("\n"))
        })
        .collect();
    assert!(found.is_empty(), "{}", report.join("\n"));
}

#[test]
fn the_checker_sees_a_circle() {
    let sources = [
        source("a", "mod b; use b::Thing; // crate::c::x\n"),
        source(
            "a::b",
            "use super::Other;\nfn f() { let s = \"crate::c::x\"; }\n",
        ),
        source("c", "#[cfg(test)]\nmod tests {\n    use super::*;\n}\n"),
    ];
    let graph = import_graph(&sources);
    assert_eq!(circles(&graph), vec![vec![module("a"), module("a::b")]]);
    assert!(graph[&module("a")].len() == 1, "comments name nothing");
    assert!(
        graph[&module("c")].is_empty(),
        "a test module reaches its own file"
    );
}

/// Each function's first line and length (from `fn` to its closing brace), outside the
/// file's test module.
fn long_functions(code: &str) -> Vec<(String, usize, usize)> {
    let body = &code[..test_module_start(code).unwrap_or(code.len())];
    let bytes = body.as_bytes();
    let line_at = |pos: usize| body[..pos].matches('\n').count() + 1;
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = body[from..].find("fn ") {
        let start = from + at;
        from = start + 3;
        if start > 0 && is_ident(bytes[start - 1]) {
            continue;
        }
        let name: String = body[start + 3..]
            .chars()
            .take_while(|&c| c.is_alphanumeric() || c == '_')
            .collect();
        let Some(open) = body[start..].find(['{', ';']).map(|o| start + o) else {
            continue;
        };
        if bytes[open] == b';' {
            continue;
        }
        let mut depth = 0usize;
        let mut close = None;
        for (i, &b) in bytes.iter().enumerate().skip(open) {
            match b {
                b'{' => depth += 1,
                b'}' => {
                    depth -= 1;
                    if depth == 0 {
                        close = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        if let Some(close) = close {
            let (first, last) = (line_at(start), line_at(close));
            out.push((name, first, last - first + 1));
        }
    }
    out
}

#[test]
fn no_long_function_or_file_in_src() {
    let mut problems = Vec::new();
    for source in sources() {
        let lines = source.code.lines().count();
        if lines > FILE_LIMIT {
            problems.push(format!(
                "{}: {lines} lines (limit {FILE_LIMIT})",
                source.name
            ));
        }
        if source.name.ends_with("tests.rs") {
            continue;
        }
        for (name, line, length) in long_functions(&source.code) {
            if length > FUNCTION_LIMIT {
                problems.push(format!(
                    "{}:{line} fn {name}: {length} lines (limit {FUNCTION_LIMIT})",
                    source.name
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_checker_measures_a_function() {
    let code = code_only("fn short() {\n    let s = \"}\";\n}\n\nfn two() -> u8 {\n    2\n}\n");
    assert_eq!(
        long_functions(&code),
        vec![("short".to_string(), 1, 3), ("two".to_string(), 5, 3)]
    );
}
