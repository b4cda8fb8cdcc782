//! Command-line style arguments, shared by `bsv` and `runRecipe`: positional values in the
//! recipe's order (missing ones take the recipe's default) plus `--flag value` options.
//!
//! Numbers parse like Python's `float()` / `int()` (surrounding spaces allowed, `1e-3`, `+2`),
//! but NaN and infinities are rejected: no recipe means them.

use crate::error::RecipeError;

/// How a value is entered and read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ArgKind {
    /// A real number (finite).
    Number,
    /// A whole number; any whole-number notation is accepted (`1e3`, `1000.0`).
    Integer,
    /// A seed of numpy's `default_rng`: a whole number in `[0, 2^63)`.
    Seed,
    /// `len` numbers separated by commas.
    List { len: usize },
    /// An input file, named by its path (traj-resample's CSV).
    File,
    /// One of a few words.
    Choice(&'static [&'static str]),
    /// Points `x,y;x,y;...` (each coordinate within the argument's limits); empty = none
    /// given (umeyama-2d's `--x`).
    Points,
}

/// A lower or upper limit of a value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// No limit on this side.
    None,
    /// The value may equal the limit.
    Incl(f64),
    /// The value must stay strictly on the inside of the limit.
    Excl(f64),
}

impl Bound {
    /// The limit's value, if there is one.
    pub fn value(self) -> Option<f64> {
        match self {
            Bound::None => None,
            Bound::Incl(v) | Bound::Excl(v) => Some(v),
        }
    }

    /// Whether `x` satisfies this bound taken as a lower limit.
    pub fn allows_from_below(self, x: f64) -> bool {
        match self {
            Bound::None => true,
            Bound::Incl(m) => x >= m,
            Bound::Excl(m) => x > m,
        }
    }

    /// Whether `x` satisfies this bound taken as an upper limit.
    pub fn allows_from_above(self, x: f64) -> bool {
        match self {
            Bound::None => true,
            Bound::Incl(m) => x <= m,
            Bound::Excl(m) => x < m,
        }
    }
}

/// One argument of a recipe, stated once: its name, its default as the recipe writes it, a
/// short English help (CLI), how it is entered, its unit, its limits and the Fluent id of the
/// hint that states those limits in words (`locales/*/recipes.ftl`).
///
/// The limits here are the ones the kernel enforces for this argument alone (cross-field
/// limits, such as rows = duration ÷ step, are checked by the recipe and reported with every
/// argument involved, see [`RecipeError::params`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArgSpec {
    pub name: &'static str,
    pub default: &'static str,
    pub help: &'static str,
    pub kind: ArgKind,
    /// "m", "s", "deg", "mm", "rad", ... (`None`: a plain number).
    pub unit: Option<&'static str>,
    pub min: Bound,
    pub max: Bound,
    /// Fluent id of the hint (recipes.ftl), `recipe-<id>-hint-<name>`.
    pub hint_id: &'static str,
    /// A `--flag` that may be given several times, each value kept in order (rrt-2d's
    /// `--obstacle`); any other flag keeps its last value.
    pub repeat: bool,
}

impl ArgSpec {
    /// A number argument without unit or limits (set them with the `const` builders).
    pub const fn number(name: &'static str, default: &'static str, help: &'static str) -> ArgSpec {
        ArgSpec {
            name,
            default,
            help,
            kind: ArgKind::Number,
            unit: None,
            min: Bound::None,
            max: Bound::None,
            hint_id: "",
            repeat: false,
        }
    }

    /// A seed of numpy's `default_rng`: a whole number from 0 to 2^63 - 1.
    pub const fn seed(name: &'static str, default: &'static str, help: &'static str) -> ArgSpec {
        ArgSpec::number(name, default, help)
            .kind(ArgKind::Seed)
            .limits(Bound::Incl(0.0), Bound::Incl(crate::rng::SEED_MAX as f64))
    }

    /// A whole number from `min` to `max`.
    pub const fn integer(
        name: &'static str,
        default: &'static str,
        help: &'static str,
        min: i64,
        max: i64,
    ) -> ArgSpec {
        ArgSpec::number(name, default, help)
            .kind(ArgKind::Integer)
            .limits(Bound::Incl(min as f64), Bound::Incl(max as f64))
    }

    /// The same argument entered as `kind`.
    pub const fn kind(self, kind: ArgKind) -> ArgSpec {
        ArgSpec { kind, ..self }
    }

    /// The same argument measured in `unit`.
    pub const fn unit(self, unit: &'static str) -> ArgSpec {
        ArgSpec {
            unit: Some(unit),
            ..self
        }
    }

    /// The same argument with these limits.
    pub const fn limits(self, min: Bound, max: Bound) -> ArgSpec {
        ArgSpec { min, max, ..self }
    }

