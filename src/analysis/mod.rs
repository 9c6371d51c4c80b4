//! Analyses built on the solver: spectra, force contributions, parameter sweeps, the
//! initial-condition map, beat measurement, strain (paper §3.3–§4.4) and sensing body rotation
//! through strain.

pub mod angles;
pub mod beat;
pub mod classify;
pub mod contribution;
pub mod ic_map;
pub mod neural;
pub mod psd;
pub mod resonance;
pub mod rotation_classify;
pub mod sensing;
pub mod spectra;
pub mod sspoc;
pub mod strain;
pub mod sweep;

/// Checks that every series has `n` samples (as `like`, e.g. `qs[0]`) and only finite values;
/// `name(k)` names series `k` in the error. Shared by the strain map and the sensing analysis.
pub(crate) fn check_series<'a>(
    series: impl IntoIterator<Item = &'a [f64]>,
    n: usize,
    like: &str,
    name: impl Fn(usize) -> String,
) -> crate::Result<()> {
    for (k, q) in series.into_iter().enumerate() {
        if q.len() != n {
            return Err(crate::WingbeatError::invalid(
                name(k),
                format!("{} samples", q.len()),
                format!("{n} samples, as {like}"),
            ));
        }
        if let Some(i) = q.iter().position(|v| !v.is_finite()) {
            return Err(crate::WingbeatError::invalid(
                format!("{}[{i}]", name(k)),
                q[i],
                "finite numbers",
            ));
        }
    }
    Ok(())
}
