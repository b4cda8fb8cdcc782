//! "LeRobot dataset" (`data-download="so101_lerobot_v3.zip"`): the session's labelled episodes
//! as a LeRobot dataset v3.0 (`crate::so101::dataset`). Everything but the page's slot
//! ([`DatasetSlot`]: the progress line and, once fetched, the exporter) is a wasm chunk of its
//! own, fetched on the first export and never in the page's first load: the parquet and zip
//! writers and the exporter ([`ExportUi`]), which writes in slices between tasks, each slice
//! replaying a few hundred steps at a time for [`MS_PER_TASK`], with a progress line
//! (`data-so101="dataset-progress"`, `data-state` `writing|done|none|failed`). The last zip
//! written and the labels it was written from are kept: while the session's labels are those,
//! the evidence lists the zip with its SHA-256.

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::{Blob, BlobPropertyBag, Element};

use crate::i18n::FluentArg;
use crate::so101::dataset::{DatasetError, ExportJob, LabelledEpisode, ZIP_NAME};
use crate::so101::Episode;
use crate::teleop::session::{label_id, Artifact, ExtraArtifact, Session, DATASET_TYPE};
use crate::ui::ctx;
use crate::ui::kit::chunk_fns::ChunkFns;
use crate::ui::kit::scope::Scope;
use crate::ui::page::SplitLoaderError;
use crate::ui::schedule::{now_ms, Timer};

/// Simulation steps replayed between two clock reads.
const STEPS_PER_PIECE: usize = 250;
/// Time spent writing per task, ms (the page stays responsive while a long session is
/// written, with room under the 50 ms of a long task on a slower machine).
const MS_PER_TASK: f64 = 12.0;

/// The exporter, behind the chunk's code.
pub trait ExportUi {
    /// Writes the dataset of `session`'s labelled episodes (as they are now) and offers the
    /// zip; a click while one is written is ignored.
    fn start(&self, session: &Session<Episode>);
    /// The zip's artifact for the evidence, if one was written from `session`'s labels as
    /// they are now.
    fn artifact_for(&self, session: &Session<Episode>) -> Option<ExtraArtifact>;
    /// The progress line in the new language.
    fn relocalize(&self);
}

/// The chunk's function: the exporter writing its progress to the given line.
pub type Open = fn(Element) -> Rc<dyn ExportUi>;

fn open(progress: Element) -> Rc<dyn ExportUi> {
    DatasetExport::new(progress)
}

/// The dataset writer's chunk.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(so101_dataset, fallible)]
pub fn load() -> Result<Open, SplitLoaderError> {
    Ok(open)
}

/// Without the `split` feature the writer is in the one wasm.
#[cfg(not(feature = "split"))]
pub async fn load() -> Result<Open, SplitLoaderError> {
    Ok(open)
}

/// The page's side: the progress line, the chunk's function once fetched, the exporter once
/// opened.
pub struct DatasetSlot {
    progress: Element,
    pub fns: ChunkFns<Open>,
    ui: RefCell<Option<Rc<dyn ExportUi>>>,
}

impl DatasetSlot {
    /// Finds the progress line under `root`.
    pub fn find(root: &Element) -> Result<DatasetSlot, JsValue> {
        Ok(DatasetSlot {
            progress: crate::ui::dom::find(root, "[data-so101=\"dataset-progress\"]", "so101")?,
            fns: ChunkFns::default(),
            ui: RefCell::new(None),
        })
    }

    /// The exporter (opened with `open` the first time).
    pub fn ui(&self, open: Open) -> Rc<dyn ExportUi> {
        self.ui
            .borrow_mut()
            .get_or_insert_with(|| open(self.progress.clone()))
            .clone()
    }

    /// See [`ExportUi::artifact_for`] (none before the first export).
    pub fn artifact_for(&self, session: &Session<Episode>) -> Option<ExtraArtifact> {
        self.ui.borrow().as_ref()?.artifact_for(session)
    }

    /// See [`ExportUi::relocalize`].
    pub fn relocalize(&self) {
        if let Some(ui) = self.ui.borrow().as_ref() {
            ui.relocalize();
        }
    }

    /// The chunk could not be fetched (`failed`); nothing to say once it came after all.
    pub fn show_unloaded(&self, failed: bool) {
        if failed {
            let _ = self.progress.set_attribute("data-state", "failed");
            self.progress
                .set_text_content(Some(&ctx::t("so101-dataset-unloaded")));
            crate::ui::dom::show(&self.progress, true);
        }
    }
}

/// What the labels of `session` are, as far as the dataset is concerned: each labelled
/// episode's number, label, category and note.
fn fingerprint(session: &Session<Episode>) -> String {
    session
        .episodes
        .iter()
        .filter_map(|e| {
            e.label.map(|l| {
                let category = e.category.map_or("", |c| c.id());
                format!("{}:{}:{category}:{}\n", e.number, label_id(l), e.note)
            })
        })
        .collect()
}

/// The labelled episodes of `session`, in their order.
fn labelled(session: &Session<Episode>) -> Vec<LabelledEpisode> {
    session
        .episodes
        .iter()
        .filter_map(|e| {
            e.label.map(|label| LabelledEpisode {
                episode: (*e.episode).clone(),
                label,
                category: e.category,
                note: e.note.clone(),
            })
        })
        .collect()
}

