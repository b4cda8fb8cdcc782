//! Command-line style arguments, shared by `bsv` and `runRecipe`: positional values in the
//! recipe's order (missing ones take the recipe's default) plus `--flag value` options.
//!
//! Numbers parse like Python's `float()` / `int()` (surrounding spaces allowed, `1e-3`, `+2`),
//! but NaN and infinities are rejected: no recipe means them.

use crate::error::RecipeError;

/// One argument of a recipe: its name, its default as the recipe writes it, and a short help.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArgSpec {
    pub name: &'static str,
    pub default: &'static str,
    pub help: &'static str,
}

/// Parsed arguments of one recipe call.
#[derive(Debug, Clone, Default)]
pub struct Args {
    positional: Vec<String>,
    flags: Vec<(String, String)>,
    inputs: Vec<(String, String)>,
}

impl Args {
    /// Splits raw arguments into positional values and `--flag value` / `--flag=value`
    /// options, checking both against what the recipe takes. `--out` is never a recipe flag;
    /// callers that support it remove it first.
    pub fn parse(
        raw: &[String],
        positional: &[ArgSpec],
        flags: &[ArgSpec],
    ) -> Result<Args, RecipeError> {
        let mut out = Args::default();
        let mut iter = raw.iter();
        while let Some(arg) = iter.next() {
            if let Some(name) = flag_name(arg) {
                let (name, inline) = match name.split_once('=') {
                    Some((n, v)) => (n, Some(v.to_string())),
                    None => (name, None),
                };
                if !flags.iter().any(|f| f.name == name) {
                    return Err(RecipeError::UnknownFlag {
                        flag: format!("--{name}"),
                    });
                }
                let value = match inline {
                    Some(v) => v,
                    None => iter
                        .next()
                        .cloned()
                        .ok_or_else(|| RecipeError::MissingFlagValue {
                            flag: format!("--{name}"),
                        })?,
                };
                out.flags.retain(|(n, _)| n != name);
                out.flags.push((name.to_string(), value));
            } else {
                out.positional.push(arg.clone());
            }
        }
        if out.positional.len() > positional.len() {
            return Err(RecipeError::TooManyArgs {
                max: positional.len(),
                got: out.positional.len(),
            });
        }
        Ok(out)
    }

    /// Attaches input files by name (the CLI reads them from disk; the browser passes what the
    /// user opened), so that a positional path argument can be resolved to text.
    pub fn with_inputs(mut self, inputs: Vec<(String, String)>) -> Args {
        self.inputs = inputs;
        self
    }

    /// The text of input file `name`, if it was attached.
    pub fn input(&self, name: &str) -> Option<&str> {
        self.inputs
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.as_str())
    }

    /// The raw text of positional argument `index`, or `default` when it was not given.
    pub fn text<'a>(&'a self, index: usize, spec: &'a ArgSpec) -> &'a str {
        self.positional
            .get(index)
            .map(String::as_str)
            .unwrap_or(spec.default)
    }

    /// Whether positional argument `index` was given.
    pub fn has(&self, index: usize) -> bool {
        self.positional.get(index).is_some()
    }

    /// Positional argument `index` as a finite float.
    pub fn f64(&self, index: usize, spec: &ArgSpec) -> Result<f64, RecipeError> {
        parse_f64(spec.name, self.text(index, spec))
    }

    /// Positional argument `index` as an integer.
    pub fn i64(&self, index: usize, spec: &ArgSpec) -> Result<i64, RecipeError> {
        parse_i64(spec.name, self.text(index, spec))
    }

    /// The raw text of a flag, or its default.
    pub fn flag_text<'a>(&'a self, spec: &'a ArgSpec) -> &'a str {
        self.flags
            .iter()
            .find(|(n, _)| n == spec.name)
            .map(|(_, v)| v.as_str())
            .unwrap_or(spec.default)
    }

    /// A flag as a finite float, or its default.
    pub fn flag_f64(&self, spec: &ArgSpec) -> Result<f64, RecipeError> {
        parse_f64(spec.name, self.flag_text(spec))
    }
}

fn flag_name(arg: &str) -> Option<&str> {
    let rest = arg.strip_prefix("--")?;
    // "--" alone, or a negative number such as "-0.5", is not a flag.
    if rest.is_empty() || rest.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
        None
    } else {
        Some(rest)
    }
}

/// Parses a float like Python's `float()`, rejecting NaN and infinities.
pub fn parse_f64(param: &str, text: &str) -> Result<f64, RecipeError> {
    let cleaned = text.trim().replace('_', "");
    let value: f64 = cleaned.parse().map_err(|_| RecipeError::NotANumber {
        param: param.to_string(),
        value: text.to_string(),
    })?;
    finite(param, value)
}

/// Rejects NaN and infinities (typed callers bypass the argument parser).
pub fn finite(param: &str, value: f64) -> Result<f64, RecipeError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(RecipeError::NotFinite {
            param: param.to_string(),
        })
    }
}

