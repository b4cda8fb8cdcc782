//! The Robot Pilot page's exports written in slices: a 60 s episode's `teleop_episode_<n>.csv`
//! is 6,000 rows (about 1.6 MB) and the session's `teleop_session_evidence.json` lists the
//! SHA-256 of every episode's CSV, so both are made a few hundred rows at a time
//! ([`ExportJob::step`]) between the page's tasks, with the rows done and to do for a progress
//! line. The bytes are the kernel's: the episode CSV's slices one after the other are
//! [`crate::teleop::episode_csv`], and the evidence is [`Session::evidence`] (each episode's
//! CSV hashed as it is written, never held whole).
//!
//! A job works on a snapshot of the session taken when it starts (the episodes are shared,
//! not copied): what the pilot does meanwhile (labels, new episodes) goes into the next
//! export.

use std::rc::Rc;

use crate::teleop::session::{episode_file_name, Artifact, Session, Sha256, EVIDENCE_NAME};
use crate::teleop::{episode_csv_head, push_episode_csv_rows, Episode};

/// What a job writes.
#[derive(Debug, Clone)]
enum Kind {
    /// One episode's CSV: the slices are the file.
    Episode {
        episode: Rc<Episode>,
        head_done: bool,
    },
    /// The evidence: every episode's CSV hashed, then the JSON.
    Evidence {
        session: Box<Session>,
        ended_at: String,
        /// The episode being hashed (index into the session's episodes).
        index: usize,
        hasher: Option<Sha256>,
        artifacts: Vec<Artifact>,
        written: bool,
    },
}

/// A file being written in slices.
#[derive(Debug, Clone)]
pub struct ExportJob {
    file: String,
    kind: Kind,
    /// The next row of the episode being written or hashed.
    next_row: usize,
    rows_done: usize,
    rows_total: usize,
}

impl ExportJob {
    /// `teleop_episode_<number>.csv` of `session` (`None`: no such episode).
    pub fn episode(session: &Session, number: usize) -> Option<ExportJob> {
        let entry = session.episodes.iter().find(|e| e.number == number)?;
        let rows_total = entry.episode.records.len();
        Some(ExportJob {
            file: episode_file_name(number),
            kind: Kind::Episode {
                episode: Rc::clone(&entry.episode),
                head_done: false,
            },
            next_row: 0,
            rows_done: 0,
            rows_total,
        })
    }

    /// `teleop_session_evidence.json` of `session`, `ended_at` its end time if it has none.
    pub fn evidence(session: &Session, ended_at: &str) -> ExportJob {
        let rows_total = session
            .episodes
            .iter()
            .map(|e| e.episode.records.len())
            .sum();
        ExportJob {
            file: EVIDENCE_NAME.to_string(),
            kind: Kind::Evidence {
                session: Box::new(session.clone()),
                ended_at: ended_at.to_string(),
                index: 0,
                hasher: None,
                artifacts: Vec::new(),
                written: false,
            },
            next_row: 0,
            rows_done: 0,
            rows_total,
        }
    }

