//! The last successful run, as the result panel shows it: its arguments, the recipe's output
//! (or the worker's files and warnings), and the table previews of its CSV files.

use crate::recipes::{CsvFile, RecipeOutput};
use crate::ui::ctx;
use crate::ui::kit::worker::{Localized, WorkerFile, WorkerOutput};
use crate::view::command_line::RunArgs;
use crate::view::form::fluent_args;
use crate::view::table::{preview, Preview};

/// The last successful run.
pub(super) struct Shown {
    /// The arguments it ran with.
    pub args: RunArgs,
    /// The input file it read, by name.
    pub input_name: Option<String>,
    pub output: RecipeOutput,
    /// One preview per file of `output`.
    pub previews: Vec<Preview>,
    /// A worker run's files as Blobs (then `output`'s texts are only their first lines;
    /// background.rs).
    pub blobs: Vec<WorkerFile>,
    /// A worker run's warnings, formatted in both languages by the worker (a page run's are
    /// `output.warnings`).
    pub worker_warnings: Vec<Localized>,
}

impl Shown {
    /// A run's result, with its previews (one scan of each file for its row count).
    pub fn new(args: RunArgs, input_name: Option<String>, output: RecipeOutput) -> Shown {
        let previews = output.files.iter().map(|f| preview(&f.text)).collect();
        Shown {
            args,
            input_name,
            output,
            previews,
            blobs: Vec::new(),
            worker_warnings: Vec::new(),
        }
    }

    /// A worker run's result: previews from each file's head, sizes and row counts from the
    /// worker, the bytes left in the Blobs.
    pub fn from_worker(args: RunArgs, input_name: Option<String>, out: WorkerOutput) -> Shown {
        let previews = out
            .files
            .iter()
            .map(|f| Preview {
                total_rows: f.rows as usize,
                ..preview(&f.head)
            })
            .collect();
        let output = RecipeOutput {
            files: out
                .files
                .iter()
                .map(|f| CsvFile {
                    name: f.name.clone(),
                    text: f.head.clone(),
                })
                .collect(),
            summary: out.summary,
            warnings: Vec::new(),
        };
        Shown {
            args,
            input_name,
            output,
            previews,
            blobs: out.files,
            worker_warnings: out.warnings,
        }
    }

    /// The run's warnings in the current language.
    pub fn warnings(&self) -> Vec<String> {
        self.output
            .warnings
            .iter()
            .map(|w| ctx::t_args(w.message_id(), &fluent_args(w.message_args())))
            .chain(self.worker_warnings.iter().map(|w| w.text().to_string()))
            .collect()
    }

    /// The size in bytes of file `name`.
    pub fn bytes(&self, name: &str, text: &str) -> u64 {
        self.blobs
            .iter()
            .find(|b| b.name == name)
            .map_or(text.len() as u64, |b| b.bytes)
    }
}
