//! The arguments of one run and the equivalent command lines, from the recipe's facts and the
//! form's texts: `bsv <id> <positional> [--flag value ...]` and `python <recipe>.py
//! <positional>`, quoted for a POSIX shell so that a copied line runs as written.
//!
//! Positional values are written in order up to the last one that differs from its default,
//! or, when all are defaults, as many as can be written before an empty one (traj-resample's
//! path): `bsv pid-step 1.2 0.4 0.05 0.8 80`, `bsv traj-resample`, `bsv traj-resample '' 0.05`.
//! Options are written only when they differ from their defaults; the Python recipes take no
//! options, so their line carries the positional values only (pages say so when options are
//! set).

use super::field::{typed, FieldDef};

/// `text` as one POSIX shell word: as it is when it holds only plain characters, else in
/// single quotes (`''` for an empty word).
pub fn shell_word(text: &str) -> String {
    let plain = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.,+/:=@%".contains(c));
    if plain {
        text.to_string()
    } else {
        format!("'{}'", text.replace('\'', r"'\''"))
    }
}

/// The arguments of one run, as the command line spells them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunArgs {
    /// Recipe id.
    pub recipe: &'static str,
    /// Every positional value in order, defaults filled in (an empty path means the sample).
    pub positional: Vec<String>,
    /// The positional defaults, in order.
    defaults: Vec<&'static str>,
    /// Options that differ from their defaults: `(name, value)`.
    pub flags: Vec<(String, String)>,
}

impl RunArgs {
    /// The run of `fields` with the texts typed in them (`None` or blank = the default).
    pub fn new(recipe: &'static str, fields: &[FieldDef], texts: &[Option<String>]) -> RunArgs {
        let mut positional = Vec::new();
        let mut defaults = Vec::new();
        let mut flags = Vec::new();
        for (index, field) in fields.iter().enumerate() {
            let value = typed(texts, index).unwrap_or(field.default());
            if field.flag {
                if value != field.default() {
                    flags.push((field.name().to_string(), value.to_string()));
                }
            } else {
                positional.push(value.to_string());
                defaults.push(field.default());
            }
        }
        RunArgs {
            recipe,
            positional,
            defaults,
            flags,
        }
    }

    /// What the kernel parses: every positional value, then `--name value` per option.
    pub fn raw(&self) -> Vec<String> {
        let mut raw = self.positional.clone();
        for (name, value) in &self.flags {
            raw.push(format!("--{name}"));
            raw.push(value.clone());
        }
        raw
    }

    /// The positional values the command lines write (see the module docs).
    fn positional_words(&self) -> Vec<String> {
        let last_changed = self
            .positional
            .iter()
            .zip(&self.defaults)
            .rposition(|(value, default)| value != default)
            .map_or(0, |i| i + 1);
        let leading = self
            .positional
            .iter()
            .take_while(|value| !value.is_empty())
            .count();
        self.positional
            .iter()
            .take(last_changed.max(leading))
            .map(|v| shell_word(v))
            .collect()
    }

    /// `bsv <id> <args> [--flag value ...]`.
    pub fn bsv_command(&self) -> String {
        let mut words = vec!["bsv".to_string(), self.recipe.to_string()];
        words.extend(self.positional_words());
        for (name, value) in &self.flags {
            words.push(format!("--{name}"));
            words.push(shell_word(value));
        }
        words.join(" ")
    }

    /// `python <script> <args>` (positional values only).
    pub fn python_command(&self, script: &str) -> String {
        let mut words = vec!["python".to_string(), script.to_string()];
        words.extend(self.positional_words());
        words.join(" ")
    }

