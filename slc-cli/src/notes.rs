//! The sentences the commands print beside their numbers: what a count
//! counts, how a time was measured.

/// What the path tracer's light count counts, said where it is printed.
pub const PT_LIGHTS_NOTE: &str = "emissive triangles and the scene file's [[light]] entries; the primary light ([primary]) makes the VPL application's RSM and is not a path-tracing light";

/// How a GPU frame's stages were timed, in words.
pub fn timing_note(t: slc_scene::backend::Timing) -> &'static str {
    match t {
        slc_scene::backend::Timing::GpuTimestamps => {
            "GPU timestamps around each stage's pass, one command encoder per frame"
        }
        slc_scene::backend::Timing::Wall => {
            "wall clock per stage (each stage submitted alone: the adapter has no timestamp queries, or is a software one whose timestamps do not bracket the work)"
        }
    }
}
