//! A line of text made from a value in the current language (a refused edit, what the keys
//! move): hidden while there is no value, made again on a language switch.

use std::cell::Cell;

use web_sys::Element;

use crate::ui::dom;

/// The line: its element, the value it says and how the value is said.
pub struct MessageLine<T: Copy> {
    element: Element,
    value: Cell<Option<T>>,
    text: fn(T) -> String,
}

impl<T: Copy> MessageLine<T> {
    /// Drives `element` (hidden until a value is set), saying a value with `text`.
    pub fn new(element: Element, text: fn(T) -> String) -> MessageLine<T> {
        MessageLine {
            element,
            value: Cell::new(None),
            text,
        }
    }

    /// The value said now.
    pub fn get(&self) -> Option<T> {
        self.value.get()
    }

    /// Says `value` (`None`: hides the line).
    pub fn set(&self, value: Option<T>) {
        self.value.set(value);
        self.relocalize();
    }

    /// Writes the line again in the current language.
    pub fn relocalize(&self) {
        let text = self.value.get().map(self.text);
        self.element.set_text_content(text.as_deref());
        dom::show(&self.element, text.is_some());
    }
}
