//! An input file on the page (a file argument: traj-resample's CSV): choosing one (refused
//! above the kernel's limit, else read, with stale reads dropped), going back to the built-in
//! labeled sample, and the line under the file picker that says which input the run uses. A
//! file that is not UTF-8 is refused beside the picker with the byte offset, as `bsv` refuses
//! it.

use super::file::InputFile;
use super::state::{Page, Status};
use super::texts;
use crate::recipes::traj_resample;
use crate::ui::ctx::t_strings;
use crate::ui::kit::form::Message;
use crate::ui::kit::input_file::{self, Picked, ReadProblem};

/// A file name usable as a positional argument (one starting with `-` gets `./`).
fn path_word(name: &str) -> String {
    match name {
        "" => "input.csv".to_string(),
        n if n.starts_with('-') => format!("./{n}"),
        n => n.to_string(),
    }
}

impl Page {
    /// "Use the built-in labeled sample": forget the opened file.
    pub(super) fn use_sample(&self) {
        {
            let mut st = self.st.borrow_mut();
            st.input = None;
            st.missing_file = None;
            st.file_problem = None;
            st.url.file_settled();
            st.read_generation += 1;
            st.reading = None;
        }
        if let Some(input) = self.form.borrow().file_input() {
            input.set_value("");
        }
        self.after_input_change();
    }

    /// A file was chosen: refuse it above the kernel's limit, else read it.
    pub(super) fn on_file_chosen(&self) {
        let chosen = self.form.borrow().file_input().and_then(input_file::chosen);
        let Some(Picked { name, bytes, blob }) = chosen else {
            return;
        };
        let name = path_word(&name);
        let limit = traj_resample::MAX_INPUT_BYTES;
        if bytes > limit {
            {
                let mut st = self.st.borrow_mut();
                st.file_problem = Some(Message::Text {
                    id: "drills-file-too-large",
                    args: vec![
                        ("name", name),
                        ("size", texts::size_text(bytes)),
                        ("limit", texts::size_text(limit)),
                    ],
                });
                st.read_generation += 1;
                st.reading = None;
            }
            if let Some(input) = self.form.borrow().file_input() {
                input.set_value("");
            }
            self.after_input_change();
            return;
        }
        let generation = {
            let mut st = self.st.borrow_mut();
            st.read_generation += 1;
            st.reading = Some(name.clone());
            st.file_problem = None;
            st.status = Status::Reading(name.clone());
            st.read_generation
        };
        self.render_status();
        self.render_file_status();
        let weak = self.weak.borrow().clone();
        input_file::read_text(&name.clone(), &blob, move |result| {
            let Some(page) = weak.upgrade() else {
                return;
            };
            page.file_read(generation, name, bytes, result);
        });
    }

    /// The chosen file's text arrived (or reading failed).
    fn file_read(
        &self,
        generation: u32,
        name: String,
        bytes: u64,
        result: Result<String, ReadProblem>,
    ) {
        {
            let mut st = self.st.borrow_mut();
            if st.read_generation != generation {
                return;
            }
            st.reading = None;
            st.status = Status::Idle;
            match result {
                Ok(text) => {
                    let shape = traj_resample::shape_of(&text);
                    st.input = Some(InputFile {
                        name,
                        bytes,
                        text,
                        shape,
                    });
                    st.missing_file = None;
                    st.url.file_settled();
                    st.file_problem = None;
                }
                Err(ReadProblem::Browser(reason)) => {
                    st.file_problem = Some(Message::Text {
                        id: "drills-file-unreadable",
                        args: vec![("name", name), ("reason", reason)],
                    });
                }
                Err(ReadProblem::Decode(error)) => {
                    st.file_problem = Some(Message::Recipe(error));
                }
            }
        }
        if let Some(input) = self.form.borrow().file_input() {
            input.set_value("");
        }
        self.after_input_change();
    }

    /// The input file changed: check, show, write the URL, run if small.
    fn after_input_change(&self) {
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        {
            let mut st = self.st.borrow_mut();
            if st.status != Status::Running {
                st.status = Status::Idle;
            }
        }
        self.auto_run();
        self.render_status();
    }

    /// traj-resample's line under the file picker: which input the run uses.
    pub(super) fn render_file_status(&self) {
        let form = self.form.borrow();
        let Some(status) = form.file_status.as_ref() else {
            return;
        };
        let st = self.st.borrow();
        let text = if let Some(name) = &st.reading {
            t_strings("drills-reading", &[("name", name.clone())])
        } else if let Some(file) = &st.input {
            let mut args = vec![
                ("name", file.name.clone()),
                ("size", texts::size_text(file.bytes)),
            ];
            match &file.shape {
                Ok(shape) => {
                    args.push(("rows", texts::group(shape.rows)));
                    args.push(("joints", shape.joints.to_string()));
                    t_strings("drills-file-using-rows", &args)
                }
                _ => t_strings("drills-file-using", &args),
            }
        } else if let Some(name) = &st.missing_file {
            t_strings("drills-file-missing", &[("name", name.clone())])
        } else {
            let rows = traj_resample::shape_of(traj_resample::SAMPLE).map_or(0, |s| s.rows);
            t_strings(
                "drills-file-using-sample",
                &[
                    ("name", traj_resample::SAMPLE_NAME.to_string()),
                    ("rows", rows.to_string()),
                ],
            )
        };
        status.set_text_content(Some(&text));
    }
}
