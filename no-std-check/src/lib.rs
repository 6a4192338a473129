//! Links slc-core into a `#![no_std]` static library and uses its API, so a
//! std dependency anywhere below slc-core breaks this build.
#![no_std]

use core::alloc::{GlobalAlloc, Layout};
use slc_core::glam::Vec3;
use slc_core::range::{RangeParams, random_range2, slc_keep, slc_weight};

/// Never allocates: proves only that the code links without std.
struct NoAlloc;

unsafe impl GlobalAlloc for NoAlloc {
    unsafe fn alloc(&self, _: Layout) -> *mut u8 {
        core::ptr::null_mut()
    }
    unsafe fn dealloc(&self, _: *mut u8, _: Layout) {}
}

#[global_allocator]
static ALLOC: NoAlloc = NoAlloc;

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// SLC-weighted contribution of one light at squared distance `d2`.
#[unsafe(no_mangle)]
pub extern "C" fn slc_weighted(intensity: f32, d2: f32, xi: f32) -> f32 {
    let Ok(p) = RangeParams::new(0.01, 1.0) else { return 0.0 };
    let rt2 = p.threshold_range2(Vec3::splat(intensity));
    if slc_keep(random_range2(rt2, xi), d2) { intensity / d2 * slc_weight(rt2, d2) } else { 0.0 }
}

/// Touches the parser, the hierarchy and the WGSL text so they link too.
#[unsafe(no_mangle)]
pub extern "C" fn slc_link_all() -> usize {
    let a = slc_core::ies::IesProfile::parse("TILT=NONE").is_ok() as usize;
    let b = slc_core::bsh::Bsh::build(&[]).map(|t| t.len()).unwrap_or(0);
    a + b + slc_core::wgsl::library().len()
}
