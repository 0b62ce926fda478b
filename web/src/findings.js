// The report's first page: the findings an ergonomist reads first (review/src/findings.rs computes
// them): time at each RULA action level, the worst moments with a still of the posture (front and
// right side views of the fused skeleton, coloured by score), and per body region what was found and
// the warnings' advice. Printed as page 1; on screen behind the "Findings" button.
import { esc } from './panels.js';
import { strainCss } from './colormap.js';
import { nearestFrame } from './data.js';

const LEVEL_TEXT = ['', 'acceptable', 'investigate; change may be needed', 'investigate and change soon', 'investigate and change now'];
/** A verdict's word, badge class and meaning (`dwell`: the warnings' dwell, seconds). */
function verdict(v, dwell) {
  const d = `${fmt(dwell, 0)} s`;
  const all = {
    change: ['Change', 'danger', `held at or past its warning score for ${d} or more, or the operator was warned`],
    brief: ['Brief', 'warn', `reached its warning score only for moments under ${d}`],
    acceptable: ['Acceptable', 'ok', 'never at its warning score'],
    not_scored: ['Not scored', '', 'never seen well enough to score'],
  };
  return Object.hasOwn(all, v) ? all[v] : [String(v), '', ''];
}

const fmt = (v, d = 1) => (v == null || !Number.isFinite(+v) ? '–' : (+v).toFixed(d));
const cap = (s) => String(s || '').replace(/^./, (c) => c.toUpperCase());

/** Seconds as "4.5 s", "41 s", "3 min 12 s" or "2 h 05 min" (rounded first, so 119.6 s is "2 min 00 s"). */
export function duration(s) {
  if (!Number.isFinite(s)) return '–';
  if (s < 9.95) return `${s.toFixed(1)} s`;
  const whole = Math.round(s);
  if (whole < 60) return `${whole} s`;
  if (whole < 3600) return `${Math.floor(whole / 60)} min ${String(whole % 60).padStart(2, '0')} s`;
  const minutes = Math.round(s / 60);
  return `${Math.floor(minutes / 60)} h ${String(minutes % 60).padStart(2, '0')} min`;
}

// BlazePose indices (review JSON `landmarks` order).
const L_SHOULDER = 11, R_SHOULDER = 12, L_HIP = 23, R_HIP = 24;

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => {
  const n = Math.hypot(...a);
  return n > 1e-9 ? a.map((v) => v / n) : null;
};

/**
 * The body's axes at one frame: up (the world's), across (left to right shoulder, else hip, made
 * horizontal) and forward (up × across: where the chest faces). `null` without shoulders or hips.
 */
function bodyAxes(p, up) {
  const at = (k) => [p[3 * k], p[3 * k + 1], p[3 * k + 2]];
  const ok = (k) => Number.isFinite(p[3 * k]);
  let a = null;
  if (ok(L_SHOULDER) && ok(R_SHOULDER)) a = sub(at(R_SHOULDER), at(L_SHOULDER));
  else if (ok(L_HIP) && ok(R_HIP)) a = sub(at(R_HIP), at(L_HIP));
  if (!a) return null;
  const across = unit(sub(a, up.map((u) => u * dot(a, up))));
  if (!across) return null;
  return { up, across, forward: cross(up, across) };
}

/**
 * A still of frame f: the skeleton seen from the front (the operator facing the reader) and from
 * their right side (facing the picture's right), on one scale, bones coloured by score. Empty when the frame has no
 * body axes.
 */
