// Session facts, state changes, warnings list, per-region summary and joint-angle histograms.
import uPlot from 'uplot';
import { scoreCss, levelCss, RULA_TOP } from './colormap.js';
import { legColor, outcomeClass, eventClass, eventText } from './timeline.js';

export const SESSION_COLORS = ['#4ea1ff', '#ffa94d'];
const AXIS = '#8b9bb0';
const GRID = 'rgba(139,155,176,0.12)';

export function esc(s) {
  return String(s ?? '').replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

const fmtDeg = (v) => String(+(+v).toFixed(1));
const fmt = (v, d = 1) => (v == null || !Number.isFinite(+v) ? '–' : (+v).toFixed(d));
const titleCase = (s) => String(s || '').replace(/^./, (c) => c.toUpperCase());

export function fmtBytes(b) {
  if (b == null) return '–';
  if (b < 1024) return `${b} B`;
  if (b < 1024 * 1024) return `${(b / 1024).toFixed(1)} KiB`;
  return `${(b / 1024 / 1024).toFixed(1)} MiB`;
}

function heightText(f) {
  if (f.height_m == null) return '<span class="muted">not measured</span>';
  const u = f.height_uncertainty_m != null ? ` ± ${(f.height_uncertainty_m * 100).toFixed(1)} cm` : '';
  return `${f.height_m.toFixed(3)} m${u}`;
}

const BASIS = {
  interval: 'its stature interval lies inside the class',
  expected_rula: 'across a boundary: the lowest expected RULA',
  most_probable: 'across a boundary: the most probable class',
};

function classText(f) {
  if (!f.height_class) return '<span class="muted">undecided</span>';
  const badge = `<span class="badge">${esc(f.height_class)}</span>`;
  if (f.class_probability == null) return badge;
  const basis = BASIS[f.decision_basis] ?? f.decision_basis ?? '';
  const cost = f.expected_rula_cost != null ? `, expected RULA cost ${f.expected_rula_cost >= 0 ? '+' : ''}${f.expected_rula_cost.toFixed(2)}` : '';
  const c = f.expected_rula_cost;
  const costNote = `<br><span class="muted small cost-note">Probability: the chance that the operator's stature lies in this class (measured height and its uncertainty).${c == null
    ? ''
    : ` Expected RULA cost: the handover's expected RULA grand score (points, 1–7) with this class's trajectory minus with the operator's own class's, over the stature's uncertainty (the twin's curves). ${
        Math.abs(c) < 0.05 ? 'Near 0: no difference in practice.' : c < 0 ? 'Negative: this class is expected to suit the operator better.' : 'Positive: expected that much worse, the price of an uncertain class.'
      }`}</span>`;
  return `${badge} <span class="small">probability ${f.class_probability.toFixed(2)}${cost}</span><br><span class="muted small">${esc(basis)}</span>${costNote}`;
}

function hashText(h) {
  if (!h) return '<span class="muted">none locked</span>';
  return `<code title="${esc(h)}">${esc(String(h).slice(0, 12))}…</code>`;
}

function approvalText(f) {
  if (!f.approved_by.length) return '<span class="badge warn">not approved</span>';
  return f.approved_by.map((a) => `<span class="badge ok">${esc(a)}</span>`).join(' ');
}

function sourceText(s) {
  const src = s.source;
  const parts = [fmtBytes(src.bytes), src.messages != null ? `${src.messages} messages` : null, s.overview ? `${s.overview.recorded} frames (${s.n} on this page)` : `${s.n} frames`];
  const dur = s.n > 1 ? ` · ${(s.t[s.n - 1] - s.t[0]).toFixed(1)} s` : '';
  const complete = src.complete ? '<span class="badge ok">complete</span>' : '<span class="badge danger">incomplete</span>';
  return `${parts.filter(Boolean).join(' · ')}${dur} ${complete}`;
}

/** Facts for one session (a definition list) or two (a table with A and B columns). */
export function renderFacts(el, sessions) {
  const rows = [
    ['Recording', (s) => `<span class="file" title="${esc(s.source.file ?? s.label)}">${esc(s.source.file ?? s.label)}</span><br><span class="muted small">${sourceText(s)}</span>`],
    ['Operator height', (s) => heightText(s.facts)],
    ['Height class', (s) => classText(s.facts)],
    ['Locked trajectory', (s) => hashText(s.facts.trajectory_sha256)],
    ['Approved by', (s) => approvalText(s.facts)],
    ['Parts taken', (s) => (s.hasPartsTaken ? String(s.partsTaken.length) : '<span class="muted">not recorded</span>')],
  ];
  if (sessions.length === 1) {
    const s = sessions[0];
    el.innerHTML = `<h2>Session facts</h2><dl class="facts">${rows.map(([k, f]) => `<dt>${k}</dt><dd>${f(s)}</dd>`).join('')}</dl>`;
  } else {
    el.innerHTML = `<h2>Session facts</h2><table class="facts-table"><thead><tr><th></th>${sessions
      .map((s, i) => `<th><span class="sess-dot" style="background:${SESSION_COLORS[i]}"></span>${'AB'[i]}</th>`)
      .join('')}</tr></thead><tbody>${rows.map(([k, f]) => `<tr><th>${k}</th>${sessions.map((s) => `<td>${f(s)}</td>`).join('')}</tr>`).join('')}</tbody></table>`;
  }
}

