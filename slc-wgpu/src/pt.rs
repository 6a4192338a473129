//! Application B on the GPU: a wavefront progressive path tracer built from
//! slc-shared-shaders' kernels only. Per pass (one sample per pixel):
//!
//! 1. `light_update`: every light's random range `r² = r_t²/(1−ξ)` from the
//!    same `ξ = light_xi(seed, pass, key)` as the CPU path tracer (its key from
//!    `slc_core::xi::xi_keys`: point, spot and IES lights rotate together);
//! 2. `bsh_tail`, then `bsh_refit`: the BSH's range tail for those ranges
//!    (the largest spheres, tested flat after the tree: `Bsh::with_tail`)
//!    and the tree refitted to them, one dispatch per level, deepest first.
//!    With [`GpuPt::set_grid`], `bsh_grid` then lists the refitted leaves
//!    in a uniform grid (slc-core's `BshGrid`) that `pt_connect` looks up
//!    instead of walking the tree (the same lights in the same order);
//! 3. per bounce, `pt_extend` (camera or BSDF ray, closest hit through the
//!    geometry BVH, emission with MIS, next ray, Russian roulette) and
//!    `pt_connect` (BSH traversal into a k-slot reservoir, RR test at the
//!    sampled point, shadow ray, MIS whose light pdf includes p_rr).
//!
//! The methods are `slc-reservoir` with k = [`RESERVOIR_K`] and the power
//! heuristic, exactly as the CPU's [`PtMethod::SlcReservoir`], the
//! importance-weighted `slc-weighted` (k = [`WEIGHTED_K`]), the plain `slc`
//! (every in-range light), and the `uniform`, `power` and `lightbvh`
//! baselines (one light; ranges +∞; the light BVH built by slc-scene and
//! walked by the same slc-core steps as the CPU's); the two
//! backends draw their per-path random numbers differently, so they agree in
//! expectation (the tests crate checks it), not pixel by pixel.
//!
//! `pt_connect`'s shadow rays walk the same WGSL BVH as `pt_extend`'s
//! closest hits, on every adapter; [`GpuPt::with_shadow_rays`] with
//! [`ShadowRays::RayQuery`] casts them as the adapter's ray queries instead
//! (one acceleration structure over the scene's triangles, built before the
//! first pass; the BVH stays for `pt_extend`), on a device opened with
//! wgpu's `EXPERIMENTAL_RAY_QUERY` ([`GpuContext::ray_query`]). The segments
//! and their offsets are the same (`occluded`, geometry.wgsl), so the image
//! is the software walk's wherever the two agree on a segment (Mesa 25's
//! lavapipe does not on a few segments toward thin triangle lights:
//! docs/results/pt-ray-queries.md).

use crate::grid::GpuGrid;
use crate::kernel::{KernelLayout, UniformSlots, pipeline, read_back, storage, zeroed};
use crate::lights::{GpuLightSet, WG};
use crate::occluders::{self, GpuAccel};
use crate::passes::ShadowRays;
use crate::timing::Timer;
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::range::RangeParams;
use slc_core::ray::{ray_t_min, surface_offset};
use slc_scene::backend::{PathTracer, Timing};
use slc_scene::occluders::Occluders;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings, RESERVOIR_K, WEIGHTED_K};
use slc_scene::scene::Material;
use slc_shared_shaders::layout::{
    GpuGeoNode, GpuMaterial, GpuPathState, GpuPathVertex, GpuTriangle, NO_LIGHT, PtParams,
    ShadeParams,
};
use slc_shared_shaders::{Features, Heuristic, Kernel, Selection, generate};
use std::time::Instant;

/// Longest path the uniform slots are sized for (`PtSettings::max_depth`).
const MAX_DEPTH: u32 = 64;

/// BVH nodes, triangles and vertex normals, as [`geometry`] gives them.
type Geometry = (Vec<GpuGeoNode>, Vec<GpuTriangle>, Vec<[f32; 4]>);

