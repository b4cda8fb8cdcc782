//! Split points outside the page table: a part of the app that the app's build cuts off into a
//! wasm chunk of its own, fetched the first time it is asked for (the page table's own split
//! points are `page!` lines, [`crate::ui::page`]).

/// `split_point!(chunk, fn name() -> Type = value)` defines `async fn name()`, resolving to
/// `value`. The app's build (feature `split`) puts `value` and all that only it reaches into
/// the wasm chunk `chunk`, fetched on the first call (an `Err` when it cannot be fetched; the
/// next call tries again); without the feature it is in the one wasm and resolves at once.
macro_rules! split_point {
    ($chunk:ident, fn $name:ident() -> $ty:ty = $value:expr) => {
        #[cfg(feature = "split")]
        #[wasm_split_helpers::wasm_split($chunk, fallible)]
        fn $name() -> Result<$ty, $crate::ui::page::SplitLoaderError> {
            Ok($value)
        }

        #[cfg(not(feature = "split"))]
        async fn $name() -> Result<$ty, $crate::ui::page::SplitLoaderError> {
            Ok($value)
        }
    };
}

pub(crate) use split_point;
