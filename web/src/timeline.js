// uPlot timeline of one session: grand score left/right and action level, warnings marked,
// a cursor line at the current frame; a click anywhere on the plot seeks to that time.
import uPlot from 'uplot';
import { frameAtOrBefore, legAt } from './data.js';

const AXIS = '#8b9bb0';
const GRID = 'rgba(139,155,176,0.12)';
const KIND_COLOR = { raised: '#ef5350', changed: '#ffb020', cleared: '#38d39f' };

export const SERIES_COLORS = { left: '#4ea1ff', right: '#ffa94d', action: '#e05cff' };

// The robot strip along the top of the plot: one band per leg, coloured by its direction.
// By the leg's constant (ergocell_msgs/ControllerEvent LEG_TO_HANDOVER = 1, LEG_TO_HOME = 2), never its words.
export const LEG_COLORS = { 1: '#26c6da', 2: '#c0ca33' };
const LEG_OTHER = '#90a4ae';
export const legColor = (leg) => (leg && LEG_COLORS[leg.leg_id]) || LEG_OTHER;
const HOLD_COLOR = '#ef5350';
const STRIP_PX = 14; // the strip's height, CSS px; score 7 stays below it
const BAND_TOP_PX = 2;
const BAND_PX = 10;
// Outcomes of a leg that ended well, or was cut short by ergocell itself.
const OK_OUTCOMES = new Set(['succeeded', 'sent']);
const HELD_OUTCOMES = new Set(['held', 'canceled', 'replaced']);

/** The class of an outcome: ok, warn (held by ergocell) or bad (the controller refused or failed). */
export function outcomeClass(outcome) {
  if (OK_OUTCOMES.has(outcome)) return 'ok';
  if (HELD_OUTCOMES.has(outcome)) return 'warn';
  return 'danger';
}

/** A leg's outcome in words. */
export function outcomeText(l) {
  if (l.outcome === 'sent' || !l.end_known) return 'no end reported: drawn to its planned end';
  if (l.outcome === 'held') return 'held before its planned end';
  if (l.outcome === 'replaced') return 'the next leg was sent before its planned end';
  return l.outcome || 'ended';
}

/** A controller event's kind in words. */
const EVENT_TEXT = {
  goal_sent: 'goal sent',
  accepted: 'goal accepted',
  rejected: 'goal rejected',
  no_response: 'no answer to the goal',
  failed: 'goal failed',
  finished: 'goal finished',
  cancel_requested: 'cancel requested',
  monitor: 'execution monitor',
  driver: 'KUKA driver',
};
export const eventText = (kind) => EVENT_TEXT[kind] || kind || 'event';

/** How bad a controller event is: ok, warn or bad (for its colour). */
export function eventClass(e) {
  if (e.kind === 'finished') return outcomeClass(e.status || 'finished');
  if (e.kind === 'rejected' || e.kind === 'failed' || e.kind === 'no_response') return 'danger';
  if (e.kind === 'driver') return e.status === 'ready' ? 'ok' : 'warn';
  if (e.kind === 'monitor' || e.kind === 'cancel_requested') return 'warn';
  return 'info';
}

function fmtT(v) {
  return v == null ? '–' : `${v.toFixed(2)} s`;
}

function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

const UNC_BAND_PX = 9;
const UNC_EDGE = 'rgba(255,210,122,0.7)';
let hatchCache = null;

/** A diagonal-hatch fill (light amber stripes) for the uncertain band. */
function hatch(ctx) {
  const px = uPlot.pxRatio;
  if (hatchCache && hatchCache.px === px) return hatchCache.pattern;
  const n = Math.max(4, Math.round(6 * px));
  const c = document.createElement('canvas');
  c.width = n;
  c.height = n;
  const g = c.getContext('2d');
  g.fillStyle = 'rgba(255,210,122,0.12)';
  g.fillRect(0, 0, n, n);
  g.strokeStyle = 'rgba(255,210,122,0.65)';
  g.lineWidth = 1.2 * px;
  g.beginPath();
  for (const o of [-n, 0, n]) {
    g.moveTo(o, n);
    g.lineTo(o + n, 0);
  }
  g.stroke();
  const pattern = ctx.createPattern(c, 'repeat');
  hatchCache = { px, pattern };
  return pattern;
}

