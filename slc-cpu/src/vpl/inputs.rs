//! The method-independent part of a frame: the G-buffer with what the
//! shading and the denoise derive from it (tilings, filter planes), the
//! VPLs of the reflective shadow map, and the primary light's direct term.

use super::denoise::Denoiser;
use super::direct::direct_light;
use super::tiling::Tiling;
use super::{NEAR_REGION, NEAR_TILE, ms, rsm};
use crate::gbuffer::render_gbuffer_into;
use crate::geometry::Geometry;
use glam::Vec3;
use slc_scene::scene::Scene;
use slc_scene::vpl::{GBuffer, PERIOD, VplInputs, VplSettings, VplStats};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

/// What a frame derives from the G-buffer alone, rebuilt with it: the
/// pixels tiled for the far field (at the default tile size) and the near
/// field, and the denoise with its G-buffer planes (behind a lock so that
/// frames render through `&self`; frames rendered at once take turns at
/// the filter).
#[derive(Default)]
pub(super) struct FromGBuffer {
    pub(super) far: Tiling,
    /// The tile size `far` was built for.
    pub(super) far_tile: usize,
    pub(super) near: Tiling,
    pub(super) denoiser: Mutex<Denoiser>,
}

impl FromGBuffer {
    pub(super) fn build(&mut self, gb: &GBuffer) {
        self.far_tile = VplSettings::default().tile as usize;
        self.far.interleaved_into(gb, PERIOD as usize, self.far_tile);
        self.near.regions_into(gb, NEAR_REGION, NEAR_TILE);
        self.denoiser.get_mut().unwrap_or_else(PoisonError::into_inner).set_gbuffer(gb);
    }
}

/// The method-independent part of a frame: G-buffer with its tilings and
/// denoise planes (unless `camera_moved` is false), VPLs (RSM) and direct light, rendered
/// into `inputs`, `geometric`, `direct` and `from_gbuffer` (memory reused at the
/// same size), with their times in the returned statistics (G-buffer 0
/// when not rendered; what is derived from it counts as G-buffer).
pub(super) fn frame_inputs(
    scene: &Scene,
    geo: &Geometry,
    camera_moved: bool,
    inputs: &mut VplInputs,
    geometric: &mut Vec<Vec3>,
    direct: &mut Vec<Vec3>,
    from_gbuffer: &mut FromGBuffer,
) -> VplStats {
    let mut base = VplStats::default();
    if camera_moved {
        let t = Instant::now();
        render_gbuffer_into(scene, geo, &mut inputs.gbuffer, geometric);
        from_gbuffer.build(&inputs.gbuffer);
        base.gbuffer_ms = ms(t);
    }
    let t = Instant::now();
    rsm::reflective_shadow_map_into(scene, geo, &mut inputs.vpls);
    base.rsm_ms = ms(t);
    let t = Instant::now();
    direct_light(scene, geo, &inputs.gbuffer, geometric, direct);
    base.direct_ms = ms(t);
    base.vpls = inputs.vpls.len();
    base
}
