//! The indirect pass's record: its uniforms and dispatches in order, built
//! from the settings (only the stages they run) after checking them and
//! the inputs.

use super::*;

impl IndirectPass {
    /// The record's uniforms and dispatches in order (only those its
    /// settings run); checks the inputs and settings first.
    pub(crate) fn dispatches(
        &mut self,
        inputs: &IndirectInputs,
        st: &IndirectSettings,
        counted: bool,
    ) -> Result<Recording, GpuError> {
        let view = inputs.check(&self.desc, st.seed, st.frame)?;
        let (slc, fixed_r2) = kernel_form(&st.culling)?;
        if !(st.min_distance.is_finite() && st.min_distance >= 0.0) {
            return Err(GpuError::Setting(format!(
                "indirect pass: min distance {} must be finite and non-negative",
                st.min_distance
            )));
        }
        if let Some(r) = st.near_radius
            && !(r.is_finite() && r >= 0.0)
        {
            return Err(GpuError::Setting(format!(
                "indirect pass: near radius {r} must be finite and non-negative"
            )));
        }
        if let Some(x) = st.fixed_xi {
            slc_core::range::Xi::new(x)
                .map_err(|e| GpuError::Setting(format!("indirect pass: {e}")))?;
        }
        let (w, h) = (self.desc.width, self.desc.height);
        let count = self.desc.vpls.count() as u32;
        let rsm_size = match self.desc.vpls {
            VplSourceDesc::Rsm { size } => size,
            VplSourceDesc::Buffer { .. } => 0,
        };
        let (mode, exposure, error_bound) = match st.culling {
            Culling::Stochastic(p) => (p.measure().mode(), p.exposure(), p.error_bound()),
            _ => (0, 1.0, 1.0),
        };
        let min_d2 = st.min_distance * st.min_distance;
        let near_r2 = st.near_r2();
        let gpu = &self.gpu;
        let mut uploads = Uploads::default();
        uploads.push(&self.view, &view);
        uploads.push(
            &self.pack_params,
            &PackParams {
                count,
                size: rsm_size,
                per_subset: self.hierarchy.per_subset,
                mode,
                exposure,
                error_bound,
                scale: slc_core::interleave::interleave_flux_scale(self.desc.period()),
                slc: slc as u32,
                // No culling: the kernel's finite stand-in for +∞.
                fixed_r2: if fixed_r2.is_finite() { fixed_r2 } else { f32::MAX },
                pad0: 0,
                pad1: 0,
                pad2: 0,
            },
        );
        uploads.push(
            &self.frame_params,
            &FrameParams {
                light_count: self.hierarchy.slots() as u32,
                seed: st.seed,
                frame: st.frame,
                fixed_xi: st.fixed_xi.unwrap_or(-1.0),
            },
        );
        let mut vpl_params = VplParams {
            width: w,
            height: h,
            min_d2,
            near_r2,
            subset_shift: interleave_shift(st.seed, st.frame, self.desc.period()),
            ..bytemuck::Zeroable::zeroed()
        };
        self.hierarchy.fill(&mut vpl_params, near_r2 > 0.0);
        uploads.push(&self.vpl_params, &vpl_params);
        let tex = wgpu::BindingResource::TextureView;
        let b = crate::kernel::whole;
        let g = inputs.gbuffer;
        let (view_slots, vpl_slots, irradiance, filtered, guide) =
            (&self.view, &self.vpl_params, &self.irradiance, &self.filtered, &self.guide);
        let (tiled_layout, near_layout, outs) =
            (&self.tiled_layout, &self.near_layout, &self.pack_outputs);
        let [lights, _, rt2, r2, near_slots] = outs;
        let boxes = &self.boxes;
        let specular = self.specular.as_ref();
        let table = inputs.materials.map(|m| m.table);
        /// The G-buffer readers' common bindings, then `rest`.
        fn with<'b>(
            base: &[(&'static str, wgpu::BindingResource<'b>)],
            rest: &[(&'static str, &'b wgpu::Buffer)],
        ) -> Vec<(&'static str, wgpu::BindingResource<'b>)> {
            base.iter()
                .cloned()
                .chain(rest.iter().map(|&(name, buf)| (name, buf.as_entire_binding())))
                .collect()
        }
        let base = || {
            [
                ("params", vpl_slots.binding()),
                ("view", view_slots.binding()),
                (g.surface_name(), tex(g.surface_view())),
                ("normal_tex", tex(g.normal)),
            ]
        };
        // The buffers `vpl_tiled` and `vpl_near` bind besides the G-buffer,
        // before the glossy or counting ones; `vpl_near` adds to the raw
        // (0) or the denoised (1) irradiance.
        let tiled_rest = || {
            vec![
                ("lights", lights),
                ("rt2", rt2),
                ("r2", r2),
                ("boxes", boxes),
                ("irradiance", irradiance),
                ("guide", guide),
            ]
        };
        let near_rest = |k: usize| {
            let target = [irradiance, filtered][k];
            vec![
                ("lights", lights),
                ("near_slots", near_slots),
                ("boxes", boxes),
                ("rt2", rt2),
                ("r2", r2),
                ("irradiance", target),
            ]
        };
        // The kernels that read the G-buffer in place: bound to the
        // engine's views (and material table), cached by them.
        let groups = self.gbuffer_cache.get(
            (g.surface_view().clone(), g.normal.clone(), table.cloned()),
            || {
                let base = base();
                // The glossy kernels' material table and specular target.
                let glossy = |k: usize| match (table, specular) {
                    (Some(t), Some(sp)) => vec![("materials", t), ("specular", &sp[k])],
                    _ => Vec::new(),
                };
                let near = |k: usize| {
                    let mut rest = near_rest(k);
                    rest.extend(glossy(k));
                    near_layout.group(gpu, 0, &with(&base, &rest))
                };
                let mut tiled = tiled_rest();
                tiled.extend(glossy(0));
                GbufferGroups {
                    tiled: tiled_layout.group(gpu, 0, &with(&base, &tiled)),
                    near: [near(0), near(1)],
                }
            },
        );
        // The counting kernels' groups: the same buffers, Lambertian, and
        // each field's counters.
        let counted = match (counted, self.counting.as_mut()) {
            (false, _) => None,
            (true, None) => {
                return Err(GpuError::Setting("indirect pass: counting kernels not built".into()));
            }
            (true, Some(c)) => {
                let (tl, nl, counters) = (&c.tiled_layout, &c.near_layout, &c.counters);
                let groups = c.groups.get((g.surface_view().clone(), g.normal.clone()), || {
                    let base = base();
                    let near = |k| {
                        let mut rest = near_rest(k);
                        rest.push(("counters", &counters[1]));
                        nl.group(gpu, 0, &with(&base, &rest))
                    };
                    let mut tiled = tiled_rest();
                    tiled.push(("counters", &counters[0]));
                    CountGroups {
                        tiled: tl.group(gpu, 0, &with(&base, &tiled)),
                        near: [near(0), near(1)],
                    }
                });
                Some((groups, &c.tiled, &c.near))
            }
        };
        let (pack, pack_slots) = (&self.pack.layout, &self.pack_params);
        let key = match inputs.vpls {
            VplInput::Rsm { position, normal, flux } => {
                PackKey::Rsm(Box::new([position.clone(), normal.clone(), flux.clone()]))
            }
            VplInput::Buffer(buf) => PackKey::Buffer(buf.clone()),
        };
        let pack_group = self.pack_cache.get(key, || {
            let mut res = vec![("params", pack_slots.binding())];
            match inputs.vpls {
                VplInput::Rsm { position, normal, flux } => res.extend([
                    ("rsm_position", tex(position)),
                    ("rsm_normal", tex(normal)),
                    ("rsm_flux", tex(flux)),
                ]),
                VplInput::Buffer(buf) => res.push(("records", b(buf))),
            }
            for (name, buf) in ["lights", "ids", "rt2", "r2", "near_slots"].into_iter().zip(outs) {
                res.push((name, b(buf)));
            }
            pack.group(gpu, 0, &res)
        });
        let result = if st.denoise { &self.filtered } else { &self.irradiance };
        let export = &self.export.layout;
        let specular_view = inputs.materials.map(|m| m.specular);
        let key = (
            g.surface_view().clone(),
            g.normal.clone(),
            inputs.output.clone(),
            specular_view.cloned(),
            st.denoise,
        );
        let export_group = self.export_cache.get(key, || {
            let mut res = vec![
                ("view", view_slots.binding()),
                (g.surface_name(), tex(g.surface_view())),
                ("normal_tex", tex(g.normal)),
                ("irradiance", b(result)),
                ("out_tex", tex(inputs.output)),
            ];
            if let (Some(sp), Some(view)) = (specular, specular_view) {
                res.extend([
                    ("specular", b(&sp[st.denoise as usize])),
                    ("specular_tex", tex(view)),
                ]);
            }
            export.group(gpu, 0, &res)
        });
        let method = st.culling.kind();
        let (tiled_group, near_groups, tiled, near) = match counted {
            Some((c, tiled, near)) => {
                (c.tiled, c.near, Pipe::find(tiled, method)?, Pipe::find(near, method)?)
            }
            None => (
                groups.tiled,
                groups.near,
                Pipe::find(&self.tiled, method)?,
                Pipe::find(&self.near, method)?,
            ),
        };
        let (gx, gy) = (w.div_ceil(TILE), h.div_ceil(TILE));
        let p = self.desc.period();
        let (sub_w, sub_h) = (w.div_ceil(p), h.div_ceil(p));
        let off = |_: &UniformSlots| Some(0);
        let d = Dispatch::new;
        // The G-buffer readers' two dynamic uniforms, in binding order:
        // params (VplParams), view (ViewParams).
        let both = || vec![0, 0];
        let d2 = Dispatch::with_offsets;
        let mut out = vec![d(
            Stage::VplGeneration,
            &self.pack.pipeline,
            pack_group,
            off(&self.pack_params),
            [count.div_ceil(CLUSTER), 1, 1],
        )];
        if slc {
            out.push(d(
                Stage::LightUpdate,
                &self.update.pipeline,
                self.update_group.clone(),
                off(&self.frame_params),
                [(self.hierarchy.slots() as u32).div_ceil(WG), 1, 1],
            ));
        }
        // The culling hierarchies' boxes, once the ranges are drawn: the
        // far field's when it is culled, the near field's when there is one.
        let near_field = near_r2 > 0.0;
        if method != CullKind::None || near_field {
            let max_dim = self.gpu.limits.max_compute_workgroups_per_dimension;
            out.push(d(
                Stage::Bounds,
                Pipe::find(&self.clusters, method)?,
                self.clusters_group.clone(),
                off(&self.vpl_params),
                self.hierarchy.cluster_dispatch(near_field, max_dim),
            ));
            out.push(d(
                Stage::Bounds,
                &self.groups.pipeline,
                self.groups_group.clone(),
                off(&self.vpl_params),
                self.hierarchy.group_dispatch(near_field, max_dim),
            ));
        }
        out.push(d2(
            Stage::Shading,
            tiled,
            tiled_group,
            both(),
            [sub_w.div_ceil(TILE), sub_h.div_ceil(TILE), p * p],
        ));
        if st.denoise {
            // The irradiance, then the specular correction by the same filter.
            for group in &self.denoise_groups {
                let (pipeline, vpl) = (&self.denoise.pipeline, off(&self.vpl_params));
                out.push(d(Stage::Denoise, pipeline, group.clone(), vpl, [gx, gy, 1]));
            }
        }
        if near_field {
            let [raw, denoised] = near_groups;
            out.push(d2(
                Stage::NearField,
                near,
                if st.denoise { denoised } else { raw },
                both(),
                [gx, gy, 1],
            ));
        }
        out.push(d(
            Stage::IrradianceExport,
            &self.export.pipeline,
            export_group,
            off(&self.view),
            [gx, gy, 1],
        ));
        Ok(Recording { uploads, dispatches: out })
    }
}
