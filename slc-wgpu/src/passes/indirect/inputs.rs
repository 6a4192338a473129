//! What an engine gives the [`IndirectPass`]: what the pass is built for
//! ([`IndirectPassDesc`], [`VplSourceDesc`]), each record's resources
//! ([`IndirectInputs`], [`VplInput`], [`IndirectMaterials`]) and settings
//! ([`IndirectSettings`]), the checks of the resources against the
//! descriptor, and [`vpl_buffer`] for VPLs made on the host.

#[cfg(doc)]
use super::IndirectPass;
use crate::kernel::storage;
use crate::passes::{Culling, FLOAT_INPUTS, GBuffer, SurfaceDesc, check_optional, check_view};
use crate::{GpuContext, GpuError};
use slc_scene::vpl::{NEAR_FACTOR, PERIOD};
use slc_shared_shaders::layout::{GpuMaterial, GpuVplRecord, ViewParams};

/// Default capacity of `vpl_tiled`'s tile light list
/// ([`IndirectPassDesc::tile_list`]; 8 KiB of workgroup memory): a subset
/// with more lights is culled and shaded in chunks of this size.
pub const TILE_LIST: u32 = 2048;

/// Where the indirect pass gets its VPLs, fixed at creation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VplSourceDesc {
    /// A reflective shadow map of `size × size` texels (`size` a multiple of
    /// 8): one VPL per texel.
    Rsm {
        /// Edge in texels.
        size: u32,
    },
    /// A buffer of `count` [`GpuVplRecord`]s (`count` a multiple of 64).
    Buffer {
        /// Number of VPLs.
        count: u32,
    },
}

impl VplSourceDesc {
    /// The number of VPLs.
    pub(crate) fn count(self) -> u64 {
        match self {
            VplSourceDesc::Rsm { size } => size as u64 * size as u64,
            VplSourceDesc::Buffer { count } => count as u64,
        }
    }
}

/// What an [`IndirectPass`] is built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndirectPassDesc {
    /// G-buffer and output width.
    pub width: u32,
    /// G-buffer and output height.
    pub height: u32,
    /// Where the G-buffer's surface comes from.
    pub surface: SurfaceDesc,
    /// The VPL source.
    pub vpls: VplSourceDesc,
    /// Format of the output storage texture: `Rgba16Float` or `Rgba32Float`.
    pub output_format: wgpu::TextureFormat,
    /// Interleaved sampling (the paper's): each pixel of an 8×8 block
    /// shades its own subset of 1/64 of the VPLs at 64 times their flux,
    /// and the denoise filters over the block. `false`: every VPL at every
    /// pixel (period 1), 64 times the work: with [`Culling::None`], no
    /// denoise and no near field (`near_radius: Some(0.0)`), the exact sum,
    /// a reference to measure the interleaved image against.
    pub interleaved: bool,
    /// Capacity of `vpl_tiled`'s per-tile light list, in lights (at least
    /// 64, a cluster; 4 bytes of workgroup memory each): a subset with more
    /// lights streams through it in chunks. The near field's `vpl_near`
    /// splits it into one list per quarter of the tile (a quarter each, at
    /// least 64). Default [`TILE_LIST`].
    pub tile_list: u32,
    /// Built with the material input (see the module docs): every record
    /// takes [`IndirectInputs::materials`] and also writes the specular
    /// correction `S` of glossy pixels. `false` (the default): Lambertian,
    /// no material input.
    pub glossy: bool,
}

impl IndirectPassDesc {
    /// `width × height` with VPLs from `vpls`, a `Depth32Float` depth
    /// buffer, `Rgba16Float` output, interleaved, the default tile list,
    /// Lambertian (no material input).
    pub fn new(width: u32, height: u32, vpls: VplSourceDesc) -> IndirectPassDesc {
        IndirectPassDesc {
            width,
            height,
            surface: SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float },
            vpls,
            output_format: wgpu::TextureFormat::Rgba16Float,
            interleaved: true,
            tile_list: TILE_LIST,
            glossy: false,
        }
    }

    /// The interleave period: [`PERIOD`], or 1 when not interleaved.
    pub(crate) fn period(&self) -> u32 {
        if self.interleaved { PERIOD } else { 1 }
    }
}

