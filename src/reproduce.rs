//! The paper's claims (§3–4) next to what wingbeat computes, each with a verdict.
//!
//! Every verdict is computed from numbers, never asserted. The thresholds used to turn a
//! number into "holds" / "fails" are written next to each claim so a reader can disagree
//! with them. The paper preset is used as printed (Tables 3–6), zero initial conditions.

use crate::analysis::beat::measure;
use crate::analysis::contribution::Contributions;
use crate::analysis::ic_map::{ic_map, IcAttribution, IcMap, IcMapOptions};
use crate::analysis::psd::{welch, Detrend, WelchOptions};
use crate::analysis::strain::peak_abs;
use crate::analysis::sweep::{sweep, SweepOptions, SweepParam};
use crate::config::SimConfig;
use crate::error::Result;
use crate::fem::{compute_modes, Clamp, FemInput, FemModes, ShellMaterial};
use crate::kinematics::Compiled;
use crate::model::{coefficients, stiffness_coefficient, ForceTerm};
use crate::simulate::{simulate, SimResult};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How a claim fared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The computation supports the claim.
    Holds,
    /// Part of the claim holds, part does not (explained in `computed`).
    Partly,
    /// The computation contradicts the claim.
    Fails,
    /// The claim is an input of the model (nothing to compute).
    Input,
}

impl Verdict {
    fn word(self) -> &'static str {
        match self {
            Verdict::Holds => "HOLDS",
            Verdict::Partly => "PARTLY",
            Verdict::Fails => "FAILS",
            Verdict::Input => "INPUT",
        }
    }
}

/// One claim.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Claim {
    /// Short id.
    pub id: String,
    /// Where in the paper.
    pub section: String,
    /// The claim, paraphrased.
    pub paper_says: String,
    /// What wingbeat computes, with numbers and the threshold used.
    pub computed: String,
    /// Verdict.
    pub verdict: Verdict,
}

/// The whole report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// Case description.
    pub case: String,
    /// The claims.
    pub claims: Vec<Claim>,
    /// Counts per verdict.
    pub summary: Summary,
}

/// Counts per verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub struct Summary {
    /// Claims that hold.
    pub holds: usize,
    /// Claims that partly hold.
    pub partly: usize,
    /// Claims that fail.
    pub fails: usize,
    /// Claims that are inputs.
    pub input: usize,
}

impl Report {
    /// A readable report.
    pub fn to_text(&self) -> String {
        let mut s = format!("wingbeat reproduce — {}\n\n", self.case);
        for c in &self.claims {
            s.push_str(&format!(
                "[{}] {} ({})\n  paper:    {}\n  wingbeat: {}\n\n",
                c.verdict.word(),
                c.id,
                c.section,
                c.paper_says,
                c.computed
            ));
        }
        s.push_str(&format!(
            "summary: {} hold, {} partly, {} fail, {} inputs\n",
            self.summary.holds, self.summary.partly, self.summary.fails, self.summary.input
        ));
        s
    }
}

/// Amplitudes of harmonics 0..=nmax of a T-periodic function sampled at `n` points:
/// [mean, A_1, A_2, ...] with f(t) ≈ mean + Σ A_n cos(n ω_d t + φ_n).
pub fn harmonic_amplitudes(f: impl Fn(f64) -> f64, period: f64, nmax: usize) -> Vec<f64> {
    let n = 512;
    let xs: Vec<f64> = (0..n).map(|j| f(j as f64 * period / n as f64)).collect();
    (0..=nmax)
        .map(|h| {
            let (mut c, mut s) = (0.0, 0.0);
            for (j, x) in xs.iter().enumerate() {
                let th = 2.0 * PI * (h * j % n) as f64 / n as f64;
                c += x * th.cos();
                s += x * th.sin();
            }
            let m = (c * c + s * s).sqrt() / n as f64;
            if h == 0 {
                c / n as f64
            } else {
                2.0 * m
            }
        })
        .collect()
}

fn argmax_ac(a: &[f64]) -> (usize, f64) {
    let total: f64 = a.iter().skip(1).map(|v| v * v).sum();
    let (k, v) =
        a.iter().enumerate().skip(1).fold(
            (1, 0.0),
            |b, (k, &v)| if v.abs() > b.1 { (k, v.abs()) } else { b },
        );
    (k, if total > 0.0 { v * v / total } else { 0.0 })
}

fn share(a: &[f64], h: usize) -> f64 {
    let total: f64 = a.iter().skip(1).map(|v| v * v).sum();
    if total > 0.0 {
        a[h] * a[h] / total
    } else {
        0.0
    }
}