/// The geometry BVH as the kernels read it: the scene's triangles as one
/// mesh at the identity (slc-scene's [`Occluders`], the layout the direct
/// pass's shadows use too), the triangles in leaf order with their
/// material and light, and their vertex normals (three per triangle, the
/// same order; geometric ones where the scene has none).
fn geometry(occ: &Occluders, pts: &PtScene) -> Geometry {
    let scene = pts.scene();
    let source: Vec<usize> = (0..occ.triangles().len()).map(|i| occ.source(i).1 as usize).collect();
    let lot = pts.light_of_triangle();
    let tris = occluders::gpu_triangles(occ, |i| {
        let light = lot[source[i]];
        (scene.material_of[source[i]], if light == u32::MAX { NO_LIGHT } else { light })
    });
    let normals = source
        .iter()
        .flat_map(|&i| scene.vertex_normals(i).map(|n| [n.x, n.y, n.z, 0.0]))
        .collect();
    (occluders::gpu_nodes(occ), tris, normals)
}

/// A scene material as the kernels read it.
pub(crate) fn gpu_material(m: &Material) -> GpuMaterial {
    GpuMaterial::new(m.albedo, m.emission, m.metallic, m.roughness, m.f0, m.f90)
}

/// The kernels' light selection for `method`, and its `k`.
fn selection(method: PtMethod) -> (Selection, usize) {
    match method {
        PtMethod::Slc => (Selection::All, RESERVOIR_K),
        PtMethod::SlcReservoir => (Selection::Reservoir, RESERVOIR_K),
        PtMethod::SlcWeighted => (Selection::Weighted, WEIGHTED_K),
        PtMethod::Uniform => (Selection::Uniform, RESERVOIR_K),
        PtMethod::Power => (Selection::Power, RESERVOIR_K),
        PtMethod::LightBvh => (Selection::LightBvh, RESERVOIR_K),
    }
}

/// One path-tracer kernel: its WGSL per method (at [`PtMethod::index`]),
/// generated and validated by [`GpuPt::new`], and the pipelines built from
/// it on a method's first render (a user of one method compiles two
/// pipelines, not twelve); its bind group.
struct Kernels {
    name: &'static str,
    layout: wgpu::BindGroupLayout,
    wgsl: Vec<String>,
    pipelines: Vec<Option<wgpu::ComputePipeline>>,
    bind_group: wgpu::BindGroup,
}

impl Kernels {
    /// Builds `method`'s pipeline if no render has used it yet.
    fn prepare(&mut self, gpu: &GpuContext, table: &wgpu::BindGroupLayout, method: PtMethod) {
        let i = method.index();
        if self.pipelines[i].is_none() {
            let wgsl = self.wgsl[i].clone();
            self.pipelines[i] = Some(pipeline(gpu, self.name, wgsl, &[&self.layout, table]));
        }
    }

    /// `method`'s pipeline, built by [`Kernels::prepare`].
    fn get(&self, method: PtMethod) -> &wgpu::ComputePipeline {
        self.pipelines[method.index()].as_ref().expect("prepared before the render encodes")
    }
}

/// GPU buffers and pipelines for one [`PtScene`] and image size. Keeps a
/// clone of the context (no lifetime ties it to the caller's); a render
/// takes `&mut self`, since every render writes the same buffers.
pub struct GpuPt {
    gpu: GpuContext,
    width: u32,
    height: u32,
    set: GpuLightSet,
    camera: (Vec3, Vec3, Vec3, Vec3),
    diag: f32,
    radiance: wgpu::Buffer,
    readback: wgpu::Buffer,
    pt_params: UniformSlots,
    shade_params: UniformSlots,
    extend: Kernels,
    connect: Kernels,
    /// The scene's triangles as an acceleration structure, where
    /// `pt_connect` casts ray queries.
    accel: Option<GpuAccel>,
    /// The pass's grids over the BSH's leaves (Lambertian receivers, and
    /// glossy ones where the scene has a specular material), where
    /// [`GpuPt::set_grid`] turns them on.
    grid: GpuGrid,
}

