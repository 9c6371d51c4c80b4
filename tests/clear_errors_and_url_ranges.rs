//! Clear errors for the FE reproductions (a 1e-9 mm outline, a
//! modulus of 1e-300 Pa), one owner for the URL and core ranges (www/state.js against
//! src/params.rs), the FE work budget (a 5 000-point outline), and a regression test for each
//! remaining reproduction of the issue's "Unclear errors" list.
// Runs the CLI binary and Node: native only.
#![cfg(not(target_arch = "wasm32"))]

use std::process::Command;
use std::time::{Duration, Instant};
use wingbeat::fem::{self, FemInput};
use wingbeat::params::{MATERIAL_RANGES, PARAMS, WING_PARAMS};

mod common_cli;
use common_cli::run_timed as run;

/// The default outline resampled to `n` points evenly along its perimeter (same shape).
pub fn resampled_manduca(n: usize) -> Vec<[f64; 2]> {
    let p = fem::manduca_planform();
    let m = p.len();
    let seg: Vec<f64> = (0..m)
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % m]);
            ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
        })
        .collect();
    let total: f64 = seg.iter().sum();
    let mut out = Vec::with_capacity(n);
    let (mut i, mut acc) = (0, 0.0);
    for k in 0..n {
        let s = total * k as f64 / n as f64;
        while acc + seg[i] < s {
            acc += seg[i];
            i += 1;
        }
        let t = (s - acc) / seg[i];
        let (a, b) = (p[i], p[(i + 1) % m]);
        out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    }
    out
}

/// Prints mesh size, system size, estimated work and measured time of a few FE runs (the
/// calibration of `fem::FE_MAX_WORK` in docs/limits.md). Release build:
/// `cargo test --release --test clear_errors_and_url_ranges -- --ignored --nocapture calibration`.
#[test]
#[ignore = "measurement, minutes"]
fn fe_work_calibration() {
    let opt = fem::EigenOptions::default();
    let mut cases: Vec<(String, FemInput)> = Vec::new();
    for (h, n) in [(2.0, 6), (1.0, 6), (0.75, 6), (0.5, 6), (1.0, 64), (0.3, 6)] {
        cases.push((
            format!("default wing h={h} mm, {n} modes"),
            FemInput {
                mesh_size_mm: Some(h),
                n_modes: n,
                ..FemInput::default()
            },
        ));
    }
    for n in [1000, 2000, 5000] {
        cases.push((
            format!("default outline resampled to {n} points, automatic h"),
            FemInput {
                planform_mm: resampled_manduca(n),
                ..FemInput::default()
            },
        ));
    }
    for (name, input) in cases {
        let t0 = Instant::now();
        let (outline, mesh, h) = fem::mesh_input(&input).unwrap();
        let clamped = fem::clamp_nodes(&outline, &mesh, input.clamp).unwrap();
        let size = fem::assembly::system_size(&mesh, &clamped);
        let work = fem::fe_work(&size, input.n_modes, &opt);
        let t_mesh = t0.elapsed().as_secs_f64();
        print!(
            "{name}: h {h} mm, {} nodes, {} dofs, envelope {:.3e}, factor {:.3e}, work {:.3e}, mesh {t_mesh:.2} s",
            mesh.nodes.len(),
            size.n_dofs,
            size.envelope as f64,
            size.factor_work,
            work
        );
        let solve_up_to: f64 = std::env::var("CAL_SOLVE_UP_TO")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(6e9);
        if work > solve_up_to {
            println!(", not solved");
            continue;
        }
        let t1 = Instant::now();
        let r = fem::solve_mesh(&mesh, &clamped, &input.material, input.n_modes, "cal");
        let dt = t1.elapsed().as_secs_f64();
        println!(
            ", solve {dt:.2} s ({:.2} ns per unit), {}",
            dt / work * 1e9,
            if r.is_ok() { "ok" } else { "error" }
        );
    }
}

fn err_text<T: std::fmt::Debug>(r: wingbeat::Result<T>) -> String {
    r.expect_err("refused").to_string()
}