fn fmt_c(c: &Contributions) -> String {
    format!(
        "Euler {:.1} %, centrifugal {:.1} %, Coriolis {:.1} %",
        c.euler, c.centrifugal, c.coriolis
    )
}

fn claim(id: &str, section: &str, says: &str, computed: String, verdict: Verdict) -> Claim {
    Claim {
        id: id.into(),
        section: section.into(),
        paper_says: says.into(),
        computed,
        verdict,
    }
}

fn yes(b: bool) -> Verdict {
    if b {
        Verdict::Holds
    } else {
        Verdict::Fails
    }
}

/// Element size of the FE runs in the report, mm (a compromise between time and accuracy:
/// f1 is within about 2 % of the fine-mesh value).
pub const FE_MESH_MM: f64 = 1.5;

/// What several claims share, computed once: the paper case, its kinematics, the FE runs of
/// §3.1, the harmonic content of the mode-1 force terms, and the 2 s and 10 s simulations.
struct Context {
    cfg: SimConfig,
    /// Flap frequency f_d, Hz.
    fd: f64,
    /// Flap period, s.
    period: f64,
    /// Sample rate, Hz.
    fs: f64,
    kin: Compiled,
    /// FE of the default outline: root clamp, the material as printed, a 3 mm basal strip.
    fe: FemModes,
    printed: FemModes,
    strip: FemModes,
    /// Harmonic amplitudes 0..=NH of mode 1's Euler, centrifugal and Coriolis forces and of
    /// the stiffness coefficient.
    he: Vec<f64>,
    hc: Vec<f64>,
    hr: Vec<f64>,
    hs: Vec<f64>,
    /// The paper case over 2 s and over 10 s (where a beat is measured).
    sim: SimResult,
    sim_long: SimResult,
    /// The FE wing (fe-wing preset) over 2 s in a vacuum, air and helium.
    wing_vac: SimResult,
    wing_air: SimResult,
    wing_he: SimResult,
}

/// Harmonics examined in the Fig. 4 claims.
const NH: usize = 8;

impl Context {
    fn new() -> Result<Self> {
        let cfg = SimConfig::paper();
        let fd = cfg.kinematics.flap_freq_hz;
        let period = 1.0 / fd;
        let kin = cfg.kinematics.compile();
        let fe_in = FemInput {
            n_modes: 2,
            mesh_size_mm: Some(FE_MESH_MM),
            ..Default::default()
        };
        let fe = compute_modes(&fe_in)?;
        let printed = compute_modes(&FemInput {
            material: ShellMaterial::paper_as_printed(),
            ..fe_in.clone()
        })?;
        let strip = compute_modes(&FemInput {
            clamp: Clamp::Strip { x_mm: 3.0 },
            ..fe_in
        })?;
        let m1 = &cfg.modes[0];
        let kin_ref = &kin;
        let term =
            |k: usize| move |t: f64| coefficients(m1, &kin_ref.state(t)).force(ForceTerm::ALL[k]);
        let he = harmonic_amplitudes(term(0), period, NH);
        let hc = harmonic_amplitudes(term(1), period, NH);
        let hr = harmonic_amplitudes(term(2), period, NH);
        let hs = harmonic_amplitudes(|t| stiffness_coefficient(&kin.state(t)), period, NH);
        let sim = simulate(&cfg)?;
        let sim_long = simulate(&SimConfig {
            duration_s: 10.0,
            ..cfg.clone()
        })?;
        let wing = SimConfig::fe_wing()?;
        let in_medium = |rho: f64| {
            simulate(&SimConfig {
                aero: crate::aero::AeroConfig::with_density(rho),
                ..wing.clone()
            })
        };
        let wing_vac = simulate(&wing)?;
        let wing_air = in_medium(crate::aero::AIR_DENSITY)?;
        let wing_he = in_medium(crate::aero::HELIUM_DENSITY)?;
        Ok(Context {
            wing_vac,
            wing_air,
            wing_he,
            fs: cfg.sample_rate_hz,
            fd,
            period,
            kin,
            fe,
            printed,
            strip,
            he,
            hc,
            hr,
            hs,
            sim,
            sim_long,
            cfg,
        })
    }
}

/// One claim of the paper, checked against the computation.
type ClaimCheck = fn(&Context) -> Result<Claim>;

/// The claims of the report, in the paper's order.
const CLAIMS: [ClaimCheck; 19] = [
    material_as_printed,
    natural_frequencies,
    force_magnitudes,
    stiffness_coriolis_2wd,
    centrifugal_3wd,
    euler_wd,
    mode1_coriolis_dominant,
    mode1_coriolis_beat,
    mode2_centrifugal_dominant,
    mode2_beat_3wd,
    beat_proportional_to_gamma0,
    fig6_coriolis_vs_gamma0,
    fig7_ic_map,
    fig8_damping,
    fig9_shear_largest,
    fig9_strain_beat,
    air_erases_beat,
    air_suppresses_3wd,
    helium_vs_air,
];

