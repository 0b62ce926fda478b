// uPlot timeline of one session: grand score left/right and action level, warnings marked,
// a cursor line at the current frame; a click anywhere on the plot seeks to that time.
import uPlot from 'uplot';
import { frameAtOrBefore } from './data.js';

const AXIS = '#8b9bb0';
const GRID = 'rgba(139,155,176,0.12)';
const KIND_COLOR = { raised: '#ef5350', changed: '#ffb020', cleared: '#38d39f' };

export const SERIES_COLORS = { left: '#4ea1ff', right: '#ffa94d', action: '#e05cff' };

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

  const opts = {
    width: Math.max(200, container.clientWidth),
    height,
    padding: [14, 12, 0, 0],
    scales: {
      x: { time: false, range: [t0, t1] },
      y: { range: [0, 7.6] },
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
    for (const { el, t: wt } of markers) {
      const x = u.valToPos(wt, 'x');
      el.style.left = `${x}px`;
      el.classList.toggle('tip-left', x > w * 0.6);
      el.hidden = x < -1 || x > w + 1;
    }
  }

  // Stretches with no frame at all (no skeleton fused, e.g. while too few cameras saw the
  // operator): break the lines there and shade the stretch, rather than hold the last score.
  const dts = [];
  for (let i = 1; i < t.length; i++) dts.push(t[i] - t[i - 1]);
  dts.sort((a, b) => a - b);
  const dtMed = dts.length ? dts[dts.length >> 1] : 0;
  const gaps = [];
  if (dtMed > 0) for (let i = 1; i < t.length; i++) if (t[i] - t[i - 1] > Math.max(0.5, 3 * dtMed)) gaps.push([t[i - 1] + dtMed, t[i]]);
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
  if (s.hasUncertain) {
    opts.hooks.setLegend = [
      (u) => {
        if (!uncCell) return;
        const j = u.legend.idx;
        const sides = j == null ? null : [uncL[j] && 'L', uncR[j] && 'R'].filter(Boolean);
        uncCell.textContent = sides == null ? '–' : sides.length ? sides.join(' + ') : 'no';
      },
    ];
  }
  let uncCell = null;
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