/// Parses an integer like Python's `int()` (no decimal point).
pub fn parse_i64(param: &str, text: &str) -> Result<i64, RecipeError> {
    let cleaned = text.trim().replace('_', "");
    cleaned.parse().map_err(|_| RecipeError::NotAnInteger {
        param: param.to_string(),
        value: text.to_string(),
    })
}

/// Parses a whole-number argument like Python's `int()` and checks `min <= value <= max`.
/// A well-formed integer too long for i64 is out of range, not "not a whole number".
pub fn parse_count(param: &str, text: &str, min: i64, max: i64) -> Result<i64, RecipeError> {
    let value = match parse_i64(param, text) {
        Ok(v) => v,
        Err(e) => {
            let digits = text.trim().trim_start_matches(['+', '-']);
            let integral = !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit());
            return match text.trim().parse::<f64>() {
                Ok(v) if integral => Err(out_of_range(param, v, min, max)),
                _ => Err(e),
            };
        }
    };
    check_count(param, value, min, max)
}

/// Checks `min <= value <= max` for a whole-number parameter.
pub fn check_count(param: &str, value: i64, min: i64, max: i64) -> Result<i64, RecipeError> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(out_of_range(param, value as f64, min, max))
    }
}

fn out_of_range(param: &str, value: f64, min: i64, max: i64) -> RecipeError {
    RecipeError::OutOfRange {
        param: param.to_string(),
        value,
        min: min as f64,
        max: max as f64,
    }
}

/// Checks `value > 0`.
pub fn positive(param: &str, value: f64) -> Result<f64, RecipeError> {
    if value > 0.0 {
        Ok(value)
    } else {
        Err(RecipeError::NotPositive {
            param: param.to_string(),
            value,
        })
    }
}

/// Checks `min <= value <= max`.
pub fn in_range(param: &str, value: f64, min: f64, max: f64) -> Result<f64, RecipeError> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(RecipeError::OutOfRange {
            param: param.to_string(),
            value,
            min,
            max,
        })
    }
}

/// Checks that a derived row/cell/iteration count stays within `limit`.
pub fn within_limit(param: &str, count: f64, limit: u64) -> Result<u64, RecipeError> {
    if count.is_finite() && count >= 0.0 && count <= limit as f64 {
        Ok(count as u64)
    } else {
        let count = if count.is_finite() && count > 0.0 {
            count.min(u64::MAX as f64) as u64
        } else {
            u64::MAX
        };
        Err(RecipeError::TooLarge {
            param: param.to_string(),
            count,
            limit,
        })
    }
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    const POS: [ArgSpec; 2] = [
        ArgSpec {
            name: "L1",
            default: "0.12",
            help: "",
        },
        ArgSpec {
            name: "seed",
            default: "7",
            help: "",
        },
    ];
    const FLAGS: [ArgSpec; 1] = [ArgSpec {
        name: "damping",
        default: "0.05",
        help: "",
    }];

    fn strings(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn defaults_positional_and_flags() {
        let a = Args::parse(&strings(&["-0.5", "--damping=0.1"]), &POS, &FLAGS).unwrap();
        assert_eq!(a.f64(0, &POS[0]).unwrap(), -0.5);
        assert_eq!(a.i64(1, &POS[1]).unwrap(), 7);
        assert_eq!(a.flag_f64(&FLAGS[0]).unwrap(), 0.1);
        let a = Args::parse(&strings(&["--damping", "0"]), &POS, &FLAGS).unwrap();
        assert_eq!(a.flag_f64(&FLAGS[0]).unwrap(), 0.0);
    }

    #[test]
    fn rejects_what_python_would_choke_on() {
        let bad = |v: &[&str]| Args::parse(&strings(v), &POS, &FLAGS);
        assert!(matches!(
            bad(&["1", "2", "3"]),
            Err(RecipeError::TooManyArgs { max: 2, got: 3 })
        ));
        assert!(matches!(
            bad(&["--nope", "1"]),
            Err(RecipeError::UnknownFlag { .. })
        ));
        assert!(matches!(
            bad(&["--damping"]),
            Err(RecipeError::MissingFlagValue { .. })
        ));
        let a = bad(&["abc", "7.5"]).unwrap();
        assert!(matches!(
            a.f64(0, &POS[0]),
            Err(RecipeError::NotANumber { .. })
        ));
        assert!(matches!(
            a.i64(1, &POS[1]),
            Err(RecipeError::NotAnInteger { .. })
        ));
        let a = bad(&["nan"]).unwrap();
        assert!(matches!(
            a.f64(0, &POS[0]),
            Err(RecipeError::NotFinite { .. })
        ));
        assert_eq!(parse_f64("x", " 1e-3 ").unwrap(), 1e-3);
    }

    #[test]
    fn limits() {
        assert!(positive("dt", 0.0).is_err());
        assert!(in_range("n", 5.0, 1.0, 4.0).is_err());
        assert_eq!(within_limit("n", 10.0, 10).unwrap(), 10);
        assert!(within_limit("n", f64::INFINITY, 10).is_err());
    }
}