    /// The file's name.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The file's MIME type.
    pub fn mime(&self) -> &'static str {
        match self.kind {
            Kind::Episode { .. } => "text/csv",
            Kind::Evidence { .. } => "application/json",
        }
    }

    /// Rows written or hashed, and of how many.
    pub fn progress(&self) -> (usize, usize) {
        (self.rows_done, self.rows_total)
    }

    /// Whether the whole file has been given out.
    pub fn is_done(&self) -> bool {
        match &self.kind {
            Kind::Episode { head_done, .. } => *head_done && self.next_row >= self.rows_total,
            Kind::Evidence { written, .. } => *written,
        }
    }

    /// Writes (or hashes) up to `rows` more rows and returns the next piece of the file: the
    /// pieces one after the other are the file's text. The evidence's one piece is its whole
    /// text, given with the last rows.
    pub fn step(&mut self, rows: usize) -> String {
        let rows = rows.max(1);
        match &mut self.kind {
            Kind::Episode { episode, head_done } => {
                let mut out = String::new();
                if !*head_done {
                    out = episode_csv_head(episode);
                    *head_done = true;
                }
                let end = (self.next_row + rows).min(self.rows_total);
                out.reserve((end - self.next_row) * 260);
                push_episode_csv_rows(&mut out, episode, self.next_row..end);
                self.rows_done += end - self.next_row;
                self.next_row = end;
                out
            }
            Kind::Evidence {
                session,
                ended_at,
                index,
                hasher,
                artifacts,
                written,
            } => {
                let mut budget = rows;
                while budget > 0 && *index < session.episodes.len() {
                    let entry = &session.episodes[*index];
                    let episode = &entry.episode;
                    let h = hasher.get_or_insert_with(|| {
                        let mut h = Sha256::new();
                        h.update(episode_csv_head(episode).as_bytes());
                        h
                    });
                    let n = episode.records.len();
                    let end = (self.next_row + budget).min(n);
                    let mut text = String::with_capacity((end - self.next_row) * 260);
                    push_episode_csv_rows(&mut text, episode, self.next_row..end);
                    h.update(text.as_bytes());
                    budget -= end - self.next_row;
                    self.rows_done += end - self.next_row;
                    self.next_row = end;
                    if end >= n {
                        if let Some(h) = hasher.take() {
                            artifacts.push(Artifact {
                                path: episode_file_name(entry.number),
                                bytes: h.len(),
                                sha256: h.finish_hex(),
                            });
                        }
                        *index += 1;
                        self.next_row = 0;
                    }
                }
                if *index >= session.episodes.len() && !*written {
                    *written = true;
                    return session.evidence_with(ended_at, artifacts);
                }
                String::new()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::teleop::pilot::{fly, plan};
    use crate::teleop::session::InputDevice;
    use crate::teleop::{episode_csv, SceneConfig, Task};

    fn session() -> Session {
        let mut s = Session::new("Pilot 7", InputDevice::Keyboard, "2026-12-02T05:00:00.000Z");
        let reach = SceneConfig {
            task: Task::from_id("reach").unwrap(),
            noise_sigma: 0.05,
            latency_steps: 3,
            ..SceneConfig::default()
        };
        for config in [SceneConfig::default(), reach] {
            let e = fly(config.clone(), plan(&config), 6000).unwrap();
            s.record(e, false);
        }
        // An episode with no steps (ended at once).
        let empty = fly(SceneConfig::default(), Vec::new(), 0).unwrap();
        s.record(empty, true);
        s
    }

    fn run(job: &mut ExportJob, rows: usize) -> (String, usize) {
        let mut text = String::new();
        let mut steps = 0;
        while !job.is_done() {
            text.push_str(&job.step(rows));
            steps += 1;
            let (done, total) = job.progress();
            assert!(done <= total);
            assert!(steps < 100_000);
        }
        (text, steps)
    }

    #[test]
    fn an_episode_in_slices_is_the_kernel_csv() {
        let s = session();
        for entry in &s.episodes {
            for rows in [1, 250, 100_000] {
                let mut job = ExportJob::episode(&s, entry.number).unwrap();
                assert_eq!(job.file(), episode_file_name(entry.number));
                assert_eq!(job.mime(), "text/csv");
                let (text, steps) = run(&mut job, rows);
                assert_eq!(text, episode_csv(&entry.episode), "{rows} rows a slice");
                let n = entry.episode.records.len();
                assert_eq!(job.progress(), (n, n));
                assert_eq!(steps, n.div_ceil(rows).max(1));
            }
        }
        assert!(ExportJob::episode(&s, 9).is_none());
    }

    #[test]
    fn the_evidence_hashed_in_slices_is_the_sessions() {
        let s = session();
        let total: usize = s.episodes.iter().map(|e| e.episode.records.len()).sum();
        assert!(total > 1000, "{total}");
        let want = s.evidence("2026-12-02T05:30:00.000Z");
        for rows in [1, 333, 1_000_000] {
            let mut job = ExportJob::evidence(&s, "2026-12-02T05:30:00.000Z");
            assert_eq!(job.mime(), "application/json");
            let (text, steps) = run(&mut job, rows);
            assert_eq!(text, want, "{rows} rows a slice");
            assert_eq!(job.progress(), (total, total));
            if rows == 333 {
                assert!(steps >= total / 333, "{steps} slices");
            }
        }
        // A session without episodes: the evidence at the first step.
        let empty = Session::new("p", InputDevice::Gamepad, "2026-12-02T05:00:00.000Z");
        let mut job = ExportJob::evidence(&empty, "2026-12-02T05:30:00.000Z");
        assert_eq!(job.step(10), empty.evidence("2026-12-02T05:30:00.000Z"));
        assert!(job.is_done());
    }
}