/// The VPLs of one frame.
#[derive(Clone, Copy, Debug)]
pub enum VplInput<'a> {
    /// RSM textures (see the module table).
    Rsm {
        /// World position of the texel's surface.
        position: &'a wgpu::TextureView,
        /// Its unit normal.
        normal: &'a wgpu::TextureView,
        /// Reflected flux (rgb).
        flux: &'a wgpu::TextureView,
    },
    /// A storage buffer of [`GpuVplRecord`]s.
    Buffer(&'a wgpu::Buffer),
}

/// The material input of a glossy pass ([`IndirectPassDesc::glossy`]).
#[derive(Clone, Copy, Debug)]
pub struct IndirectMaterials<'a> {
    /// [`GpuMaterial`]s; a pixel's index is its normal texel's `w`.
    pub table: &'a wgpu::Buffer,
    /// Where the specular correction `S` goes (the output's format and size,
    /// `STORAGE_BINDING`).
    pub specular: &'a wgpu::TextureView,
}

/// The engine's resources for one record.
#[derive(Clone, Copy, Debug)]
pub struct IndirectInputs<'a> {
    /// The G-buffer.
    pub gbuffer: GBuffer<'a>,
    /// The VPLs.
    pub vpls: VplInput<'a>,
    /// Where the irradiance goes.
    pub output: &'a wgpu::TextureView,
    /// The materials and the specular output: required by a glossy pass,
    /// refused by a Lambertian one (`None`).
    pub materials: Option<IndirectMaterials<'a>>,
}

impl IndirectInputs<'_> {
    /// Checks these inputs against the pass's descriptor `desc` (formats,
    /// sizes, usages) and makes the record's [`ViewParams`] (`seed`,
    /// `frame`: its random streams).
    pub(crate) fn check(
        &self,
        desc: &IndirectPassDesc,
        seed: u32,
        frame: u32,
    ) -> Result<ViewParams, GpuError> {
        let size = (desc.width, desc.height);
        let tex = wgpu::TextureUsages::TEXTURE_BINDING;
        let view = self.gbuffer.check(desc.surface, size, seed, frame)?;
        check_view(
            "output",
            self.output,
            size,
            &[desc.output_format],
            wgpu::TextureUsages::STORAGE_BINDING,
        )?;
        check_optional(
            "materials",
            self.materials.is_some(),
            desc.glossy,
            "a material table and a specular output",
            "IndirectPassDesc::glossy",
        )?;
        if let Some(m) = self.materials {
            check_view(
                "specular output",
                m.specular,
                size,
                &[desc.output_format],
                wgpu::TextureUsages::STORAGE_BINDING,
            )?;
            let entry = std::mem::size_of::<GpuMaterial>() as u64;
            if m.table.size() < entry || !m.table.usage().contains(wgpu::BufferUsages::STORAGE) {
                return Err(GpuError::Binding {
                    name: "material table",
                    expected: format!(
                        "at least {entry} bytes (one GpuMaterial) with STORAGE usage"
                    ),
                    found: format!("{} bytes, {:?}", m.table.size(), m.table.usage()),
                });
            }
        }
        match (self.vpls, desc.vpls) {
            (VplInput::Rsm { position, normal, flux }, VplSourceDesc::Rsm { size }) => {
                check_view("RSM position", position, (size, size), &FLOAT_INPUTS, tex)?;
                check_view("RSM normal", normal, (size, size), &FLOAT_INPUTS, tex)?;
                check_view("RSM flux", flux, (size, size), &FLOAT_INPUTS, tex)?;
            }
            (VplInput::Buffer(b), VplSourceDesc::Buffer { count }) => {
                let need = count as u64 * std::mem::size_of::<GpuVplRecord>() as u64;
                if b.size() < need || !b.usage().contains(wgpu::BufferUsages::STORAGE) {
                    return Err(GpuError::Binding {
                        name: "VPL buffer",
                        expected: format!(
                            "at least {need} bytes ({count} GpuVplRecords) with STORAGE usage"
                        ),
                        found: format!("{} bytes, {:?}", b.size(), b.usage()),
                    });
                }
            }
            (VplInput::Rsm { .. }, VplSourceDesc::Buffer { .. }) => {
                return Err(GpuError::Binding {
                    name: "VPLs",
                    expected: "a VPL buffer (the pass was built for one)".into(),
                    found: "RSM textures".into(),
                });
            }
            (VplInput::Buffer(_), VplSourceDesc::Rsm { .. }) => {
                return Err(GpuError::Binding {
                    name: "VPLs",
                    expected: "RSM textures (the pass was built for an RSM)".into(),
                    found: "a buffer".into(),
                });
            }
        }
        Ok(view)
    }
}

