//! The wgpu renderer: pipelines, buffers and the per-frame uniform block.
//!
//! GPU data layout (see `shaders/wing.wgsl`):
//! * wing vertex buffer, uploaded once, stride 140 bytes: `pos: vec3` (x, y, camber z) then
//!   `phi0, phi1, ex0, ex1, ey0, ey1, gxy0, gxy1: vec4` — each packs modes 0–3 and 4–7;
//! * `u32` index buffer of the triangles;
//! * a line vertex buffer (fixed frame, I″–J″–K″ triad, body axis, stroke-plane outline) and a
//!   stroke-plane quad, stride 32 bytes (`pos: vec3, colour: vec4, space: f32`);
//! * one 272-byte uniform block per frame ([`Uniforms`]).

use super::mesh::WingMesh;
use super::scene::{
    self, legend_for, CleanFrame, ColourMode, FrameParams, Legend, Mat4, OrbitCamera,
};
use super::{RenderError, MAX_MODES};
use bytemuck::{Pod, Zeroable};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use wgpu::util::DeviceExt;

/// Depth buffer format (WebGL2-compatible).
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;

/// Background colour (linear).
pub const BACKGROUND: wgpu::Color = wgpu::Color {
    r: 0.012,
    g: 0.014,
    b: 0.02,
    a: 1.0,
};

/// [`BACKGROUND`] as the clear value for a target of `format`: unchanged on sRGB targets (the
/// hardware encodes), sRGB-encoded by hand on plain-UNORM ones (WebGPU's `bgra8unorm` canvas),
/// where the shaders also encode, so both backends show the same background.
pub fn background_for(format: wgpu::TextureFormat) -> wgpu::Color {
    if format.is_srgb() {
        return BACKGROUND;
    }
    let enc = |c: f64| {
        if c <= 0.003_130_8 {
            12.92 * c
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        }
    };
    wgpu::Color {
        r: enc(BACKGROUND.r),
        g: enc(BACKGROUND.g),
        b: enc(BACKGROUND.b),
        a: BACKGROUND.a,
    }
}

/// An adapter, its device and queue: what both front ends of the renderer (offscreen and the
/// browser's canvas) need before they can build a [`Renderer`].
pub struct GpuContext {
    /// The adapter the device was created on.
    pub adapter: wgpu::Adapter,
    /// The device, with [`device_limits`] for the adapter.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
}

/// The limits the renderer asks for: WebGL2's downlevel defaults, raised only in texture size
/// to what the adapter offers, so that native tests exercise the browser's WebGL2 limits.
pub fn device_limits(adapter: &wgpu::Adapter) -> wgpu::Limits {
    wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits())
}

/// Requests an adapter from `instance` (compatible with `surface` when given) and a device
/// with [`device_limits`]. `label` names the device; `no_adapter_hint` is appended to the
/// error when no adapter is found (what the user can install or enable). The one place the
/// GPU device is set up, for offscreen rendering and the browser view alike.
pub async fn open_device(
    instance: &wgpu::Instance,
    surface: Option<&wgpu::Surface<'_>>,
    power_preference: wgpu::PowerPreference,
    label: &str,
    no_adapter_hint: &str,
) -> Result<GpuContext, RenderError> {
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference,
            force_fallback_adapter: false,
            compatible_surface: surface,
            apply_limit_buckets: false,
        })
        .await
        .map_err(|e| RenderError::NoAdapter(format!("{e}{no_adapter_hint}")))?;
    let (device, queue) = adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some(label),
            required_features: wgpu::Features::empty(),
            required_limits: device_limits(&adapter),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::MemoryUsage,
            trace: wgpu::Trace::Off,
        })
        .await
        .map_err(|e| RenderError::Device(e.to_string()))?;
    Ok(GpuContext {
        adapter,
        device,
        queue,
    })
}

