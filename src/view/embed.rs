//! The postMessage API of an embedded page, shaped like reveal.js's: what a host page may ask
//! and what the page answers, as JSON values. Plain Rust, so `cargo test` covers every
//! malformed message; `crate::ui::embed_api` carries the messages and acts on them.
//!
//! - A request is `{"namespace":"bsv","id":…,"method":…,"args":[…]}`, as an object or as its
//!   JSON text (reveal.js's form). Anything else with another namespace, or not an object, is
//!   for someone else and gets no answer, and so are this API's own replies and events (a
//!   `result`, `error` or `event` without a `method`); every other message gets one reply.
//! - A reply is `{"namespace":"bsv","id":…,"result":…}` or `{"namespace":"bsv","id":…,
//!   "error":"<message>"}`, with the request's `id` (`null` when it had none or an unusable
//!   one), in the form the request came in (object or JSON text).
//! - Methods: `getState`, `setState(state)`, `getReadouts`, `step(n)` (`n` a whole number,
//!   default 1, negative steps back), `reset`.
//! - Events to the host: `{"namespace":"bsv","event":"ready"|"statechange"|"readouts",…}`.
//!
//! A state is an object of URL keys; its values are strings or numbers (as the link writes
//! them), and `null` removes the key (the page's default). `lang` and `embed` are the shell's,
//! not a page's state.

use serde_json::{Map, Number, Value};

use crate::view::url::{IgnoredKey, IgnoredReason, EMBED_KEY, LANG_KEY};

/// The `namespace` of every message of this API.
pub const NAMESPACE: &str = "bsv";

/// The most steps one `step(n)` takes, either way.
pub const MAX_STEPS: i64 = 1_000_000;

/// One change of a `setState`: a key and its new value (`None`: remove the key).
pub type StateChange = (String, Option<String>);

/// What a request asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum Method {
    GetState,
    /// The changes whose values are usable, and the keys whose values are not (neither a
    /// string, a number nor `null`).
    SetState {
        changes: Vec<StateChange>,
        invalid: Vec<String>,
    },
    GetReadouts,
    Step(i64),
    Reset,
}

/// A well-formed request.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The host's id, given back in the reply (a string, a number or `null`).
    pub id: Value,
    pub method: Method,
}

/// What a message is to this API.
#[derive(Debug, Clone, PartialEq)]
pub enum Message {
    /// Not for this API: no reply.
    NotForUs,
    Request(Request),
    /// For this API but unusable: the reply is an error with `id` and `error`.
    Malformed {
        id: Value,
        error: String,
    },
}

/// Reads a message given as JSON text: text that does not start with `{` is not for this API;
/// text that does but is not JSON is malformed.
pub fn parse_text(text: &str) -> Message {
    if !text.starts_with('{') {
        return Message::NotForUs;
    }
    match serde_json::from_str::<Value>(text) {
        Ok(value) => parse(&value),
        Err(error) => malformed(Value::Null, format!("not valid JSON: {error}")),
    }
}

/// Reads a message given as a value.
pub fn parse(data: &Value) -> Message {
    let Some(object) = data.as_object() else {
        return Message::NotForUs;
    };
    if object.get("namespace").and_then(Value::as_str) != Some(NAMESPACE) {
        return Message::NotForUs;
    }
    // This API's own replies and events (from a page this one embeds, such as the presenter
    // view's picture of the next step) ask nothing: answering them would start an endless
    // exchange of errors between the two pages.
    let answer_or_event = ["event", "result", "error"]
        .iter()
        .any(|key| object.contains_key(*key));
    if answer_or_event && !object.contains_key("method") {
        return Message::NotForUs;
    }
    let id = match object.get("id") {
        None | Some(Value::Null) => Value::Null,
        Some(id @ (Value::String(_) | Value::Number(_))) => id.clone(),
        Some(_) => return malformed(Value::Null, "id must be a string or a number".into()),
    };
    let name = match object.get("method") {
        Some(Value::String(name)) => name.as_str(),
        Some(_) => return malformed(id, "method must be a string".into()),
        None => return malformed(id, "no method".into()),
    };
    let args: &[Value] = match object.get("args") {
        None => &[],
        Some(Value::Array(args)) => args,
        Some(_) => return malformed(id, "args must be an array".into()),
    };
    let method = match name {
        "getState" => no_args(name, args).map(|()| Method::GetState),
        "getReadouts" => no_args(name, args).map(|()| Method::GetReadouts),
        "reset" => no_args(name, args).map(|()| Method::Reset),
        "step" => step_count(args).map(Method::Step),
        "setState" => state_changes(args),
        _ => Err(format!(
            "unknown method {name:?} (getState, setState, getReadouts, step, reset)"
        )),
    };
    match method {
        Ok(method) => Message::Request(Request { id, method }),
        Err(error) => malformed(id, error),
    }
}