impl GpuPt {
    /// Uploads the scene (lights, IES table, BSH, geometry BVH, materials)
    /// and generates every method's kernels for a `width × height` image (a
    /// method's pipelines are built on its first render). Buffer,
    /// binding-count, dispatch and traversal-depth limits are checked first.
    pub fn new(gpu: &GpuContext, pts: &PtScene, width: u32, height: u32) -> Result<Self, GpuError> {
        Self::with_shadow_rays(gpu, pts, width, height, ShadowRays::Software)
    }

    /// [`GpuPt::new`] with `pt_connect`'s shadow rays cast as `rays` (the
    /// module docs). [`ShadowRays::RayQuery`] on a device without wgpu's
    /// `EXPERIMENTAL_RAY_QUERY`, or past its acceleration-structure limits,
    /// is a typed error before anything is uploaded.
    pub fn with_shadow_rays(
        gpu: &GpuContext,
        pts: &PtScene,
        width: u32,
        height: u32,
        rays: ShadowRays,
    ) -> Result<Self, GpuError> {
        slc_scene::check_size(width, height).map_err(|e| GpuError::Setting(e.to_string()))?;
        let pixels = width as u64 * height as u64;
        let occ = Occluders::from_triangles(&pts.scene().triangles)?;
        let ray_query = rays == ShadowRays::RayQuery;
        if ray_query {
            occluders::check_accel_limits(gpu, &occ)?;
        }
        let (geo_nodes, geo_tris, geo_normals) = geometry(&occ, pts);
        let lim = &gpu.limits;
        let max_binding = lim.max_storage_buffer_binding_size;
        gpu.require(
            "max_storage_buffer_binding_size (geometry)",
            geo_tris.len() as u64 * 48,
            max_binding,
        )?;
        gpu.require(
            "max_storage_buffer_binding_size (path states)",
            pixels * std::mem::size_of::<GpuPathState>() as u64,
            max_binding,
        )?;
        // pt_extend: 12 in group 0 (pt_connect: 12 with the grid); the IES, power and
        // cone tables and the light BVH in group 1.
        gpu.require(
            "max_storage_buffers_per_shader_stage",
            16,
            lim.max_storage_buffers_per_shader_stage as u64,
        )?;
        gpu.require(
            "max_storage_buffer_binding_size (vertex normals)",
            geo_tris.len() as u64 * 48,
            max_binding,
        )?;
        gpu.require(
            "max_compute_workgroups_per_dimension (pixels)",
            pixels.div_ceil(WG as u64),
            lim.max_compute_workgroups_per_dimension as u64,
        )?;
        let ls = pts.light_set();
        let set = GpuLightSet::new(
            gpu,
            ls.lights(),
            ls.bounds(),
            pts.bsh(),
            &ls.power_table(),
            ls.cones(),
            Some(pts.light_bvh()),
        )?;
        let glossy = pts.scene().materials.iter().any(Material::has_specular);
        let grid = GpuGrid::new(gpu, &set, pts.bsh(), pts.scene().bounds(), glossy)?;
        let base = Features {
            lights: set.types,
            workgroup_size: WG,
            heuristic: Heuristic::Power,
            ..Features::default()
        };
        let s = |label: &str, bytes: &[u8]| storage(gpu, label, bytes, wgpu::BufferUsages::empty());
        let geo_nodes_buf = s("geo nodes", bytemuck::cast_slice(&geo_nodes));
        let geo_tris_buf = s("geo tris", bytemuck::cast_slice(&geo_tris));
        let geo_normals_buf = s("geo normals", bytemuck::cast_slice(&geo_normals));
        let materials: Vec<GpuMaterial> = pts.scene().materials.iter().map(gpu_material).collect();
        let materials_buf = s("materials", bytemuck::cast_slice(&materials));
        let rw = wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_DST
            | wgpu::BufferUsages::COPY_SRC;
        let candidates = zeroed(gpu, "candidates", pixels * 4, rw);
        let paths = zeroed(gpu, "paths", pixels * std::mem::size_of::<GpuPathState>() as u64, rw);
        let vertices =
            zeroed(gpu, "vertices", pixels * std::mem::size_of::<GpuPathVertex>() as u64, rw);
        let radiance = zeroed(gpu, "radiance", pixels * 16, rw);
        let readback = zeroed(
            gpu,
            "radiance readback",
            pixels * 16,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        // One extend per depth and a last one that only adds the emission its
        // BSDF sample finds.
        let pt_params = UniformSlots::new::<PtParams>(gpu, "pt params", MAX_DEPTH as u64 + 1);
        let shade_params = UniformSlots::new::<ShadeParams>(gpu, "shade params", MAX_DEPTH as u64);
        // One bind group per kernel; one pipeline per light selection,
        // built on the selection's first render.
        // Group 0 of each kernel, bound by its binding table's names (the
        // tables do not depend on the light selection); group 1 is the
        // light set's tables.
        let accel = if ray_query { Some(GpuAccel::new(gpu, &occ)?) } else { None };
        // Every group-0 resource of the two kernels by its binding name:
        // each kernel binds those its binding table binds (pt_connect with
        // ray queries binds geo_tlas, not geo_nodes and geo_tris).
        let whole = crate::kernel::whole;
        let mut resources = vec![
            ("lights", whole(&set.lights)),
            ("rt2", whole(&set.rt2)),
            ("r2", whole(&set.r2)),
            ("bsh_nodes", whole(&set.bsh)),
            ("light_leaf", whole(&set.leaf)),
            ("geo_nodes", whole(&geo_nodes_buf)),
            ("geo_tris", whole(&geo_tris_buf)),
            ("materials", whole(&materials_buf)),
            ("geo_normals", whole(&geo_normals_buf)),
            ("candidates", whole(&candidates)),
            ("paths", whole(&paths)),
            ("vertices", whole(&vertices)),
            ("radiance", whole(&radiance)),
            ("grid", whole(&grid.grid)),
            ("grid_entries", whole(&grid.entries)),
        ];
        if let Some(a) = &accel {
            resources.push(("geo_tlas", wgpu::BindingResource::AccelerationStructure(&a.tlas)));
        }
        let kernel = |k: Kernel, f: &Features, params: &UniformSlots| {
            let wgsl = PtMethod::ALL
                .iter()
                .map(|&m| {
                    let (selection, k_slots) = selection(m);
                    generate(k, &Features { selection, reservoir_k: k_slots as u32, ..*f })
                })
                .collect::<Result<Vec<_>, _>>()?;
            let layout = KernelLayout::new(gpu, k, f)?;
            let mut res = vec![("params", params.binding())];
            res.extend(resources.iter().filter(|(name, _)| layout.binds(name)).cloned());
            let bind_group = layout.group(gpu, 0, &res);
            let pipelines = vec![None; wgsl.len()];
            let layout = layout.group_layout(0).clone();
            Ok::<_, GpuError>(Kernels { name: k.name(), layout, wgsl, pipelines, bind_group })
        };
        let extend = kernel(Kernel::PtExtend, &base, &pt_params)?;
        let connect = kernel(
            Kernel::PtConnect,
            &Features { ray_query, bsh_grid: true, ..base },
            &shade_params,
        )?;
        let cam = &pts.scene().camera;
        let (f, r, u) = cam.scaled_basis(width, height);
        let g = GpuPt {
            gpu: gpu.clone(),
            width,
            height,
            set,
            camera: (cam.position, r, u, f),
            diag: pts.scene().diagonal(),
            radiance,
            readback,
            pt_params,
            shade_params,
            extend,
            connect,
            accel,
            grid,
        };
        gpu.wait()?;
        Ok(g)
    }

    /// Renders `passes` more passes into `acc` (which must match the image
    /// size and hold passes of the same settings): pass numbers continue
    /// from `acc.passes`, so a render split over calls equals one call.
    /// Time is GPU time from timestamps where the adapter has them, else
    /// wall time around the submitted passes; the second value says which
    /// (`true`: timestamps).
    pub fn render(
        &mut self,
        acc: &mut PtRender,
        s: &PtSettings,
        passes: u32,
    ) -> Result<bool, GpuError> {
        if acc.size() != (self.width, self.height) {
            return Err(GpuError::Setting(format!(
                "accumulation is {:?}, the GPU scene was set up for {}x{}",
                acc.size(),
                self.width,
                self.height
            )));
        }
        if !(1..=MAX_DEPTH).contains(&s.max_depth) {
            return Err(GpuError::Setting(format!(
                "max depth {} must be in 1..={MAX_DEPTH}",
                s.max_depth
            )));
        }
        let params = RangeParams::new(s.error_bound, s.exposure)
            .map_err(|e| GpuError::Setting(e.to_string()))?;
        let gpu = &self.gpu;
        self.extend.prepare(gpu, &self.set.table_layout, s.method);
        self.connect.prepare(gpu, &self.set.table_layout, s.method);
        let (extend, connect) = (self.extend.get(s.method), self.connect.get(s.method));
        // The baselines cull nothing: r_t² = +∞ makes p = 1 and r² = +∞.
        self.set.set_threshold(gpu, s.method.culls().then_some(&params));
        let pixels = self.width * self.height;
        let mut enc = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("clear") });
        enc.clear_buffer(&self.radiance, 0, None);
        // The acceleration structure's build, once, before the first pass.
        if let Some(a) = &mut self.accel {
            a.record_builds(&mut enc);
        }
        gpu.queue.submit([enc.finish()]);
        let (pos, right, up, fwd) = self.camera;
        // Timestamps for every pass, or none (then wall time).
        let mut timer = if passes <= 2048 { Timer::new(gpu, passes) } else { None };
        let t = Instant::now();
        for k in 0..passes {
            let pass = acc.passes + k;
            self.set.set_frame(gpu, s.seed, pass);
            let pt: Vec<PtParams> = (0..=s.max_depth)
                .map(|depth| PtParams {
                    cam_pos: pos,
                    width: self.width,
                    cam_right: right,
                    height: self.height,
                    cam_up: up,
                    depth,
                    cam_forward: fwd,
                    seed: s.seed,
                    pass_index: pass,
                    max_depth: s.max_depth,
                    eps: surface_offset(self.diag),
                    t_min: ray_t_min(self.diag),
                })
                .collect();
            self.pt_params.write(gpu, &pt);
            let shade: Vec<ShadeParams> = (0..s.max_depth)
                .map(|depth| ShadeParams {
                    point_count: pixels,
                    seed: s.seed,
                    frame: pass.wrapping_mul(MAX_DEPTH).wrapping_add(depth),
                    eps: surface_offset(self.diag),
                })
                .collect();
            self.shade_params.write(gpu, &shade);
            let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("slc pt pass"),
            });
            {
                let writes = timer.as_mut().and_then(|t| t.next());
                let mut cp = enc.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("slc pt pass"),
                    timestamp_writes: writes,
                });
                // The baselines cull nothing: their ranges are +∞ in every
                // pass (written once per call), and no BSH is walked.
                if s.method.culls() {
                    self.set.encode(&mut cp);
                    self.grid.encode(&mut cp);
                } else if k == 0 {
                    self.set.encode_update(&mut cp);
                } else {
                    self.set.bind_tables(&mut cp);
                }
                for depth in 0..=s.max_depth as usize {
                    cp.set_pipeline(extend);
                    cp.set_bind_group(0, &self.extend.bind_group, &[self.pt_params.offset(depth)]);
                    cp.dispatch_workgroups(pixels.div_ceil(WG), 1, 1);
                    // The last extend only adds the emission its BSDF
                    // sample finds (MIS's other share of the last vertex).
                    if depth < s.max_depth as usize {
                        cp.set_pipeline(connect);
                        cp.set_bind_group(
                            0,
                            &self.connect.bind_group,
                            &[self.shade_params.offset(depth)],
                        );
                        cp.dispatch_workgroups(pixels.div_ceil(WG), 1, 1);
                    }
                }
            }
            if k + 1 == passes
                && let Some(t) = &timer
            {
                t.resolve(&mut enc);
            }
            gpu.queue.submit([enc.finish()]);
        }
        gpu.wait()?;
        let wall_ms = t.elapsed().as_secs_f64() * 1e3;
        let (ms, timestamps) = match &timer {
            Some(t) if passes > 0 => (t.total_ms(gpu)?, true),
            _ => (wall_ms, false),
        };
        let data: Vec<[f32; 4]> = read_back(gpu, &self.radiance, &self.readback)?;
        let sum: Vec<Vec3> = data.iter().map(|d| Vec3::new(d[0], d[1], d[2])).collect();
        acc.accumulate(&sum, passes, ms);
        Ok(timestamps)
    }
}