    /// The same argument with its hint's Fluent id.
    pub const fn hint(self, hint_id: &'static str) -> ArgSpec {
        ArgSpec { hint_id, ..self }
    }

    /// The same flag, repeatable: every value is kept ([`Args::flag_texts`]).
    pub const fn repeatable(self) -> ArgSpec {
        ArgSpec {
            repeat: true,
            ..self
        }
    }

    /// Fluent id of the label: `recipe-<id>-arg-<name>`, or `recipe-<id>-flag-<name>` for a
    /// `--flag` option.
    pub fn label_id(&self, recipe_id: &str, flag: bool) -> String {
        let kind = if flag { "flag" } else { "arg" };
        format!("recipe-{recipe_id}-{kind}-{}", self.name)
    }

    /// Checks `value` against this argument's own limits (finite, `min`, `max`).
    pub fn check(&self, value: f64) -> Result<f64, RecipeError> {
        finite(self.name, value)?;
        if self.min.allows_from_below(value) && self.max.allows_from_above(value) {
            return Ok(value);
        }
        if self.min == Bound::Excl(0.0) && self.max == Bound::None {
            return Err(RecipeError::NotPositive {
                param: self.name.to_string(),
                value,
            });
        }
        Err(RecipeError::OutOfRange {
            param: self.name.to_string(),
            value,
            min: self.min.value().unwrap_or(f64::NEG_INFINITY),
            max: self.max.value().unwrap_or(f64::INFINITY),
        })
    }

    /// Checks one field's text on its own, as the recipe reads it: a number (or whole number,
    /// seed, list of numbers) within this argument's limits; a choice among its words. Returns
    /// the value (the first for a list; 0 for a file or a choice). Cross-field limits are the
    /// recipe's `plan` to check.
    pub fn check_text(&self, text: &str) -> Result<f64, RecipeError> {
        match self.kind {
            ArgKind::Number => self.check(parse_f64(self.name, text)?),
            ArgKind::Integer => {
                let value = match parse_i64(self.name, text) {
                    Ok(v) => v as f64,
                    Err(RecipeError::OutOfRange { value, .. }) => value,
                    Err(e) => return Err(e),
                };
                self.check(value)
            }
            ArgKind::Seed => parse_seed(self.name, text).map(|v| v as f64),
            ArgKind::List { .. } => Ok(self.list(text)?.first().copied().unwrap_or(0.0)),
            ArgKind::Choice(choices) => {
                let word = text.trim().to_ascii_lowercase();
                if choices.contains(&word.as_str()) {
                    Ok(0.0)
                } else {
                    Err(RecipeError::BadChoice {
                        param: self.name.to_string(),
                        value: text.to_string(),
                        choices: choices.join(", "),
                    })
                }
            }
            ArgKind::File => Ok(0.0),
            ArgKind::Points => Ok(self.points(text)?.first().map_or(0.0, |p: &[f64; 2]| p[0])),
        }
    }

    /// A points argument's values (`0.5,-1;2,0.25`): `x,y` pairs separated by semicolons,
    /// each coordinate a finite number within this argument's limits; a blank text is no
    /// points. A pair with another count of numbers is [`RecipeError::WrongCount`].
    pub fn points(&self, text: &str) -> Result<Vec<[f64; 2]>, RecipeError> {
        if text.trim().is_empty() {
            return Ok(Vec::new());
        }
        text.split(';')
            .map(|pair| {
                let values = pair
                    .split(',')
                    .map(|item| parse_f64(self.name, item).and_then(|v| self.check(v)))
                    .collect::<Result<Vec<f64>, _>>()?;
                match values[..] {
                    [x, y] => Ok([x, y]),
                    _ => Err(RecipeError::WrongCount {
                        param: self.name.to_string(),
                        expected: 2,
                        got: values.len(),
                    }),
                }
            })
            .collect()
    }

    /// A list argument's values (`0.35,0.25,0.65,0.75`): each a finite number within this
    /// argument's limits, then exactly `len` of them (any other kind: one value).
    pub fn list(&self, text: &str) -> Result<Vec<f64>, RecipeError> {
        let values = text
            .split(',')
            .map(|item| parse_f64(self.name, item).and_then(|v| self.check(v)))
            .collect::<Result<Vec<f64>, _>>()?;
        if let ArgKind::List { len } = self.kind {
            if values.len() != len {
                return Err(RecipeError::WrongCount {
                    param: self.name.to_string(),
                    expected: len,
                    got: values.len(),
                });
            }
        }
        Ok(values)
    }

