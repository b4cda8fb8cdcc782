//! The counters under the world view: the iteration, nodes, rejections by reason, the path
//! and its length (the kit's readouts), the nodes per second while playing, and the polite
//! summary a screen reader hears.

use std::cell::Cell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::i18n::FluentArg;
use crate::pyfmt::fixed;
use crate::ui::ctx;
use crate::ui::kit::readouts::Readouts;
use crate::ui::schedule::now_ms;
use crate::view::rrt::rate_per_s;

use super::run::Run;

/// The counters component.
pub struct Counters {
    readouts: Readouts,
    /// Nodes/second while playing: the sample's start (ms, nodes) and the last rate.
    rate_from: Cell<Option<(f64, usize)>>,
    rate: Cell<Option<f64>>,
}

impl Counters {
    /// Finds the readouts under `root`.
    pub fn find(root: &Element) -> Result<Counters, JsValue> {
        Ok(Counters {
            readouts: Readouts::find(root)?,
            rate_from: Cell::new(None),
            rate: Cell::new(None),
        })
    }

    /// Shows the counters of the iteration shown; `playing`: the rate is sampled.
    pub fn show(&self, run: &Run, playing: bool) {
        let rrt = run.shown();
        let counts = rrt.counts();
        let path = rrt.path();
        let n = rrt.nodes().len();
        let group = |v: usize| crate::pyfmt::group_u64(v as u64);
        let r = &self.readouts;
        r.set("iteration", &group(rrt.iterations()));
        r.set("nodes", &group(n));
        r.set("rejected_out", &group(counts.out_of_square));
        r.set("rejected_collision", &group(counts.collision));
        r.set("rejected_zero", &group(counts.zero_length));
        r.set("path_points", &group(path.len()));
        r.set(
            "length",
            &if path.is_empty() {
                "—".to_string()
            } else {
                fixed(rrt.path_length(), 3)
            },
        );
        if playing {
            let now = now_ms();
            match self.rate_from.get() {
                Some((t0, n0)) => {
                    if let Some(rate) = rate_per_s(n0, n, now - t0) {
                        self.rate.set(Some(rate));
                        self.rate_from.set(Some((now, n)));
                    }
                }
                None => self.rate_from.set(Some((now, n))),
            }
        } else {
            self.rate_from.set(None);
            self.rate.set(None);
        }
        r.set(
            "nodes_per_s",
            &self
                .rate
                .get()
                .map_or("—".to_string(), |v| group(v.round() as usize)),
        );
        r.announce(&ctx::t_args(
            "rrt-live",
            &[
                ("it", FluentArg::Number(rrt.iterations() as f64)),
                ("nodes", FluentArg::Number(n as f64)),
            ],
        ));
    }
}
