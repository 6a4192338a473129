//! A frame's working memory kept for the next frame: the far and near
//! fields' per-receiver results and the pixel buffers a [`Shaded`] holds
//! (megabytes: fresh ones cost a page fault per 4 KiB on first touch).

use super::VplContext;
use super::fields::PerReceiver;
use super::shade::LightList;
use glam::Vec3;
#[cfg(doc)]
use slc_scene::vpl::Shaded;

/// A frame's working memory kept for the next frame (its buffers are
/// megabytes: fresh ones cost a page fault per 4 KiB on first touch): the
/// far and near fields' per-receiver results, and the pixel buffers a
/// [`Shaded`] hands to [`VplContext::finish`], returned by it. Frames
/// rendered at once take what is there; one that finds it taken
/// allocates its own.
#[derive(Default)]
pub(super) struct Reused {
    pub(super) far: PerReceiver,
    pub(super) near: PerReceiver,
    /// The near field's light list.
    pub(super) near_lights: LightList,
    pub(super) vec3: Vec<Vec<Vec3>>,
    pub(super) counts: Vec<Vec<u32>>,
}

impl Reused {
    /// Pixel buffers of each type kept at most (a frame's [`Shaded`] holds
    /// four of `Vec3`, one of counts).
    const KEEP: usize = 4;

    /// A pixel buffer of `Vec3` (empty, with the memory of a kept one).
    pub(super) fn vec3(&mut self) -> Vec<Vec3> {
        take_buffer(&mut self.vec3)
    }

    /// A pixel buffer of counts, as [`Reused::vec3`].
    pub(super) fn counts(&mut self) -> Vec<u32> {
        take_buffer(&mut self.counts)
    }

    /// Adds `r`'s memory to this one's where this one has none.
    fn absorb(&mut self, r: Reused) {
        if self.far.out.capacity() == 0 {
            self.far = r.far;
        }
        if self.near.out.capacity() == 0 {
            self.near = r.near;
        }
        if self.near_lights.capacity() == 0 {
            self.near_lights = r.near_lights;
        }
        keep_buffers(&mut self.vec3, r.vec3);
        keep_buffers(&mut self.counts, r.counts);
    }
}

/// A buffer of `pool` emptied (a new one where the pool has none).
fn take_buffer<T>(pool: &mut Vec<Vec<T>>) -> Vec<T> {
    let mut v = pool.pop().unwrap_or_default();
    v.clear();
    v
}

/// Adds the buffers of `more` that hold memory to `pool`, up to
/// [`Reused::KEEP`].
fn keep_buffers<T>(pool: &mut Vec<Vec<T>>, more: Vec<Vec<T>>) {
    pool.extend(more.into_iter().filter(|v| v.capacity() > 0));
    pool.truncate(Reused::KEEP);
}

impl VplContext {
    /// The reused memory (none when another frame holds the lock).
    pub(super) fn take_reused(&self) -> Reused {
        self.reuse.try_lock().map(|mut r| std::mem::take(&mut *r)).unwrap_or_default()
    }

    /// Keeps `r`'s memory for the next frame (drops it when another frame
    /// holds the lock, or where memory is kept already).
    pub(super) fn keep_reused(&self, r: Reused) {
        if let Ok(mut kept) = self.reuse.try_lock() {
            kept.absorb(r);
        }
    }
}
