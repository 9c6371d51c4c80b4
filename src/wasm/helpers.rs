//! Plain-Rust helpers of the wasm API: no JS types here, so they build and are tested natively
//! (`cargo test --features web`).

use crate::config::SimConfig;
use crate::error::{Result, WingbeatError};

/// Most output values per run (samples × modes) the web API accepts. Tighter than the core's
/// [`crate::config::MAX_SAMPLE_VALUES`] because a wasm32 instance has at most 4 GiB of memory
/// and running out of it aborts the instance instead of returning an error: with about twelve
/// f64 series per mode alive at once (responses, forces, spectra, typed-array copies) this
/// cap keeps a run near 200 MB.
pub const WEB_MAX_SAMPLE_VALUES: usize = 2_000_000;

/// Most work one run may take in the browser ([`crate::simulate::run_cost`], step
/// equivalents): a fifth of the native [`crate::simulate::MAX_RUN_WORK`], about 1 s natively
/// and 1.5–2 s in wasm, since `analyze` runs on the page's thread. The lab's own range (flap
/// 5–60 Hz, up to 8 FE modes of a wing) stays far below it.
pub const WEB_MAX_RUN_WORK: f64 = 1.0e6;

/// Checks the web API's own resource caps (after the core's `validate`, which checks the rest).
pub fn check_web_caps(cfg: &SimConfig) -> Result<()> {
    let n = cfg.duration_s * cfg.sample_rate_hz + 1.0;
    let values = n * cfg.modes.len() as f64;
    if !values.is_finite() || values > WEB_MAX_SAMPLE_VALUES as f64 {
        return Err(WingbeatError::ResourceCap {
            field: "duration_s × sample_rate_hz × modes".into(),
            requested: format!("{values:.0} values"),
            cap: format!("{WEB_MAX_SAMPLE_VALUES} values in the browser lab"),
            why: "wasm32 memory: running out aborts the page's wasm instance".into(),
        });
    }
    crate::simulate::check_run_cost(cfg, WEB_MAX_RUN_WORK, "run in the browser")?;
    if !cfg.aero.is_vacuum() && !cfg.modes.is_empty() {
        // The air run's price with the quadrature's nominal size (strips × 2 Gauss stations ×
        // chord points; a notched planform adds chord intervals, the core re-checks exactly).
        let points = 2 * cfg.aero.strips * cfg.aero.chord_points;
        let cost = crate::aero::simulate::air_run_cost(cfg, points);
        if cost.is_nan() || cost > WEB_MAX_RUN_WORK {
            return Err(WingbeatError::ResourceCap {
                field: "run in air in the browser (modes² × quadrature points × steps per flap period)".into(),
                requested: format!("{} step equivalents", crate::error::num(cost.round())),
                cap: format!("{} step equivalents", crate::error::num(WEB_MAX_RUN_WORK)),
                why: "computing time in the browser; fewer modes, a shorter run, fewer `aero.strips` / `aero.chord_points`, or a higher flap frequency".into(),
            });
        }
    }
    Ok(())
}

/// Checks that a series given by a caller is non-empty and finite; `field` names it in errors.
pub fn check_series(field: &str, x: &[f64]) -> Result<()> {
    if x.is_empty() {
        return Err(WingbeatError::invalid(
            field,
            "0 samples",
            "at least 1 sample",
        ));
    }
    if x.len() > crate::config::MAX_SAMPLES {
        return Err(WingbeatError::invalid(
            field,
            format!("{} samples", x.len()),
            format!("at most {} samples", crate::config::MAX_SAMPLES),
        ));
    }
    if let Some(i) = x.iter().position(|v| !v.is_finite()) {
        return Err(WingbeatError::invalid(
            format!("{field}[{i}]"),
            x[i],
            "finite numbers",
        ));
    }
    Ok(())
}

/// Largest m ≤ n of the form 2^a·3^b·5^c (0 for n = 0): an FFT length without large prime
/// factors.
pub fn smooth_len(n: usize) -> usize {
    let mut m = n;
    while m > 1 {
        let mut r = m;
        for p in [2, 3, 5] {
            while r % p == 0 {
                r /= p;
            }
        }
        if r == 1 {
            return m;
        }
        m -= 1;
    }
    m
}