fn malformed(id: Value, error: String) -> Message {
    Message::Malformed { id, error }
}

fn no_args(name: &str, args: &[Value]) -> Result<(), String> {
    if args.is_empty() {
        Ok(())
    } else {
        Err(format!("{name} takes no arguments"))
    }
}

fn step_count(args: &[Value]) -> Result<i64, String> {
    match args {
        [] => Ok(1),
        [Value::Number(n)] => n
            .as_i64()
            .or_else(|| n.as_f64().filter(|x| x.fract() == 0.0).map(|x| x as i64))
            .filter(|n| n.abs() <= MAX_STEPS)
            .ok_or_else(|| format!("step(n): n must be a whole number within ±{MAX_STEPS}")),
        [_] => Err("step(n): n must be a number".into()),
        _ => Err("step takes one argument, n".into()),
    }
}

fn state_changes(args: &[Value]) -> Result<Method, String> {
    let [Value::Object(state)] = args else {
        return Err("setState(state): state must be one object of URL keys".into());
    };
    let mut changes = Vec::new();
    let mut invalid = Vec::new();
    for (key, value) in state {
        match value {
            Value::String(text) => changes.push((key.clone(), Some(text.clone()))),
            Value::Number(n) => changes.push((key.clone(), Some(number_text(n)))),
            Value::Null => changes.push((key.clone(), None)),
            _ => invalid.push(key.clone()),
        }
    }
    Ok(Method::SetState { changes, invalid })
}

/// A number as a link writes it: integers without a point, others in the shortest form that
/// reads back the same.
fn number_text(n: &Number) -> String {
    n.to_string()
}

/// Whether `key` is the shell's (`lang`, `embed`), not a page's.
pub fn is_shell_key(key: &str) -> bool {
    key == LANG_KEY || key == EMBED_KEY
}

/// The query after `changes`: a changed key keeps its place, a new one goes last, a removed
/// one goes.
pub fn apply_changes(query: &[(String, String)], changes: &[StateChange]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = query.to_vec();
    for (key, value) in changes {
        match (out.iter().position(|(k, _)| k == key), value) {
            (Some(at), Some(value)) => out[at].1.clone_from(value),
            (Some(at), None) => {
                out.remove(at);
            }
            (None, Some(value)) => out.push((key.clone(), value.clone())),
            (None, None) => {}
        }
    }
    out
}

/// A query as a state object (values as the link writes them).
pub fn state_object(query: &[(String, String)]) -> Value {
    Value::Object(
        query
            .iter()
            .map(|(k, v)| (k.clone(), Value::String(v.clone())))
            .collect(),
    )
}

/// The name of a reason in a reply.
pub fn reason_name(reason: IgnoredReason) -> &'static str {
    match reason {
        IgnoredReason::Unknown => "unknown",
        IgnoredReason::Invalid | IgnoredReason::Flagged => "invalid",
        IgnoredReason::File => "file",
    }
}

/// The error of a `setState` whose `ignored` keys were not used, and the same keys as
/// `[{"key":…,"reason":…}]`.
pub fn ignored_error(ignored: &[IgnoredKey]) -> (String, Value) {
    let named: Vec<String> = ignored
        .iter()
        .map(|k| format!("{} ({})", k.key, reason_name(k.reason)))
        .collect();
    let list = ignored
        .iter()
        .map(|k| {
            let mut entry = Map::new();
            entry.insert("key".into(), Value::String(k.key.clone()));
            entry.insert("reason".into(), reason_name(k.reason).into());
            Value::Object(entry)
        })
        .collect();
    (
        format!(
            "setState: these keys were not used and keep their last good value: {}",
            named.join(", ")
        ),
        Value::Array(list),
    )
}

fn envelope(id: Option<&Value>) -> Map<String, Value> {
    let mut message = Map::new();
    message.insert("namespace".into(), NAMESPACE.into());
    if let Some(id) = id {
        message.insert("id".into(), id.clone());
    }
    message
}

/// The reply to request `id` with `result`.
pub fn reply(id: &Value, result: Value) -> Value {
    let mut message = envelope(Some(id));
    message.insert("result".into(), result);
    Value::Object(message)
}

/// The error reply to request `id`, with `extra` fields (such as `ignored`).
pub fn error_reply(id: &Value, error: &str, extra: Vec<(&str, Value)>) -> Value {
    let mut message = envelope(Some(id));
    message.insert("error".into(), error.into());
    for (key, value) in extra {
        message.insert(key.into(), value);
    }
    Value::Object(message)
}