/// The per-frame uniform block, `std140`-compatible (only `mat4` and `vec4` members).
#[repr(C)]
#[derive(Debug, Clone, Copy, Pod, Zeroable)]
pub struct Uniforms {
    /// Projection × view.
    pub view_proj: Mat4,
    /// R_x(α)·R_y(β).
    pub frame_rot: Mat4,
    /// R_x(α)·R_y(β)·R_z(γ).
    pub wing_rot: Mat4,
    /// q_0..q_3 (true scale).
    pub q0: [f32; 4],
    /// q_4..q_7.
    pub q1: [f32; 4],
    /// Eye position.
    pub eye: [f32; 4],
    /// Unit direction toward the light.
    pub light: [f32; 4],
    /// Exaggeration, colour mode, 1/legend limit, 1 if the target is sRGB.
    pub params: [f32; 4],
}

/// Floats per wing vertex: position (3) + 4 quantities × [`MAX_MODES`].
pub const WING_VERTEX_FLOATS: usize = 3 + 4 * MAX_MODES;

#[repr(C)]
#[derive(Debug, Clone, Copy, Pod, Zeroable)]
struct LineVertex {
    pos: [f32; 3],
    colour: [f32; 4],
    space: f32,
}

/// What [`Renderer::update`] reports about the frame it prepared.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameReport {
    /// Legend for the strain colouring (`None` when the colouring is plain).
    pub legend: Option<Legend>,
    /// The largest true out-of-plane deflection |Σ φ_k q_k| on the wing, metres.
    pub max_deflection_m: f32,
    /// The exaggeration the deflection is drawn with.
    pub exaggeration: f32,
    /// Values that had to be sanitised, and similar notices.
    pub warnings: Vec<String>,
}

/// The flexing-wing renderer, in the style of the wgpu examples.
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    format: wgpu::TextureFormat,
    wing_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    plane_pipeline: wgpu::RenderPipeline,
    uniform_buf: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    wing_vb: wgpu::Buffer,
    wing_ib: wgpu::Buffer,
    n_indices: u32,
    line_vb: wgpu::Buffer,
    n_line_vertices: u32,
    plane_vb: wgpu::Buffer,
    n_plane_vertices: u32,
    depth: Option<(wgpu::Texture, wgpu::TextureView)>,
    size: (u32, u32),
    mesh: WingMesh,
    frame: CleanFrame,
    lost: Arc<AtomicBool>,
    error: Arc<Mutex<Option<String>>>,
    warnings: Vec<String>,
    /// The orbit camera; the page drives it with drag / zoom / keys.
    pub camera: OrbitCamera,
}

fn pack_vertices(mesh: &WingMesh) -> Vec<f32> {
    let n_modes = mesh.n_modes().min(MAX_MODES);
    let mut v = vec![0.0f32; mesh.nodes.len() * WING_VERTEX_FLOATS];
    for (i, p) in mesh.nodes.iter().enumerate() {
        let o = i * WING_VERTEX_FLOATS;
        v[o..o + 3].copy_from_slice(p);
        for k in 0..n_modes {
            v[o + 3 + k] = mesh.shapes[k][i];
            let e = mesh.strains[k][i];
            v[o + 3 + MAX_MODES + k] = e[0];
            v[o + 3 + 2 * MAX_MODES + k] = e[1];
            v[o + 3 + 3 * MAX_MODES + k] = e[2];
        }
    }
    v
}

