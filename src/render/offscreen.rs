//! Native headless rendering (pollster): RGBA images for golden tests, the CLI and benchmarks.
//!
//! The device is created with `Limits::downlevel_webgl2_defaults()` (raised only in texture
//! size to what the adapter offers), so native tests exercise the same limits as the browser's
//! WebGL2 path.

use super::gpu::{open_device, FrameReport, Renderer};
use super::mesh::WingMesh;
use super::scene::{ColourMode, FrameParams, OrbitCamera};
use super::RenderError;
use crate::config::SimConfig;
use std::time::Duration;

/// The colour format of offscreen images.
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// A tightly packed RGBA8 (sRGB) image, rows top to bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct RgbaImage {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
    /// `width · height · 4` bytes.
    pub pixels: Vec<u8>,
}

impl RgbaImage {
    /// The RGBA value at (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let o = ((y * self.width + x) * 4) as usize;
        [
            self.pixels[o],
            self.pixels[o + 1],
            self.pixels[o + 2],
            self.pixels[o + 3],
        ]
    }

    /// Encodes as PNG.
    pub fn to_png(&self) -> Result<Vec<u8>, RenderError> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            let mut w = enc
                .write_header()
                .map_err(|e| RenderError::Io(e.to_string()))?;
            w.write_image_data(&self.pixels)
                .map_err(|e| RenderError::Io(e.to_string()))?;
        }
        Ok(out)
    }

    /// Writes a PNG file.
    pub fn write_png(&self, path: &std::path::Path) -> Result<(), RenderError> {
        let bytes = self.to_png()?;
        std::fs::write(path, bytes).map_err(|e| RenderError::Io(format!("{}: {e}", path.display())))
    }

    /// Decodes an 8-bit RGBA or RGB PNG.
    pub fn from_png(bytes: &[u8]) -> Result<RgbaImage, RenderError> {
        let dec = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = dec
            .read_info()
            .map_err(|e| RenderError::Io(e.to_string()))?;
        let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
        let info = reader
            .next_frame(&mut buf)
            .map_err(|e| RenderError::Io(e.to_string()))?;
        let pixels = match (info.color_type, info.bit_depth) {
            (png::ColorType::Rgba, png::BitDepth::Eight) => buf[..info.buffer_size()].to_vec(),
            (png::ColorType::Rgb, png::BitDepth::Eight) => buf[..info.buffer_size()]
                .chunks(3)
                .flat_map(|c| [c[0], c[1], c[2], 255])
                .collect(),
            other => return Err(RenderError::Io(format!("unsupported PNG format {other:?}"))),
        };
        Ok(RgbaImage {
            width: info.width,
            height: info.height,
            pixels,
        })
    }
}

/// A GPU device, a [`Renderer`] and a read-back texture of a fixed size.
pub struct Offscreen {
    device: wgpu::Device,
    queue: wgpu::Queue,
    adapter_info: wgpu::AdapterInfo,
    renderer: Renderer,
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    readback: wgpu::Buffer,
    width: u32,
    height: u32,
    padded_row: u32,
}

/// Creates an instance (backends from `WGPU_BACKEND`, default all), an adapter and a device
/// with WebGL2-level limits ([`super::gpu::open_device`]).
pub async fn request_device() -> Result<(wgpu::Adapter, wgpu::Device, wgpu::Queue), RenderError> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let ctx = open_device(
        &instance,
        None,
        wgpu::PowerPreference::from_env().unwrap_or_default(),
        "wingbeat render",
        " (install a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers libvulkan1` for lavapipe)",
    )
    .await?;
    Ok((ctx.adapter, ctx.device, ctx.queue))
}