export function renderStates(el, sessions, onSeek) {
  const blocks = sessions.map((s, si) => {
    const items = s.facts.states
      .map((st) => {
        const t = Number(st.t);
        return `<li><button class="linkish" data-s="${si}" data-t="${Number.isFinite(t) ? t : ''}"><span class="t">${fmt(t, 2)} s</span><span class="state state-${esc(st.state)}">${esc(String(st.state ?? '').replace(/_/g, ' '))}</span></button>${st.reason ? `<span class="reason">${esc(st.reason)}</span>` : ''}</li>`;
      })
      .join('');
    const head = sessions.length > 1 ? `<h3><span class="sess-dot" style="background:${SESSION_COLORS[si]}"></span>${'AB'[si]} · ${esc(s.label)}</h3>` : '';
    return `${head}<ol class="events">${items || '<li class="muted">no state changes recorded</li>'}</ol>`;
  });
  el.innerHTML = `<h2>State changes</h2><div class="scroll">${blocks.join('')}</div>`;
  wireSeek(el, onSeek);
}

// Controller events listed in the robot card beside the legs: what is not already a leg's start or end.
const LISTED_EVENTS = new Set(['rejected', 'failed', 'no_response', 'cancel_requested', 'monitor', 'driver']);

/** A leg's outcome as a badge. */
function outcomeBadge(l) {
  if (!l.end_known || l.outcome === 'sent') return '<span class="badge" title="nothing reported its end: drawn to its planned end">sent · end planned</span>';
  return `<span class="badge ${outcomeClass(l.outcome)}">${esc(String(l.outcome || 'ended').replace(/_/g, ' '))}</span>`;
}

/** Per session: the robot's legs (start, direction, duration, outcome), holds, parts taken and the controller's notable events; a click seeks. */
export function renderRobot(el, sessions, onSeek) {
  const blocks = sessions.map((s, si) => {
    const items = [
      ...s.robotLegs.map((l) => ({
        t: l.t_start,
        html: `<span class="leg-name"><i class="leg-chip" style="background:${legColor(l)}"></i>${esc(l.leg || 'leg')}</span></button><span class="dur" title="${l.planned_s != null ? `planned ${l.planned_s.toFixed(2)} s` : ''}">${(l.t_end - l.t_start).toFixed(2)} s</span>${outcomeBadge(l)}${
          l.feedback_count != null ? `<span class="reason">${l.feedback_count} feedback message${l.feedback_count === 1 ? '' : 's'}${l.max_error != null ? ` · largest joint error ${l.max_error.toFixed(4)} rad` : ''}</span>` : ''
        }${l.text ? `<span class="reason">${esc(l.text)}</span>` : ''}`,
      })),
      ...s.robotHolds.map((t) => ({ t, html: '<span class="kind kind-raised">hold</span></button>' })),
      ...s.partsTaken.map((p) => ({ t: p.t, html: `<span class="kind kind-cleared">part ${esc(p.part ?? '')} taken</span></button>${p.hand ? `<span class="muted small">${esc(p.hand)} hand</span>` : ''}` })),
      ...s.robotEvents
        .filter((e) => LISTED_EVENTS.has(e.kind))
        .map((e) => {
          const c = eventClass(e);
          const kind = c === 'danger' ? 'raised' : c === 'ok' ? 'cleared' : 'changed';
          return { t: e.t, html: `<span class="kind kind-${kind}">${esc(eventText(e.kind))}${e.status ? ` · ${esc(e.status.replace(/_/g, ' '))}` : ''}</span></button>${e.text ? `<span class="reason">${esc(e.text)}</span>` : ''}` };
        }),
    ].sort((a, b) => a.t - b.t);
    const list = items.map((it) => `<li><button class="linkish" data-s="${si}" data-t="${it.t}"><span class="t">${fmt(it.t, 2)} s</span>${it.html}</li>`).join('');
    const n = (k, one, many) => `${k} ${k === 1 ? one : many}`;
    const sum = s.robotLegs.length || s.robotHolds.length || s.robotEvents.length
      ? `<div class="robot-sum">${[n(s.robotLegs.length, 'leg', 'legs'), s.hasPartsTaken ? n(s.partsTaken.length, 'part taken', 'parts taken') : null, n(s.robotHolds.length, 'hold', 'holds'), s.robotEvents.length ? n(s.robotEvents.length, 'controller event', 'controller events') : null].filter(Boolean).join(' · ')}</div>`
      : '';
    const head = sessions.length > 1 ? `<h3><span class="sess-dot" style="background:${SESSION_COLORS[si]}"></span>${'AB'[si]} · ${esc(s.label)}</h3>` : '';
    return `${head}${sum}<ol class="events">${list || '<li class="muted">no robot commands recorded</li>'}</ol>`;
  });
  const total = sessions.reduce((a, s) => a + s.robotLegs.length, 0);
  el.innerHTML = `<h2>Robot <span class="count" title="legs">${total}</span><span class="hint">legs sent, holds, parts taken; click to jump</span></h2><div class="scroll">${blocks.join('')}</div>`;
  wireSeek(el, onSeek);
}

