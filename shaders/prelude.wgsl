// Shared by every shader of the renderer: `src/render/gpu.rs` compiles each one as
//   generated colour-map constants + this prelude + the shader's own file.
// The colour-map constants `DIVERGING_0` .. `DIVERGING_4` (sRGB stops at t = 0, ¼, ½, ¾, 1) are
// written by `gpu::colour_map_wgsl` from `scene::DIVERGING_STOPS`, the one definition of the
// map. `tests/render_layout.rs` checks that `Uniforms` below has the size and field offsets of
// the Rust `gpu::Uniforms` (std140: only mat4 and vec4 members) and that the constants equal
// the Rust stops.

struct Uniforms {
    view_proj: mat4x4<f32>,
    // R_x(α)·R_y(β): the rotating frame I″–J″–K″.
    frame_rot: mat4x4<f32>,
    // R_x(α)·R_y(β)·R_z(γ): the wing.
    wing_rot: mat4x4<f32>,
    // True modal coordinates q_0..q_3 and q_4..q_7.
    q0: vec4<f32>,
    q1: vec4<f32>,
    // Eye position (xyz).
    eye: vec4<f32>,
    // Direction toward the light (xyz), unit.
    light: vec4<f32>,
    // x: exaggeration, y: colour mode (0 plain, 1 ε_x, 2 ε_y, 3 γ_xy, 4 magnitude, 5 field),
    // z: 1 / legend limit, w: 1 when the target is sRGB (else the shader gamma-encodes).
    params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> u: Uniforms;

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return pow(c, vec3<f32>(2.2));
}

// Moreland's cool-warm diverging map: piecewise linear between the five stops.
fn diverging(t: f32) -> vec3<f32> {
    let x = clamp(t, 0.0, 1.0) * 4.0;
    if (x < 1.0) {
        return mix(DIVERGING_0, DIVERGING_1, x);
    } else if (x < 2.0) {
        return mix(DIVERGING_1, DIVERGING_2, x - 1.0);
    } else if (x < 3.0) {
        return mix(DIVERGING_2, DIVERGING_3, x - 2.0);
    }
    return mix(DIVERGING_3, DIVERGING_4, x - 3.0);
}
