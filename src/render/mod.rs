//! The 3-D renderer of the flexing wing (feature `render`), built on wgpu.
//!
//! * [`mesh`]: [`WingMesh`], the FE interface (nodes, triangles, per-mode shapes and strains),
//!   plus an analytic Manduca-like stand-in;
//! * [`scene`]: the rotation convention, the orbit camera, per-frame parameters (sanitised so
//!   no NaN reaches the GPU), the diverging strain colour map and its legend;
//! * [`gpu`]: [`Renderer`], in the style of the wgpu examples (`new`, `resize`, `update`,
//!   `render`), with shaders in `shaders/*.wgsl`, kept WebGL2-compatible;
//!   [`gpu::open_device`] sets up the GPU device for both front ends;
//! * `offscreen` (native only): headless rendering to RGBA / PNG with pollster (the CLI's
//!   `render` command lives in `src/cli/render.rs`);
//! * the browser's `WingView` (WebGPU when the browser has it, WebGL2 otherwise) lives with
//!   the rest of the wasm API, in `src/wasm/view.rs` (features `web` and `render`).
//!
//! The mesh is uploaded once; per frame only a 272-byte uniform block changes. See
//! `docs/render.md` for the GPU data layout and the measured numbers.

pub mod gpu;
pub mod mesh;
pub mod scene;

#[cfg(not(target_arch = "wasm32"))]
pub mod offscreen;

pub use gpu::{FrameReport, Renderer};
pub use mesh::WingMesh;
pub use scene::{ColourMode, FrameParams, Legend, OrbitCamera, OrbitKey};

#[cfg(not(target_arch = "wasm32"))]
pub use offscreen::{render_frames, render_offscreen, Offscreen, RenderOptions, RgbaImage};

/// The most modes the GPU path draws: their shapes and strains are packed four modes per
/// `vec4` vertex attribute (9 attributes in all, within WebGL2's 16), because WebGL2 has no
/// storage buffers in the vertex stage. Further modes are ignored with a warning.
pub const MAX_MODES: usize = 8;

/// What can go wrong in the renderer. (A GPU-specific error type kept out of the core's
/// `WingbeatError`; `From<RenderError> for String` serves the CLI.)
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// No GPU adapter (native: install a Vulkan driver such as lavapipe; browser: neither
    /// WebGPU nor WebGL2 is available).
    #[error("no GPU adapter found: {0}")]
    NoAdapter(String),
    /// The adapter refused to create a device with the limits the renderer needs.
    #[error("could not create a GPU device: {0}")]
    Device(String),
    /// The GPU device was lost (driver reset, tab backgrounded for long, ...).
    #[error("the GPU device was lost: {0}")]
    DeviceLost(String),
    /// A width or height of zero (e.g. a collapsed canvas); nothing is drawn.
    #[error("zero-size render target {width}×{height}: nothing to draw")]
    ZeroSize {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// A render target larger than the device allows.
    #[error("render target {width}×{height} exceeds the device limit of {max} pixels per side")]
    TooLarge {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// The device's `max_texture_dimension_2d`.
        max: u32,
    },
    /// The canvas / window surface could not be created or configured.
    #[error("surface error: {0}")]
    Surface(String),
    /// A wgpu validation or out-of-memory error, or a failed read-back.
    #[error("GPU error: {0}")]
    Gpu(String),
    /// Invalid input (mesh, configuration) from the core.
    #[error(transparent)]
    Input(#[from] crate::error::WingbeatError),
    /// Writing an image failed.
    #[error("I/O error: {0}")]
    Io(String),
}

impl From<RenderError> for crate::WingbeatError {
    fn from(e: RenderError) -> crate::WingbeatError {
        match e {
            RenderError::Input(inner) => inner,
            other => crate::WingbeatError::Render(other.to_string()),
        }
    }
}

impl From<RenderError> for String {
    fn from(e: RenderError) -> String {
        e.to_string()
    }
}