/** How sure a warning's band was: its probability in words, "near the limit" below 90 %. */
function sureText(w) {
  const p = typeof w.band_probability === 'number' && Number.isFinite(w.band_probability) ? w.band_probability : null;
  if (p === null) return ' <span class="sure muted">· how sure: not known</span>';
  return ` <span class="sure${w.near_limit ? ' near' : ''}">· ${Math.round(p * 100)} % sure${w.near_limit ? ', near the limit' : ''}</span>`;
}

export function renderWarnings(el, sessions, onSeek) {
  const blocks = sessions.map((s, si) => {
    const items = s.warnings
      .map(
        (w) =>
          `<li><button class="linkish" data-s="${si}" data-t="${w.t}"><span class="t">${fmt(w.t, 2)} s</span><span class="kind kind-${esc(w.kind)}">${esc(w.kind)}</span></button><span class="reason">${esc(w.message || `${w.side} ${w.region}`)}${sureText(w)}</span></li>`,
      )
      .join('');
    const head = sessions.length > 1 ? `<h3><span class="sess-dot" style="background:${SESSION_COLORS[si]}"></span>${'AB'[si]} · ${esc(s.label)}</h3>` : '';
    return `${head}<ol class="events">${items || '<li class="muted">no posture warnings</li>'}</ol>`;
  });
  const total = sessions.reduce((a, s) => a + s.warnings.length, 0);
  el.innerHTML = `<h2>Posture warnings <span class="count">${total}</span></h2><div class="scroll">${blocks.join('')}</div>`;
  wireSeek(el, onSeek);
}

function wireSeek(el, onSeek) {
  el.querySelectorAll('button[data-t]').forEach((b) => {
    b.addEventListener('click', () => {
      const t = parseFloat(b.dataset.t);
      if (Number.isFinite(t)) onSeek(Number(b.dataset.s), t);
    });
  });
}

function regionKey(r) {
  return `${r.name}|${r.side || ''}`;
}

/**
 * A row's colour for score k: RULA's scores on the page's one scale (the 3D view's: 1 deep blue …
 * 7 deep red, whatever the region), the action level and REBA each on their own. Data written before
 * rows carried their `scale` is told apart by name.
 */
function rowColour(r, max) {
  const scale = r.scale ?? (r.name === 'action level' ? 'action_level' : r.name === 'REBA score' || max > RULA_TOP ? 'reba' : 'rula');
  return scale === 'rula' ? (k) => scoreCss(k) : (k) => levelCss(k, max);
}

function shareBar(r, tag) {
  if (!r) return '<div class="sharebar empty-bar"><span class="muted small">not scored</span></div>';
  const max = Math.max(1, Number(r.max_score) || (r.time_share || []).length || 1);
  const colour = rowColour(r, max);
  const share = Array.isArray(r.time_share) ? r.time_share : [];
  if (!share.some((v) => Number(v) > 0)) return `<div class="sharebar">${tag ? `<span class="tag">${tag}</span>` : ''}<div class="bar"></div><span class="muted small">no scored frames</span></div>`;
  const segs = share
    .map((v, i) => {
      const pct = Math.max(0, Number(v) || 0) * 100;
      if (pct <= 0) return '';
      const label = pct >= 7 ? `${i + 1}` : '';
      return `<span class="seg" style="width:${pct.toFixed(2)}%;background:${colour(i + 1)}" title="score ${i + 1}: ${pct.toFixed(1)} % of scored time">${label}</span>`;
    })
    .join('');
  return `<div class="sharebar">${tag ? `<span class="tag">${tag}</span>` : ''}<div class="bar">${segs}</div></div>`;
}

