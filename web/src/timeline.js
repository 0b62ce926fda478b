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
  const u = new uPlot(opts, data, container);

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
