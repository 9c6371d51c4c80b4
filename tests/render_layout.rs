//! The WGSL and the Rust side of the renderer agree: the prelude's `Uniforms` struct has the
//! size and field offsets of `gpu::Uniforms`, every shader (prelude + own file) parses and
//! validates with naga, and the colour-map constants the shaders see are the Rust stops.
//! No GPU needed.
#![cfg(all(feature = "render", not(target_arch = "wasm32")))]

use std::mem::{offset_of, size_of};
use wgpu::naga;
use wingbeat::render::gpu::{shader_source, Shader, Uniforms};
use wingbeat::render::scene::DIVERGING_STOPS;

fn module(shader: Shader) -> naga::Module {
    let src = shader_source(shader);
    naga::front::wgsl::parse_str(&src)
        .unwrap_or_else(|e| panic!("{shader:?}: {}", e.emit_to_string(&src)))
}

#[test]
fn every_shader_parses_and_validates() {
    for shader in Shader::ALL {
        let m = module(shader);
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(&m)
        .unwrap_or_else(|e| panic!("{shader:?}: {e:?}"));
    }
}

#[test]
fn wgsl_uniform_block_matches_the_rust_struct() {
    let rust: [(&str, usize); 8] = [
        ("view_proj", offset_of!(Uniforms, view_proj)),
        ("frame_rot", offset_of!(Uniforms, frame_rot)),
        ("wing_rot", offset_of!(Uniforms, wing_rot)),
        ("q0", offset_of!(Uniforms, q0)),
        ("q1", offset_of!(Uniforms, q1)),
        ("eye", offset_of!(Uniforms, eye)),
        ("light", offset_of!(Uniforms, light)),
        ("params", offset_of!(Uniforms, params)),
    ];
    for shader in Shader::ALL {
        let m = module(shader);
        let ty = m
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some("Uniforms"))
            .map(|(_, t)| t)
            .unwrap_or_else(|| panic!("{shader:?}: no `Uniforms` struct"));
        let naga::TypeInner::Struct { members, span } = &ty.inner else {
            panic!("{shader:?}: `Uniforms` is not a struct");
        };
        assert_eq!(*span as usize, size_of::<Uniforms>(), "{shader:?}: size");
        assert_eq!(size_of::<Uniforms>(), 272, "the documented 272-byte block");
        let wgsl: Vec<(&str, usize)> = members
            .iter()
            .map(|m| (m.name.as_deref().unwrap_or("?"), m.offset as usize))
            .collect();
        assert_eq!(wgsl, rust, "{shader:?}: field names and offsets");
    }
}

#[test]
fn shaders_see_the_rust_colour_map() {
    let m = module(Shader::Wing);
    for (i, (t, rgb)) in DIVERGING_STOPS.iter().enumerate() {
        // The prelude's `diverging` assumes evenly spaced stops.
        assert_eq!(*t, i as f32 / 4.0, "stop {i} position");
        let name = format!("DIVERGING_{i}");
        let (_, c) = m
            .constants
            .iter()
            .find(|(_, c)| c.name.as_deref() == Some(name.as_str()))
            .unwrap_or_else(|| panic!("no constant {name}"));
        let naga::Expression::Compose { components, .. } = &m.global_expressions[c.init] else {
            panic!("{name} is not a vector constructor");
        };
        let got: Vec<f32> = components
            .iter()
            .map(|h| match m.global_expressions[*h] {
                naga::Expression::Literal(naga::Literal::F32(v)) => v,
                ref other => panic!("{name}: component {other:?}"),
            })
            .collect();
        assert_eq!(got, rgb.to_vec(), "{name}");
    }
}