function meanChip(r) {
  if (!r || r.mean == null) return '<span class="muted">–</span>';
  const max = Math.max(1, Number(r.max_score) || 1);
  return `<span class="chip" style="background:${rowColour(r, max)(Math.min(max, Math.max(1, r.mean)))}"></span>${fmt(r.mean, 2)}`;
}

// Exposure over time: for each score level reached (2 up), how many separate stretches and the
// longest one ("≥3 4× 0.6 s"); a gap in the recording or an unscored frame ends a stretch.
function exposureCell(r) {
  const e = (r && Array.isArray(r.exposure) ? r.exposure : []).filter((x) => x.episodes > 0);
  if (!e.length) return '<span class="muted">–</span>';
  return e
    .map((x) => `<span class="expo" title="score ≥ ${x.at_least}: ${x.episodes} episode(s), longest ${fmt(x.longest_secs, 1)} s, ${fmt(x.total_secs, 1)} s in all">≥${x.at_least} ${x.episodes}× ${fmt(x.longest_secs, 1)} s</span>`)
    .join(' · ');
}

export function renderRegions(el, sessions) {
  const keys = [];
  const maps = sessions.map((s) => {
    const m = new Map();
    for (const r of s.regions) {
      const k = regionKey(r);
      if (!keys.includes(k)) keys.push(k);
      m.set(k, r);
    }
    return m;
  });
  if (!keys.length) {
    el.innerHTML = '<h2>Body regions</h2><div class="empty">No RULA scores in this recording.</div>';
    return;
  }
  const cmp = sessions.length > 1;
  // The highest score the row reached (its last score with scored time), and the top of its scale.
  const peak = (r) => {
    const xs = (r && r.time_share) || [];
    for (let i = xs.length - 1; i >= 0; i--) if (Number(xs[i]) > 0) return i + 1;
    return '–';
  };
  const peakTitle = 'the highest score reached / the top of the row\'s scale';
  const head = cmp
    ? `<tr><th>Region</th><th class="num">mean A</th><th class="num">mean B</th><th class="num">Δ B−A</th><th class="num" title="${peakTitle}">highest A, B / top</th><th>Share of scored time per score (A above B)</th></tr>`
    : `<tr><th>Region</th><th class="num">mean</th><th class="num" title="${peakTitle}">highest / top</th><th>Share of scored time per score</th><th title="per score level reached: separate stretches at or above it × the longest stretch">Exposure: episodes × longest</th></tr>`;
  const body = keys
    .map((k) => {
      const rs = maps.map((m) => m.get(k));
      const r0 = rs.find(Boolean);
      const name = `${r0.side ? `${titleCase(r0.side)} ` : ''}${r0.name}`;
      const max = r0.max_score ?? '–';
      if (!cmp) return `<tr><th>${esc(titleCase(name))}</th><td class="num">${meanChip(rs[0])}</td><td class="num">${esc(peak(rs[0]))} / ${esc(max)}</td><td>${shareBar(rs[0])}</td><td class="small">${exposureCell(rs[0])}</td></tr>`;
      const [a, b] = rs;
      let delta = '<span class="muted">–</span>';
      if (a && b && a.mean != null && b.mean != null) {
        const d = b.mean - a.mean;
        delta = `<span class="${d < -0.05 ? 'better' : d > 0.05 ? 'worse' : 'muted'}">${d > 0 ? '+' : ''}${d.toFixed(2)}</span>`;
      }
      return `<tr><th>${esc(titleCase(name))}</th><td class="num">${meanChip(a)}</td><td class="num">${meanChip(b)}</td><td class="num">${delta}</td><td class="num">${esc(peak(a))}, ${esc(peak(b))} / ${esc(max)}</td><td>${shareBar(a, 'A')}${shareBar(b, 'B')}</td></tr>`;
    })
    .join('');
  el.innerHTML = `<h2>Body regions <span class="hint">RULA score per region, grand score per side and the worse side's action level; REBA score per side below when recorded; bar segments coloured by score, as in the 3D view: 1 deep blue … 7 deep red, the same colour for the same score in every row; "top" is the highest score the row's scale has</span></h2><table class="regions"><thead>${head}</thead><tbody>${body}</tbody></table>`;
}

