use wingbeat::config::SimConfig;
use wingbeat::solve::ModalOde;
fn main() {
    let cfg = SimConfig::paper();
    for _ in 0..3 {
        wingbeat::simulate::simulate(&cfg).unwrap();
    }
    let t0 = std::time::Instant::now();
    for _ in 0..20 {
        wingbeat::simulate::simulate(&cfg).unwrap();
    }
    println!("simulate {:?}", t0.elapsed() / 20);
    let kin = cfg.kinematics.compile();
    let t0 = std::time::Instant::now();
    for _ in 0..20 {
        wingbeat::simulate::propagate_mode(&kin, &cfg.modes[0], 1e-4, 20001).unwrap();
    }
    println!("propagate {:?}", t0.elapsed() / 20);
    let t0 = std::time::Instant::now();
    for _ in 0..20 {
        wingbeat::simulate::floquet_for(&kin, &cfg.modes[0]);
    }
    println!("floquet {:?}", t0.elapsed() / 20);
    let ode = ModalOde::new(&kin, &cfg.modes[0]);
    let ph: Vec<f64> = (0..400).map(|j| j as f64 * 1e-4).collect();
    let t0 = std::time::Instant::now();
    for _ in 0..20 {
        wingbeat::solve::propagator::period_map(&ode, 0.04, &ph);
    }
    println!("period_map {:?}", t0.elapsed() / 20);
}