/// Builds the report for the paper's forward-flight case.
pub fn reproduce() -> Result<Report> {
    let ctx = Context::new()?;
    let claims = CLAIMS
        .iter()
        .map(|check| check(&ctx))
        .collect::<Result<Vec<_>>>()?;
    let mut summary = Summary::default();
    for c in &claims {
        match c.verdict {
            Verdict::Holds => summary.holds += 1,
            Verdict::Partly => summary.partly += 1,
            Verdict::Fails => summary.fails += 1,
            Verdict::Input => summary.input += 1,
        }
    }
    Ok(Report {
        case: "paper preset: forward flight α0 = 0.8, β0 = 0.5, γ0 = 0.2 rad, f_d = 25 Hz; modes 62.5 / 86.9 Hz with Table 4 vectors as printed; ζ = 0; q(0) = q̇(0) = 0; 2 s at 10 kHz (10 s where a beat is measured)".into(),
        claims,
        summary,
    })
}

// ---- §3.1: the FE step, with wingbeat's own shell model of the synthetic outline ----

fn material_as_printed(c: &Context) -> Result<Claim> {
    let f1 = c.fe.freq_hz[0];
    Ok(claim(
        "material-as-printed",
        "§3.1, Table 2",
        "A paper wing with t = 81 µm, E = 10 MPa, ρ = 860 kg/m³, ν = 0.3 and 13 % camber has f1 = 62.5 Hz.",
        format!(
            "Shell FE of the synthetic Manduca-like outline ({FE_MESH_MM} mm mesh, root clamp): E = 10 MPa gives f1 = {:.3} Hz. Frequencies scale with √E; f1 = 62.5 Hz needs E ≈ {:.1} GPa — the printed 10 MPa is a unit slip. Threshold: within 10 % of 62.5 Hz.",
            c.printed.freq_hz[0],
            crate::fem::PAPER_FREQUENCIES_E_PA * (62.5 / f1).powi(2) / 1e9
        ),
        yes((c.printed.freq_hz[0] / 62.5 - 1.0).abs() < 0.1),
    ))
}

fn natural_frequencies(c: &Context) -> Result<Claim> {
    let (fe, strip) = (&c.fe, &c.strip);
    let (f1, f2) = (fe.freq_hz[0], fe.freq_hz[1]);
    let (s1, s2) = (strip.freq_hz[0], strip.freq_hz[1]);
    let paper_ratio = crate::presets::PAPER_FREQ_HZ[1] / crate::presets::PAPER_FREQ_HZ[0];
    Ok(claim(
        "natural-frequencies",
        "§3.1, Table 3",
        "The paper wing's first two modes are spanwise bending at 62.5 Hz and spanwise torsion at 86.9 Hz (f2/f1 = 1.39), within 4.5 % of the insect's 60 / 84 Hz.",
        format!(
            "Synthetic outline, 13 % camber, E = {:.2} GPa: root-edge clamp gives {:.1} Hz ({}) and {:.1} Hz ({}), f2/f1 = {:.2}; clamping a 3 mm basal strip gives {:.1} / {:.1} Hz, f2/f1 = {:.2} (paper {:.2}). f2/f1 depends strongly on how the root is held, and the outline is not the paper's CT-traced wing, so the pair is reproduced only in part. The modal-model presets use Table 3 as printed. Thresholds: f2/f1 within 10 % of 1.39 for the root clamp (holds) or only for the strip (partly).",
            crate::fem::PAPER_FREQUENCIES_E_PA / 1e9,
            f1,
            fe.kinds[0],
            f2,
            fe.kinds[1],
            f2 / f1,
            s1,
            s2,
            s2 / s1,
            paper_ratio
        ),
        if ((f2 / f1) / paper_ratio - 1.0).abs() < 0.1 {
            Verdict::Holds
        } else if ((s2 / s1) / paper_ratio - 1.0).abs() < 0.1 {
            Verdict::Partly
        } else {
            Verdict::Fails
        },
    ))
}

// ---- Fig. 4: magnitudes and spectra of the system parameters (mode 1) ----

