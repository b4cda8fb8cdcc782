//! The pilot's devices on the SO-101 page, mapped by `crate::so101::input`: the held keys, the
//! gamepad (polled once per frame, read as `#/teleop` reads it), the gizmo's clutch drag and
//! the gripper's state they all toggle.

use glam::DVec2;

use crate::so101::input::{HeldKeys, PadMapper, PadOutput};
use crate::view::so101::Handle;

/// A gizmo handle held: which, where the press began and where the pointer is (CSS px).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clutch {
    pub handle: Handle,
    pub start: DVec2,
    pub now: DVec2,
}

/// The devices' state.
#[derive(Default)]
pub struct Devices {
    pub keys: HeldKeys,
    pub pad: PadMapper,
    /// The connected pad's name, `None` when none has shown itself.
    pub pad_name: Option<String>,
    pub pad_out: PadOutput,
    /// The gizmo's drag, while held, and its axes.
    pub clutch: Option<Clutch>,
    pub clutch_axes: [f64; 6],
    pub gripper_closed: bool,
    /// An input arrived since the last frame.
    pub fresh: bool,
}

impl Devices {
    /// The six axes of all devices together, each clamped to [−1, 1].
    pub fn axes(&self) -> [f64; 6] {
        let k = self.keys.axes_of::<6>();
        let p = self.pad_out.axes;
        let c = if self.clutch.is_some() {
            self.clutch_axes
        } else {
            [0.0; 6]
        };
        std::array::from_fn(|i| (k[i] + p[i] + c[i]).clamp(-1.0, 1.0))
    }

    /// Polls the first gamepad; returns whether it gave input this poll.
    pub fn poll_pad(&mut self, dead_zone: f64) -> bool {
        let snap = crate::ui::pages::teleop::devices::first_pad();
        self.pad_name = snap.as_ref().map(|s| s.id.clone());
        match snap {
            Some(s) => {
                let out = self.pad.map(&s, dead_zone);
                if out.toggle_gripper {
                    self.gripper_closed = !self.gripper_closed;
                }
                if out.active {
                    self.fresh = true;
                }
                self.pad_out = out;
                out.active
            }
            None => {
                self.pad_out = PadOutput::default();
                false
            }
        }
    }

    /// Forgets the held keys and the clutch.
    pub fn clear(&mut self) {
        self.keys.clear();
        self.clutch = None;
        self.clutch_axes = [0.0; 6];
    }
}
