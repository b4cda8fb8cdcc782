//! The pilot pages' control state, shown large over the arm's view: engaged (the chosen device
//! flies the arm; Space pauses) or paused (nothing moves; Space flies again). It is the one
//! place the state is said beside the view; the engage button, the `Control` readout and the
//! key agree with it. `data-control` carries the state for tests and styles; the words follow
//! the input device (keys, gamepad or a drag on the view).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::InputDevice;
use crate::ui::dom;

/// The indicator's markup, `data-<attr>="control"` for the page to find it.
pub fn markup(attr: &str) -> String {
    format!(
        "<p class=\"pilot-control\" data-{attr}=\"control\" data-testid=\"control-state\" \
         data-control=\"engaged\" data-i18n=\"teleop-control-engaged\"></p>"
    )
}

/// The message that says `engaged` (or paused) for `device`.
pub fn message_id(engaged: bool, device: InputDevice) -> &'static str {
    match (engaged, device) {
        (true, InputDevice::Keyboard) => "teleop-control-engaged",
        (true, InputDevice::Gamepad) => "teleop-control-engaged-pad",
        (true, InputDevice::Pointer) => "teleop-control-engaged-pointer",
        (false, InputDevice::Keyboard) => "teleop-control-paused",
        (false, _) => "teleop-control-paused-button",
    }
}

/// Shows `engaged` (or paused) with `device` on `indicator`.
pub fn show(indicator: &Element, engaged: bool, device: InputDevice) -> Result<(), JsValue> {
    let state = if engaged { "engaged" } else { "paused" };
    let id = message_id(engaged, device);
    if indicator.get_attribute("data-control").as_deref() == Some(state)
        && indicator.get_attribute("data-i18n").as_deref() == Some(id)
    {
        return Ok(());
    }
    indicator.set_attribute("data-control", state)?;
    dom::set_i18n(indicator, id)
}