fn force_magnitudes(c: &Context) -> Result<Claim> {
    let m1 = &c.cfg.modes[0];
    let kin = &c.kin;
    let peak = |k: usize| {
        (0..2000)
            .map(|j| {
                let t = j as f64 * c.period / 2000.0;
                coefficients(m1, &kin.state(t))
                    .force(ForceTerm::ALL[k])
                    .abs()
            })
            .fold(0.0, f64::max)
    };
    let (pe, pc, pr) = (peak(0), peak(1), peak(2));
    Ok(claim(
        "force-magnitudes",
        "§3.3, Fig. 4",
        "For mode 1 the Euler force has the largest magnitude, the Coriolis force the second largest, the centrifugal force the smallest.",
        format!("Peak |F| over a flap: Euler {pe:.4e}, Coriolis {pr:.4e}, centrifugal {pc:.4e} (Table 4 units)."),
        yes(pe > pr && pr > pc),
    ))
}

fn stiffness_coriolis_2wd(c: &Context) -> Result<Claim> {
    let (hs, hr) = (&c.hs, &c.hr);
    let (ks, ss) = argmax_ac(hs);
    let (kr, sr) = argmax_ac(hr);
    Ok(claim(
        "stiffness-coriolis-2wd",
        "§3.3",
        "The stiffness term and the Coriolis force vary nearly sinusoidally at about 2ω_d.",
        format!(
            "Strongest oscillating harmonic: stiffness coefficient S = α̇²cos²β + β̇² {ks}ω_d ({:.1} % of its AC power), Coriolis {kr}ω_d ({:.1} %). Both also have a large mean: S {:.4e} rad²/s², Coriolis {:.4e} (vs 2ω_d amplitude {:.4e}). Threshold: dominant harmonic 2 with > 90 % of AC power.",
            100.0 * ss,
            100.0 * sr,
            hs[0],
            hr[0],
            hr[2]
        ),
        yes(ks == 2 && kr == 2 && ss > 0.9 && sr > 0.9),
    ))
}

fn centrifugal_3wd(c: &Context) -> Result<Claim> {
    let hc = &c.hc;
    let (kc, _) = argmax_ac(hc);
    Ok(claim(
        "centrifugal-3wd",
        "§3.3",
        "The centrifugal force oscillates predominantly at 3ω_d, with a subharmonic at ω_d.",
        format!(
            "Centrifugal harmonic amplitudes (mode 1): ω_d {:.3e}, 2ω_d {:.3e}, 3ω_d {:.3e}, 4ω_d {:.3e}; strongest is {kc}ω_d ({:.1} % of AC power at ω_d, {:.1} % at 3ω_d). Thresholds: holds if 3ω_d carries ≥ 2/3 of the AC power; partly if it is strongest but the ω_d part is comparable.",
            hc[1],
            hc[2],
            hc[3],
            hc[4],
            100.0 * share(hc, 1),
            100.0 * share(hc, 3)
        ),
        if kc == 3 && share(hc, 3) >= 2.0 / 3.0 {
            Verdict::Holds
        } else if kc == 3 || hc[3] > 0.5 * hc[kc] {
            Verdict::Partly
        } else {
            Verdict::Fails
        },
    ))
}

fn euler_wd(c: &Context) -> Result<Claim> {
    let he = &c.he;
    let (ke, se) = argmax_ac(he);
    Ok(claim(
        "euler-wd",
        "§3.3",
        "The Euler force oscillates at ω_d with superharmonics 2ω_d, 3ω_d, …; 3ω_d and above are negligible.",
        format!(
            "Euler harmonic amplitudes: ω_d {:.3e}, 2ω_d {:.3e}, 3ω_d {:.3e}, 4ω_d {:.3e}; strongest {ke}ω_d ({:.1} % of AC power); 3ω_d and above carry {:.2} %. Threshold: ω_d strongest and ≥ 3ω_d below 5 %.",
            he[1],
            he[2],
            he[3],
            he[4],
            100.0 * se,
            100.0 * (3..=NH).map(|h| share(he, h)).sum::<f64>()
        ),
        yes(ke == 1 && (3..=NH).map(|h| share(he, h)).sum::<f64>() < 0.05),
    ))
}

// ---- §3.4: responses ----

fn mode1_coriolis_dominant(c: &Context) -> Result<Claim> {
    let c1 = c.sim.modes[0].contribution_percent;
    Ok(claim(
        "mode1-coriolis-dominant",
        "§3.4, Fig. 5; §4.1",
        "Mode 1's response is dominated by the Coriolis force; the Euler force gives the second largest response; the centrifugal contribution is very minor.",
        format!("Contributions over 2 s: {} (shares need not sum to 100 %: cross terms).", fmt_c(&c1)),
        yes(c1.coriolis > c1.euler && c1.euler > c1.centrifugal && c1.centrifugal < 10.0),
    ))
}