    /// The limits in English words, for `bsv --help` ("from 0 to 1,000,000", "more than 0,
    /// no upper limit", "any number"), with the unit.
    pub fn limits_text(&self) -> String {
        use crate::pyfmt::human;
        let unit = self.unit.map(|u| format!(" {u}")).unwrap_or_default();
        let low = match self.min {
            Bound::None => None,
            Bound::Incl(v) => Some(format!("at least {}{unit}", human(v))),
            Bound::Excl(v) => Some(format!("more than {}{unit}", human(v))),
        };
        let high = match self.max {
            Bound::None => None,
            Bound::Incl(v) => Some(format!("at most {}{unit}", human(v))),
            Bound::Excl(v) => Some(format!("less than {}{unit}", human(v))),
        };
        if let (Bound::Incl(a), Bound::Incl(b)) = (self.min, self.max) {
            if !matches!(
                self.kind,
                ArgKind::Seed | ArgKind::Choice(_) | ArgKind::File
            ) {
                let whole = if self.kind == ArgKind::Integer {
                    "a whole number "
                } else {
                    ""
                };
                return format!("{whole}from {} to {}{unit}", human(a), human(b));
            }
        }
        match (&self.kind, low, high) {
            (ArgKind::Choice(choices), _, _) => format!("one of {}", choices.join(", ")),
            (ArgKind::File, _, _) => "a CSV file".to_string(),
            (ArgKind::Points, Some(l), Some(h)) => {
                format!("points x,y separated by semicolons, each coordinate {l} and {h}")
            }
            (ArgKind::Points, _, _) => "points x,y separated by semicolons".to_string(),
            (ArgKind::List { len }, Some(l), Some(h)) => {
                format!("{len} numbers separated by commas, each {l} and {h}")
            }
            (ArgKind::List { len }, _, _) => format!("{len} numbers separated by commas"),
            (ArgKind::Seed, _, _) => "a whole number from 0 to 9,223,372,036,854,775,807".into(),
            (_, Some(l), Some(h)) => format!("{l} and {h}"),
            (_, Some(l), None) => format!("{l}, no upper limit"),
            (_, None, Some(h)) => h,
            (_, None, None) => "any number".to_string(),
        }
    }
}

/// The cost of a run before running it: rows (or cells, iterations) of work. Pages use it to
/// decide whether to run at once, on a worker, or only on request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    pub rows: u64,
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
                let Some(spec) = flags.iter().find(|f| f.name == name) else {
                    return Err(RecipeError::UnknownFlag {
                        flag: format!("--{name}"),
                    });
                };
                let value = match inline {
                    Some(v) => v,
                    None => iter
                        .next()
                        .cloned()
                        .ok_or_else(|| RecipeError::MissingFlagValue {
                            flag: format!("--{name}"),
                        })?,
                };
                if !spec.repeat {
                    out.flags.retain(|(n, _)| n != name);
                }
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

    /// Every value given for a flag, in order (empty when it was not given; one value for a
    /// flag that is not [`ArgSpec::repeat`]).
    pub fn flag_texts<'a>(&'a self, spec: &ArgSpec) -> Vec<&'a str> {
        self.flags
            .iter()
            .filter(|(n, _)| n == spec.name)
            .map(|(_, v)| v.as_str())
            .collect()
    }

    /// Whether a flag was given.
    pub fn has_flag(&self, spec: &ArgSpec) -> bool {
        self.flags.iter().any(|(n, _)| n == spec.name)
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

/// Parses a whole number: Python `int()` notation (`800`, `+2`, `1_000`) or any float notation
/// whose value is whole (`1e3`, `1000.0`). A whole value beyond i64 is out of range (reported
/// against i64's own limits), not "not a whole number".
pub fn parse_i64(param: &str, text: &str) -> Result<i64, RecipeError> {
    let cleaned = text.trim().replace('_', "");
    if let Ok(v) = cleaned.parse::<i64>() {
        return Ok(v);
    }
    let not_integer = || RecipeError::NotAnInteger {
        param: param.to_string(),
        value: text.to_string(),
    };
    let integral_digits = {
        let digits = cleaned.trim_start_matches(['+', '-']);
        !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit())
    };
    match cleaned.parse::<f64>() {
        Ok(v) if v.is_finite() && (v.fract() == 0.0 || integral_digits) => {
            // 2^63 is the first f64 beyond i64::MAX.
            if (-9_223_372_036_854_775_808.0..9_223_372_036_854_775_808.0).contains(&v) {
                Ok(v as i64)
            } else {
                Err(out_of_range(param, v, i64::MIN, i64::MAX))
            }
        }
        _ => Err(not_integer()),
    }
}

/// Parses a whole-number argument ([`parse_i64`]) and checks `min <= value <= max`.
pub fn parse_count(param: &str, text: &str, min: i64, max: i64) -> Result<i64, RecipeError> {
    match parse_i64(param, text) {
        Ok(v) => check_count(param, v, min, max),
        Err(RecipeError::OutOfRange { value, .. }) => Err(out_of_range(param, value, min, max)),
        Err(e) => Err(e),
    }
}