/// Scene decorations scaled to the span `l`: (line list, stroke-plane triangles).
fn scene_geometry(l: f32) -> (Vec<LineVertex>, Vec<LineVertex>) {
    let mut lines = Vec::new();
    let mut seg = |a: [f32; 3], b: [f32; 3], colour: [f32; 4], space: f32| {
        lines.push(LineVertex {
            pos: a,
            colour,
            space,
        });
        lines.push(LineVertex {
            pos: b,
            colour,
            space,
        });
    };
    let o = [0.0; 3];
    // Fixed frame I, J, K: dim.
    let d = 0.35 * l;
    seg(o, [d, 0.0, 0.0], [0.55, 0.25, 0.25, 1.0], 0.0);
    seg(o, [0.0, d, 0.0], [0.25, 0.5, 0.25, 1.0], 0.0);
    seg(o, [0.0, 0.0, d], [0.25, 0.3, 0.6, 1.0], 0.0);
    // Rotating frame I″, J″, K″: bright.
    let r = 0.7 * l;
    seg(o, [r, 0.0, 0.0], [1.0, 0.25, 0.2, 1.0], 1.0);
    seg(o, [0.0, 0.45 * l, 0.0], [0.3, 1.0, 0.3, 1.0], 1.0);
    seg(o, [0.0, 0.0, 0.45 * l], [0.35, 0.55, 1.0, 1.0], 1.0);
    // Body axis along J through the wing root.
    seg(
        [0.0, 0.6 * l, 0.0],
        [0.0, -1.3 * l, 0.0],
        [0.85, 0.85, 0.85, 1.0],
        0.0,
    );
    // Stroke plane: the I–K plane through the root, perpendicular to the body axis.
    let (x0, x1, z) = (-0.1 * l, 1.1 * l, 0.9 * l);
    let corners = [[x0, 0.0, -z], [x1, 0.0, -z], [x1, 0.0, z], [x0, 0.0, z]];
    let edge = [0.4, 0.48, 0.7, 1.0];
    for i in 0..4 {
        seg(corners[i], corners[(i + 1) % 4], edge, 0.0);
    }
    let fill = [0.45, 0.55, 0.85, 0.08];
    let plane = [0, 1, 2, 0, 2, 3]
        .iter()
        .map(|&i| LineVertex {
            pos: corners[i],
            colour: fill,
            space: 0.0,
        })
        .collect();
    (lines, plane)
}

fn attr(location: u32, offset: usize, format: wgpu::VertexFormat) -> wgpu::VertexAttribute {
    wgpu::VertexAttribute {
        format,
        offset: offset as u64,
        shader_location: location,
    }
}

