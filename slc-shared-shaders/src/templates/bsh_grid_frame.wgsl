/// The frame of the grid whose words start at `h` in `grid` (read through
/// the including kernel's `grid_word`; `bsh_grid` stage 1 writes them): no
/// cells along x where the pass has no such grid.
fn grid_frame(h: u32) -> GridFrame {
    var f: GridFrame;
    f.lo = vec3f(bitcast<f32>(grid_word(h)), bitcast<f32>(grid_word(h + 1u)), bitcast<f32>(grid_word(h + 2u)));
    f.nx = grid_word(h + 3u);
    f.hi = vec3f(bitcast<f32>(grid_word(h + 4u)), bitcast<f32>(grid_word(h + 5u)), bitcast<f32>(grid_word(h + 6u)));
    f.ny = grid_word(h + 7u);
    f.inv = vec3f(bitcast<f32>(grid_word(h + 8u)), bitcast<f32>(grid_word(h + 9u)), bitcast<f32>(grid_word(h + 10u)));
    f.nz = grid_word(h + 11u);
    return f;
}

/// The largest range lobe `rl.w` the grid whose words start at `h` serves.
fn grid_reach(h: u32) -> f32 {
    return bitcast<f32>(grid_word(h + 12u));
}
