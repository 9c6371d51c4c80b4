//! The 3-D view of the wasm API (wasm32, features `web` and `render`): `WingView` draws the
//! flexing wing into a canvas with the renderer of [`crate::render`], with WebGPU when the
//! browser has it and WebGL2 otherwise.
//!
//! ```js
//! const view = await WingView.create(canvas, meshJsonOrNull);
//! view.backend();                       // "webgpu" or "webgl2"
//! const legend = view.set_frame(alpha, beta, gamma, new Float64Array(q), exaggeration, 4);
//! view.render();
//! view.setPose(alpha, beta, gamma, q); view.render();   // animation: pose and q only
//! view.orbit(dx, dy); view.zoom(1.1); view.resize(w, h);
//! view.setCamera(tx, ty, tz, yaw, pitch, distance);   // or, from the current direction:
//! const cam = view.fitPoints(new Float32Array(xyz), 0.04); // [tx, ty, tz, yaw, pitch, distance]
//! view.set_scene(showAxes, showStrokePlane, showBodyAxis);
//! view.setNodeField(new Float64Array(nNodes), limitOrNull);   // then set_frame(…, 5): a whole-wing map
//! WingView.colourMap();                 // [t, r, g, b, …]: the colour map, for 2-D drawings
//! ```
//! Every failure reaches JS as a `JsError` with a readable message.

use super::marshal::{bool_arg, f64_array_arg, finite_arg, int_arg, kind, number_arg, text_arg};
use crate::render::gpu::{open_device, Renderer};
use crate::render::mesh::WingMesh;
use crate::render::scene::{ColourMode, FrameParams, Legend, OrbitCamera, OrbitKey};
use crate::render::RenderError;
use wasm_bindgen::prelude::*;

fn js_err(e: RenderError) -> JsError {
    JsError::new(&e.to_string())
}

/// A wing view bound to one canvas.
#[wasm_bindgen]
pub struct WingView {
    renderer: Renderer,
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    backend: String,
    frame: FrameParams,
    legend: Option<Legend>,
    warnings: Vec<String>,
}

/// Most values `fitPoints` takes (x, y, z triples: a million points).
const MAX_FIT_VALUES: usize = 3_000_000;
/// Largest |coordinate| (m) and |angle| (rad) `setCamera` takes (the camera's own limits are far
/// inside: distance 1e-3 to 1e3 m).
const MAX_CAMERA: f64 = 1e6;
/// Largest canvas side `resize` takes, device pixels (browsers cap canvases near 32 767).
const MAX_CANVAS_PX: usize = 32_768;

/// The canvas argument of the constructors: an `HTMLCanvasElement` (the page's canvas) or an
/// `OffscreenCanvas` (one handed to a worker with `transferControlToOffscreen`, so the view
/// draws off the main thread: www/render-worker.js), else an error naming it. Returns the wgpu
/// target and the drawing buffer's size.
fn canvas_arg(canvas: JsValue) -> Result<(wgpu::SurfaceTarget<'static>, u32, u32), JsError> {
    let what = kind(&canvas);
    let canvas = match canvas.dyn_into::<web_sys::HtmlCanvasElement>() {
        Ok(c) => {
            let (w, h) = (c.width(), c.height());
            return Ok((wgpu::SurfaceTarget::Canvas(c), w, h));
        }
        Err(v) => v,
    };
    match canvas.dyn_into::<web_sys::OffscreenCanvas>() {
        Ok(c) => {
            let (w, h) = (c.width(), c.height());
            Ok((wgpu::SurfaceTarget::OffscreenCanvas(c), w, h))
        }
        Err(_) => Err(super::marshal::err(crate::WingbeatError::invalid(
            "canvas",
            what,
            "an HTMLCanvasElement or an OffscreenCanvas",
        ))),
    }
}