/// Per-record settings of the indirect pass: all it honours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IndirectSettings {
    /// How VPLs are culled (stochastic, clamped or not at all).
    pub culling: Culling,
    /// Seed of the per-VPL ξ.
    pub seed: u32,
    /// Frame number (a new ξ set and a new shift of the subset map per
    /// frame).
    pub frame: u32,
    /// Give every VPL this ξ (in `[0, 1)`) instead of its own
    /// `xi_for(seed, frame, i)`: not an estimator on its own, but averaging
    /// records over a grid of ξ is quadrature of the expectation over ξ
    /// (how the tests prove the pass unbiased). `None` (the default) for
    /// rendering.
    pub fixed_xi: Option<f32>,
    /// Cross-bilateral filter over the interleaving window.
    pub denoise: bool,
    /// Clamp distance of the VPL fall-off `1/max(d², min_distance²)`
    /// (scene units, finite, ≥ 0).
    pub min_distance: f32,
    /// Near-field radius `R_n`: VPLs closer than it are shaded at every
    /// pixel, unscaled and undenoised (`None`:
    /// [`NEAR_FACTOR`] × `min_distance`; `Some(0)`: no split).
    pub near_radius: Option<f32>,
}

impl Default for IndirectSettings {
    /// Stochastic culling at the default error bound
    /// ([`Culling::default`]), exposure 1; seed 1, frame 0; denoised; 5 cm
    /// clamp distance, the default near field.
    fn default() -> Self {
        IndirectSettings {
            culling: Culling::default(),
            seed: 1,
            frame: 0,
            fixed_xi: None,
            denoise: true,
            min_distance: 0.05,
            near_radius: None,
        }
    }
}

impl IndirectSettings {
    /// The reference's settings from these (the same seed, frame and clamp
    /// distance): every VPL at every pixel, no ξ, no denoise, no near
    /// split. Record them with a pass built with `interleaved: false`.
    pub fn reference(&self) -> IndirectSettings {
        IndirectSettings {
            culling: Culling::None,
            fixed_xi: None,
            denoise: false,
            near_radius: Some(0.0),
            ..*self
        }
    }

    /// `R_n²` of the near-field split.
    pub(crate) fn near_r2(&self) -> f32 {
        let r = self.near_radius.unwrap_or(NEAR_FACTOR * self.min_distance);
        r * r
    }
}

/// Uploads `records` as a storage buffer of the device (a helper for
/// engines and tests that make VPL records on the host).
pub fn vpl_buffer(gpu: &GpuContext, records: &[GpuVplRecord]) -> wgpu::Buffer {
    storage(gpu, "slc vpl records", bytemuck::cast_slice(records), wgpu::BufferUsages::empty())
}