/** A bar of shares over levels `first..`, coloured like a score out of `n` levels. */
function levelBar(shares, first, what) {
  const xs = Array.isArray(shares) ? shares.map((v) => Math.max(0, Number(v) || 0)) : [];
  if (!xs.some((v) => v > 0)) return '<span class="muted small">–</span>';
  const segs = xs
    .map((v, i) => {
      const pct = v * 100;
      if (pct <= 0) return '';
      const level = i + first;
      return `<span class="seg" style="width:${pct.toFixed(2)}%;background:${levelCss(i + 1, xs.length)}" title="${what} ${level}: ${pct.toFixed(1)} %">${pct >= 9 ? level : ''}</span>`;
    })
    .join('');
  return `<div class="sharebar"><div class="bar">${segs}</div></div>`;
}

/** Why a static hold is not acceptable, in words. */
function holdText(h) {
  if (h.not_acceptable_secs > 4 || h.limit_secs == null) {
    return `${fmt(h.duration_secs, 1)} s, ${fmt(h.not_acceptable_secs, 1)} s of it in a zone not acceptable at any duration (up to ${fmt(h.peak_deg, 0)}°)`;
  }
  return `${fmt(h.duration_secs, 1)} s, longer than the ${fmt(h.limit_secs, 0)} s allowed at its largest angle (up to ${fmt(h.peak_deg, 0)}°)`;
}

/** What the posture cost column holds, in words. */
const COST_TITLE = "the worse side's RULA grand score plus how far its angles lie into their bands, time-weighted over the frames whose angles were all observed";

/** A summary's time-weighted mean posture cost (`PostureCostTime`), or a dash when never known. */
function meanCost(c) {
  return c && c.secs > 0 ? fmt(c.point_secs / c.secs, 3) : '–';
}

/**
 * Exposure by task segment (walking, floor pick, handover, in place) and ISO 11226's static
 * postures, from the session summary (one session; a comparison shows the first).
 */
export function renderSegments(el, sessions) {
  const s = sessions[0];
  const summary = s.summary || {};
  const phases = Array.isArray(summary.phases) ? summary.phases : [];
  const statics = Array.isArray(summary.static_postures) ? summary.static_postures : [];
  const hasReba = Array.isArray(summary.reba_score) && summary.reba_score.length > 0;
  const cmp = sessions.length > 1 ? ` <span class="hint">session A (${esc(s.label)})</span>` : '';
  let html = `<h2>Task segments${cmp} <span class="hint">from the skeleton (walking, floor pick) and the robot (handover: a part on its way or waiting); action level of the worse side per segment</span></h2>`;
  if (!phases.length) {
    html += '<div class="empty">No task segments: the recording has no skeletons with hips.</div>';
  } else {
    const rows = phases
      .map((p) => {
        const e3 = (p.action_level_exposure || []).find((x) => x.at_least === 3);
        const stretch = e3 && e3.episodes > 0 ? `${e3.episodes}× · longest ${fmt(e3.longest_secs, 1)} s` : '<span class="muted">–</span>';
        return `<tr data-phase="${esc(p.phase)}"><th>${esc(titleCase(p.phase))}</th><td class="num">${fmt(p.duration_secs, 1)} s</td><td class="num">${fmt(p.time_share * 100, 1)} %</td><td class="num">${esc(p.episodes)}</td><td>${levelBar(p.action_level_share, 1, 'action level')}</td><td class="small">${stretch}</td>${hasReba ? `<td>${levelBar(p.reba_action_level_share, 0, 'REBA action level')}</td>` : ''}<td class="num">${p.peak_grand_score ?? '–'}</td><td class="num posture-cost">${meanCost(p.posture_cost)}</td></tr>`;
      })
      .join('');
    html += `<table class="regions segments"><thead><tr><th>Segment</th><th class="num">time</th><th class="num">share</th><th class="num">episodes</th><th>RULA action level 1–4</th><th>at level ≥ 3</th>${hasReba ? '<th>REBA action level 0–4</th>' : ''}<th class="num">peak grand</th><th class="num" title="${COST_TITLE}">posture cost</th></tr></thead><tbody>${rows}</tbody></table>`;
    html += `<div class="hint session-cost">Posture cost over the session: <span class="num">${meanCost(summary.posture_cost)}</span> (${COST_TITLE})</div>`;
  }
  html += `<h2 class="sub">Static postures <span class="hint">ISO 11226: held &gt; 4 s outside the acceptable zone · trunk 20°–60° for at most 4 min at 20° down to 1 min at 60°; beyond 60° or extended, and the neck outside 0°–25°, not acceptable · upper arm (from vertical) beyond 60° not acceptable; its 20°–60° holding-time curve has no readable source, so those holds are counted for you to judge · ergocell's: extension counts beyond 5°, a return to the zone shorter than 1 s does not end a hold</span></h2>`;
  if (!statics.length) {
    html += '<div class="empty">No trunk or neck angles in this recording.</div>';
  } else {
    const rows = statics
      .map((p) => {
        const worst = (p.holds || []).filter((h) => h.exceeded).sort((a, b) => b.duration_secs - a.duration_secs)[0];
        const w = worst ? holdText(worst) : '<span class="muted">–</span>';
        const bad = p.exceeded > 0 ? `<span class="badge danger">${esc(p.exceeded)}</span>` : '<span class="badge ok">0</span>';
        const unknown = p.limit_unknown > 0 ? `<span class="badge warn" title="held 20°–60°: ISO 11226 limits this by a holding time no readable source gives — judge them">${esc(p.limit_unknown)}</span>` : '<span class="muted">0</span>';
        return `<tr data-part="${esc(p.part)}"><th>${esc(titleCase(String(p.part).replace(/_/g, ' ')))}</th><td class="num">${esc(p.static_holds)}</td><td class="num">${bad}</td><td class="num">${unknown}</td><td class="num">${fmt(p.longest_secs, 1)} s</td><td class="small">${w}</td></tr>`;
      })
      .join('');
    html += `<table class="regions statics"><thead><tr><th>Body part</th><th class="num">static holds</th><th class="num">not acceptable</th><th class="num">no known limit</th><th class="num">longest</th><th>worst not acceptable</th></tr></thead><tbody>${rows}</tbody></table>`;
  }
  el.innerHTML = html;
}