fn mode1_coriolis_beat(c: &Context) -> Result<Claim> {
    let (fd, fs) = (c.fd, c.fs);
    let fl1 = &c.sim.modes[0].floquet;
    let b1 = measure(&c.sim_long.modes[0].q.coriolis, fs, fd, 0.0, 1.0);
    let pred1 = (fl1.effective_freq_hz - 2.0 * fd).abs();
    let meas1 = b1.beat_freq_hz.unwrap_or(f64::NAN);
    Ok(claim(
        "mode1-coriolis-beat",
        "§3.4, §4",
        "The Coriolis response of mode 1 shows a clear beat between the 2ω_d forcing and the effective natural frequency of mode 1.",
        format!(
            "Floquet effective frequency {:.4} Hz (unforced 62.5 Hz, naive averaged-stiffness estimate {:.4} Hz) ⇒ predicted beat {:.4} Hz (period {:.4} s). Measured from the 10 s response envelope: {:.4} Hz, modulation index {:.2}. Threshold: index > 0.2 and measured within 1 % of predicted.",
            fl1.effective_freq_hz,
            fl1.averaged_freq_hz,
            pred1,
            1.0 / pred1,
            meas1,
            b1.modulation_index
        ),
        yes(b1.modulation_index > 0.2 && ((meas1 - pred1) / pred1).abs() < 0.01),
    ))
}

