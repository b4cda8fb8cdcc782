//! The dataset zip written in pieces, so that a page keeps every task short: each labelled
//! episode replayed a bounded number of steps at a time ([`FrameReplay`]) and added; then the
//! data file written in one piece, the other files in the next, the zip in the last
//! ([`ExportJob::writing_next`] says when the next piece is one of those, the longest, for a
//! page to start a task with it).

use super::{zip, DatasetBuilder, DatasetError, FrameReplay};
use crate::so101::Episode;
use crate::teleop::{FailureCategory, Label};

/// The zip's name on the page (`data-download`).
pub const ZIP_NAME: &str = "so101_lerobot_v3.zip";

/// An episode with what the pilot said of it: label, failure category, note.
#[derive(Debug, Clone, PartialEq)]
pub struct LabelledEpisode {
    /// The episode.
    pub episode: Episode,
    /// Its label.
    pub label: Label,
    /// Its failure category, if any.
    pub category: Option<FailureCategory>,
    /// The pilot's note.
    pub note: String,
}

/// The dataset of some labelled episodes, written a piece at a time ([`ExportJob::advance`]).
///
/// # Example
/// ```
/// use bsv_playground::so101::dataset::{dataset_files, zip, ExportJob, LabelledEpisode};
/// use bsv_playground::so101::{Command, Episode, SceneConfig};
/// use bsv_playground::teleop::Label;
///
/// let commands = vec![Command::with_axes([0.5, 0.0, -0.2, 0.0, 0.0, 0.0], false); 30];
/// let episode = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
/// let labelled = LabelledEpisode { episode: episode.clone(), label: Label::Success, category: None, note: String::new() };
/// let mut job = ExportJob::new(vec![labelled]);
/// let bytes = loop {
///     if let Some(done) = job.advance(7) {
///         break done.unwrap();
///     }
/// };
/// let whole = zip(&dataset_files(&[(&episode, Label::Success, None, "")]).unwrap()).unwrap();
/// assert_eq!(bytes, whole);
/// ```
#[derive(Debug, Clone)]
pub struct ExportJob {
    episodes: Vec<LabelledEpisode>,
    builder: Option<DatasetBuilder>,
    replay: Option<FrameReplay>,
    next: usize,
    /// The data file, once written (the piece after writes the others).
    data: Option<Vec<u8>>,
    /// The dataset's files, once written (the last piece zips them).
    files: Option<Vec<(String, Vec<u8>)>>,
}

impl ExportJob {
    /// The job for `episodes`, in their order.
    pub fn new(episodes: Vec<LabelledEpisode>) -> ExportJob {
        ExportJob {
            episodes,
            builder: Some(DatasetBuilder::new()),
            replay: None,
            next: 0,
            data: None,
            files: None,
        }
    }

    /// Whether the next piece writes the files or zips them (every episode is in).
    pub fn writing_next(&self) -> bool {
        self.next >= self.episodes.len()
    }

    /// Episodes in the dataset.
    pub fn total(&self) -> usize {
        self.episodes.len()
    }

    /// Episodes added so far.
    pub fn done(&self) -> usize {
        self.next
    }

    /// Replays up to `max_steps` steps (at least one piece of work), or, once every episode is
    /// in, writes the data file, then the others, then zips them: `Some` with the zip's bytes (or why it could not
    /// be written) when the job is over, `None` while there is more to do.
    pub fn advance(&mut self, max_steps: usize) -> Option<Result<Vec<u8>, DatasetError>> {
        match self.step(max_steps.max(1)) {
            Ok(None) => None,
            Ok(Some(bytes)) => Some(Ok(bytes)),
            Err(e) => {
                self.next = self.episodes.len();
                self.builder = None;
                Some(Err(e))
            }
        }
    }

    fn step(&mut self, max_steps: usize) -> Result<Option<Vec<u8>>, DatasetError> {
        let Some(item) = self.episodes.get(self.next) else {
            if let Some(files) = self.files.take() {
                return zip(&files).map(Some);
            }
            if let Some(data) = self.data.take() {
                let builder = self.builder.take().ok_or(DatasetError::NoEpisodes)?;
                self.files = Some(builder.finish_with(data)?);
                return Ok(None);
            }
            let builder = self.builder.as_ref().ok_or(DatasetError::NoEpisodes)?;
            self.data = Some(builder.data_file()?);
            return Ok(None);
        };
        let replay = match self.replay.as_mut() {
            Some(r) => r,
            None => self.replay.insert(FrameReplay::new(&item.episode)?),
        };
        if replay.advance(&item.episode, max_steps)? {
            let frames = self.replay.take().map(FrameReplay::into_frames);
            if let (Some(frames), Some(builder)) = (frames, self.builder.as_mut()) {
                builder.add_frames(&item.episode, frames, item.label, item.category, &item.note);
            }
            self.next += 1;
        }
        Ok(None)
    }
}