/// The points of `fitPoints` / `fitCamera`: x, y, z triples as f32.
fn fit_points_arg(xyz: &JsValue) -> Result<Vec<[f32; 3]>, JsError> {
    let xyz: Vec<f32> = f64_array_arg(xyz, "xyz", 0, MAX_FIT_VALUES)?
        .into_iter()
        .map(|v| v as f32)
        .collect();
    if xyz.len() % 3 != 0 {
        return Err(JsError::new(&format!(
            "fitPoints: {} values is not a list of x, y, z triples",
            xyz.len()
        )));
    }
    Ok(xyz.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}

/// The camera `[tx, ty, tz, yaw, pitch, distance]` of `camera()`.
fn camera_vec(c: &OrbitCamera) -> Vec<f64> {
    vec![
        c.target[0] as f64,
        c.target[1] as f64,
        c.target[2] as f64,
        c.yaw as f64,
        c.pitch as f64,
        c.distance as f64,
    ]
}

/// The pose arguments of `set_frame` and `setPose`: three numbers (non-finite ones are drawn as
/// 0 and reported by the renderer) and the modal coordinates (at most one per mode).
fn pose_args(
    alpha: &JsValue,
    beta: &JsValue,
    gamma: &JsValue,
    q: &JsValue,
) -> Result<(f64, f64, f64, Vec<f64>), JsError> {
    let a = number_arg(alpha, "alpha", "a number, rad")?;
    let b = number_arg(beta, "beta", "a number, rad")?;
    let g = number_arg(gamma, "gamma", "a number, rad")?;
    let q = f64_array_arg(q, "q", 0, crate::model::MAX_MODES)?;
    Ok((a, b, g, q))
}

fn set(obj: &js_sys::Object, key: &str, v: JsValue) {
    let _ = js_sys::Reflect::set(obj, &JsValue::from_str(key), &v);
}

fn parse_mesh(mesh_json: &JsValue) -> Result<WingMesh, JsError> {
    if mesh_json.is_null() || mesh_json.is_undefined() {
        return Ok(WingMesh::synthetic(40, 16));
    }
    let text = if mesh_json.is_string() {
        text_arg(
            mesh_json,
            "mesh_json",
            super::marshal::MAX_TEXT_CHARS,
            "the FE mesh as JSON text or an object",
        )?
    } else {
        super::marshal::check_js_value(mesh_json, "mesh_json").map_err(|m| JsError::new(&m))?;
        js_sys::JSON::stringify(mesh_json)
            .map_err(|_| JsError::new("mesh: could not serialise the object to JSON"))?
            .as_string()
            .unwrap_or_default()
    };
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| {
        super::marshal::err(crate::WingbeatError::invalid(
            "mesh_json",
            format!("not JSON ({e})"),
            "the FE mesh as JSON text or an object, or null for the synthetic wing",
        ))
    })?;
    WingMesh::from_fe_json(&v).map_err(|e| JsError::new(&format!("mesh_json: {e}")))
}

#[wasm_bindgen]
impl WingView {
    /// Creates the view. `mesh_json`: the FE mesh (object or JSON string), or null for the
    /// synthetic wing. Rejects with a clear reason when neither WebGPU nor WebGL2 works, the
    /// canvas is zero-sized, or the mesh is invalid.
    pub async fn create(
        #[wasm_bindgen(unchecked_param_type = "HTMLCanvasElement | OffscreenCanvas")]
        canvas: JsValue,
        mesh_json: JsValue,
    ) -> Result<WingView, JsError> {
        let mesh = parse_mesh(&mesh_json)?;
        let canvas = canvas_arg(canvas)?;
        Self::with_mesh(canvas, mesh).await
    }

