//! The session's files, written (the Academy's evidence hashes every episode's CSV) and read
//! back from what the pilot opens: a wasm chunk of their own, so that the page is live before
//! they arrive. The page fetches them once its first frame is drawn; a download or an open
//! waits for them if they are still on their way. The chunk also reads the session stored in
//! the browser: a page with one stored is built once the chunk is here
//! (`crate::ui::kit::late_page`).

use crate::so101::Episode;
use crate::teleop::session::{ExtraArtifact, Session, SessionError, SessionLoader};
use crate::ui::page::SplitLoaderError;

/// The session's files as `(name, text)`, the evidence's end time given.
pub type Write = fn(&Session<Episode>, &str) -> Vec<(String, String)>;
/// The evidence with more files listed after the episodes' (the LeRobot dataset written).
pub type Evidence = fn(&Session<Episode>, &str, &[ExtraArtifact]) -> String;
/// The session that saved files make, or what is wrong with them.
pub type Read = fn(&[(String, String)]) -> Result<Session<Episode>, SessionError>;
/// The stored session's text read, ready to be simulated again (`None`: not a stored session).
pub type Restore = fn(&str) -> Option<SessionLoader<Episode>>;

/// Writing and reading the session's files.
#[derive(Clone, Copy)]
pub struct Files {
    pub write: Write,
    pub evidence: Evidence,
    pub read: Read,
    pub restore: Restore,
}

const FILES: Files = Files {
    write: Session::<Episode>::files,
    evidence: evidence_with,
    read: Session::<Episode>::from_files,
    restore: SessionLoader::<Episode>::new,
};

fn evidence_with(session: &Session<Episode>, ended_at: &str, extra: &[ExtraArtifact]) -> String {
    session.evidence_with_extra(ended_at, &session.episode_artifacts(), extra)
}

/// The files' chunk.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(so101_files, fallible)]
pub fn load() -> Result<Files, SplitLoaderError> {
    Ok(FILES)
}

/// Without the `split` feature the files are in the one wasm.
#[cfg(not(feature = "split"))]
pub async fn load() -> Result<Files, SplitLoaderError> {
    Ok(FILES)
}