impl Offscreen {
    /// A headless renderer of `width × height` pixels for `mesh`.
    pub fn new(width: u32, height: u32, mesh: &WingMesh) -> Result<Self, RenderError> {
        if width == 0 || height == 0 {
            return Err(RenderError::ZeroSize { width, height });
        }
        let (adapter, device, queue) = pollster::block_on(request_device())?;
        let mut renderer = Renderer::new(&device, &queue, OFFSCREEN_FORMAT, mesh)?;
        renderer.resize(width, height)?;
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("offscreen colour"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: OFFSCREEN_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let padded_row = (width * 4).div_ceil(align) * align;
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("offscreen read-back"),
            size: padded_row as u64 * height as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Ok(Offscreen {
            adapter_info: adapter.get_info(),
            device,
            queue,
            renderer,
            texture,
            view,
            readback,
            width,
            height,
            padded_row,
        })
    }

    /// Adapter name and backend, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan)`.
    pub fn adapter_name(&self) -> String {
        format!(
            "{} ({:?})",
            self.adapter_info.name, self.adapter_info.backend
        )
    }

    /// The renderer (camera, warnings, ...).
    pub fn renderer(&mut self) -> &mut Renderer {
        &mut self.renderer
    }

    /// Renders one frame and waits for the GPU; no read-back (for timing).
    pub fn render_only(&mut self, frame: &FrameParams) -> Result<FrameReport, RenderError> {
        let report = self.renderer.update(frame);
        self.renderer.render(&self.view)?;
        self.device
            .poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout: Some(Duration::from_secs(60)),
            })
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        Ok(report)
    }

    /// Renders one frame and reads it back.
    pub fn render(&mut self, frame: &FrameParams) -> Result<(RgbaImage, FrameReport), RenderError> {
        let report = self.renderer.update(frame);
        Ok((self.render_current()?, report))
    }

    /// Renders what the renderer holds now (after [`Renderer::update`] or
    /// [`Renderer::update_pose`]) and reads it back.
    pub fn render_current(&mut self) -> Result<RgbaImage, RenderError> {
        self.renderer.render(&self.view)?;
        let mut enc = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("read-back"),
            });
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.padded_row),
                    rows_per_image: Some(self.height),
                },
            },
            wgpu::Extent3d {
                width: self.width,
                height: self.height,
                depth_or_array_layers: 1,
            },
        );
        self.queue.submit(Some(enc.finish()));
        let (tx, rx) = std::sync::mpsc::channel();
        self.readback.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout: Some(Duration::from_secs(60)),
            })
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        rx.recv()
            .map_err(|e| RenderError::Gpu(e.to_string()))?
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        let mut pixels = Vec::with_capacity((self.width * self.height * 4) as usize);
        {
            let data = self
                .readback
                .get_mapped_range(..)
                .map_err(|e| RenderError::Gpu(e.to_string()))?;
            for row in 0..self.height as usize {
                let o = row * self.padded_row as usize;
                pixels.extend_from_slice(&data[o..o + self.width as usize * 4]);
            }
        }
        self.readback.unmap();
        Ok(RgbaImage {
            width: self.width,
            height: self.height,
            pixels,
        })
    }
}

/// One frame, headless: RGBA8 (sRGB) bytes, `width · height · 4` of them. `camera: None`
/// frames the wing with [`OrbitCamera::for_span`].
pub fn render_offscreen(
    width: u32,
    height: u32,
    mesh: &WingMesh,
    frame: &FrameParams,
    camera: Option<OrbitCamera>,
) -> Result<Vec<u8>, RenderError> {
    let mut off = Offscreen::new(width, height, mesh)?;
    if let Some(c) = camera {
        off.renderer().camera = c;
    }
    Ok(off.render(frame)?.0.pixels)
}

/// Options for [`render_frames`].
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// Frames, evenly spaced over the last simulated flap period (1 = its last sample).
    pub frames: usize,
    /// Deflection exaggeration; `None` picks one so the largest drawn deflection over the
    /// frames is 15 % of the span (never below 1).
    pub exaggeration: Option<f64>,
    /// Colouring.
    pub colour: ColourMode,
    /// Camera; `None` frames the wing.
    pub camera: Option<OrbitCamera>,
    /// Draw axes and the body axis.
    pub show_axes: bool,
    /// Draw the stroke plane.
    pub show_stroke_plane: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 640,
            height: 480,
            frames: 1,
            exaggeration: None,
            colour: ColourMode::Magnitude,
            camera: None,
            show_axes: true,
            show_stroke_plane: true,
        }
    }
}

/// Cap on frames per call.
pub const MAX_FRAMES: usize = 10_000;

/// What [`render_frames_report`] did, for the CLI to print.
#[derive(Debug, Clone, PartialEq)]
pub struct FramesSummary {
    /// Times of the frames, s.
    pub times: Vec<f64>,
    /// The exaggeration used.
    pub exaggeration: f64,
    /// Largest true deflection over the frames, metres.
    pub max_deflection_m: f64,
    /// The fixed legend (same for every frame), if the colouring is a strain.
    pub legend: Option<super::Legend>,
    /// Adapter used.
    pub adapter: String,
    /// Notices (mode-count mismatch, sanitised values, ...).
    pub warnings: Vec<String>,
}