impl Renderer {
    /// Builds pipelines and uploads the mesh once. `format` is the colour target's format;
    /// for a non-sRGB target the shaders gamma-encode themselves.
    ///
    /// Errors: an invalid mesh ([`RenderError::Input`], naming the field) or a GPU validation
    /// error. Modes beyond [`MAX_MODES`] are dropped with a warning ([`Renderer::warnings`]).
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        format: wgpu::TextureFormat,
        mesh: &WingMesh,
    ) -> Result<Self, RenderError> {
        mesh.validate()?;
        let mut warnings = Vec::new();
        let mut mesh = mesh.clone();
        if mesh.n_modes() > MAX_MODES {
            warnings.push(format!(
                "the mesh has {} modes; the renderer draws the first {MAX_MODES}",
                mesh.n_modes()
            ));
            mesh.shapes.truncate(MAX_MODES);
            mesh.strains.truncate(MAX_MODES);
        }

        let lost = Arc::new(AtomicBool::new(false));
        let error: Arc<Mutex<Option<String>>> = Arc::new(Mutex::new(None));
        {
            let lost = lost.clone();
            let error = error.clone();
            device.set_device_lost_callback(move |reason, msg| {
                lost.store(true, Ordering::SeqCst);
                if let Ok(mut e) = error.lock() {
                    *e = Some(format!("{reason:?}: {msg}"));
                }
            });
        }
        {
            let error = error.clone();
            device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
                if let Ok(mut slot) = error.lock() {
                    if slot.is_none() {
                        *slot = Some(e.to_string());
                    }
                }
            }));
        }

        let wing_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("wing.wgsl"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/wing.wgsl").into()),
        });
        let line_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("lines.wgsl"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/lines.wgsl").into()),
        });

        let uniform_buf = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("wing uniforms"),
            size: std::mem::size_of::<Uniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("wing uniforms"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<Uniforms>() as u64),
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("wing uniforms"),
            layout: &bgl,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform_buf.as_entire_binding(),
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("wing"),
            bind_group_layouts: &[Some(&bgl)],
            immediate_size: 0,
        });

        let f4 = wgpu::VertexFormat::Float32x4;
        let mut wing_attrs = vec![attr(0, 0, wgpu::VertexFormat::Float32x3)];
        for a in 0..(4 * MAX_MODES / 4) {
            wing_attrs.push(attr(1 + a as u32, 4 * (3 + 4 * a), f4));
        }
        let wing_layout = wgpu::VertexBufferLayout {
            array_stride: (WING_VERTEX_FLOATS * 4) as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wing_attrs,
        };
        let line_attrs = [
            attr(0, 0, wgpu::VertexFormat::Float32x3),
            attr(1, 12, f4),
            attr(2, 28, wgpu::VertexFormat::Float32),
        ];
        let line_layout = wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<LineVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &line_attrs,
        };

        let depth = |write: bool| {
            Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(write),
                depth_compare: Some(wgpu::CompareFunction::LessEqual),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            })
        };
        let pipeline = |label: &str,
                        shader: &wgpu::ShaderModule,
                        vb: wgpu::VertexBufferLayout<'_>,
                        topology: wgpu::PrimitiveTopology,
                        blend: Option<wgpu::BlendState>,
                        depth_write: bool| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: shader,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(vb)],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: depth(depth_write),
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: shader,
                    entry_point: Some("fs_main"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let wing_pipeline = pipeline(
            "wing",
            &wing_shader,
            wing_layout,
            wgpu::PrimitiveTopology::TriangleList,
            None,
            true,
        );
        let line_pipeline = pipeline(
            "lines",
            &line_shader,
            line_layout.clone(),
            wgpu::PrimitiveTopology::LineList,
            None,
            true,
        );
        let plane_pipeline = pipeline(
            "stroke plane",
            &line_shader,
            line_layout,
            wgpu::PrimitiveTopology::TriangleList,
            Some(wgpu::BlendState::ALPHA_BLENDING),
            false,
        );

        let wing_vb = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("wing vertices"),
            contents: bytemuck::cast_slice(&pack_vertices(&mesh)),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
        let wing_ib = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("wing indices"),
            contents: bytemuck::cast_slice(&indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        let span = mesh.span().max(1e-6);
        let (lines, plane) = scene_geometry(span);
        let line_vb = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("scene lines"),
            contents: bytemuck::cast_slice(&lines),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let plane_vb = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("stroke plane"),
            contents: bytemuck::cast_slice(&plane),
            usage: wgpu::BufferUsages::VERTEX,
        });

        let (frame, _) = FrameParams::default().sanitise();
        let renderer = Renderer {
            device: device.clone(),
            queue: queue.clone(),
            format,
            wing_pipeline,
            line_pipeline,
            plane_pipeline,
            uniform_buf,
            bind_group,
            wing_vb,
            wing_ib,
            n_indices: indices.len() as u32,
            line_vb,
            n_line_vertices: lines.len() as u32,
            plane_vb,
            n_plane_vertices: plane.len() as u32,
            depth: None,
            size: (0, 0),
            camera: OrbitCamera::for_span(span),
            mesh,
            frame,
            lost,
            error,
            warnings,
        };
        renderer.check()?;
        Ok(renderer)
    }

    /// Notices from construction (e.g. modes dropped beyond [`MAX_MODES`]).
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The mesh as drawn (modes beyond the cap removed).
    pub fn mesh(&self) -> &WingMesh {
        &self.mesh
    }

    /// The colour target format given to [`Renderer::new`].
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// The current render-target size (0×0 before the first successful [`Renderer::resize`]).
    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// Returns the first GPU error reported since the last check, or device loss.
    fn check(&self) -> Result<(), RenderError> {
        let msg = self.error.lock().ok().and_then(|mut e| e.take());
        if self.lost.load(Ordering::SeqCst) {
            return Err(RenderError::DeviceLost(
                msg.unwrap_or_else(|| "unknown reason".into()),
            ));
        }
        match msg {
            Some(m) => Err(RenderError::Gpu(m)),
            None => Ok(()),
        }
    }

    /// Sets the render-target size, recreating the depth buffer. A zero width or height (a
    /// collapsed canvas) is refused with [`RenderError::ZeroSize`] and the previous size is kept;
    /// so is a size over the device limit.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), RenderError> {
        if width == 0 || height == 0 {
            return Err(RenderError::ZeroSize { width, height });
        }
        let max = self.device.limits().max_texture_dimension_2d;
        if width > max || height > max {
            return Err(RenderError::TooLarge { width, height, max });
        }
        if self.size == (width, height) && self.depth.is_some() {
            return Ok(());
        }
        let tex = self.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("depth"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        });
        let view = tex.create_view(&Default::default());
        self.depth = Some((tex, view));
        self.size = (width, height);
        Ok(())
    }

    /// Prepares a frame: sanitises `params` (non-finite → 0, reported in the warnings), computes
    /// the legend on the CPU and uploads the uniform block. Cheap: no mesh data moves.
    pub fn update(&mut self, params: &FrameParams) -> FrameReport {
        let (f, warnings) = params.sanitise();
        self.frame = f;
        let q = &f.q[..self.mesh.n_modes()];
        let field = if f.colour == ColourMode::Plain {
            Vec::new()
        } else {
            self.mesh.strain_field(q)
        };
        let legend = legend_for(f.colour, &field, f.strain_range);
        let inv_range = legend.as_ref().map_or(0.0, |l| 1.0 / l.max);
        let (w, h) = self.size;
        let aspect = if h > 0 { w as f32 / h as f32 } else { 1.0 };
        let eye = self.camera.eye();
        let to_eye = scene_normalize(sub3(eye, self.camera.target));
        // A key light from the viewer's upper right, oblique enough that the camber's
        // chordwise curvature shows as a shading gradient.
        let right = scene_normalize(cross3([0.0, 0.0, 1.0], to_eye));
        let up = cross3(to_eye, right);
        let light = scene_normalize([
            0.5 * to_eye[0] + 0.8 * right[0] + 0.6 * up[0],
            0.5 * to_eye[1] + 0.8 * right[1] + 0.6 * up[1],
            0.5 * to_eye[2] + 0.8 * right[2] + 0.6 * up[2],
        ]);
        let u = Uniforms {
            view_proj: self.camera.view_proj(aspect),
            frame_rot: scene::frame_rotation(f.alpha, f.beta),
            wing_rot: scene::wing_rotation(f.alpha, f.beta, f.gamma),
            q0: [f.q[0], f.q[1], f.q[2], f.q[3]],
            q1: [f.q[4], f.q[5], f.q[6], f.q[7]],
            eye: [eye[0], eye[1], eye[2], 1.0],
            light: [light[0], light[1], light[2], 0.0],
            params: [
                f.exaggeration,
                f.colour.index() as f32,
                inv_range,
                if self.format.is_srgb() { 1.0 } else { 0.0 },
            ],
        };
        self.queue
            .write_buffer(&self.uniform_buf, 0, bytemuck::bytes_of(&u));
        FrameReport {
            legend,
            max_deflection_m: self.mesh.max_deflection(q),
            exaggeration: f.exaggeration,
            warnings,
        }
    }

    /// Records and submits the frame into `target` (which must have the size given to
    /// [`Renderer::resize`] and the format given to [`Renderer::new`]).
    pub fn render(&mut self, target: &wgpu::TextureView) -> Result<(), RenderError> {
        self.check()?;
        let Some((_, depth)) = &self.depth else {
            return Err(RenderError::ZeroSize {
                width: self.size.0,
                height: self.size.1,
            });
        };
        let mut enc = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("wing frame"),
            });
        {
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("wing"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(background_for(self.format)),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_bind_group(0, &self.bind_group, &[]);
            pass.set_pipeline(&self.wing_pipeline);
            pass.set_vertex_buffer(0, self.wing_vb.slice(..));
            pass.set_index_buffer(self.wing_ib.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..self.n_indices, 0, 0..1);
            if self.frame.show_axes {
                pass.set_pipeline(&self.line_pipeline);
                pass.set_vertex_buffer(0, self.line_vb.slice(..));
                pass.draw(0..self.n_line_vertices, 0..1);
            }
            if self.frame.show_stroke_plane {
                pass.set_pipeline(&self.plane_pipeline);
                pass.set_vertex_buffer(0, self.plane_vb.slice(..));
                pass.draw(0..self.n_plane_vertices, 0..1);
            }
        }
        self.queue.submit(Some(enc.finish()));
        self.check()
    }
}

fn sub3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn scene_normalize(a: [f32; 3]) -> [f32; 3] {
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if n > 0.0 && n.is_finite() {
        [a[0] / n, a[1] / n, a[2] / n]
    } else {
        [0.0, 0.0, 1.0]
    }
}