/// An event to the host: `name` and its fields.
pub fn event(name: &str, fields: Vec<(&str, Value)>) -> Value {
    let mut message = envelope(None);
    message.insert("event".into(), name.into());
    for (key, value) in fields {
        message.insert(key.into(), value);
    }
    Value::Object(message)
}

/// A readout's text split into its number and what follows it (its unit when the page writes
/// the unit in the same text): `"1.25 J"` is `(Some(1.25), "J")`, `"—"` is `(None, "")`. A
/// minus sign (U+2212) counts as `-`.
pub fn split_number(text: &str) -> (Option<f64>, String) {
    let text = text.trim();
    let (head, rest) = text.split_once(char::is_whitespace).unwrap_or((text, ""));
    match parse_number(head) {
        Some(x) => (Some(x), rest.trim().to_string()),
        None => (None, String::new()),
    }
}

/// A readout's number: its `data-value` when that reads as one, else the number its text
/// starts with.
pub fn readout_number(data_value: Option<&str>, text: &str) -> Option<f64> {
    data_value
        .and_then(parse_number)
        .or_else(|| split_number(text).0)
}

/// A finite number written as the page writes one (`data-value`, a readout's text).
pub fn parse_number(text: &str) -> Option<f64> {
    text.trim()
        .replace('\u{2212}', "-")
        .parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
}