export function stillSvg(s, f) {
  const p = s.positions[f];
  const st = s.strain[f];
  const axes = p && bodyAxes(p, s.up);
  if (!axes) return '<div class="still-missing muted small">no skeleton at this moment</div>';
  const pts = [];
  for (let k = 0; k < s.nl; k++) {
    if (!Number.isFinite(p[3 * k])) { pts.push(null); continue; }
    const v = [p[3 * k], p[3 * k + 1], p[3 * k + 2]];
    // front: the operator's right on the reader's left
    pts.push({ front: -dot(v, axes.across), side: dot(v, axes.forward), h: dot(v, axes.up) });
  }
  const valid = pts.filter(Boolean);
  const hs = valid.map((q) => q.h);
  const fr = valid.map((q) => q.front);
  const sd = valid.map((q) => q.side);
  const span = (xs) => [Math.min(...xs), Math.max(...xs)];
  const [h0, h1] = span(hs);
  const [f0, f1] = span(fr);
  const [s0, s1] = span(sd);
  const H = 118, PAD = 7;
  const scale = (H - 2 * PAD) / Math.max(0.5, h1 - h0);
  const viewW = (lo, hi) => Math.max(60, (hi - lo) * scale + 2 * PAD);
  const view = (key, lo, hi, title) => {
    const w = viewW(lo, hi);
    const mid = (lo + hi) / 2;
    const x = (q) => (w / 2 + (q[key] - mid) * scale).toFixed(1);
    const y = (q) => (PAD + (h1 - q.h) * scale).toFixed(1);
    const lines = s.bones
      .map(([a, b]) => {
        const qa = pts[a], qb = pts[b];
        if (!qa || !qb) return '';
        const strain = Math.max(Number.isFinite(st[a]) ? st[a] : -1, Number.isFinite(st[b]) ? st[b] : -1);
        return `<line x1="${x(qa)}" y1="${y(qa)}" x2="${x(qb)}" y2="${y(qb)}" stroke="${strainCss(strain < 0 ? null : strain)}" stroke-width="3" stroke-linecap="round"/>`;
      })
      .join('');
    const floor = `<line x1="4" y1="${(H - PAD / 2).toFixed(1)}" x2="${(w - 4).toFixed(1)}" y2="${(H - PAD / 2).toFixed(1)}" class="floor"/>`;
    return `<figure class="view"><svg viewBox="0 0 ${w.toFixed(0)} ${H}" width="${w.toFixed(0)}" height="${H}" role="img" aria-label="${esc(title)}">${floor}${lines}</svg><figcaption>${esc(title)}</figcaption></figure>`;
  };
  return `<div class="still">${view('front', f0, f1, 'front')}${view('side', s0, s1, 'right side')}</div>`;
}

function levelsTable(fi) {
  const scored = fi.action_level_secs.reduce((a, b) => a + b, 0);
  const total = scored + fi.unscored_secs;
  const rows = fi.action_level_secs
    .map((secs, i) => {
      const share = scored > 0 ? (secs / scored) * 100 : 0;
      return `<tr class="al-row al${i + 1}"><th>${i + 1}</th><td>${esc(LEVEL_TEXT[i + 1])}</td><td class="num">${duration(secs)}</td><td class="num">${fmt(share, 1)} %</td><td><div class="sharebar"><div class="bar"><span class="seg lvl${i + 1}" style="width:${share.toFixed(2)}%"></span></div></div></td></tr>`;
    })
    .join('');
  const unscored = total > 0 ? `<tr class="muted"><th>–</th><td>not scored (operator not seen well enough)</td><td class="num">${duration(fi.unscored_secs)}</td><td class="num">${fmt((fi.unscored_secs / total) * 100, 1)} % of all</td><td></td></tr>` : '';
  return `<table class="regions f-levels"><thead><tr><th>Level</th><th>RULA's meaning</th><th class="num">time</th><th class="num">share of scored time</th><th></th></tr></thead><tbody>${rows}${unscored}</tbody></table>`;
}

function momentsHtml(s, fi) {
  if (!fi.worst_moments.length) return '<p class="muted">No moment reached action level 2: nothing to show here.</p>';
  return `<div class="moments">${fi.worst_moments
    .map((m, i) => {
      const f = s.n ? nearestFrame(s.t, m.t) : -1;
      const regions = m.regions.length
        ? m.regions.map((r) => `${esc(cap(`${r.side ? `${r.side} ` : ''}${r.region}`))} ${r.score}`).join(' · ')
        : 'no region at its warning score';
      const g = (v) => (v == null ? '–' : v);
      return `<div class="moment"><div class="m-head"><b>${i + 1}. at ${fmt(m.t, 1)} s</b> <span class="badge al${m.action_level}">action level ${m.action_level}</span></div><div class="small">grand score L ${g(m.grand_left)} · R ${g(m.grand_right)}</div>${f >= 0 ? stillSvg(s, f) : ''}<div class="small">${regions}</div></div>`;
    })
    .join('')}</div>`;
}

