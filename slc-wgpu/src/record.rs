//! What a pass records: its uniform values ([`Uploads`], copied into place
//! by the record's own encoder) and its dispatches ([`Dispatch`], each with
//! the [`Stage`] that times it), together a [`Recording`]. The passes make
//! them; a pass's `record` or the frame records them.

use crate::GpuContext;
use crate::kernel::UniformSlots;
use crate::timing::Stage;
use wgpu::util::DeviceExt;

/// A record's uniform values, put in place by the record's own command
/// encoder.
///
/// `queue.write_buffer` lands before a whole submission runs, so two
/// records of a pass in one submission that wrote the same uniform would
/// both read the second's values. Staged here, a record's values travel in
/// a small buffer of their own (made for the record, initialised at
/// creation, freed by wgpu once the commands that read it have run) and
/// `copy_buffer_to_buffer` writes them into the pass's uniform buffers in
/// command order, just before the record's dispatches: any number of
/// records of a pass may share a submission, each reading its own values.
#[derive(Default)]
pub(crate) struct Uploads {
    bytes: Vec<u8>,
    /// `(offset in bytes, destination, size)` of each value.
    copies: Vec<(u64, wgpu::Buffer, u64)>,
}

impl Uploads {
    /// Stages `value` for slot 0 of `dst`.
    pub(crate) fn push<T: bytemuck::Pod>(&mut self, dst: &UniformSlots, value: &T) {
        self.push_to(&dst.buffer, value);
    }

    /// Stages `value` for the start of `dst` (a `COPY_DST` buffer).
    pub(crate) fn push_to<T: bytemuck::Pod>(&mut self, dst: &wgpu::Buffer, value: &T) {
        let at = self.bytes.len() as u64;
        let bytes = bytemuck::bytes_of(value);
        self.bytes.extend_from_slice(bytes);
        self.bytes
            .resize(self.bytes.len().next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT as usize), 0);
        self.copies.push((
            at,
            dst.clone(),
            (bytes.len() as u64).next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT),
        ));
    }

    /// Adds `other`'s values after these.
    pub(crate) fn append(&mut self, other: Uploads) {
        let base = self.bytes.len() as u64;
        self.bytes.extend_from_slice(&other.bytes);
        self.copies.extend(other.copies.into_iter().map(|(at, dst, size)| (base + at, dst, size)));
    }

    /// Records the copies of the staged values into `encoder`.
    pub(crate) fn record(&self, gpu: &GpuContext, encoder: &mut wgpu::CommandEncoder) {
        if self.copies.is_empty() {
            return;
        }
        let src = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("slc record uniforms"),
            contents: &self.bytes,
            usage: wgpu::BufferUsages::COPY_SRC,
        });
        for (at, dst, size) in &self.copies {
            encoder.copy_buffer_to_buffer(&src, *at, dst, 0, *size);
        }
    }
}

/// A record of a pass: its uniforms, copied into place first, then its
/// dispatches.
pub(crate) struct Recording {
    /// The record's uniform values.
    pub(crate) uploads: Uploads,
    /// Its dispatches, in order.
    pub(crate) dispatches: Vec<Dispatch>,
}

impl Recording {
    /// Records the uploads, then one compute pass (`label`) of every
    /// dispatch.
    pub(crate) fn record(&self, gpu: &GpuContext, encoder: &mut wgpu::CommandEncoder, label: &str) {
        self.uploads.record(gpu, encoder);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(label),
            timestamp_writes: None,
        });
        for d in &self.dispatches {
            d.record(&mut pass);
        }
    }
}

/// One recorded dispatch of a pass: its stage, pipeline, bind group (group
/// 0) with its dynamic offset (none when `offsets` is empty), and workgroup counts.
pub(crate) struct Dispatch {
    /// The stage it belongs to (what times it).
    pub(crate) stage: Stage,
    pipeline: wgpu::ComputePipeline,
    group: wgpu::BindGroup,
    offsets: Vec<u32>,
    groups: [u32; 3],
}

impl Dispatch {
    /// Records the dispatch into `pass`.
    pub(crate) fn record(&self, pass: &mut wgpu::ComputePass) {
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.group, &self.offsets);
        pass.dispatch_workgroups(self.groups[0], self.groups[1], self.groups[2]);
    }

    /// A dispatch of `pipeline` with `group` at uniform offset `offset`
    /// over `groups` workgroups.
    pub(crate) fn new(
        stage: Stage,
        pipeline: &wgpu::ComputePipeline,
        group: wgpu::BindGroup,
        offset: Option<u32>,
        groups: [u32; 3],
    ) -> Self {
        Dispatch::with_offsets(stage, pipeline, group, offset.into_iter().collect(), groups)
    }

    /// [`Dispatch::new`] with a dynamic offset per dynamic uniform of the
    /// group, in binding order.
    pub(crate) fn with_offsets(
        stage: Stage,
        pipeline: &wgpu::ComputePipeline,
        group: wgpu::BindGroup,
        offsets: Vec<u32>,
        groups: [u32; 3],
    ) -> Self {
        Dispatch { stage, pipeline: pipeline.clone(), group, offsets, groups }
    }
}