export function createTimeline(container, session, { onSeek, cursorTime, height = 190 }) {
  const s = session;
  if (!s.n) {
    container.innerHTML = '<div class="empty">No frames were recorded, so there is no timeline.</div>';
    return { redraw() {}, destroy() {} };
  }
  const t = Array.from(s.t);
  const t0 = t[0];
  const t1 = Math.max(t[t.length - 1], t0 + 0.1);
  const stepped = uPlot.paths.stepped({ align: 1 });
  const markers = [];
  const legs = s.robotLegs || [];
  const holds = s.robotHolds || [];
  const events = (s.robotEvents || []).filter((e) => e.kind !== 'goal_sent'); // goal_sent: the band's start
  const parts = s.partsTaken || [];
  const hasRobot = legs.length + holds.length + events.length + parts.length > 0;
  // With a robot strip, the score axis reaches higher so that score 7 stays below the strip (the
  // plotting area is the height less the top padding and the time axis).
  const plotPx = Math.max(40, height - 14 - 50);
  const yMax = hasRobot ? Math.max(7.6, 7.2 / (1 - (STRIP_PX + 4) / plotPx)) : 7.6;

  const opts = {
    width: Math.max(200, container.clientWidth),
    height,
    padding: [14, 12, 0, 0],
    scales: {
      x: { time: false, range: [t0, t1] },
      y: { range: [0, yMax] },
    },
    axes: [
      {
        stroke: AXIS,
        grid: { stroke: GRID, width: 1 },
        ticks: { stroke: GRID, width: 1 },
        values: (u, vals) => vals.map((v) => `${+v.toFixed(2)} s`),
        font: '11px system-ui, sans-serif',
      },
      {
        stroke: AXIS,
        grid: { stroke: GRID, width: 1 },
        ticks: { stroke: GRID, width: 1 },
        splits: () => [0, 1, 2, 3, 4, 5, 6, 7],
        values: (u, vals) => vals.map((v) => (v === 0 ? '' : String(v))),
        size: 34,
        label: 'score',
        labelSize: 16,
        labelFont: '11px system-ui, sans-serif',
        font: '11px system-ui, sans-serif',
      },
    ],
    series: [
      { label: 'time', value: (u, v) => fmtT(v) },
      { label: 'grand score L', stroke: SERIES_COLORS.left, width: 2, paths: stepped, points: { show: false }, value: (u, v) => (v == null ? '–' : v) },
      { label: 'grand score R', stroke: SERIES_COLORS.right, width: 2, paths: stepped, points: { show: false }, value: (u, v) => (v == null ? '–' : v) },
      {
        label: 'action level',
        stroke: SERIES_COLORS.action,
        fill: 'rgba(224,92,255,0.10)',
        width: 1.5,
        dash: [5, 4],
        paths: stepped,
        points: { show: false },
        value: (u, v) => (v == null ? '–' : v === 0 ? 'not scored' : v),
      },
    ],
    cursor: {
      drag: { x: false, y: false, setScale: false },
      points: { show: false },
      y: false,
    },
    legend: { show: true, live: true },
    hooks: {
      draw: [
        (u) => {
          const ctx = u.ctx;
          const { left, top, width, height: h } = u.bbox;
          ctx.save();
          for (const [g0, g1] of gaps) {
            const x0 = u.valToPos(g0, 'x', true);
            const x1 = u.valToPos(g1, 'x', true);
            ctx.fillStyle = 'rgba(139,155,176,0.10)';
            ctx.fillRect(x0, top, x1 - x0, h);
            if (x1 - x0 > 60 * uPlot.pxRatio) {
              ctx.fillStyle = '#8b9bb0';
              ctx.font = `${11 * uPlot.pxRatio}px system-ui, sans-serif`;
              ctx.textAlign = 'center';
              ctx.fillText('no skeleton', (x0 + x1) / 2, top + 14 * uPlot.pxRatio);
            }
          }
          // Uncertain stretches: a hatched band along the bottom of the plot.
          if (uncertain.length) {
            const bh = UNC_BAND_PX * uPlot.pxRatio;
            ctx.fillStyle = hatch(ctx);
            ctx.strokeStyle = UNC_EDGE;
            ctx.lineWidth = 1 * uPlot.pxRatio;
            for (const [a0, a1] of uncertain) {
              const x0 = Math.max(left, u.valToPos(a0, 'x', true));
              const x1 = Math.min(left + width, u.valToPos(a1, 'x', true));
              if (x1 <= x0) continue;
              const w = Math.max(1, x1 - x0);
              ctx.fillRect(x0, top + h - bh, w, bh);
              ctx.beginPath();
              ctx.moveTo(x0, top + h - bh + 0.5);
              ctx.lineTo(x0 + w, top + h - bh + 0.5);
              ctx.stroke();
            }
          }
          if (hasRobot) drawStrip(u, ctx);
          for (const w of s.warnings) {
            const x = Math.round(u.valToPos(w.t, 'x', true));
            if (x < left - 1 || x > left + width + 1) continue;
            ctx.strokeStyle = KIND_COLOR[w.kind] || '#ffb020';
            ctx.globalAlpha = 0.75;
            ctx.lineWidth = 1.5 * uPlot.pxRatio;
            ctx.setLineDash([3 * uPlot.pxRatio, 3 * uPlot.pxRatio]);
            ctx.beginPath();
            ctx.moveTo(x, top);
            ctx.lineTo(x, top + h);
            ctx.stroke();
          }
          const ct = cursorTime();
          if (ct != null) {
            const x = Math.round(u.valToPos(ct, 'x', true));
            ctx.globalAlpha = 1;
            ctx.setLineDash([]);
            ctx.strokeStyle = '#f4f7fb';
            ctx.lineWidth = 2 * uPlot.pxRatio;
            ctx.beginPath();
            ctx.moveTo(x, top);
            ctx.lineTo(x, top + h);
            ctx.stroke();
          }
          ctx.restore();
        },
      ],
      setSize: [(u) => placeMarkers(u)],
      ready: [(u) => placeMarkers(u)],
    },
  };

  function placeMarkers(u) {
    const w = u.over.clientWidth;
    for (const { el, t: wt, t1 } of markers) {
      const x = u.valToPos(wt, 'x');
      if (t1 != null) {
        // A span (a leg): clipped to the plot.
        const a = Math.max(0, x);
        const b = Math.min(w, u.valToPos(t1, 'x'));
        el.style.left = `${a}px`;
        el.style.width = `${Math.max(0, b - a)}px`;
        el.classList.toggle('tip-left', a > w * 0.6);
        el.hidden = b - a < 1;
        continue;
      }
      el.style.left = `${x}px`;
      el.classList.toggle('tip-left', x > w * 0.6);
      el.hidden = x < -1 || x > w + 1;
    }
  }

  /** The robot strip: a band per leg (an open, dashed end when only planned), holds as red ticks. */
  function drawStrip(u, ctx) {
    const px = uPlot.pxRatio;
    const { left, top, width } = u.bbox;
    const right = left + width;
    ctx.save();
    ctx.globalAlpha = 1;
    ctx.setLineDash([]);
    ctx.fillStyle = 'rgba(139,155,176,0.07)';
    ctx.fillRect(left, top, width, STRIP_PX * px);
    const y = top + BAND_TOP_PX * px;
    const bh = BAND_PX * px;
    ctx.font = `600 ${9.5 * px}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    for (const l of legs) {
      const a = u.valToPos(l.t_start, 'x', true);
      const b = u.valToPos(l.t_end, 'x', true);
      const x0 = Math.max(left, a);
      const x1 = Math.min(right, b);
      if (x1 - x0 < 0.5) continue;
      const color = legColor(l);
      ctx.fillStyle = color;
      if (l.end_known) {
        ctx.fillRect(x0, y, x1 - x0, bh);
        if (b <= right) {
          // The reported end: a cap, red when the controller refused or failed the leg.
          ctx.fillStyle = outcomeClass(l.outcome) === 'danger' ? HOLD_COLOR : '#0b1017';
          ctx.fillRect(x1 - 2 * px, y, 2 * px, bh);
        }
      } else {
        // Only planned: solid to 60 %, then fading out to an open, dashed end.
        const xs = x0 + (x1 - x0) * 0.6;
        ctx.fillRect(x0, y, xs - x0, bh);
        const g = ctx.createLinearGradient(xs, 0, Math.max(xs + 1, x1), 0);
        g.addColorStop(0, color);
        g.addColorStop(1, 'rgba(0,0,0,0)');
        ctx.fillStyle = g;
        ctx.fillRect(xs, y, x1 - xs, bh);
        ctx.strokeStyle = color;
        ctx.lineWidth = 1 * px;
        ctx.setLineDash([3 * px, 2 * px]);
        ctx.beginPath();
        ctx.moveTo(xs, y + 0.5 * px);
        ctx.lineTo(x1, y + 0.5 * px);
        ctx.moveTo(xs, y + bh - 0.5 * px);
        ctx.lineTo(x1, y + bh - 0.5 * px);
        if (b <= right) {
          ctx.moveTo(x1 - 0.5 * px, y);
          ctx.lineTo(x1 - 0.5 * px, y + bh);
        }
        ctx.stroke();
        ctx.setLineDash([]);
      }
      const label = l.leg || 'leg';
      if (ctx.measureText(label).width + 10 * px < x1 - x0) {
        ctx.fillStyle = '#0b1017';
        ctx.fillText(label, (x0 + x1) / 2, y + bh / 2 + 0.5 * px);
      }
    }
    ctx.fillStyle = HOLD_COLOR;
    for (const h of holds) {
      const x = Math.round(u.valToPos(h, 'x', true));
      if (x < left - 1 || x > right + 1) continue;
      ctx.fillRect(x - px, top, 2 * px, (STRIP_PX + 4) * px);
    }
    ctx.restore();
  }

  // Stretches with no frame at all (no skeleton fused, e.g. while too few cameras saw the
  // operator): break the lines there and shade the stretch, rather than hold the last score.
  const dts = [];
  for (let i = 1; i < t.length; i++) dts.push(t[i] - t[i - 1]);
  dts.sort((a, b) => a - b);
  const dtMed = dts.length ? dts[dts.length >> 1] : 0;
  const gaps = [];
  // An overview's frames stand a bucket apart outside its windows: that is no gap.
  const gapS = Math.max(0.5, 3 * dtMed, session.overview ? 1.5 * session.overview.bucketS : 0);
  if (dtMed > 0) for (let i = 1; i < t.length; i++) if (t[i] - t[i - 1] > gapS) gaps.push([t[i - 1] + dtMed, t[i]]);
  const data = [t, s.grandLeft, s.grandRight, s.actionLevel];
  if (gaps.length) {
    const cols = [[], [], [], []];
    let g = 0;
    for (let i = 0; i < t.length; i++) {
      while (g < gaps.length && gaps[g][0] < t[i]) {
        cols[0].push(gaps[g][0]);
        for (let c = 1; c < 4; c++) cols[c].push(null);
        g++;
      }
      for (let c = 0; c < 4; c++) cols[c].push(data[c][i]);
    }
    data.splice(0, 4, ...cols);
  }
  // Each side's 'uncertain' flag on the same rows (false on the inserted gap rows), and the
  // stretches where either side is uncertain: a frame's flag holds until the next frame, like the
  // stepped score lines.
  const uncL = [], uncR = [];
  {
    let i = 0;
    for (const tv of data[0]) {
      if (i < t.length && tv === t[i]) {
        uncL.push(!!s.uncertainLeft[i]);
        uncR.push(!!s.uncertainRight[i]);
        i++;
      } else {
        uncL.push(false);
        uncR.push(false);
      }
    }
  }
  const uncertain = [];
  for (let j = 0; j < data[0].length; j++) {
    if (!(uncL[j] || uncR[j])) continue;
    const a = data[0][j];
    const b = j + 1 < data[0].length ? data[0][j + 1] : a + (dtMed || 0.1);
    const last = uncertain[uncertain.length - 1];
    if (last && Math.abs(last[1] - a) < 1e-9) last[1] = b;
    else uncertain.push([a, b]);
  }
  opts.hooks.setLegend = [];
  if (s.hasUncertain) {
    opts.hooks.setLegend.push((u) => {
      if (!uncCell) return;
      const j = u.legend.idx;
      const sides = j == null ? null : [uncL[j] && 'L', uncR[j] && 'R'].filter(Boolean);
      uncCell.textContent = sides == null ? '–' : sides.length ? sides.join(' + ') : 'no';
    });
  }
  if (hasRobot) {
    opts.hooks.setLegend.push((u) => {
      if (!legCell) return;
      const j = u.legend.idx;
      const l = j == null ? null : legAt(legs, data[0][j]);
      legCell.textContent = j == null ? '–' : l ? l.leg || 'leg' : 'at rest';
    });
  }
  let uncCell = null;
  let legCell = null;
  const u = new uPlot(opts, data, container);
  if (s.hasUncertain) {
    // A legend entry for the hatched band; its value names the uncertain side(s) at the cursor.
    const body = u.root.querySelector('.u-legend tbody');
    if (body) {
      const row = document.createElement('tr');
      row.className = 'u-series u-unc';
      row.title = "a side's score rests on low-confidence landmarks or held inputs";
      row.innerHTML = '<th><div class="u-marker"></div><div class="u-label">uncertain (low-confidence landmarks)</div></th><td class="u-value">–</td>';
      body.appendChild(row);
      uncCell = row.querySelector('.u-value');
    }
  }
  if (hasRobot) {
    // A legend entry for the robot strip; its value names the leg under way at the cursor.
    const body = u.root.querySelector('.u-legend tbody');
    if (body) {
      const row = document.createElement('tr');
      row.className = 'u-series u-robot';
      row.title = 'the strip at the top: each robot leg (red ticks: holds; diamonds: controller events and parts taken)';
      row.innerHTML = `<th><div class="u-marker" style="background:linear-gradient(90deg, ${LEG_COLORS[1]} 50%, ${LEG_COLORS[2]} 50%)"></div><div class="u-label">robot leg</div></th><td class="u-value">–</td>`;
      body.appendChild(row);
      legCell = row.querySelector('.u-value');
    }
  }

  // Warning flags with their message on hover (inside the plot overlay, so a click on one also seeks).
  for (const w of s.warnings) {
    const el = document.createElement('div');
    el.className = `wmark ${KIND_COLOR[w.kind] ? w.kind : 'changed'}`;
    const side = w.side ? `${w.side} ` : '';
    el.innerHTML = `<div class="flag"></div><div class="tip"><b>${fmtT(w.t)} · ${escapeHtml(w.kind || '')}</b> ${escapeHtml(side + (w.region || ''))}${w.score != null ? ` · score ${escapeHtml(w.score)}` : ''}${w.action_level != null ? ` · action level ${escapeHtml(w.action_level)}` : ''}<br>${escapeHtml(w.message || '')}</div>`;
    el.setAttribute('aria-label', `${w.kind} warning at ${fmtT(w.t)}: ${w.message || ''}`);
    u.over.appendChild(el);
    markers.push({ el, t: w.t });
  }
  // The robot strip's hover targets: each leg's span, then the controller events and parts taken.
  for (const l of legs) {
    const el = document.createElement('div');
    el.className = `rmark leg ${outcomeClass(l.outcome)}`;
    el.dataset.color = legColor(l);
    el.dataset.leg = l.leg;
    el.dataset.t = String(l.t_start);
    el.dataset.tEnd = String(l.t_end);
    const dur = l.t_end - l.t_start;
    const planned = l.planned_s != null ? ` · planned ${l.planned_s.toFixed(2)} s` : '';
    const fb = l.feedback_count != null ? `<br>${l.feedback_count} feedback message${l.feedback_count === 1 ? '' : 's'}${l.max_error != null ? ` · largest joint error ${l.max_error.toFixed(4)} rad` : ''}` : '';
    el.innerHTML = `<div class="tip"><b>${escapeHtml(l.leg || 'robot leg')}</b> ${fmtT(l.t_start)} – ${fmtT(l.t_end)} (${dur.toFixed(2)} s${planned})<br>${escapeHtml(outcomeText(l))}${fb}${l.text ? `<br>${escapeHtml(l.text)}` : ''}</div>`;
    el.setAttribute('aria-label', `robot leg ${l.leg} at ${fmtT(l.t_start)}: ${outcomeText(l)}`);
    u.over.appendChild(el);
    markers.push({ el, t: l.t_start, t1: l.t_end });
  }
  for (const e of events) {
    const el = document.createElement('div');
    el.className = `rmark ev ${eventClass(e)}`;
    const what = [e.leg, e.status, e.kind === 'finished' && e.error_code ? `error code ${e.error_code}` : '', e.kind === 'monitor' && e.max_error != null ? `worst ${(e.max_error * 100).toFixed(0)} % of the tolerance` : '']
      .filter(Boolean)
      .join(' · ');
    el.innerHTML = `<div class="flag"></div><div class="tip"><b>${fmtT(e.t)} · ${escapeHtml(eventText(e.kind))}</b>${what ? ` ${escapeHtml(what)}` : ''}${e.text ? `<br>${escapeHtml(e.text)}` : ''}</div>`;
    el.setAttribute('aria-label', `${eventText(e.kind)} at ${fmtT(e.t)}`);
    u.over.appendChild(el);
    markers.push({ el, t: e.t });
  }
  for (const p of parts) {
    const el = document.createElement('div');
    el.className = 'rmark ev part';
    const how = [p.hand ? `${p.hand} hand` : '', p.distance_m != null ? `came to ${p.distance_m.toFixed(3)} m of the handover point` : ''].filter(Boolean).join(', ');
    el.innerHTML = `<div class="flag"></div><div class="tip"><b>${fmtT(p.t)} · part ${p.part ?? ''} taken</b>${how ? ` ${escapeHtml(how)}` : ''}<br>${escapeHtml(p.reason)}</div>`;
    el.setAttribute('aria-label', `part ${p.part ?? ''} taken at ${fmtT(p.t)}`);
    u.over.appendChild(el);
    markers.push({ el, t: p.t });
  }
  placeMarkers(u);

  u.over.addEventListener('click', (e) => {
    const rect = u.over.getBoundingClientRect();
    const x = Math.min(Math.max(0, e.clientX - rect.left), rect.width);
    onSeek(u.posToVal(x, 'x'));
  });
  u.over.style.cursor = 'pointer';
  u.over.title = '';

  const ro = new ResizeObserver(() => {
    const w = Math.max(200, container.clientWidth);
    if (Math.abs(w - u.width) > 1) u.setSize({ width: w, height });
  });
  ro.observe(container);

  // Off the plot, the legend reads out the current frame.
  let hovering = false;
  u.over.addEventListener('mouseenter', () => (hovering = true));
  u.over.addEventListener('mouseleave', () => {
    hovering = false;
    showCurrent();
  });
  function showCurrent() {
    const ct = cursorTime();
    if (hovering) return;
    if (ct == null) u.setLegend({ idx: null });
    else u.setLegend({ idx: frameAtOrBefore(data[0], ct) });
  }

  return {
    redraw() {
      u.redraw(false, false);
      showCurrent();
    },
    destroy() {
      ro.disconnect();
      u.destroy();
    },
  };
}