fn interp(t: &[f64], y: &[f64], at: f64) -> f64 {
    if t.is_empty() || y.is_empty() {
        return 0.0;
    }
    let n = t.len().min(y.len());
    if at <= t[0] || n == 1 {
        return y[0];
    }
    if at >= t[n - 1] {
        return y[n - 1];
    }
    let i = t[..n].partition_point(|&x| x <= at).clamp(1, n - 1);
    let f = (at - t[i - 1]) / (t[i] - t[i - 1]);
    y[i - 1] + f * (y[i] - y[i - 1])
}

/// Simulates `cfg`, then renders `opts.frames` frames of the last flap period: the wing
/// rotated by α, β, γ at each time and deflected by Σ φ_k q_k(t) (mesh mode k paired with the
/// configuration's mode k). The strain legend is fixed over all frames.
pub fn render_frames(
    cfg: &SimConfig,
    mesh: &WingMesh,
    opts: &RenderOptions,
) -> Result<Vec<RgbaImage>, RenderError> {
    render_frames_report(cfg, mesh, opts).map(|r| r.0)
}

/// [`render_frames`] plus a summary.
pub fn render_frames_report(
    cfg: &SimConfig,
    mesh: &WingMesh,
    opts: &RenderOptions,
) -> Result<(Vec<RgbaImage>, FramesSummary), RenderError> {
    use crate::error::WingbeatError;
    if opts.frames == 0 || opts.frames > MAX_FRAMES {
        return Err(
            WingbeatError::invalid("frames", opts.frames, format!("1 to {MAX_FRAMES}")).into(),
        );
    }
    mesh.validate()?;
    let sim = crate::simulate::simulate(cfg)?;
    let kin = cfg.kinematics.compile();
    let mut warnings = Vec::new();
    let n_modes = mesh.n_modes().min(sim.modes.len());
    if mesh.n_modes() != sim.modes.len() {
        warnings.push(format!(
            "the mesh has {} modes and the configuration {}; drawing the first {n_modes}",
            mesh.n_modes(),
            sim.modes.len()
        ));
    }
    let t_end = sim.t.last().copied().unwrap_or(0.0);
    let t0 = sim.t.first().copied().unwrap_or(0.0);
    let period = if sim.flap_freq_hz > 0.0 {
        1.0 / sim.flap_freq_hz
    } else {
        t_end - t0
    };
    let start = (t_end - period).max(t0);
    let times: Vec<f64> = (0..opts.frames)
        .map(|i| start + (t_end - start) * (i + 1) as f64 / opts.frames as f64)
        .collect();
    let qs: Vec<Vec<f64>> = times
        .iter()
        .map(|&t| {
            (0..n_modes)
                .map(|k| interp(&sim.t, &sim.modes[k].q.total, t))
                .collect()
        })
        .collect();

    let mut max_defl = 0.0f64;
    // One colour scale for the whole sequence: the robust limit over all frames.
    let mut strain_values = Vec::new();
    for q in &qs {
        let qf: Vec<f32> = q.iter().map(|&v| v as f32).collect();
        max_defl = max_defl.max(mesh.max_deflection(&qf) as f64);
        if opts.colour != ColourMode::Plain {
            strain_values.extend(
                mesh.strain_field(&qf)
                    .into_iter()
                    .map(|e| opts.colour.value(e)),
            );
        }
    }
    let max_strain = super::scene::robust_range(strain_values.into_iter());
    let span = mesh.span() as f64;
    let exaggeration = match opts.exaggeration {
        Some(e) => e,
        None if max_defl > 0.0 && max_defl.is_finite() => (0.15 * span / max_defl).max(1.0),
        None => 1.0,
    };

    let mut off = Offscreen::new(opts.width, opts.height, mesh)?;
    if let Some(c) = opts.camera {
        off.renderer().camera = c;
    }
    warnings.extend(off.renderer().warnings().iter().cloned());
    let mut images = Vec::with_capacity(times.len());
    let mut legend = None;
    for (i, &t) in times.iter().enumerate() {
        let s = kin.state(t);
        let frame = FrameParams {
            alpha: s.alpha,
            beta: s.beta,
            gamma: s.gamma,
            q: qs[i].clone(),
            exaggeration,
            colour: opts.colour,
            strain_range: (max_strain > 0.0).then_some(max_strain as f64),
            show_axes: opts.show_axes,
            show_stroke_plane: opts.show_stroke_plane,
            show_body_axis: opts.show_axes,
        };
        let (img, report) = off.render(&frame)?;
        for w in report.warnings {
            warnings.push(format!("frame {i}: {w}"));
        }
        legend = report.legend;
        images.push(img);
    }
    let summary = FramesSummary {
        times,
        exaggeration,
        max_deflection_m: max_defl,
        legend,
        adapter: off.adapter_name(),
        warnings,
    };
    Ok((images, summary))
}
