//! The learner's progress on the exercises kept in the browser: localStorage `bsv.progress`
//! holds the `bsv-progress` file ([`crate::view::learner_progress`]) as it is exported. Every
//! change reads the stored record first and saves it at once ([`update`]), so two tabs of the
//! app add to one record instead of overwriting each other's; a record that does not read is
//! set aside (`bsv.progress.unreadable`) as the kit's store does, never overwritten unseen.

use crate::ui::kit::store::{self, Refused, Stored};
use crate::view::learner_progress::{from_json, to_json, LearnerProgress};

/// The localStorage key.
pub const STORAGE_KEY: &str = "bsv.progress";

/// The exported file's name.
pub const FILE_NAME: &str = "bsv_progress.json";

/// The app's build, written in the record (`build`): the version, and the commit when the app
/// was built by `scripts/build-dist.sh` (which sets `BSV_BUILD`).
pub const BUILD: &str = match option_env!("BSV_BUILD") {
    Some(build) => build,
    None => concat!("bsv-playground ", env!("CARGO_PKG_VERSION")),
};

/// The stored record (an empty one when nothing readable is stored).
pub fn load() -> LearnerProgress {
    match store::read(STORAGE_KEY, from_json) {
        Stored::Read(progress) => progress,
        Stored::Nothing | Stored::SetAside => LearnerProgress::new(BUILD),
    }
}

/// Applies `change` to the stored record and saves it; the record as changed, and why the
/// browser refused to keep it, if it did.
pub fn update(change: &mut dyn FnMut(&mut LearnerProgress)) -> (LearnerProgress, Option<Refused>) {
    let mut progress = load();
    let before = progress.clone();
    change(&mut progress);
    if progress == before {
        return (progress, None);
    }
    progress.build = BUILD.to_owned();
    let refused = store::save(STORAGE_KEY, &to_json(&progress)).err();
    (progress, refused)
}