    /// The options the Python line cannot carry, as `--name value` words (empty when none).
    pub fn options_text(&self) -> String {
        self.flags
            .iter()
            .map(|(n, v)| format!("--{n} {}", shell_word(v)))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

#[cfg(test)]
mod tests {
    use super::super::field::{recipe_fields, texts_by_name};
    use super::*;
    use crate::recipes::{self, RECIPES};

    fn run_args(id: &'static str, texts: &[(&str, &str)]) -> RunArgs {
        let fields = recipe_fields(recipes::find(id).unwrap().info);
        RunArgs::new(id, &fields, &texts_by_name(&fields, texts))
    }

    /// Splits a shown line back into words as a POSIX shell would (single quotes and
    /// backslashes outside them).
    fn shell_split(line: &str) -> Vec<String> {
        let mut words = Vec::new();
        let mut word = String::new();
        let mut quoted = false;
        let mut any = false;
        let mut chars = line.chars();
        while let Some(c) = chars.next() {
            match (c, quoted) {
                ('\\', false) => word.extend(chars.next()),
                ('\'', _) => {
                    quoted = !quoted;
                    any = true;
                }
                (' ', false) => {
                    if any || !word.is_empty() {
                        words.push(std::mem::take(&mut word));
                    }
                    any = false;
                }
                (c, _) => word.push(c),
            }
        }
        if any || !word.is_empty() {
            words.push(word);
        }
        words
    }

    #[test]
    fn quotes_only_what_needs_it() {
        assert_eq!(shell_word("0.12"), "0.12");
        assert_eq!(shell_word("0.2,0.4,-0.3"), "0.2,0.4,-0.3");
        assert_eq!(shell_word(""), "''");
        assert_eq!(shell_word("my traj.csv"), "'my traj.csv'");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
        assert_eq!(
            shell_split(r"bsv x 'it'\''s' ''"),
            vec!["bsv", "x", "it's", ""]
        );
    }

    #[test]
    fn defaults_read_like_the_home_page_cards() {
        assert_eq!(
            run_args("pid-step", &[]).bsv_command(),
            "bsv pid-step 1.2 0.4 0.05 0.8 80"
        );
        assert_eq!(
            run_args("pid-step", &[]).python_command("pid_step_response.py"),
            "python pid_step_response.py 1.2 0.4 0.05 0.8 80"
        );
        assert_eq!(
            run_args("traj-resample", &[]).bsv_command(),
            "bsv traj-resample"
        );
        assert_eq!(
            run_args("dh-fk", &[]).bsv_command(),
            "bsv dh-fk 0.2,0.4,-0.3"
        );
    }

    #[test]
    fn changed_values_and_options_are_written() {
        let pid = run_args("pid-step", &[("Kp", " 2 "), ("steps", "120")]);
        assert_eq!(pid.bsv_command(), "bsv pid-step 2 0.4 0.05 0.8 120");
        assert_eq!(pid.raw(), vec!["2", "0.4", "0.05", "0.8", "120"]);
        let pend = run_args(
            "pendulum-energy",
            &[("duration_s", "2"), ("integrator", "rk4")],
        );
        assert_eq!(pend.bsv_command(), "bsv pendulum-energy 2 --integrator rk4");
        assert_eq!(
            pend.python_command("mujoco_pendulum_energy.py"),
            "python mujoco_pendulum_energy.py 2"
        );
        assert_eq!(pend.raw(), vec!["2", "--integrator", "rk4"]);
        assert_eq!(pend.options_text(), "--integrator rk4");
        let sample = run_args("traj-resample", &[("dt", "0.05")]);
        assert_eq!(sample.bsv_command(), "bsv traj-resample '' 0.05");
        let file = run_args("traj-resample", &[("csv_path", "my traj.csv")]);
        assert_eq!(file.bsv_command(), "bsv traj-resample 'my traj.csv' 0.02");
    }

    #[test]
    fn the_command_line_runs_what_the_page_runs() {
        // Parsing the written command back gives the same output as the page's raw arguments.
        for recipe in RECIPES {
            let id = recipe.info.id;
            for texts in [vec![], vec![("seed", "42"), ("goal-x", "0.5")]] {
                let args = run_args(id, &texts);
                let words = shell_split(&args.bsv_command());
                assert_eq!(&words[..2], &["bsv", id]);
                assert_eq!(
                    recipes::run(id, &words[2..]).unwrap(),
                    recipes::run(id, &args.raw()).unwrap(),
                    "{id}"
                );
            }
        }
    }
}
