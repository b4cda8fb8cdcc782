//! What a recipe run gives back: the CSV files it writes, the summary line the Python recipe
//! prints, and the warnings about the result.

use crate::error::RecipeWarning;

/// One CSV file a recipe writes.
#[derive(Debug, Clone, PartialEq)]
pub struct CsvFile {
    pub name: String,
    pub text: String,
}

/// The files and the printed summary of one recipe run.
#[derive(Debug, Clone, PartialEq)]
pub struct RecipeOutput {
    pub files: Vec<CsvFile>,
    /// Exactly what the Python recipe prints (lines joined with `\n`, no trailing newline).
    pub summary: String,
    /// What looks wrong with the result (diverged, unreachable goal...); not in the CSV.
    pub warnings: Vec<RecipeWarning>,
}

impl RecipeOutput {
    /// A run that wrote one file.
    pub fn single(name: &str, text: String, summary: String) -> RecipeOutput {
        RecipeOutput {
            files: vec![CsvFile {
                name: name.to_string(),
                text,
            }],
            summary,
            warnings: Vec::new(),
        }
    }

    /// The same output with `warnings` added.
    pub fn with_warnings(mut self, warnings: Vec<RecipeWarning>) -> RecipeOutput {
        self.warnings.extend(warnings);
        self
    }

    /// The text of the file called `name`, if the run wrote it.
    pub fn file(&self, name: &str) -> Option<&str> {
        self.files
            .iter()
            .find(|f| f.name == name)
            .map(|f| f.text.as_str())
    }
}
