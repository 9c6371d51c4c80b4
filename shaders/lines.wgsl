// Scene decorations: the fixed frame, the I″–J″–K″ triad, the body axis (line list) and the
// translucent stroke plane (triangle list, alpha-blended). Compiled after shaders/prelude.wgsl
// (the uniform block `u`, shared with wing.wgsl).

struct VertexIn {
    @location(0) pos: vec3<f32>,
    // sRGB colour and alpha.
    @location(1) colour: vec4<f32>,
    // 0: fixed frame, 1: rotating frame I″–J″–K″, 2: wing frame (with yaw).
    @location(2) space: f32,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) colour: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var world = v.pos;
    if (v.space > 1.5) {
        world = (u.wing_rot * vec4<f32>(v.pos, 1.0)).xyz;
    } else if (v.space > 0.5) {
        world = (u.frame_rot * vec4<f32>(v.pos, 1.0)).xyz;
    }
    var out: VertexOut;
    out.clip = u.view_proj * vec4<f32>(world, 1.0);
    out.colour = v.colour;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    var c = pow(in.colour.rgb, vec3<f32>(2.2));
    var a = in.colour.a;
    if (u.params.w < 0.5) {
        c = pow(c, vec3<f32>(1.0 / 2.2));
        // A non-sRGB target blends in encoded values: over the dark background, alpha^(1/2.2)
        // gives about what blending the linear colour with `alpha` gives on an sRGB target,
        // so the translucent stroke plane looks the same on both kinds of canvas.
        a = pow(a, 1.0 / 2.2);
    }
    return vec4<f32>(c, a);
}