function sameEdges(a, b) {
  return a.length === b.length && a.every((v, i) => Math.abs(v - b[i]) < 1e-9);
}

/** The bin width when the edges are evenly spaced, else null. */
function uniformStep(e) {
  const w = e[1] - e[0];
  if (!(w > 0)) return null;
  return e.every((v, i) => i === 0 || Math.abs(v - e[i - 1] - w) < 1e-6 * w) ? w : null;
}

/**
 * Two histograms on one set of bins: equal edges as they are; evenly spaced edges of the same width
 * on a common grid (the union of both ranges, counts shifted); anything else: null.
 */
function commonBins(a, b) {
  const ea = a.bin_edges.map(Number);
  const eb = b.bin_edges.map(Number);
  if (sameEdges(ea, eb)) return { edges: ea, counts: [a.counts, b.counts] };
  const w = uniformStep(ea);
  if (w === null || uniformStep(eb) === null || Math.abs(uniformStep(eb) - w) > 1e-6 * w) return null;
  const off = (eb[0] - ea[0]) / w;
  if (Math.abs(off - Math.round(off)) > 1e-6) return null;
  const lo = Math.min(ea[0], eb[0]);
  const nb = Math.round((Math.max(ea[ea.length - 1], eb[eb.length - 1]) - lo) / w);
  const edges = Array.from({ length: nb + 1 }, (_, i) => lo + i * w);
  const place = (e, c) => {
    const out = new Array(nb).fill(0);
    const k0 = Math.round((e[0] - lo) / w);
    c.forEach((v, i) => (out[k0 + i] = Number(v) || 0));
    return out;
  };
  return { edges, counts: [place(ea, a.counts), place(eb, b.counts)] };
}

// RULA score edges: a faint orange-red dotted line each (distinct from the mean and p95 lines).
const EDGE_COLOR = 'rgba(255,128,80,0.85)';
/** Edges within this many degrees of the data's range widen the plot so they show. */
const EDGE_REACH_DEG = 30;

/** The x range: the bins, widened to the score edges within EDGE_REACH_DEG of them (plus a margin). */
function plotRange(edges, scoreEdges) {
  let lo = edges[0], hi = edges[edges.length - 1];
  const near = scoreEdges.filter((e) => e >= lo - EDGE_REACH_DEG && e <= hi + EDGE_REACH_DEG);
  const pad = 5;
  for (const e of near) {
    if (e - pad < lo) lo = e - pad;
    if (e + pad > hi) hi = e + pad;
  }
  return [lo, hi];
}