/// A readout as a reply gives it: `{"value": number or null, "unit": text}`.
pub fn readout(value: Option<f64>, unit: &str) -> Value {
    let mut entry = Map::new();
    entry.insert(
        "value".into(),
        value
            .and_then(Number::from_f64)
            .map_or(Value::Null, Value::Number),
    );
    entry.insert("unit".into(), unit.into());
    Value::Object(entry)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn error_of(message: Message) -> (Value, String) {
        match message {
            Message::Malformed { id, error } => (id, error),
            other => panic!("not malformed: {other:?}"),
        }
    }

    #[test]
    fn requests_parse_from_objects_and_from_json_text() {
        let want = Message::Request(Request {
            id: json!(7),
            method: Method::Step(3),
        });
        assert_eq!(
            parse(&json!({"namespace": "bsv", "id": 7, "method": "step", "args": [3]})),
            want
        );
        assert_eq!(
            parse_text(r#"{"namespace":"bsv","id":7,"method":"step","args":[3]}"#),
            want
        );
        assert_eq!(
            parse(&json!({"namespace": "bsv", "id": "a", "method": "step"})),
            Message::Request(Request {
                id: json!("a"),
                method: Method::Step(1)
            })
        );
        assert_eq!(
            parse(&json!({"namespace": "bsv", "method": "getState"})),
            Message::Request(Request {
                id: Value::Null,
                method: Method::GetState
            })
        );
    }

    #[test]
    fn other_namespaces_and_non_objects_are_not_for_us() {
        for data in [
            json!({"namespace": "reveal", "method": "slide"}),
            json!({"method": "getState"}),
            json!("getState"),
            json!([1, 2]),
            json!(null),
            json!(3),
        ] {
            assert_eq!(parse(&data), Message::NotForUs, "{data}");
        }
        assert_eq!(parse_text("hello"), Message::NotForUs);
        assert_eq!(parse_text(r#"{"namespace":"reveal"}"#), Message::NotForUs);
    }

    #[test]
    fn every_malformed_request_gets_an_error_with_its_id() {
        let cases = [
            (json!({"namespace": "bsv"}), Value::Null, "no method"),
            (json!({"namespace": "bsv", "id": 1}), json!(1), "no method"),
            (
                json!({"namespace": "bsv", "id": 2, "method": "fly"}),
                json!(2),
                "unknown method",
            ),
            (
                json!({"namespace": "bsv", "id": 3, "method": 42}),
                json!(3),
                "method must be",
            ),
            (
                json!({"namespace": "bsv", "id": {}, "method": "getState"}),
                Value::Null,
                "id must be",
            ),
            (
                json!({"namespace": "bsv", "id": 4, "method": "getState", "args": "x"}),
                json!(4),
                "args must be",
            ),
            (
                json!({"namespace": "bsv", "id": 5, "method": "getReadouts", "args": [1]}),
                json!(5),
                "no arguments",
            ),
            (
                json!({"namespace": "bsv", "id": 6, "method": "setState"}),
                json!(6),
                "one object",
            ),
            (
                json!({"namespace": "bsv", "id": 7, "method": "setState", "args": [[1]]}),
                json!(7),
                "one object",
            ),
            (
                json!({"namespace": "bsv", "id": 8, "method": "step", "args": [1.5]}),
                json!(8),
                "whole number",
            ),
            (
                json!({"namespace": "bsv", "id": 9, "method": "step", "args": ["3"]}),
                json!(9),
                "must be a number",
            ),
            (
                json!({"namespace": "bsv", "id": 10, "method": "step", "args": [1e12]}),
                json!(10),
                "whole number",
            ),
            (
                json!({"namespace": "bsv", "id": 11, "method": "step", "args": [1, 2]}),
                json!(11),
                "one argument",
            ),
        ];
        for (data, id, error) in cases {
            let (got_id, got) = error_of(parse(&data));
            assert_eq!(got_id, id, "{data}");
            assert!(got.contains(error), "{data}: {got}");
        }
        let (id, error) = error_of(parse_text("{\"namespace\":\"bsv\""));
        assert_eq!(id, Value::Null);
        assert!(error.starts_with("not valid JSON"), "{error}");
    }

    #[test]
    fn set_state_takes_strings_numbers_and_null_and_names_other_values() {
        let message = parse(&json!({"namespace": "bsv", "id": 1, "method": "setState",
            "args": [{"q1": 0.5, "q2": "1.25", "elbow": null, "ws": true, "L1": {}}]}));
        let Message::Request(Request {
            method:
                Method::SetState {
                    mut changes,
                    mut invalid,
                },
            ..
        }) = message
        else {
            panic!("{message:?}");
        };
        changes.sort();
        invalid.sort();
        assert_eq!(
            changes,
            vec![
                ("elbow".to_string(), None),
                ("q1".to_string(), Some("0.5".to_string())),
                ("q2".to_string(), Some("1.25".to_string())),
            ]
        );
        assert_eq!(invalid, vec!["L1".to_string(), "ws".to_string()]);
    }

    #[test]
    fn changes_keep_order_add_last_and_remove() {
        let q = |pairs: &[(&str, &str)]| crate::view::url::query(pairs);
        let query = q(&[("a", "1"), ("b", "2"), ("c", "3")]);
        let changes = vec![
            ("b".to_string(), Some("20".to_string())),
            ("d".to_string(), Some("4".to_string())),
            ("a".to_string(), None),
            ("z".to_string(), None),
        ];
        assert_eq!(
            apply_changes(&query, &changes),
            q(&[("b", "20"), ("c", "3"), ("d", "4")])
        );
    }

    #[test]
    fn replies_and_events_carry_the_namespace() {
        assert_eq!(
            reply(&json!(3), json!({"q1": "1"})),
            json!({"namespace": "bsv", "id": 3, "result": {"q1": "1"}})
        );
        assert_eq!(
            error_reply(&Value::Null, "no method", vec![]),
            json!({"namespace": "bsv", "id": null, "error": "no method"})
        );
        assert_eq!(
            event("ready", vec![("page", json!("ik-2r"))]),
            json!({"namespace": "bsv", "event": "ready", "page": "ik-2r"})
        );
        let (error, list) =
            ignored_error(&[IgnoredKey::unknown("nope"), IgnoredKey::invalid("q1")]);
        assert!(error.contains("nope (unknown), q1 (invalid)"), "{error}");
        assert_eq!(
            list,
            json!([{"key": "nope", "reason": "unknown"}, {"key": "q1", "reason": "invalid"}])
        );
    }

    #[test]
    fn readout_texts_split_into_number_and_unit() {
        assert_eq!(split_number("1.25 J"), (Some(1.25), "J".to_string()));
        assert_eq!(split_number(" -0.5 "), (Some(-0.5), String::new()));
        assert_eq!(
            split_number("\u{2212}2 % of E(0) per s"),
            (Some(-2.0), "% of E(0) per s".to_string())
        );
        assert_eq!(split_number("1.5e-7"), (Some(1.5e-7), String::new()));
        assert_eq!(split_number("—"), (None, String::new()));
        assert_eq!(split_number(""), (None, String::new()));
        assert_eq!(parse_number("inf"), None);
        assert_eq!(
            readout(Some(2.0), "mm"),
            json!({"value": 2.0, "unit": "mm"})
        );
        assert_eq!(readout(None, ""), json!({"value": null, "unit": ""}));
    }

    #[test]
    fn replies_and_events_of_an_embedded_page_get_no_answer() {
        for message in [
            json!({"namespace": "bsv", "event": "ready", "page": "ik-2r"}),
            json!({"namespace": "bsv", "id": 1, "result": {"q1": "1"}}),
            json!({"namespace": "bsv", "id": null, "error": "no method"}),
        ] {
            assert_eq!(parse(&message), Message::NotForUs, "{message}");
            assert_eq!(parse_text(&message.to_string()), Message::NotForUs);
        }
        // With a method it is a request, whatever else it carries.
        assert!(matches!(
            parse(&json!({"namespace": "bsv", "method": "getState", "event": "x"})),
            Message::Request(_)
        ));
    }
}