    /// Creates the view from the flat arrays of `feModes` (`nodes`, `triangles`, `shapes`,
    /// `strain_nodes`; see `WingMesh::from_flat`), so the FE wing crosses as typed arrays,
    /// not JSON. An empty `strain_nodes` draws without strain colours.
    #[wasm_bindgen(js_name = createFromArrays)]
    pub async fn create_from_arrays(
        #[wasm_bindgen(unchecked_param_type = "HTMLCanvasElement | OffscreenCanvas")]
        canvas: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] nodes: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Uint32Array | number[]")] triangles: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] shapes: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] strain_nodes: JsValue,
    ) -> Result<WingView, JsError> {
        let (max_nodes, max_tris) = super::wing::flat_mesh_caps();
        let max_modes = crate::model::MAX_MODES;
        let nodes = f64_array_arg(&nodes, "nodes", 3, 3 * max_nodes)?;
        let triangles = super::marshal::u32_array_arg(&triangles, "triangles", 3, 3 * max_tris)?;
        let shapes = f64_array_arg(&shapes, "shapes", 0, max_nodes * max_modes)?;
        let strain_nodes =
            f64_array_arg(&strain_nodes, "strain_nodes", 0, 3 * max_nodes * max_modes)?;
        let canvas = canvas_arg(canvas)?;
        let mesh = WingMesh::from_flat(&nodes, &triangles, &shapes, &strain_nodes)
            .map_err(|e| JsError::new(&format!("mesh: {e}")))?;
        Self::with_mesh(canvas, mesh).await
    }

    /// Creates the view with the synthetic wing on an `n_span` × `n_chord` grid (each clamped
    /// to 1..=1000; `2·n_span·n_chord − n_chord` triangles), e.g. for frame-time benchmarks.
    #[wasm_bindgen(js_name = createSynthetic)]
    pub async fn create_synthetic(
        #[wasm_bindgen(unchecked_param_type = "HTMLCanvasElement | OffscreenCanvas")]
        canvas: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] n_span: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] n_chord: JsValue,
    ) -> Result<WingView, JsError> {
        let n_span = int_arg(&n_span, "n_span", 1, 1000)?;
        let n_chord = int_arg(&n_chord, "n_chord", 1, 1000)?;
        let canvas = canvas_arg(canvas)?;
        let mesh = WingMesh::synthetic(n_span, n_chord);
        Self::with_mesh(canvas, mesh).await
    }

    /// The number of triangles drawn.
    pub fn triangles(&self) -> u32 {
        self.renderer.mesh().triangles.len() as u32
    }
}

impl WingView {
    async fn with_mesh(
        (target, width, height): (wgpu::SurfaceTarget<'static>, u32, u32),
        mesh: WingMesh,
    ) -> Result<WingView, JsError> {
        if width == 0 || height == 0 {
            return Err(js_err(RenderError::ZeroSize { width, height }));
        }
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL;
        let instance = wgpu::util::new_instance_with_webgpu_detection(desc).await;
        let surface = instance.create_surface(target).map_err(|e| {
            js_err(RenderError::Surface(format!(
                "{e} (the canvas may already have a 2d context, or WebGL2 is disabled)"
            )))
        })?;
        let ctx = open_device(
            &instance,
            Some(&surface),
            wgpu::PowerPreference::default(),
            "wingbeat view",
            ": this browser offers neither WebGPU nor WebGL2",
        )
        .await
        .map_err(js_err)?;
        let (adapter, device, queue) = (ctx.adapter, ctx.device, ctx.queue);
        let backend = match adapter.get_info().backend {
            wgpu::Backend::BrowserWebGpu => "webgpu".to_string(),
            wgpu::Backend::Gl => "webgl2".to_string(),
            other => format!("{other:?}").to_lowercase(),
        };
        let caps = surface.get_capabilities(&adapter);
        // WebGL2: a plain-UNORM canvas format, so wgpu presents with a framebuffer blit; an
        // sRGB one makes it present through an extra full-canvas shader pass (its sRGB
        // conversion), which a software rasteriser pays for in fill every frame. The shaders
        // gamma-encode themselves on a non-sRGB target (as on WebGPU's canvas formats).
        let want_srgb = backend != "webgl2";
        let format = caps
            .formats
            .iter()
            .copied()
            .find(|f| f.is_srgb() == want_srgb)
            .or_else(|| caps.formats.first().copied())
            .ok_or_else(|| {
                js_err(RenderError::Surface(
                    "the canvas offers no colour format".into(),
                ))
            })?;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            color_space: Default::default(),
            width,
            height,
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps
                .alpha_modes
                .first()
                .copied()
                .unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: vec![],
        };
        surface.configure(&device, &config);
        let mut renderer = Renderer::new(&device, &queue, format, &mesh).map_err(js_err)?;
        renderer.resize(width, height).map_err(js_err)?;
        let warnings = renderer.warnings().to_vec();
        Ok(WingView {
            renderer,
            surface,
            device,
            queue,
            config,
            backend,
            frame: FrameParams::default(),
            legend: None,
            warnings,
        })
    }
}