fn mode2_centrifugal_dominant(c: &Context) -> Result<Claim> {
    let c2 = c.sim.modes[1].contribution_percent;
    let (dom2, _) = c2.dominant();
    Ok(claim(
        "mode2-centrifugal-dominant",
        "§3.4; §5",
        "Mode 2's response is dominated by the centrifugal force; Euler and Coriolis contributions are comparatively low.",
        format!("Contributions: {}; the largest is {dom2}.", fmt_c(&c2)),
        if dom2 == "centrifugal" {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
    ))
}

fn mode2_beat_3wd(c: &Context) -> Result<Claim> {
    let (fd, fs) = (c.fd, c.fs);
    let fl2 = &c.sim.modes[1].floquet;
    let b2c = measure(&c.sim_long.modes[1].q.centrifugal, fs, fd, 0.0, 1.0);
    let b2t = measure(&c.sim_long.modes[1].q.total, fs, fd, 0.0, 1.0);
    let pred2 = (fl2.effective_freq_hz - 3.0 * fd).abs();
    let close = |m: Option<f64>| m.is_some_and(|m| ((m - pred2) / pred2).abs() < 0.02);
    Ok(claim(
        "mode2-beat-3wd",
        "§3.4",
        "Mode 2 shows a beat between 3ω_d and its effective natural frequency.",
        format!(
            "Effective frequency {:.4} Hz ⇒ predicted |f_eff − 3f_d| = {:.4} Hz. Measured envelope frequency: centrifugal response {} (index {:.2}); total response {} (index {:.2}). Threshold: within 2 % and index > 0.1.",
            fl2.effective_freq_hz,
            pred2,
            b2c.beat_freq_hz.map_or("none".into(), |f| format!("{f:.4} Hz")),
            b2c.modulation_index,
            b2t.beat_freq_hz.map_or("none".into(), |f| format!("{f:.4} Hz")),
            b2t.modulation_index
        ),
        if close(b2c.beat_freq_hz) && b2c.modulation_index > 0.1 && close(b2t.beat_freq_hz) && b2t.modulation_index > 0.1 {
            Verdict::Holds
        } else if (close(b2c.beat_freq_hz) && b2c.modulation_index > 0.1) || (close(b2t.beat_freq_hz) && b2t.modulation_index > 0.1) {
            Verdict::Partly
        } else {
            Verdict::Fails
        },
    ))
}

// ---- §4: beat amplitude ∝ γ0 ----

fn beat_proportional_to_gamma0(c: &Context) -> Result<Claim> {
    let half = crate::analysis::sweep::apply(&c.cfg, SweepParam::Gamma0, 0.1)?;
    let sim_half = simulate(&half)?;
    let ratio = peak_abs(&c.sim.modes[0].q.coriolis) / peak_abs(&sim_half.modes[0].q.coriolis);
    Ok(claim(
        "beat-proportional-to-gamma0",
        "§4",
        "The beat amplitude is proportional to the yaw amplitude γ0.",
        format!(
            "Peak Coriolis response of mode 1 at γ0 = 0.2 over γ0 = 0.1: {ratio:.12} (exactly 2 expected: the Coriolis force is linear in γ̇). Threshold: |ratio − 2| < 1e-9."
        ),
        yes((ratio - 2.0).abs() < 1e-9),
    ))
}

// ---- §4.1, Fig. 6 ----

fn fig6_coriolis_vs_gamma0(c: &Context) -> Result<Claim> {
    let c1 = c.sim.modes[0].contribution_percent;
    let sw = sweep(
        &c.cfg,
        &SweepOptions {
            param: SweepParam::Gamma0,
            from: 0.0,
            to: 0.3,
            points: 31,
        },
        |_, _| {},
    )?;
    let at = |g: f64| {
        sw.points
            .iter()
            .min_by(|a, b| (a.value - g).abs().total_cmp(&(b.value - g).abs()))
            .map(|p| p.modes[0].contribution_percent)
            .unwrap_or(c1)
    };
    let (c01, c02, c03) = (at(0.1), at(0.2), at(0.3));
    let spread = [c01.coriolis, c02.coriolis, c03.coriolis]
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    Ok(claim(
        "fig6-coriolis-vs-gamma0",
        "§4.1, Fig. 6",
        "At γ0 = 0.2 the Coriolis contribution is substantially larger than the other two; across the forward-flight range even large changes of γ0 change it only slightly.",
        format!(
            "Mode-1 Coriolis share: γ0 = 0.1: {:.1} %, 0.2: {:.1} %, 0.3: {:.1} % (Euler at 0.2: {:.1} %, centrifugal {:.1} %). Spread over 0.1–0.3: {:.1} points. Thresholds: at 0.2 Coriolis > 2 × each other term; spread < 15 points.",
            c01.coriolis,
            c02.coriolis,
            c03.coriolis,
            c02.euler,
            c02.centrifugal,
            spread.1 - spread.0
        ),
        match (c02.coriolis > 2.0 * c02.euler && c02.coriolis > 2.0 * c02.centrifugal, spread.1 - spread.0 < 15.0) {
            (true, true) => Verdict::Holds,
            (false, false) => Verdict::Fails,
            _ => Verdict::Partly,
        },
    ))
}

// ---- §4.2, Fig. 7 ----

fn fig7_ic_map(c: &Context) -> Result<Claim> {
    let icf = ic_map(&c.cfg, &IcMapOptions::default())?;
    let icc = ic_map(
        &c.cfg,
        &IcMapOptions {
            attribution: IcAttribution::Carried,
            ..Default::default()
        },
    )?;
    Ok(claim(
        "fig7-ic-map",
        "§4.2, Fig. 7",
        "Over initial conditions bounded by the zero-start response's extremes, the Coriolis contribution exceeds 60 % for most initial conditions and stays at about 33 % or more even at the extremes.",
        format!(
            "101 × 101 map, mode 1. Coriolis partial from rest (default): > 60 % on {:.1} % of the map, range {:.1}–{:.1} %. Coriolis partial carrying the initial conditions: > 60 % on {:.1} %, range {:.1}–{:.1} %. Thresholds: > 60 % on at least half the map and minimum ≥ 30 %.",
            100.0 * icf.fraction_above_60,
            icf.min_percent,
            icf.max_percent,
            100.0 * icc.fraction_above_60,
            icc.min_percent,
            icc.max_percent
        ),
        {
            let ok = |m: &IcMap| m.fraction_above_60 >= 0.5 && m.min_percent >= 30.0;
            match (ok(&icf), ok(&icc)) {
                (true, true) => Verdict::Holds,
                (false, false) => Verdict::Fails,
                _ => Verdict::Partly,
            }
        },
    ))
}

// ---- §4.3, Fig. 8 ----

fn fig8_damping(c: &Context) -> Result<Claim> {
    let (fd, fs) = (c.fd, c.fs);
    let damped = SimConfig {
        duration_s: 10.0,
        ..crate::analysis::sweep::apply(&c.cfg, SweepParam::Zeta, 0.01)?
    };
    let sd = simulate(&damped)?;
    let early = measure(&sd.modes[0].q.coriolis, fs, fd, 0.0, 0.1);
    let late = measure(&sd.modes[0].q.coriolis, fs, fd, 0.8, 1.0);
    let tail = &sd.modes[0].q.coriolis[(0.8 * sd.t.len() as f64) as usize..];
    let spec = welch(
        tail,
        fs,
        &WelchOptions {
            detrend: Detrend::Mean,
            ..Default::default()
        },
        Some(fd),
    )?;
    let top = spec.peaks.first().map_or(f64::NAN, |p| p.freq_hz);
    Ok(claim(
        "fig8-damping",
        "§4.3, Fig. 8",
        "With 1 % damping the beat in mode 1's Coriolis response fades; after several seconds only the forced vibration at 2ω_d remains.",
        format!(
            "ζ = 0.01, 10 s: envelope modulation index {:.3} in the first second, {:.4} in the last two (free vibration decays as e^(−ζωt), time constant {:.3} s). Strongest oscillation in the last two seconds: {top:.2} Hz (2ω_d = {:.1} Hz). Thresholds: late index < 0.2 × early and peak within 1 Hz of 2f_d.",
            early.modulation_index,
            late.modulation_index,
            1.0 / (0.01 * c.cfg.modes[0].omega()),
            2.0 * fd
        ),
        yes(late.modulation_index < 0.2 * early.modulation_index && (top - 2.0 * fd).abs() < 1.0),
    ))
}

// ---- §4.4, Fig. 9 ----

fn fig9_shear_largest(c: &Context) -> Result<Claim> {
    let st = c.sim.strain.as_ref().expect("paper preset carries strains");
    let (ex, ey, gxy) = (
        peak_abs(&st.eps_x),
        peak_abs(&st.eps_y),
        peak_abs(&st.gamma_xy),
    );
    Ok(claim(
        "fig9-shear-largest",
        "§4.4, Fig. 9; §5",
        "The shear strain γ_xy at P has by far the largest magnitude; ε_x and ε_y are comparatively negligible.",
        format!(
            "Peak |strain| at P over 2 s (Table 6 × Table 4 units): ε_x {ex:.4e}, ε_y {ey:.4e}, γ_xy {gxy:.4e}. Mode 1 dominates q, and its Table 6 ε_y (−1577) exceeds its γ_xy (691)."
        ),
        yes(gxy > ex && gxy > ey),
    ))
}

fn fig9_strain_beat(c: &Context) -> Result<Claim> {
    let (fd, fs) = (c.fd, c.fs);
    let sl = c
        .sim_long
        .strain
        .as_ref()
        .expect("paper preset carries strains");
    let mods = [
        measure(&sl.eps_x, fs, fd, 0.0, 1.0).modulation_index,
        measure(&sl.eps_y, fs, fd, 0.0, 1.0).modulation_index,
        measure(&sl.gamma_xy, fs, fd, 0.0, 1.0).modulation_index,
    ];
    Ok(claim(
        "fig9-strain-beat",
        "§4.4",
        "All three strain components show the beat.",
        format!("Envelope modulation index over 10 s: ε_x {:.2}, ε_y {:.2}, γ_xy {:.2}. Threshold: > 0.1 each.", mods[0], mods[1], mods[2]),
        yes(mods.iter().all(|m| *m > 0.1)),
    ))
}

// ---- Beyond the paper: the wing in air (src/aero; docs/model.md, "The wing in air") ----

/// Amplitude of the harmonic at `f` Hz of `x` sampled at `fs` Hz over its last `periods` flap
/// periods of `fd` Hz (a whole number of periods, so harmonics of f_d fall on bins).
fn amplitude_at(x: &[f64], fs: f64, fd: f64, f: f64, periods: f64) -> f64 {
    let n = ((periods / fd) * fs).round() as usize;
    let tail = &x[x.len().saturating_sub(n)..];
    let (mut c, mut s) = (0.0, 0.0);
    for (j, v) in tail.iter().enumerate() {
        let th = 2.0 * PI * f * j as f64 / fs;
        c += v * th.cos();
        s += v * th.sin();
    }
    2.0 * (c * c + s * s).sqrt() / tail.len().max(1) as f64
}

fn air_erases_beat(c: &Context) -> Result<Claim> {
    let a = c.wing_air.modes[0].air.as_ref();
    let h = c.wing_he.modes[0].air.as_ref();
    let tau_a = a.and_then(|m| m.decay_time_s).unwrap_or(f64::INFINITY);
    let tau_h = h.and_then(|m| m.decay_time_s).unwrap_or(f64::INFINITY);
    let beat = c.wing_vac.modes[0]
        .floquet
        .beat_period_s
        .unwrap_or(f64::NAN);
    Ok(claim(
        "air-erases-beat",
        "beyond the paper: air (Eberle et al. 2015)",
        "Not the paper's (it neglects air): the Coriolis beat is the free vibration drifting against the forced response, so it lives only as long as the free vibration; the damping measured on moth wings (C = 63 s⁻¹·M, ζ ≈ 0.08 at 62.5 Hz) would make it decay with a time constant of about one wingbeat (32 ms).",
        format!(
            "FE wing (4 modes) in quasi-steady air: mode 1's Floquet decay time constant is {:.1} ms in air (1.2 kg/m³), {:.0} ms in helium (0.18 kg/m³), none in a vacuum (beat period {:.3} s there). Threshold: the beat does not survive one second in air (decay time < 1 s).",
            tau_a * 1e3,
            tau_h * 1e3,
            beat
        ),
        yes(tau_a < 1.0),
    ))
}

/// The basal strain component with the largest 1 × f_d amplitude in a vacuum, and its name.
fn basal_component(r: &SimResult) -> Option<(&'static str, usize)> {
    let s = r.strain.as_ref()?;
    let comps = [&s.eps_x, &s.eps_y, &s.gamma_xy];
    let fs = 1.0 / (r.t[1] - r.t[0]);
    let fd = r.flap_freq_hz;
    let (i, _) = comps
        .iter()
        .enumerate()
        .map(|(i, x)| (i, amplitude_at(x, fs, fd, fd, 40.0)))
        .fold((0, -1.0), |b, v| if v.1 > b.1 { v } else { b });
    Some((["ε_x", "ε_y", "γ_xy"][i], i))
}

/// [`basal_component`] of the vacuum run with its sample rate and flap frequency (Hz).
fn basal(c: &Context) -> Result<(&'static str, usize, f64, f64)> {
    let (name, i) =
        basal_component(&c.wing_vac).ok_or_else(|| crate::WingbeatError::NonFinite {
            what: "air claims".into(),
            detail: "the fe-wing preset carries no strain point".into(),
        })?;
    let fs = 1.0 / (c.wing_vac.t[1] - c.wing_vac.t[0]);
    Ok((name, i, fs, c.wing_vac.flap_freq_hz))
}

fn strain_component(r: &SimResult, i: usize) -> &[f64] {
    let s = r
        .strain
        .as_ref()
        .expect("the fe-wing preset has strain at P");
    [&s.eps_x, &s.eps_y, &s.gamma_xy][i]
}

fn air_suppresses_3wd(c: &Context) -> Result<Claim> {
    let (name, i, fs, fd) = basal(c)?;
    let amp = |r: &SimResult, h: f64| amplitude_at(strain_component(r, i), fs, fd, h * fd, 40.0);
    let (v1, v3) = (amp(&c.wing_vac, 1.0), amp(&c.wing_vac, 3.0));
    let (a1, a3) = (amp(&c.wing_air, 1.0), amp(&c.wing_air, 3.0));
    let drop3 = a3 < 0.5 * v3;
    let grow1 = a1 > v1;
    Ok(claim(
        "air-3wd",
        "beyond the paper: air (J. Vib. Acoust. 142(2):021012, 2020)",
        "Not the paper's: a flexible wing flapped at about a third of its natural frequency shows a large 3ω basal-strain response in vacuum, strongly attenuated in air, while the 1ω response grows.",
        format!(
            "FE wing, basal {name} at P over the last 40 flap periods of 2 s: 1ω {:.3e} → {:.3e} (×{:.2}), 3ω {:.3e} → {:.3e} (×{:.2}) from vacuum to air; 3ω/1ω {:.3} → {:.3}. Thresholds: 3ω falls below half and 1ω grows (partly: one of the two).",
            v1, a1, a1 / v1, v3, a3, a3 / v3, v3 / v1, a3 / a1
        ),
        match (drop3, grow1) {
            (true, true) => Verdict::Holds,
            (false, false) => Verdict::Fails,
            _ => Verdict::Partly,
        },
    ))
}

fn helium_vs_air(c: &Context) -> Result<Claim> {
    let (name, i, fs, fd) = basal(c)?;
    let rms = |r: &SimResult| {
        let x = strain_component(r, i);
        let n = ((40.0 / fd) * fs).round() as usize;
        let tail = &x[x.len().saturating_sub(n)..];
        (tail.iter().map(|v| v * v).sum::<f64>() / tail.len().max(1) as f64).sqrt()
    };
    let (ra, rh, rv) = (rms(&c.wing_air), rms(&c.wing_he), rms(&c.wing_vac));
    let rel = (rh - ra).abs() / ra;
    let share = |r: &SimResult| r.modes[0].contribution_percent.aerodynamic.unwrap_or(0.0);
    Ok(claim(
        "helium-vs-air",
        "beyond the paper: air (Combes & Daniel 2003)",
        "Not the paper's: Manduca wings flapped in air and in helium (15 % of air's density) bend in nearly the same pattern; an FE model put the difference down to fluid damping rather than aerodynamic forces.",
        format!(
            "FE wing, RMS basal {name} at P over the last 40 flap periods: air {ra:.3e}, helium {rh:.3e} (differ by {:.1} %), vacuum {rv:.3e}; mode 1's aerodynamic share {:.1} % in air, {:.1} % in helium. Threshold (\"only slightly\"): helium within 10 % of air.",
            100.0 * rel,
            share(&c.wing_air),
            share(&c.wing_he)
        ),
        yes(rel < 0.10),
    ))
}
