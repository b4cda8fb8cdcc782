//! The session's files, written (an episode's CSV and the Academy's evidence, which hashes
//! every episode's CSV, in slices; the episodes table at once) and read back from what the
//! pilot opens: a wasm chunk of their own, so that the page is live before they arrive. The
//! page fetches them once it is mounted; a download or an open waits for them if they are
//! still on their way. The chunk also reads the session stored in the browser: a page with
//! one stored is built once the chunk is here (`crate::ui::kit::late_page`).

use crate::teleop::session::{
    episode_file_name, Session, SessionError, SessionLoader, EVIDENCE_NAME,
};
use crate::ui::page::SplitLoaderError;
use crate::view::teleop_export::ExportJob;

/// A file being written in slices ([`ExportJob`] behind the chunk's own table of functions).
pub trait FileJob {
    /// The file's name.
    fn file(&self) -> &str;
    /// The file's MIME type.
    fn mime(&self) -> &'static str;
    /// Rows written or hashed, and of how many.
    fn progress(&self) -> (usize, usize);
    /// Whether the whole file has been given out.
    fn is_done(&self) -> bool;
    /// The next piece of the file, up to `rows` more rows.
    fn step(&mut self, rows: usize) -> String;
}

impl FileJob for ExportJob {
    fn file(&self) -> &str {
        ExportJob::file(self)
    }
    fn mime(&self) -> &'static str {
        ExportJob::mime(self)
    }
    fn progress(&self) -> (usize, usize) {
        ExportJob::progress(self)
    }
    fn is_done(&self) -> bool {
        ExportJob::is_done(self)
    }
    fn step(&mut self, rows: usize) -> String {
        ExportJob::step(self, rows)
    }
}

/// The job writing a file of the session (`None`: no such file), the evidence's end time
/// given.
pub type Job = fn(&str, &Session, &str) -> Option<Box<dyn FileJob>>;
/// The session that saved files make, or what is wrong with them.
pub type Read = fn(&[(String, String)]) -> Result<Session, SessionError>;
/// The stored session's text read, ready to be simulated again (`None`: not a stored session).
pub type Restore = fn(&str) -> Option<SessionLoader>;

/// Writing and reading the session's files.
#[derive(Clone, Copy)]
pub struct Files {
    pub job: Job,
    /// `teleop_episodes.csv` of the session.
    pub episodes_csv: fn(&Session) -> String,
    pub read: Read,
    pub restore: Restore,
}

/// The job writing `file` of `session` (`None`: no such file).
fn job_of(file: &str, session: &Session, ended_at: &str) -> Option<Box<dyn FileJob>> {
    if file == EVIDENCE_NAME {
        return Some(Box::new(ExportJob::evidence(session, ended_at)));
    }
    session
        .episodes
        .iter()
        .find(|e| episode_file_name(e.number) == file)
        .and_then(|e| ExportJob::episode(session, e.number))
        .map(|job| Box::new(job) as Box<dyn FileJob>)
}

const FILES: Files = Files {
    job: job_of,
    episodes_csv: Session::episodes_csv,
    read: Session::from_files,
    restore: SessionLoader::new,
};

/// The files' chunk.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(teleop_files, fallible)]
pub fn load() -> Result<Files, SplitLoaderError> {
    Ok(FILES)
}

/// Without the `split` feature the files are in the one wasm.
#[cfg(not(feature = "split"))]
pub async fn load() -> Result<Files, SplitLoaderError> {
    Ok(FILES)
}