#[test]
fn a_tiny_outline_is_refused_by_name() {
    // The issue's case: a 1e-9 mm outline used to fail with "invalid value for `clamp.x_mm`:
    // Root".
    let tiny = geometry_square(1e-9);
    let e = err_text(fem::compute_modes(&FemInput {
        planform_mm: tiny.clone(),
        ..FemInput::default()
    }));
    assert!(
        e.contains("`planform`")
            && e.contains("span")
            && e.contains("1e-9 mm")
            && e.contains("0.01 mm"),
        "{e}"
    );
    assert!(!e.contains("clamp"), "{e}");
    let e = err_text(fem::geometry::outline_summary(&tiny));
    assert!(e.contains("`planform`"), "{e}");
    // a sliver: wide enough, but almost no area
    let sliver = vec![[0.0, 0.0], [0.0, -1e-4], [40.0, -10.0001], [40.0, -10.0]];
    let e = err_text(fem::geometry::validate_outline(&sliver));
    assert!(
        e.contains("`planform`") && e.contains("bounding box"),
        "{e}"
    );
    // the smallest accepted outline still solves
    let fe = fem::compute_modes(&FemInput {
        planform_mm: fem::geometry::rectangle_planform(0.05, 0.02),
        n_modes: 2,
        ..FemInput::default()
    })
    .unwrap();
    assert!(fe.freq_hz.iter().all(|f| f.is_finite() && *f > 0.0));
}