function histogramPlot(container, edges, hists, scoreEdges = []) {
  // hists: [{counts, mean, p95, color}], all on `edges`; bars show % of that session's samples.
  let [x0, x1] = plotRange(edges, scoreEdges);
  // Widened for score edges: empty bins of the same width out to the new range, so that the bars
  // keep their width (uPlot sizes bars by the spacing of the x values).
  let k0 = 0;
  const step = uniformStep(edges);
  if (step !== null && (x0 < edges[0] || x1 > edges[edges.length - 1])) {
    k0 = Math.ceil((edges[0] - x0) / step - 1e-9);
    const k1 = Math.ceil((x1 - edges[edges.length - 1]) / step - 1e-9);
    const lo = edges[0] - k0 * step;
    edges = Array.from({ length: edges.length + k0 + k1 }, (_, i) => lo + i * step);
    [x0, x1] = [edges[0], edges[edges.length - 1]];
  }
  const centres = edges.slice(0, -1).map((e, i) => (e + edges[i + 1]) / 2);
  const series = [{ label: 'angle', value: (u, v) => (v == null ? '–' : `${v.toFixed(0)}°`) }];
  const data = [centres];
  const overlay = hists.length > 1;
  const shown = scoreEdges.filter((e) => e >= x0 && e <= x1);
  if (shown.length) container.title = `RULA score changes at ${shown.map((e) => `${fmtDeg(e)}°`).join(', ')} (dotted lines)`;
  hists.forEach((h, i) => {
    const total = h.counts.reduce((a, c) => a + (Number(c) || 0), 0) || 1;
    data.push(centres.map((_, j) => (j < k0 || j - k0 >= h.counts.length ? null : ((Number(h.counts[j - k0]) || 0) / total) * 100)));
    series.push({
      label: overlay ? 'AB'[i] : '% of samples',
      stroke: h.color,
      fill: `${h.color}${overlay ? 'bb' : '99'}`,
      width: 1,
      // Two sessions: paired bars, A left of the bin centre and B right of it.
      paths: uPlot.paths.bars({ size: [overlay ? 0.45 : 0.86, Infinity], align: overlay ? (i === 0 ? -1 : 1) : 0 }),
      points: { show: false },
      value: (u, v) => (v == null ? '–' : `${v.toFixed(1)} %`),
    });
  });
  const width = Math.max(180, container.clientWidth);
  const u = new uPlot(
    {
      width,
      height: 150,
      padding: [shown.length ? 14 : 8, 16, 0, 0],
      legend: { show: false },
      cursor: { drag: { x: false, y: false, setScale: false }, points: { show: false }, y: false },
      scales: { x: { time: false, range: [x0, x1] }, y: { range: (u, min, max) => [0, Math.max(5, Math.ceil(max / 5) * 5)] } },
      axes: [
        { stroke: AXIS, grid: { show: false }, ticks: { stroke: GRID }, values: (u, v) => v.map((x) => `${x}°`), font: '10px system-ui, sans-serif', size: 28 },
        { stroke: AXIS, grid: { stroke: GRID }, ticks: { stroke: GRID }, values: (u, v) => v.map((x) => `${x}%`), font: '10px system-ui, sans-serif', size: 40 },
      ],
      series,
      hooks: {
        draw: [
          (u) => {
            const ctx = u.ctx;
            const { top, height } = u.bbox;
            const px = uPlot.pxRatio;
            ctx.save();
            // Score edges first (under the mean/p95 lines), labelled in the top margin.
            ctx.strokeStyle = EDGE_COLOR;
            ctx.fillStyle = EDGE_COLOR;
            ctx.lineWidth = 1.2 * px;
            ctx.setLineDash([1.5 * px, 2.5 * px]);
            ctx.font = `${9 * px}px system-ui, sans-serif`;
            ctx.textAlign = 'center';
            ctx.textBaseline = 'bottom';
            let labelEnd = -Infinity;
            for (const e of shown) {
              const x = Math.round(u.valToPos(e, 'x', true)) + 0.5;
              ctx.beginPath();
              ctx.moveTo(x, top);
              ctx.lineTo(x, top + height);
              ctx.stroke();
              // A label that would overlap the previous one is left out (the plot's tooltip lists all).
              const label = `${fmtDeg(e)}°`;
              const w = ctx.measureText(label).width;
              if (x - w / 2 < labelEnd + 3 * px) continue;
              ctx.fillText(label, x, top - 1 * px);
              labelEnd = x + w / 2;
            }
            for (const h of hists) {
              for (const [v, dash] of [[h.mean, []], [h.p95, [4, 3]]]) {
                if (v == null || !Number.isFinite(v)) continue;
                const x = Math.round(u.valToPos(v, 'x', true));
                ctx.strokeStyle = overlay ? h.color : '#f4f7fb';
                ctx.lineWidth = 1.5 * uPlot.pxRatio;
                ctx.setLineDash(dash.map((d) => d * uPlot.pxRatio));
                ctx.beginPath();
                ctx.moveTo(x, top);
                ctx.lineTo(x, top + height);
                ctx.stroke();
              }
            }
            ctx.restore();
          },
        ],
      },
    },
    data,
    container,
  );
  new ResizeObserver(() => {
    const w = Math.max(180, container.clientWidth);
    if (Math.abs(w - u.width) > 1) u.setSize({ width: w, height: 150 });
  }).observe(container);
}

