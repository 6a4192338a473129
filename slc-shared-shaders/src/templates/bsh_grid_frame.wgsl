/// The pass's grid frame from the first words of `grid` (read through the
/// including kernel's `grid_word`; `bsh_grid` stage 1 writes them): no
/// cells along x where the pass has no grid.
fn grid_frame() -> GridFrame {
    var f: GridFrame;
    f.lo = vec3f(bitcast<f32>(grid_word(0u)), bitcast<f32>(grid_word(1u)), bitcast<f32>(grid_word(2u)));
    f.nx = grid_word(3u);
    f.hi = vec3f(bitcast<f32>(grid_word(4u)), bitcast<f32>(grid_word(5u)), bitcast<f32>(grid_word(6u)));
    f.ny = grid_word(7u);
    f.inv = vec3f(bitcast<f32>(grid_word(8u)), bitcast<f32>(grid_word(9u)), bitcast<f32>(grid_word(10u)));
    f.nz = grid_word(11u);
    return f;
}

/// The largest range lobe `rl.w` the pass's grid serves.
fn grid_reach() -> f32 {
    return bitcast<f32>(grid_word(12u));
}
