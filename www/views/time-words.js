// @ts-check
// The words of the responses panel (views/time.js): the beat explained for the selected mode
// (its period from the Floquet numbers, what damping does to it, the formula) and the list of
// force-term shares with bars. Each writes into a box it is given.
import { el, rich } from '../dom.js';
import { fmt } from '../format.js';
import { modulation, shares, smooth } from '../beat.js';
import { color } from '../plot.js';

/**
 * Writes the beat's explanation for mode k into `box` (and its numbers into box.dataset).
 * @param {HTMLElement} box
 * @param {import('../pkg/wingbeat.js').Analysis} a
 * @param {number} k
 * @param {import('../lab.js').LabState} s
 * @param {import('../beat.js').BeatInfo} b
 * @param {import('../beat.js').BeatFate} f
 */
export function writeBeat(box, a, k, s, b, f) {
  const m = a.sim.modes[k];
  const t = a.sim.t;
  box.replaceChildren();
  box.dataset.beatPeriod = b.period == null ? '' : String(b.period);
  box.dataset.beatFate = f.kind;
  box.dataset.beatTau = f.tau == null ? '' : String(f.tau);
  box.dataset.beatGoneAt = f.goneAt == null ? '' : String(f.goneAt);
  const p = (/** @type {string} */ markup) => el('p', {}, rich(markup));
  const sigma = m.floquet.growth_rate_per_s;
  // In a fluid the air damps the free vibration too (the core's cycle-averaged ζ_a).
  const cause = m.air
    ? `the air’s damping (cycle-averaged ζ_a = ${fmt(m.air.aero_damping_ratio, 3)}) plus ζ = ${fmt(s.zeta, 3)}, in ${fmt(Number(s.air_density), 3)} kg/m³`
    : `−ζω_{${k + 1}} with ζ = ${fmt(s.zeta, 3)}`;
  const tauText =
    f.tau == null ? '' : `τ = −1/σ = ${fmt(f.tau, 3)} s (σ = ${fmt(sigma, 3)} 1/s, the Floquet growth rate; ${cause})`;
  if (f.kind === 'gone' && f.goneAt != null) {
    box.append(
      el(
        'p',
        { class: 'wl-beat-lead' },
        el('strong', { class: 'wl-beat-value' }, rich(`No beat to see in mode ${k + 1}`)),
        rich(
          `: damping makes the wing’s free vibration die out as exp(−t/τ), ${tauText}. Its swing is down to ${fmt(100 * f.floor, 2)} % after ${fmt(f.goneAt, 3)} s, before one beat period (T_{beat} = ${fmt(b.period, 4)} s) has passed, so the response settles straight into the forced vibration at ${b.n}·f_d = ${fmt(b.fHarm, 6)} Hz.`,
        ),
      ),
    );
    return;
  }
  if (b.period == null) {
    box.append(p(`**No beat in mode ${k + 1}.**`.replace(/\*\*/g, '')));
    box.append(
      p(
        b.stable
          ? `The effective frequency f_{eff} = ${fmt(b.fEff, 6)} Hz sits on a flap harmonic, so there is nothing to beat against.`
          : `The largest Floquet multiplier |λ| = ${fmt(b.maxModulus, 6)} exceeds 1: the response grows every flap (a parametric instability) instead of beating.`,
      ),
    );
    return;
  }
  const strong = el(
    'strong',
    { class: 'wl-beat-value', 'data-beat': String(b.period) },
    rich(`T_{beat} = ${fmt(b.period, 4)} s`),
  );
  const lead =
    f.kind === 'decays'
      ? el(
          'p',
          { class: 'wl-beat-lead' },
          'The beat decays: the responses — clearest in the Coriolis envelope (red) — swell and fade every ',
          strong,
          rich(
            ` only at first (shaded), because damping makes the wing’s free vibration die out as exp(−t/τ), ${tauText}.`,
          ),
        )
      : el(
          'p',
          { class: 'wl-beat-lead' },
          'The beat: the responses — clearest in the Coriolis envelope (red) — swell and fade once every ',
          strong,
          ' (shaded; dotted lines repeat it).',
        );
  const formula = p(
    `The wing rings at its effective natural frequency f_{eff} = ${fmt(b.fEff, 6)} Hz while the flapping drives it at ${b.n}·f_d = ${b.n} × ${fmt(b.fd, 4)} Hz = ${fmt(b.fHarm, 6)} Hz; the two drift in and out of step: ` +
      `T_{beat} = 1/|f_{eff} − n·f_d| = 1/|${fmt(b.fEff, 6)} − ${fmt(b.fHarm, 6)}| Hz = ${fmt(b.period, 4)} s.`,
  );
  formula.className = 'wl-beat-formula';
  box.append(lead);
  if (f.kind === 'decays' && f.goneAt != null) {
    const hi = t[t.length - 1];
    const env = smooth(a.envelope[k] || new Float64Array(t.length), a.sim.sample_rate_hz / a.sim.flap_freq_hz);
    const early = modulation(t, env, t[0] + 1 / b.fd, Math.min(f.goneAt, t[0] + 1 / b.fd + 2 * b.period));
    const late = modulation(t, env, f.goneAt, hi - 1 / b.fd);
    const t4 = Math.max(f.goneAt, t[0] + 0.8 * (hi - t[0]));
    const tail = modulation(t, env, t4, hi - 1 / b.fd);
    const gone = p(
      `After ${fmt(f.goneAt, 3)} s (${fmt(Math.log(1 / f.floor), 2)} τ) the free vibration is below ${fmt(100 * f.floor, 2)} % of its start and the beat is gone: only the forced vibration at ${b.n}·f_d remains and the envelope is flat (grey in both plots). Measured swing of the envelope, (max − min)/(max + min): ${fmt(early, 3)} over the first two beats, ${fmt(late, 2)} from ${fmt(f.goneAt, 3)} s on, ${fmt(tail, 2)} from ${fmt(t4, 3)} s to the end of the ${fmt(hi, 3)} s run.`,
    );
    gone.className = 'wl-beat-gone';
    gone.dataset.early = String(early);
    gone.dataset.late = String(late);
    gone.dataset.tail = String(tail);
    box.append(gone);
  } else if (f.kind === 'steady' && f.tau != null) {
    box.append(
      p(
        `Damping fades it slowly: the free vibration decays as exp(−t/τ), ${tauText}, longer than this ${fmt(t[t.length - 1], 3)} s run would need to lose it.`,
      ),
    );
  }
  box.append(formula);
  if (s.gamma0 === 0)
    box.append(
      p(
        'With γ_0 = 0 there is no Coriolis force (the Coriolis response is zero); the other responses still beat with this period.',
      ),
    );
  if (!b.stable) box.append(p(`Unstable: |λ| = ${fmt(b.maxModulus, 6)} > 1, the response grows.`));
}

/**
 * Writes where mode k's response comes from (share of Σq² per force term) into `box`.
 * @param {HTMLElement} box
 * @param {import('../pkg/wingbeat.js').Analysis} a
 * @param {number} k
 */
export function writeShares(box, a, k) {
  box.replaceChildren(el('h3', { text: `Where mode ${k + 1}’s response comes from (share of Σq², paper §4.1)` }));
  const list = el('ul', { class: 'wl-share-list' });
  let sum = 0;
  for (const sh of shares(a, k)) {
    sum += sh.value;
    const w = Math.max(0, Math.min(100, sh.value));
    list.append(
      el(
        'li',
        { 'data-share': sh.key },
        el('span', { class: 'wl-share-name', text: sh.label }),
        el(
          'span',
          { class: 'wl-share-bar', 'aria-hidden': 'true' },
          el('span', { style: `width:${w}%;background:${color(sh.key)}` }),
        ),
        el('span', { class: 'wl-share-val', text: `${fmt(sh.value, 3)} %` }),
      ),
    );
  }
  box.append(
    list,
    el('p', {
      class: 'wl-note',
      text: `Sum ${fmt(sum, 3)} %: the partial responses are not orthogonal, so shares need not add up to 100 %.`,
    }),
  );
}