// Sign conventions, as ergonomics/src/angles.rs defines them (twists and wrist deviation: not stated
// there in anatomical terms, so no note).
const SIGN_NOTES = {
  'trunk flexion': 'forward +, extension −',
  'trunk side bend': 'towards the right +, left −',
  'neck flexion': 'forward +, extension −',
  'neck side bend': 'unsigned: either side is +',
  'upper arm flexion': 'flexion +, extension −',
  'upper arm abduction': 'outwards +, across the chest −',
  'elbow flexion': '0° = straight arm',
  'wrist flexion': 'towards the palm +, extension −',
};

export function renderAngles(el, sessions) {
  const keys = [];
  const maps = sessions.map((s) => {
    const m = new Map();
    for (const a of s.angles) {
      const k = regionKey(a);
      if (!keys.includes(k)) keys.push(k);
      m.set(k, a);
    }
    return m;
  });
  const anyEdges = sessions.some((s) => s.angles.some((a) => a.score_edges_deg.length));
  const edgeKey = anyEdges ? '<div class="angle-legend"><i class="edge-swatch"></i>dotted: where the RULA score changes</div>' : '';
  el.innerHTML = `<h2>Joint angles <span class="hint">distribution over the scored frames · solid line mean, dashed line 95th percentile</span></h2>${edgeKey}<div class="angle-grid"></div>`;
  const grid = el.querySelector('.angle-grid');
  if (!keys.length) {
    grid.outerHTML = '<div class="empty">No joint angles in this recording.</div>';
    return;
  }
  for (const k of keys) {
    const as = maps.map((m) => m.get(k));
    const a0 = as.find(Boolean);
    const unit = a0.unit === 'deg' || !a0.unit ? '°' : ` ${esc(a0.unit)}`;
    const card = document.createElement('div');
    card.className = 'angle';
    const stats = as
      .map((a, i) => {
        const tag = sessions.length > 1 ? `<span class="sess-dot" style="background:${SESSION_COLORS[i]}"></span>${'AB'[i]} ` : '';
        if (!a) return `<div class="stats">${tag}<span class="muted">not recorded</span></div>`;
        return `<div class="stats">${tag}mean <b>${fmt(a.mean)}${unit}</b> · p95 <b>${fmt(a.p95)}${unit}</b> · n ${esc(a.samples ?? '–')}</div>`;
      })
      .join('');
    // The same angle has the same edges in both sessions; the union, should they ever differ.
    const scoreEdges = [...new Set(as.flatMap((a) => (a ? a.score_edges_deg : [])))].sort((x, y) => x - y);
    const sign = SIGN_NOTES[String(a0.name)];
    // Always a line (empty when there is no note) so that the cards of a row line up.
    const note = `<div class="sign"${sign ? ' title="sign convention (ergonomics/src/angles.rs)"' : ''}>${sign ? esc(sign) : '&nbsp;'}</div>`;
    card.innerHTML = `<div class="angle-head"><span class="name">${esc(titleCase(`${a0.side ? `${a0.side} ` : ''}${a0.name}`))}</span></div>${note}${stats}<div class="plots"></div>`;
    grid.appendChild(card);
    const plots = card.querySelector('.plots');
    const valid = as
      .map((a, i) => ({ a, i }))
      .filter(({ a }) => a && Array.isArray(a.bin_edges) && a.bin_edges.length >= 2 && Array.isArray(a.counts) && a.counts.some((c) => Number(c) > 0));
    if (!valid.length) {
      plots.innerHTML = '<div class="empty small">no samples</div>';
      continue;
    }
    const color = (i) => (sessions.length > 1 ? SESSION_COLORS[i] : '#5b8def');
    const addPlot = (edges, hists) => {
      const div = document.createElement('div');
      div.className = 'hist';
      plots.appendChild(div);
      histogramPlot(div, edges, hists, scoreEdges);
    };
    // Paired bars when both sessions' bins can share one axis; otherwise one plot each.
    const both = valid.length === 2 ? commonBins(valid[0].a, valid[1].a) : null;
    if (both) {
      addPlot(both.edges, valid.map(({ a, i }, j) => ({ counts: both.counts[j], mean: a.mean, p95: a.p95, color: color(i) })));
    } else {
      for (const { a, i } of valid) addPlot(a.bin_edges.map(Number), [{ counts: a.counts, mean: a.mean, p95: a.p95, color: color(i) }]);
    }
  }
}