fn geometry_square(side: f64) -> Vec<[f64; 2]> {
    vec![[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]
}

#[test]
fn cli_tiny_outline_and_tiny_modulus_get_clear_messages() {
    let dir = std::env::temp_dir().join(format!("wingbeat-clear-errors-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let tiny = dir.join("tiny.json");
    std::fs::write(&tiny, "[[0,0],[1e-9,0],[1e-9,1e-9],[0,1e-9]]").unwrap();
    let (code, _, err, dt) = run(&["modes", "--planform", tiny.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("`planform`") && err.contains("span"), "{err}");
    assert!(dt < Duration::from_secs(10), "{dt:?}");
    // The issue's case: E = 1e-300 Pa used to end in "Krylov space exhausted at 0 vectors".
    let (code, _, err, dt) = run(&["modes", "--e-pa", "1e-300"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("`material.e_pa`")
            && err.contains("1e-300")
            && err.contains("[1000, 1e13] Pa"),
        "{err}"
    );
    assert!(!err.contains("Krylov"), "{err}");
    assert!(dt < Duration::from_secs(10), "{dt:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn material_ranges_have_one_owner() {
    // Every field the material has is checked against MATERIAL_RANGES, by name.
    let ok = fem::ShellMaterial::paper_frequencies();
    ok.validate().unwrap();
    fem::ShellMaterial::paper_as_printed().validate().unwrap();
    for r in &MATERIAL_RANGES {
        for bad in [
            r.min - r.min.abs().max(1.0) * 0.5,
            r.max * 2.0 + 1.0,
            f64::NAN,
            f64::INFINITY,
        ] {
            let mut m = ok;
            match r.field {
                "material.thickness_m" => m.thickness_m = bad,
                "material.e_pa" => m.e_pa = bad,
                "material.rho_kg_m3" => m.rho_kg_m3 = bad,
                "material.nu" => m.nu = bad,
                other => panic!("unknown field {other}"),
            }
            let e = err_text(m.validate());
            assert!(e.contains(&format!("`{}`", r.field)), "{e}");
        }
    }
    // The open interval of ν: its ends are refused.
    for nu in [-1.0, 0.5] {
        let m = fem::ShellMaterial { nu, ..ok };
        assert!(err_text(m.validate()).contains("open interval"));
    }
    // The lab's sliders (WING_PARAMS) lie inside the core's ranges (thickness in µm there).
    for r in &MATERIAL_RANGES {
        let w = WING_PARAMS
            .iter()
            .find(|p| p.key == r.wing_key)
            .expect("every material range has its wing parameter");
        let scale = if r.field == "material.thickness_m" {
            1e-6
        } else {
            1.0
        };
        let (lo, hi) = (w.min * scale, w.max * scale);
        let inside = |v: f64| {
            if r.open {
                v > r.min && v < r.max
            } else {
                v >= r.min && v <= r.max
            }
        };
        assert!(
            inside(lo) && inside(hi),
            "{}: slider [{lo}, {hi}] outside [{}, {}]",
            r.field,
            r.min,
            r.max
        );
    }
    // The solver's failure message says what to change.
    for field in ["n_modes", "mesh_size_mm", "material.e_pa"] {
        assert!(fem::eigen::SOLVER_REMEDY.contains(field));
    }
}

/// The next double above (`up`) or below `v`.
fn next(v: f64, up: bool) -> f64 {
    if v == 0.0 {
        let tiny = f64::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let b = v.to_bits();
    let grow = (v > 0.0) == up;
    f64::from_bits(if grow { b + 1 } else { b - 1 })
}

/// Runs www/state.js in Node: its tables and what `parseNumber`/`parseWing` accept for each
/// probe. `None` when Node is not installed (the lab's `npm test` always has it).
fn state_js(probes: &[(String, String)]) -> Option<serde_json::Value> {
    let root = env!("CARGO_MANIFEST_DIR");
    let script = format!(
        r#"import {{ NUMERIC, WING, parseNumber, parseWing }} from '{root}/www/state.js';
const probes = JSON.parse(process.argv[1]);
const accepted = probes.map(([key, text]) => {{
  const p = NUMERIC.find((q) => q.key === key);
  if (p) return parseNumber(p, text);
  const w = WING.find((q) => q.core === key);
  return parseWing(w, text);
}});
console.log(JSON.stringify({{ numeric: NUMERIC, wing: WING, accepted }}));"#
    );
    let out = Command::new("node")
        .args(["--input-type=module", "-e", &script])
        .arg(serde_json::to_string(probes).unwrap())
        .output()
        .ok()?;
    assert!(
        out.status.success(),
        "node: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(serde_json::from_slice(&out.stdout).unwrap())
}

#[test]
fn url_and_core_ranges_are_the_same() {
    // The issue's case: the URL parser let `zeta=-1e-13` through, then validateConfig refused.
    let mut probes: Vec<(String, String)> = vec![("zeta".into(), "-1e-13".into())];
    for p in PARAMS.iter().chain(WING_PARAMS.iter()) {
        for v in [
            p.min,
            p.max,
            p.default,
            next(p.min, false),
            next(p.max, true),
            p.min - 1e-13 * p.min.abs().max(1.0),
            p.max + 1e-13 * p.max.abs().max(1.0),
        ] {
            probes.push((p.key.to_string(), format!("{v:e}")));
        }
    }
    let Some(js) = state_js(&probes) else {
        eprintln!("node not found: skipped");
        return;
    };
    // The tables: the JS copies are the core's (keys, ranges, steps; numeric defaults too).
    let numeric = js["numeric"].as_array().unwrap();
    assert_eq!(numeric.len(), PARAMS.len());
    for (j, p) in numeric.iter().zip(PARAMS.iter()) {
        assert_eq!(j["key"], p.key);
        for (name, v) in [
            ("min", p.min),
            ("max", p.max),
            ("step", p.step),
            ("def", p.default),
        ] {
            assert_eq!(j[name].as_f64(), Some(v), "{}.{name}", p.key);
        }
    }
    let wing = js["wing"].as_array().unwrap();
    assert_eq!(wing.len(), WING_PARAMS.len());
    for (j, p) in wing.iter().zip(WING_PARAMS.iter()) {
        assert_eq!(j["core"], p.key);
        for (name, v) in [("min", p.min), ("max", p.max), ("step", p.step)] {
            assert_eq!(j[name].as_f64(), Some(v), "{}.{name}", p.key);
        }
    }
    // Every probe: the URL parser accepts it exactly when the core's range check does, and
    // whatever it accepts the core then accepts too.
    let accepted = js["accepted"].as_array().unwrap();
    for ((key, text), got) in probes.iter().zip(accepted) {
        let v: f64 = text.parse().unwrap();
        let p = wingbeat::params::find(key)
            .or_else(|| wingbeat::params::find_wing(key))
            .unwrap();
        let in_range = v >= p.min && v <= p.max;
        let integral_ok = key != "n_modes" || v.fract() == 0.0;
        assert_eq!(
            !got.is_null(),
            in_range && integral_ok,
            "{key}={text}: JS {got}"
        );
        if got.is_null() {
            continue;
        }
        let core = if wingbeat::params::find(key).is_some() {
            wingbeat::params::apply_overrides(
                &wingbeat::config::SimConfig::paper(),
                [(key.as_str(), v)],
            )
            .map(|_| ())
        } else {
            wingbeat::params::wing_input([(key.as_str(), v)], None).map(|_| ())
        };
        assert!(
            core.is_ok(),
            "{key}={text} accepted by the URL, refused by the core: {core:?}"
        );
    }
    assert!(
        accepted[0].is_null(),
        "zeta=-1e-13 must be refused by the URL parser"
    );
}

#[test]
fn clamp_messages_say_what_the_clamp_is() {
    // A strip wider than the wing: the message names the strip and says it holds everything.
    let e = err_text(fem::compute_modes(&FemInput {
        clamp: fem::Clamp::Strip { x_mm: 900.0 },
        ..FemInput::default()
    }));
    assert!(
        e.contains("`clamp.x_mm`") && e.contains("900 mm") && !e.contains("Strip {"),
        "{e}"
    );
    // A root clamp on an outline without a root edge names the clamp, not `clamp.x_mm`.
    let off = vec![[1.0, 0.0], [1.0, -5.0], [20.0, -5.0], [20.0, 0.0]];
    let e = err_text(fem::compute_modes(&FemInput {
        planform_mm: off,
        ..FemInput::default()
    }));
    assert!(e.contains("`clamp`") && !e.contains("clamp.x_mm"), "{e}");
}

#[test]
fn cli_mode_index_errors_name_the_option() {
    for bad in ["-1", "1.5", "4294967296"] {
        let (code, _, err, _) = run(&["sweep", "ic", "--mode", bad, "--n", "3"]);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("mode"), "{err}");
        assert!(!err.contains("4294967295"), "{err}");
    }
}

#[test]
fn fe_runs_beyond_the_work_budget_are_refused_before_assembly() {
    // The issue's cases: a 5 000-point outline (inside the point cap) meshed to 17 129 nodes
    // and took 548 s and 2.5 GB; `--mesh-size-mm 0.3` took 76 s; wasm feModes at 0.3 mm with
    // 64 modes 232 s. Now each is refused after meshing, before anything is assembled.
    let dir = std::env::temp_dir().join(format!("wingbeat-clear-errors-fe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("outline5000.csv");
    let mut csv = String::from("x_mm,y_mm\n");
    for p in resampled_manduca(5000) {
        csv.push_str(&format!("{},{}\n", p[0], p[1]));
    }
    std::fs::write(&path, csv).unwrap();
    let (code, _, err, dt) = run(&["modes", "--planform", path.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("FE work") || err.contains("FE memory"),
        "{err}"
    );
    assert!(
        err.contains("mesh_size_mm") && err.contains("nodes"),
        "{err}"
    );
    assert!(dt < Duration::from_secs(10), "{dt:?}");
    let (code, _, err, dt) = run(&["modes", "--mesh-size-mm", "0.3"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("FE work") || err.contains("over the cap"),
        "{err}"
    );
    assert!(dt < Duration::from_secs(10), "{dt:?}");
    let _ = std::fs::remove_dir_all(&dir);
    // the browser's budget: 0.3 mm and 64 modes under the browser's node cap and work cap
    let t0 = Instant::now();
    let e = err_text(fem::compute_modes_capped(
        &FemInput {
            mesh_size_mm: Some(0.3),
            n_modes: 64,
            max_nodes: Some(fem::BROWSER_MAX_NODES),
            ..FemInput::default()
        },
        fem::EigenOptions::default(),
        fem::BROWSER_FE_MAX_WORK,
    ));
    assert!(e.contains("mesh_size_mm"), "{e}");
    assert!(t0.elapsed() < Duration::from_secs(10));
    // 64 modes at 0.75 mm: over the browser's budget
    let big = FemInput {
        mesh_size_mm: Some(0.75),
        n_modes: 64,
        ..FemInput::default()
    };
    let (outline, mesh, _) = fem::mesh_input(&big).unwrap();
    let clamped = fem::clamp_nodes(&outline, &mesh, big.clamp).unwrap();
    let opt = fem::EigenOptions::default();
    let e = err_text(fem::check_fe_work(
        &mesh,
        &clamped,
        64,
        &opt,
        fem::BROWSER_FE_MAX_WORK,
    ));
    assert!(e.contains("FE work") && e.contains("64 modes"), "{e}");
    // the defaults pass both budgets
    let lab = FemInput {
        mesh_size_mm: Some(1.0),
        n_modes: 2,
        ..FemInput::default()
    };
    let (outline, mesh, _) = fem::mesh_input(&lab).unwrap();
    let clamped = fem::clamp_nodes(&outline, &mesh, lab.clamp).unwrap();
    fem::check_fe_work(&mesh, &clamped, 2, &opt, fem::BROWSER_FE_MAX_WORK).unwrap();
    fem::check_fe_work(&mesh, &clamped, 6, &opt, fem::FE_MAX_WORK).unwrap();
}