/// The core's envelope ([`crate::analysis::beat::envelope`]) over the first [`smooth_len`]
/// samples, the rest holding its last value. For the live lab view, where the exact length
/// (e.g. 20001 = 3·59·113) would make the FFT several times slower.
pub fn fast_envelope(x: &[f64]) -> Vec<f64> {
    let m = smooth_len(x.len());
    let mut e = crate::analysis::beat::envelope(&x[..m]);
    let last = e.last().copied().unwrap_or(0.0);
    e.resize(x.len(), last);
    e
}

/// `None` as NaN, for typed-array columns.
pub fn opt_or_nan(v: Option<f64>) -> f64 {
    v.unwrap_or(f64::NAN)
}

/// An integer argument passed as a JS number (an index, a count): refused, naming `field`,
/// unless it is an integer in `[lo, hi]` — never rounded, wrapped or clamped (1.5, −1, NaN,
/// 2³² and ±Infinity are errors, not 1, 4294967295 or 0).
pub fn check_int(field: &str, v: f64, lo: usize, hi: usize) -> Result<usize> {
    if !(v.is_finite() && v.fract() == 0.0 && v >= lo as f64 && v <= hi as f64) {
        return Err(WingbeatError::invalid(
            field,
            v,
            format!("an integer in [{lo}, {hi}]"),
        ));
    }
    Ok(v as usize)
}

/// The mode count a caller passed as a JS number: an integer in [1, MAX_MODES].
pub fn check_mode_count(field: &str, n_modes: f64) -> Result<usize> {
    let max = crate::model::MAX_MODES;
    if !(n_modes.is_finite() && n_modes.fract() == 0.0 && n_modes >= 1.0 && n_modes <= max as f64) {
        return Err(WingbeatError::invalid(
            field,
            n_modes,
            format!("an integer in [1, {max}]"),
        ));
    }
    Ok(n_modes as usize)
}

/// Checks the flat nodal strain array of `feModes` (`strain_nodes[(k·n_nodes + i)·3 + c]`)
/// against the mode count and returns the node count.
pub fn check_strain_nodes(strain_nodes: &[f64], n_modes: usize) -> Result<usize> {
    let per = 3 * n_modes;
    if strain_nodes.is_empty() || strain_nodes.len() % per != 0 {
        return Err(WingbeatError::invalid(
            "strain_nodes",
            format!("{} values", strain_nodes.len()),
            format!("3 values per node per mode: a non-zero multiple of 3 × {n_modes}"),
        ));
    }
    if let Some(i) = strain_nodes.iter().position(|v| !v.is_finite()) {
        return Err(WingbeatError::invalid(
            format!("strain_nodes[{i}]"),
            strain_nodes[i],
            "finite numbers",
        ));
    }
    Ok(strain_nodes.len() / per)
}

/// Node positions (m) and triangles (node indices) of a mesh.
pub type FlatMesh = (Vec<[f64; 3]>, Vec<[usize; 3]>);