/// The progress line's message: its Fluent id and arguments.
type Said = (&'static str, Vec<(&'static str, FluentArg)>);

/// A job under way.
struct Running {
    job: ExportJob,
    fingerprint: String,
}

/// The exporter (in the chunk).
struct DatasetExport {
    progress: Element,
    running: RefCell<Option<Running>>,
    /// The last zip written: the labels it was written from and its artifact.
    last: RefCell<Option<(String, Artifact)>>,
    /// The progress line's message (rewritten in a new language).
    said: RefCell<Option<Said>>,
    timer: Rc<Timer>,
    _scope: Scope,
}

impl ExportUi for DatasetExport {
    fn start(&self, session: &Session<Episode>) {
        if self.running.borrow().is_some() {
            return;
        }
        let episodes = labelled(session);
        if episodes.is_empty() {
            self.say("none", ("so101-dataset-none", Vec::new()));
            return;
        }
        self.say_progress(0, episodes.len());
        *self.running.borrow_mut() = Some(Running {
            job: ExportJob::new(episodes),
            fingerprint: fingerprint(session),
        });
        self.timer.schedule(0);
    }

    fn artifact_for(&self, session: &Session<Episode>) -> Option<ExtraArtifact> {
        let last = self.last.borrow();
        let (written_from, artifact) = last.as_ref()?;
        (*written_from == fingerprint(session)).then(|| ExtraArtifact {
            kind: DATASET_TYPE,
            media_type: "application/zip",
            artifact: artifact.clone(),
        })
    }

    fn relocalize(&self) {
        if let Some((id, args)) = self.said.borrow().as_ref() {
            self.progress.set_text_content(Some(&ctx::t_args(id, args)));
        }
    }
}

impl DatasetExport {
    fn new(progress: Element) -> Rc<DatasetExport> {
        Rc::new_cyclic(|me: &Weak<DatasetExport>| {
            let mut scope = Scope::new();
            let timer = scope.timer(me, DatasetExport::slice);
            DatasetExport {
                progress,
                running: RefCell::new(None),
                last: RefCell::new(None),
                said: RefCell::new(None),
                timer,
                _scope: scope,
            }
        })
    }

    /// One slice: pieces of the job for [`MS_PER_TASK`]; the zip offered at the end.
    fn slice(&self) {
        let started = now_ms();
        let mut running = self.running.borrow_mut();
        let Some(r) = running.as_mut() else {
            return;
        };
        // Replay pieces for the task's time; writing the files, and zipping them, each start a
        // task of their own (the longest pieces).
        let ended = loop {
            let ended = r.job.advance(STEPS_PER_PIECE);
            if ended.is_some() || now_ms() - started >= MS_PER_TASK || r.job.writing_next() {
                break ended;
            }
        };
        let (done, total) = (r.job.done(), r.job.total());
        let Some(result) = ended else {
            drop(running);
            self.say_progress(done, total);
            crate::ui::kit::bench_log::push_ms("__so101DatasetMs", now_ms() - started, 5000);
            self.timer.schedule(0);
            return;
        };
        let fingerprint = running.take().map(|r| r.fingerprint);
        drop(running);
        match result {
            Ok(bytes) => {
                let artifact = Artifact::of_bytes(ZIP_NAME, &bytes);
                let offered = offer(&bytes);
                self.say(
                    "done",
                    (
                        "so101-dataset-done",
                        vec![
                            ("file", ZIP_NAME.into()),
                            ("total", total.into()),
                            ("kb", (bytes.len() as f64 / 1024.0).round().into()),
                        ],
                    ),
                );
                if let Err(e) = offered {
                    web_sys::console::warn_1(&e);
                }
                *self.last.borrow_mut() = fingerprint.map(|f| (f, artifact));
            }
            Err(DatasetError::NotReplayed { step }) => self.say(
                "failed",
                (
                    "so101-dataset-failed-replay",
                    vec![("n", (done + 1).into()), ("step", step.into())],
                ),
            ),
            Err(e) => self.say(
                "failed",
                (
                    "so101-dataset-failed",
                    vec![("detail", e.to_string().into())],
                ),
            ),
        }
        crate::ui::kit::bench_log::push_ms("__so101DatasetMs", now_ms() - started, 5000);
    }

    fn say_progress(&self, done: usize, total: usize) {
        self.say(
            "writing",
            (
                "so101-dataset-writing",
                vec![("done", done.into()), ("total", total.into())],
            ),
        );
    }

    fn say(&self, state: &str, said: Said) {
        let _ = self.progress.set_attribute("data-state", state);
        self.progress
            .set_text_content(Some(&ctx::t_args(said.0, &said.1)));
        crate::ui::dom::show(&self.progress, true);
        *self.said.borrow_mut() = Some(said);
    }
}

/// Offers `bytes` as the zip.
fn offer(bytes: &[u8]) -> Result<(), JsValue> {
    let parts = js_sys::Array::new();
    parts.push(&js_sys::Uint8Array::from(bytes));
    let options = BlobPropertyBag::new();
    options.set_type("application/zip");
    let blob = Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    crate::ui::download::download_blob(&blob, ZIP_NAME)
}