/// Parses a seed of numpy's `default_rng` ([`crate::rng::parse_seed`]), also in any
/// whole-number notation (`1e3`, `7.0`).
pub fn parse_seed(param: &str, text: &str) -> Result<u64, RecipeError> {
    match crate::rng::parse_seed(param, text) {
        Err(RecipeError::NotAnInteger { .. }) => {
            let v = parse_i64(param, text).map_err(|e| match e {
                RecipeError::OutOfRange { value, .. } => RecipeError::OutOfRange {
                    param: param.to_string(),
                    value,
                    min: 0.0,
                    max: crate::rng::SEED_MAX as f64,
                },
                other => other,
            })?;
            crate::rng::parse_seed(param, &v.to_string())
        }
        other => other,
    }
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
    rows_within(param, &[], count, limit)
}

/// [`within_limit`] for a count that several arguments set together: `param` (the step, the
/// one to change first) and `also` (the span's arguments), all named by the error.
pub fn rows_within(param: &str, also: &[&str], count: f64, limit: u64) -> Result<u64, RecipeError> {
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
            also: also.iter().map(|a| a.to_string()).collect(),
            square: false,
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
        ArgSpec::number("L1", "0.12", ""),
        ArgSpec::number("seed", "7", ""),
    ];
    const FLAGS: [ArgSpec; 1] = [ArgSpec::number("damping", "0.05", "")];

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
    fn fields_check_their_own_text_by_kind_and_limits() {
        let n = ArgSpec::integer("n", "24", "", 1, 1024);
        assert_eq!(n.check_text("1e3"), Ok(1000.0));
        assert_eq!(n.check_text("24.0"), Ok(24.0));
        assert!(matches!(
            n.check_text("2.5"),
            Err(RecipeError::NotAnInteger { .. })
        ));
        assert!(matches!(
            n.check_text("1e30"),
            Err(RecipeError::OutOfRange { max, .. }) if max == 1024.0
        ));
        let dt = ArgSpec::number("dt", "0.02", "").limits(Bound::Excl(0.0), Bound::None);
        assert!(matches!(
            dt.check_text("0"),
            Err(RecipeError::NotPositive { .. })
        ));
        assert_eq!(dt.check_text(" 1e-3 "), Ok(1e-3));
        assert_eq!(dt.limits_text(), "more than 0, no upper limit");
        let seed = ArgSpec::seed("seed", "7", "");
        assert_eq!(seed.check_text("7.0"), Ok(7.0));
        assert!(seed.check_text("-1").is_err());
        let angles = ArgSpec::number("angles", "", "").kind(ArgKind::List { len: 3 });
        assert_eq!(angles.check_text("0.1,0.2,0.3"), Ok(0.1));
        assert!(matches!(
            angles.check_text("1,2"),
            Err(RecipeError::WrongCount { got: 2, .. })
        ));
        let choice =
            ArgSpec::number("integrator", "euler", "").kind(ArgKind::Choice(&["euler", "rk4"]));
        assert_eq!(choice.check_text("RK4"), Ok(0.0));
        assert!(matches!(
            choice.check_text("rk5"),
            Err(RecipeError::BadChoice { .. })
        ));
        let points = ArgSpec::number("x", "", "")
            .kind(ArgKind::Points)
            .limits(Bound::Incl(-10.0), Bound::Incl(10.0));
        assert_eq!(points.check_text(""), Ok(0.0));
        assert_eq!(
            points.points(" 1, 2 ;-0.5,3e-1"),
            Ok(vec![[1.0, 2.0], [-0.5, 0.3]])
        );
        assert!(matches!(
            points.check_text("1,2;3"),
            Err(RecipeError::WrongCount {
                expected: 2,
                got: 1,
                ..
            })
        ));
        assert!(matches!(
            points.check_text("1,20"),
            Err(RecipeError::OutOfRange { .. })
        ));
        assert!(matches!(
            points.check_text("1,2;"),
            Err(RecipeError::NotANumber { .. })
        ));
        assert_eq!(
            ArgSpec::number("L1", "", "")
                .unit("m")
                .limits(Bound::Incl(1e-6), Bound::Incl(10.0))
                .limits_text(),
            "from 0.000001 to 10 m"
        );
    }

    #[test]
    fn limits() {
        assert!(positive("dt", 0.0).is_err());
        assert!(in_range("n", 5.0, 1.0, 4.0).is_err());
        assert_eq!(within_limit("n", 10.0, 10).unwrap(), 10);
        assert!(within_limit("n", f64::INFINITY, 10).is_err());
    }
}