#[wasm_bindgen]
impl WingView {
    /// `"webgpu"` or `"webgl2"`.
    pub fn backend(&self) -> String {
        self.backend.clone()
    }

    /// Sets the pose (radians), the modal coordinates (true scale), the exaggeration and the
    /// colouring (0 plain, 1 ε_x, 2 ε_y, 3 γ_xy, 4 magnitude, 5 the node field of
    /// `setNodeField`). Non-finite values are drawn as 0
    /// and listed in the returned object's `warnings`. Returns the legend:
    /// `{component, min, max, units, data_min, data_max, exaggeration, max_deflection_m,
    /// warnings}` (`component` is `"none"` for plain colouring).
    pub fn set_frame(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] alpha: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] beta: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] gamma: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] q: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] exaggeration: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] colour_mode: JsValue,
    ) -> Result<JsValue, JsError> {
        let (alpha, beta, gamma, q) = pose_args(&alpha, &beta, &gamma, &q)?;
        let exaggeration = number_arg(&exaggeration, "exaggeration", "a number")?;
        let colour_mode = int_arg(&colour_mode, "colour_mode", 0, 5)? as u32;
        let colour = ColourMode::from_index(colour_mode).ok_or_else(|| {
            JsError::new(&format!(
                "invalid value for `colour_mode`: {colour_mode} (allowed: 0 plain, 1 ε_x, 2 ε_y, 3 γ_xy, 4 magnitude, 5 node field)"
            ))
        })?;
        self.frame.alpha = alpha;
        self.frame.beta = beta;
        self.frame.gamma = gamma;
        self.frame.q.clear();
        self.frame.q.extend_from_slice(&q);
        self.frame.exaggeration = exaggeration;
        self.frame.colour = colour;
        Ok(self.update())
    }

    /// The animation's per-frame call: sets only the pose (radians) and the modal coordinates
    /// (true scale), keeping the colouring, exaggeration and legend of the last `set_frame`,
    /// and uploads the 272-byte uniform block: no legend, no per-node work, no result object.
    /// Non-finite values are drawn as 0 and |values| > 10⁶ clamped; returns how many were
    /// changed (call `set_frame` for their names). Call `render()` after it.
    #[wasm_bindgen(js_name = setPose)]
    pub fn set_pose(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] alpha: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] beta: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] gamma: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] q: JsValue,
    ) -> Result<u32, JsError> {
        let (alpha, beta, gamma, q) = pose_args(&alpha, &beta, &gamma, &q)?;
        self.frame.alpha = alpha;
        self.frame.beta = beta;
        self.frame.gamma = gamma;
        self.frame.q.clear();
        self.frame.q.extend_from_slice(&q);
        Ok(self.renderer.update_pose(alpha, beta, gamma, &q) as u32)
    }

    /// Fixes the legend limit (colours span ±limit), or `null`/non-positive for automatic.
    pub fn set_strain_range(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] limit: JsValue,
    ) -> Result<JsValue, JsError> {
        let limit = super::marshal::opt_number_arg(&limit, "limit", "a number, null or undefined")?;
        self.frame.strain_range = limit.filter(|l| l.is_finite() && *l > 0.0);
        Ok(self.update())
    }

    /// Sets the node field drawn with colour mode 5: one value per node of the mesh (e.g. the
    /// RMS or peak of a strain component over a run, from `strainField`), and the legend limit
    /// (colours span 0…limit, or ±limit when a value is negative; `null`/non-positive: the
    /// 98th percentile of |value|). Non-finite values are drawn as 0 and reported in the
    /// returned legend's `warnings`. Rejects a length other than the node count, changing nothing.
    #[wasm_bindgen(js_name = setNodeField)]
    pub fn set_node_field(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] values: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number | null | undefined")] limit: JsValue,
    ) -> Result<JsValue, JsError> {
        let n = self.renderer.mesh().nodes.len();
        let values = f64_array_arg(&values, "values", n, n)?;
        let limit = super::marshal::opt_number_arg(&limit, "limit", "a number, null or undefined")?;
        let note = self.renderer.set_node_field(&values).map_err(js_err)?;
        self.warnings
            .retain(|w| !w.contains("non-finite field value"));
        self.warnings.extend(note);
        self.frame.strain_range = limit.filter(|l| l.is_finite() && *l > 0.0);
        Ok(self.update())
    }

    /// The colour map of every strain colouring as a flat array `[t, r, g, b, …]` (t from 0 to
    /// 1, sRGB 0–1): signed values map −M…0…M onto t = 0…½…1, non-negative ones 0…M onto ½…1.
    /// The page's 2-D drawings (mode shapes, planform strain map) use it, so there is one map.
    #[wasm_bindgen(js_name = colourMap)]
    pub fn colour_map() -> Vec<f64> {
        crate::render::scene::DIVERGING_STOPS
            .iter()
            .flat_map(|(t, c)| [*t as f64, c[0] as f64, c[1] as f64, c[2] as f64])
            .collect()
    }

    /// Shows or hides the frames (fixed I, J, K and flapping I″, J″, K″), the stroke plane
    /// (fill and outline) and the body axis (`show_body_axis`; omitted: as `show_axes`).
    pub fn set_scene(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "boolean")] show_axes: JsValue,
        #[wasm_bindgen(unchecked_param_type = "boolean")] show_stroke_plane: JsValue,
        #[wasm_bindgen(unchecked_param_type = "boolean | undefined")] show_body_axis: JsValue,
    ) -> Result<(), JsError> {
        let show_axes = bool_arg(&show_axes, "show_axes")?;
        let show_stroke_plane = bool_arg(&show_stroke_plane, "show_stroke_plane")?;
        let show_body_axis = if show_body_axis.is_undefined() || show_body_axis.is_null() {
            show_axes
        } else {
            bool_arg(&show_body_axis, "show_body_axis")?
        };
        self.frame.show_axes = show_axes;
        self.frame.show_stroke_plane = show_stroke_plane;
        self.frame.show_body_axis = show_body_axis;
        self.update();
        Ok(())
    }

    /// Sets the orbit camera: the target it looks at (m, fixed frame), yaw and pitch (rad; the
    /// pitch is kept within ±(π/2 − 0.01)) and the eye–target distance (m). Rejects, changing
    /// nothing, a value that is not finite or a distance that is not positive.
    #[wasm_bindgen(js_name = setCamera)]
    pub fn set_camera(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] tx: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] ty: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] tz: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] yaw: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] pitch: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] distance: JsValue,
    ) -> Result<(), JsError> {
        let n = |v: &JsValue, f: &str| finite_arg(v, f, -MAX_CAMERA, MAX_CAMERA);
        let (tx, ty, tz) = (n(&tx, "tx")?, n(&ty, "ty")?, n(&tz, "tz")?);
        let (yaw, pitch) = (n(&yaw, "yaw")?, n(&pitch, "pitch")?);
        let distance = finite_arg(&distance, "distance", 0.0, MAX_CAMERA)?;
        if distance == 0.0 {
            return Err(super::marshal::err(crate::WingbeatError::invalid(
                "distance",
                0,
                format!("a finite number in (0, {MAX_CAMERA}] m"),
            )));
        }
        let target = [tx as f32, ty as f32, tz as f32];
        if !self
            .renderer
            .camera
            .set(target, yaw as f32, pitch as f32, distance as f32)
        {
            return Err(JsError::new(&format!(
                "invalid camera: target ({tx}, {ty}, {tz}) m, yaw {yaw}, pitch {pitch} rad, distance {distance} m (allowed: finite numbers, distance > 0)"
            )));
        }
        self.update();
        Ok(())
    }

    /// The camera as `[tx, ty, tz, yaw, pitch, distance]` (m, rad, m).
    pub fn camera(&self) -> Vec<f64> {
        camera_vec(&self.renderer.camera)
    }

    /// Frames the points `xyz` (flat x, y, z triples, m, fixed frame; e.g. the wing's outline
    /// at every pose of a flap) from the camera's current direction: the target centres their
    /// projection and the distance is the smallest that keeps all of them inside the canvas
    /// with `margin` (fraction of the half-width and half-height, 0…0.45) to spare
    /// (`OrbitCamera::fit_points`). Returns the new camera as `camera()` does. Rejects a
    /// length that is not a multiple of 3 or points that are all non-finite.
    #[wasm_bindgen(js_name = fitPoints)]
    pub fn fit_points(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float32Array | Float64Array | number[]")]
        xyz: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] margin: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let margin = finite_arg(&margin, "margin", 0.0, 0.45)? as f32;
        let pts = fit_points_arg(&xyz)?;
        let aspect = self.config.width as f32 / self.config.height.max(1) as f32;
        if !self.renderer.camera.fit_points(&pts, aspect, margin) {
            return Err(JsError::new("fitPoints: no finite point to frame"));
        }
        self.update();
        Ok(self.camera())
    }

    /// `fitPoints` without a view: the camera `camera` (`[tx, ty, tz, yaw, pitch, distance]`, as
    /// `camera()` returns it) fitted to the points `xyz` with `margin` for a canvas of aspect
    /// `aspect` (width / height, 1e-3…1e3). No GPU: the page calls it while a worker owns the
    /// view (www/wing3d/remote-view.js), so one fit serves both. Rejects what `setCamera` and
    /// `fitPoints` reject.
    #[wasm_bindgen(js_name = fitCamera)]
    pub fn fit_camera(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] camera: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float32Array | Float64Array | number[]")]
        xyz: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] margin: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] aspect: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let c = f64_array_arg(&camera, "camera", 6, 6)?;
        let margin = finite_arg(&margin, "margin", 0.0, 0.45)? as f32;
        let aspect = finite_arg(&aspect, "aspect", 1e-3, 1e3)? as f32;
        let pts = fit_points_arg(&xyz)?;
        let mut cam = OrbitCamera::for_span(1.0);
        let ok = c.iter().all(|v| v.is_finite() && v.abs() <= MAX_CAMERA)
            && c[5] > 0.0
            && cam.set(
                [c[0] as f32, c[1] as f32, c[2] as f32],
                c[3] as f32,
                c[4] as f32,
                c[5] as f32,
            );
        if !ok {
            return Err(super::marshal::err(crate::WingbeatError::invalid(
                "camera",
                format!("{c:?}"),
                format!("[tx, ty, tz, yaw, pitch, distance]: finite numbers within ±{MAX_CAMERA}, distance > 0 (m, rad)"),
            )));
        }
        if !cam.fit_points(&pts, aspect, margin) {
            return Err(JsError::new("fitPoints: no finite point to frame"));
        }
        Ok(camera_vec(&cam))
    }

    fn update(&mut self) -> JsValue {
        let report = self.renderer.update(&self.frame);
        self.legend = report.legend.clone();
        let obj = js_sys::Object::new();
        let (component, min, max, units, dmin, dmax) = match &report.legend {
            Some(l) => (l.component, l.min, l.max, l.units, l.data_min, l.data_max),
            None => ("none", 0.0, 0.0, "strain", 0.0, 0.0),
        };
        set(&obj, "component", component.into());
        set(&obj, "min", (min as f64).into());
        set(&obj, "max", (max as f64).into());
        set(&obj, "units", units.into());
        set(&obj, "data_min", (dmin as f64).into());
        set(&obj, "data_max", (dmax as f64).into());
        set(&obj, "exaggeration", (report.exaggeration as f64).into());
        set(
            &obj,
            "max_deflection_m",
            (report.max_deflection_m as f64).into(),
        );
        let warnings = js_sys::Array::new();
        for w in self.warnings.iter().chain(&report.warnings) {
            warnings.push(&JsValue::from_str(w));
        }
        set(&obj, "warnings", warnings.into());
        obj.into()
    }

    /// Draws the current frame. A lost surface is reconfigured and the frame skipped; a lost
    /// device or a GPU error rejects with its reason.
    pub fn render(&mut self) -> Result<(), JsError> {
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t)
            | wgpu::CurrentSurfaceTexture::Suboptimal(t) => t,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                return Ok(())
            }
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(&self.device, &self.config);
                return Ok(());
            }
            wgpu::CurrentSurfaceTexture::Validation => {
                return Err(js_err(RenderError::Surface(
                    "validation error acquiring the canvas texture".into(),
                )))
            }
        };
        let view = frame.texture.create_view(&Default::default());
        let result = self.renderer.render(&view);
        self.queue.present(frame);
        result.map_err(js_err)
    }

    /// Resizes the drawing buffer (device pixels): integers in [1, 32768]; anything else is
    /// refused by name, leaving the view as it was.
    pub fn resize(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] width: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] height: JsValue,
    ) -> Result<(), JsError> {
        let width = int_arg(&width, "width", 1, MAX_CANVAS_PX)? as u32;
        let height = int_arg(&height, "height", 1, MAX_CANVAS_PX)? as u32;
        self.renderer.resize(width, height).map_err(js_err)?;
        self.config.width = width;
        self.config.height = height;
        self.surface.configure(&self.device, &self.config);
        self.update();
        Ok(())
    }

    /// Orbits the camera by a drag of (dx, dy) CSS pixels.
    pub fn orbit(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] dx: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] dy: JsValue,
    ) -> Result<(), JsError> {
        let dx = finite_arg(&dx, "dx", -1e6, 1e6)?;
        let dy = finite_arg(&dy, "dy", -1e6, 1e6)?;
        self.renderer.camera.drag(dx as f32, dy as f32);
        self.update();
        Ok(())
    }

    /// Multiplies the camera distance by `factor` (> 1 zooms out).
    pub fn zoom(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "number")] factor: JsValue,
    ) -> Result<(), JsError> {
        let factor = finite_arg(&factor, "factor", 1e-6, 1e6)?;
        self.renderer.camera.zoom(factor as f32);
        self.update();
        Ok(())
    }

    /// One keyboard step: `ArrowLeft`, `ArrowRight`, `ArrowUp`, `ArrowDown`, `+`, `-`
    /// (returns false for other keys).
    pub fn key(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "string")] key: JsValue,
    ) -> Result<bool, JsError> {
        let key = text_arg(&key, "key", 64, "a KeyboardEvent key name (a string)")?;
        let k = match key.as_str() {
            "ArrowLeft" => OrbitKey::Left,
            "ArrowRight" => OrbitKey::Right,
            "ArrowUp" => OrbitKey::Up,
            "ArrowDown" => OrbitKey::Down,
            "+" | "=" => OrbitKey::ZoomIn,
            "-" | "_" => OrbitKey::ZoomOut,
            _ => return Ok(false),
        };
        self.renderer.camera.key(k);
        self.update();
        Ok(true)
    }

    /// Legend colour stops as a flat array `[value, r, g, b, value, r, g, b, ...]` (sRGB 0–1)
    /// for the current colouring; empty for plain colouring.
    pub fn legend_stops(&self) -> Vec<f64> {
        self.legend
            .as_ref()
            .map(|l| {
                l.stops()
                    .iter()
                    .flat_map(|(v, c)| [*v as f64, c[0] as f64, c[1] as f64, c[2] as f64])
                    .collect()
            })
            .unwrap_or_default()
    }
}