function regionsHtml(fi) {
  const rows = fi.regions
    .map((r) => {
      const [word, cls, why] = verdict(r.verdict, fi.dwell_s);
      const name = cap(`${r.side ? `${r.side} ` : ''}${r.region}`);
      let found;
      if (r.verdict === 'not_scored') found = '<span class="muted">not scored</span>';
      else {
        found = `highest ${r.highest} of ${r.top}`;
        if (r.share_at_warn > 0) {
          found += `; at ${r.warn_at} or more for ${fmt(r.share_at_warn * 100, 1)} % of the time (${duration(r.secs_at_warn)}, ${r.episodes_at_warn} stretch${r.episodes_at_warn === 1 ? '' : 'es'}, longest ${duration(r.longest_at_warn_secs)})`;
        } else found += `; never at ${r.warn_at} or more`;
        if (r.warnings_raised) found += `; ${r.warnings_raised} warning${r.warnings_raised === 1 ? '' : 's'} raised`;
      }
      const advice = r.advice_text ? esc(cap(r.advice_text)) : '<span class="muted">–</span>';
      return `<tr data-region="${esc(r.region)}" data-side="${esc(r.side)}"><th>${esc(name)}</th><td><span class="badge ${cls}" title="${esc(why)}">${esc(word)}</span></td><td class="small">${found}</td><td>${advice}</td></tr>`;
    })
    .join('');
  return `<table class="regions f-regions"><thead><tr><th>Region</th><th>Verdict</th><th>What was found</th><th>Recommendation</th></tr></thead><tbody>${rows}</tbody></table>`;
}

/** The findings of the first session (a comparison: of A, said in the title). */
export function renderFindings(el, sessions) {
  const s = sessions[0];
  const fi = s.findings;
  el.classList.toggle('none', !fi);
  if (!fi) {
    el.innerHTML = '<h1>Findings</h1><p class="muted">This review data holds no findings (written by an older ergocell).</p>';
    return;
  }
  // The warning scores used, in words: "3; legs 2" (the regions' own, from the data).
  const by = new Map();
  for (const r of fi.regions) if (r.warn_at != null && !by.has(r.region)) by.set(r.region, r.warn_at);
  const counts = new Map();
  for (const v of by.values()) counts.set(v, (counts.get(v) || 0) + 1);
  const common = [...counts].sort((a, b) => b[1] - a[1])[0]?.[0];
  const warnWords = [common, ...[...by].filter(([, v]) => v !== common).map(([k, v]) => `${k} ${v}`)].filter((x) => x != null).join('; ');
  const dwell = `${fmt(fi.dwell_s, 0)} s`;
  const f = s.facts;
  const dur = s.n > 1 ? duration(s.t[s.n - 1] - s.t[0]) : '–';
  const who = [
    f.height_m != null ? `operator ${f.height_m.toFixed(2)} m` : null,
    f.height_class ? `height class ${esc(f.height_class)}` : null,
    f.approved_by.length ? `robot trajectory approved by ${f.approved_by.map(esc).join(', ')}` : null,
  ].filter(Boolean).join(' · ');
  const cmp = sessions.length > 1 ? ' <span class="muted">(session A of the comparison)</span>' : '';
  el.innerHTML = `<h1>Ergonomic findings${cmp}</h1>
<p class="f-sub"><b>${esc(s.label)}</b> · ${dur} recorded${who ? ` · ${who}` : ''}</p>
<h2>Time at each RULA action level <span class="hint">the worse side, every frame (McAtamney &amp; Corlett 1993)</span></h2>
${levelsTable(fi)}
<h2>The worst moments <span class="hint">highest action level first, one per stretch, at least 10 s apart; the skeleton as fused, from the front and the operator's right, coloured by each region's RULA score (1 deep blue … 7 deep red)</span></h2>
${momentsHtml(s, fi)}
<h2>Per body region <span class="hint">"warning score": the region score at which ergocell's shipped settings warn the operator (${esc(warnWords)}). Change: held there ${dwell} or more, or warned. Brief: only for moments under ${dwell}. The recommendation is the advice the warnings give for the region's worst posture.</span></h2>
${regionsHtml(fi)}`;
}