impl GpuPt {
    /// Whether the SLC methods' passes build grids over the BSH's leaves
    /// and find a vertex's lights in its cell (slc-core's `BshGrid`, built
    /// on the GPU each pass, for Lambertian vertices and, in a scene with
    /// specular materials, glossy ones whose range lobe is within
    /// `GLOSSY_REACH` and within `SHARP_REACH`, every lobe, as the CPU path
    /// tracer does) or walk the tree for every vertex (`false`, the
    /// default). The same lights in the same order either way, so the same
    /// image. Off by default: on lavapipe the build (6 dispatches a pass
    /// for all its grids, and each cell's sort) costs more than the
    /// lookups save (docs/results/bsh-walk-visits.md); a real
    /// GPU has not measured it yet. The grids' buffers are made with the
    /// path tracer, on or off: at most 8 entries of 4 bytes a light and one
    /// a cell (`slc_core::bsh::GRID_ENTRIES_PER_LIGHT`) per grid, the sharp
    /// one at least 2¹⁸ (`SHARP_GRID_ENTRIES`; 5.1 MB for the three at
    /// 49,152 lights).
    pub fn set_grid(&mut self, on: bool) {
        self.grid.set_enabled(&self.gpu, on);
    }

    /// The most moves the grids' build may make sorting a cell's leaves by
    /// insertion in one invocation before the cell's workgroup sorts it
    /// (a bitonic sort): `slc_shared_shaders::layout::GRID_SORT_MOVES` by
    /// default, which every cell of up to 45 leaves and every cell filled
    /// almost in order stays within; 0 sorts every cell of two or more by
    /// its workgroup. The same cells, and so the same image, either way:
    /// for tests and for timing the two sorts on a device.
    pub fn set_grid_sort_moves(&mut self, moves: u32) {
        self.grid.set_sort_moves(&self.gpu, moves);
    }

    /// The BSH as the last render's refit left it, range tail included,
    /// read back: for the tests that compare it with the CPU's refit.
    #[doc(hidden)]
    pub fn read_bsh(&self, gpu: &GpuContext) -> Result<Vec<slc_core::bsh::BshNode>, GpuError> {
        let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("bsh readback"),
            size: self.set.bsh.size(),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        read_back(gpu, &self.set.bsh, &staging)
    }

    /// The last render's grid `g` (0: Lambertian, 1: glossy, 2: sharp)
    /// read back:
    /// its frame (no cells along x where it had none) and each cell's
    /// leaves (node indices), `None` where the scene has no such grid: for
    /// the tests that check it against the walk.
    #[doc(hidden)]
    pub fn read_grid(
        &self,
        gpu: &GpuContext,
        g: usize,
    ) -> Result<Option<crate::grid::GridCells>, GpuError> {
        self.grid.read(gpu, g)
    }
}

impl PathTracer for GpuPt {
    type Error = GpuError;

    fn describe(&self) -> String {
        self.gpu.describe()
    }

    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, GpuError> {
        let timestamps = GpuPt::render(self, acc, settings, passes)?;
        Ok(if timestamps { Timing::GpuTimestamps } else { Timing::Wall })
    }
}
