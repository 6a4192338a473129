//! The [`shared!`](crate::shared) macro: one block of items, emitted as Rust
//! and collected as WGSL text.

/// Emits a block of items as Rust and collects their tokens as WGSL text in a
/// `pub const WGSL: &str` beside them. Accepts `pub const`, `pub fn` and
/// `pub struct` items with doc comments (see the module docs for the rules).
/// Every `pub fn` is `#[inline]`; one marked `#[inline(always)]` before its
/// doc comment is always inlined in Rust (a hot loop's step, whose speed
/// must not depend on how rustc splits the calling crate into codegen
/// units; WGSL leaves inlining to the shader compiler).
#[macro_export]
#[doc(hidden)]
macro_rules! shared {
    (@acc [$($w:expr),*]) => {
        /// This module's shared items as WGSL source (raw `stringify!` text;
        /// `slc_core::wgsl::translate` formats it).
        pub const WGSL: &str = concat!($($w, "\n"),*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub const $name:ident : $ty:ty = $val:expr ; $($rest:tt)*) => {
        // WGSL has no `core::f32::consts`: constants are written as literals.
        $(#[$m])*
        #[allow(clippy::approx_constant, clippy::excessive_precision)]
        pub const $name: $ty = $val;
        $crate::shared!(@acc [$($w,)* stringify!(const $name: $ty = $val;)] $($rest)*);
    };
    (@acc [$($w:expr),*]
        #[inline(always)] $(#[$m:meta])* pub fn $($rest:tt)*) => {
        $crate::shared!(@fn [$($w),*] [always] $(#[$m])* pub fn $($rest)*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub fn $($rest:tt)*) => {
        $crate::shared!(@fn [$($w),*] [] $(#[$m])* pub fn $($rest)*);
    };
    // One `pub fn`, `#[inline]` or `#[inline(always)]` (`[always]`).
    (@fn [$($w:expr),*] [$($mode:ident)?]
        $(#[$m:meta])* pub fn $name:ident ( $($arg:ident : $aty:ty),* $(,)? ) -> $ret:ty $body:block
        $($rest:tt)*) => {
        $(#[$m])*
        #[inline $(($mode))?]
        #[allow(clippy::needless_return, unused_mut, clippy::collapsible_else_if, clippy::assign_op_pattern, clippy::manual_range_contains, clippy::manual_div_ceil)]
        pub fn $name($($arg: $aty),*) -> $ret $body
        $crate::shared!(@acc [$($w,)* stringify!(fn $name($($arg: $aty),*) -> $ret $body)] $($rest)*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub struct $name:ident { $($(#[$fm:meta])* pub $f:ident : $fty:ty),* $(,)? }
        $($rest:tt)*) => {
        $(#[$m])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
        pub struct $name { $($(#[$fm])* pub $f: $fty),* }
        $crate::shared!(@acc [$($w,)* stringify!(struct $name { $($f: $fty),* })] $($rest)*);
    };
    ($($items:tt)*) => { $crate::shared!(@acc [] $($items)*); };
}