/// The flat mesh arrays of `feModes` (`nodes`: x, y, z per node in m; `triangles`: three node
/// indices each) as the core's node and triangle lists, every index checked against the node
/// count `n_nodes` (which the nodal strains fix).
pub fn mesh_from_flat(nodes: &[f64], triangles: &[u32], n_nodes: usize) -> Result<FlatMesh> {
    if nodes.len() != 3 * n_nodes {
        return Err(WingbeatError::invalid(
            "nodes",
            format!("{} values", nodes.len()),
            format!("x, y, z per node: 3 × {n_nodes} values (the nodes of strain_nodes)"),
        ));
    }
    let big = crate::fem::geometry::MAX_COORD_MM * 1e-3;
    if let Some(i) = nodes
        .iter()
        .position(|v| !(v.is_finite() && v.abs() <= big))
    {
        return Err(WingbeatError::invalid(
            format!("nodes[{i}]"),
            nodes[i],
            format!("finite coordinates within ±{big} m"),
        ));
    }
    if triangles.is_empty() || triangles.len() % 3 != 0 {
        return Err(WingbeatError::invalid(
            "triangles",
            format!("{} indices", triangles.len()),
            "three node indices per triangle, at least one triangle",
        ));
    }
    if let Some(i) = triangles.iter().position(|&t| t as usize >= n_nodes) {
        return Err(WingbeatError::invalid(
            format!("triangles[{i}]"),
            triangles[i],
            format!("a node index in [0, {}]", n_nodes - 1),
        ));
    }
    let p = nodes.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    let t = triangles
        .chunks_exact(3)
        .map(|c| [c[0] as usize, c[1] as usize, c[2] as usize])
        .collect();
    Ok((p, t))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_case_is_within_web_caps() {
        check_web_caps(&SimConfig::paper()).unwrap();
    }

    #[test]
    fn web_cap_names_the_fields() {
        let cfg = SimConfig {
            duration_s: 1000.0,
            ..SimConfig::paper()
        };
        let e = check_web_caps(&cfg).unwrap_err().to_string();
        assert!(e.contains("duration_s × sample_rate_hz × modes"), "{e}");
        assert!(e.contains("2000000"), "{e}");
    }

    #[test]
    fn series_checks_name_the_bad_sample() {
        assert!(check_series("x", &[1.0, 2.0]).is_ok());
        let e = check_series("x", &[1.0, f64::NAN]).unwrap_err().to_string();
        assert!(e.contains("`x[1]`"), "{e}");
        assert!(check_series("x", &[]).is_err());
    }

    #[test]
    fn smooth_lengths() {
        assert_eq!(smooth_len(20001), 20000);
        assert_eq!(smooth_len(16384), 16384);
        assert_eq!(smooth_len(7), 6);
        assert_eq!(smooth_len(1), 1);
        assert_eq!(smooth_len(0), 0);
        // 5-smooth numbers are dense: never more than 10 % short for n ≥ 100.
        for n in 100..5000 {
            assert!(n - smooth_len(n) <= n / 10, "{n}");
        }
    }

    #[test]
    fn fast_envelope_matches_the_core_on_its_prefix() {
        let x: Vec<f64> = (0..1001).map(|i| (i as f64 * 0.3).sin()).collect();
        let e = fast_envelope(&x);
        let core = crate::analysis::beat::envelope(&x[..1000]);
        assert_eq!(e.len(), 1001);
        assert_eq!(&e[..1000], &core[..]);
        assert_eq!(e[1000], core[999]);
        assert!(fast_envelope(&[]).is_empty());
    }

    #[test]
    fn flat_mesh_checks_name_the_array() {
        assert_eq!(check_mode_count("n_modes", 3.0).unwrap(), 3);
        for bad in [0.0, 2.5, f64::NAN, 65.0] {
            let e = check_mode_count("n_modes", bad).unwrap_err().to_string();
            assert!(e.contains("n_modes") && e.contains("[1, 64]"), "{e}");
        }
        assert_eq!(check_strain_nodes(&[0.0; 12], 2).unwrap(), 2);
        assert!(check_strain_nodes(&[0.0; 10], 2).is_err());
        let e = check_strain_nodes(&[0.0, f64::NAN, 0.0], 1)
            .unwrap_err()
            .to_string();
        assert!(e.contains("strain_nodes[1]"), "{e}");
        let nodes = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        let (p, t) = mesh_from_flat(&nodes, &[0, 1, 2], 3).unwrap();
        assert_eq!(p[1], [1.0, 0.0, 0.0]);
        assert_eq!(t, vec![[0, 1, 2]]);
        let e = mesh_from_flat(&nodes, &[0, 1, 3], 3)
            .unwrap_err()
            .to_string();
        assert!(e.contains("triangles[2]") && e.contains("[0, 2]"), "{e}");
        assert!(mesh_from_flat(&nodes, &[0, 1], 3).is_err());
        assert!(mesh_from_flat(&nodes[..6], &[0, 1, 2], 3).is_err());
    }

    #[test]
    fn none_becomes_nan() {
        assert!(opt_or_nan(None).is_nan());
        assert_eq!(opt_or_nan(Some(2.0)), 2.0);
    }
}
