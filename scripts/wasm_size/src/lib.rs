//! f1 of the default wing at `mesh_mm` with backend 0 = skyline, 1 = faer.
use wingbeat::fem::{compute_modes_with, Backend, EigenOptions, FemInput};

/// First natural frequency (Hz) of the default wing, NaN on error.
#[no_mangle]
pub extern "C" fn wing_f1(mesh_mm: f64, backend: u32) -> f64 {
    let opt = EigenOptions {
        backend: if backend == 1 {
            Backend::Faer
        } else {
            Backend::Skyline
        },
        ..EigenOptions::default()
    };
    let input = FemInput {
        mesh_size_mm: Some(mesh_mm),
        ..FemInput::default()
    };
    compute_modes_with(&input, opt)
        .map(|r| r.freq_hz[0])
        .unwrap_or(f64::NAN)
}
