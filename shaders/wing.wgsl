// The flexing wing. WebGL2-compatible: no storage buffers, everything per-vertex comes from
// vertex attributes and per-frame values from one uniform block (vec4/mat4 members only).
//
// Per vertex (stride 140 bytes): undeformed position (x, y, camber z) in metres, then for up
// to 8 modes the shape φ_k and the strains ε_x,k, ε_y,k, γ_xy,k, each packed 4 modes per vec4;
// from a second buffer (stride 4 bytes) one scalar per node, the page's node field.
//
// Compiled after shaders/prelude.wgsl (the uniform block `u`, `diverging`, `srgb_to_linear`).

struct VertexIn {
    @location(0) pos: vec3<f32>,
    @location(1) phi0: vec4<f32>,
    @location(2) phi1: vec4<f32>,
    @location(3) ex0: vec4<f32>,
    @location(4) ex1: vec4<f32>,
    @location(5) ey0: vec4<f32>,
    @location(6) ey1: vec4<f32>,
    @location(7) gxy0: vec4<f32>,
    @location(8) gxy1: vec4<f32>,
    // The page's node field (second vertex buffer; colour mode 5), e.g. a run's RMS strain.
    @location(9) field: f32,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    // Colour-map coordinate in [0, 1] (0.5 = zero strain).
    @location(1) t: f32,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    let w = dot(v.phi0, u.q0) + dot(v.phi1, u.q1);
    let local = vec3<f32>(v.pos.xy, v.pos.z + u.params.x * w);
    let world = (u.wing_rot * vec4<f32>(local, 1.0)).xyz;

    let ex = dot(v.ex0, u.q0) + dot(v.ex1, u.q1);
    let ey = dot(v.ey0, u.q0) + dot(v.ey1, u.q1);
    let gxy = dot(v.gxy0, u.q0) + dot(v.gxy1, u.q1);
    let mode = u.params.y;
    var s = 0.0;
    if (mode > 0.5 && mode < 1.5) {
        s = ex;
    } else if (mode > 1.5 && mode < 2.5) {
        s = ey;
    } else if (mode > 2.5 && mode < 3.5) {
        s = gxy;
    } else if (mode > 3.5 && mode < 4.5) {
        s = sqrt(ex * ex + ey * ey + 0.5 * gxy * gxy);
    } else if (mode > 4.5) {
        s = v.field;
    }

    var out: VertexOut;
    out.clip = u.view_proj * vec4<f32>(world, 1.0);
    out.world = world;
    out.t = 0.5 + 0.5 * clamp(s * u.params.z, -1.0, 1.0);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    // Flat (per-facet) normal of the deformed surface from screen-space derivatives,
    // turned toward the viewer: two-sided lighting.
    var n = normalize(cross(dpdx(in.world), dpdy(in.world)));
    let view = normalize(u.eye.xyz - in.world);
    if (dot(n, view) < 0.0) {
        n = -n;
    }
    let l = u.light.xyz;
    var base = vec3<f32>(0.86, 0.70, 0.42);
    if (u.params.y > 0.5) {
        base = diverging(in.t);
    }
    let albedo = srgb_to_linear(base);
    let diffuse = max(dot(n, l), 0.0);
    let h = normalize(l + view);
    let spec = pow(max(dot(n, h), 0.0), 40.0);
    var c = albedo * (0.22 + 0.78 * diffuse) + vec3<f32>(0.18 * spec);
    if (u.params.w < 0.5) {
        c = pow(c, vec3<f32>(1.0 / 2.2));
    }
    return vec4<f32>(c, 1.0);
}
