// ergocell review page: entry point. Data comes from window.ERGOCELL_REVIEW_DATA (report)
// or api/review.json (`ergocell review`'s server).
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { loadData, normalizeSession, nearestFrame, frameAtOrBefore, legAt } from './data.js';
import { SkeletonView } from './view3d.js';
import { createTimeline, SERIES_COLORS, legColor } from './timeline.js';
import { renderFacts, renderStates, renderWarnings, renderRobot, renderRegions, renderSegments, renderAngles, esc, SESSION_COLORS } from './panels.js';
import { scoreCss, strainRgb, RULA_TOP } from './colormap.js';
import { renderFindings } from './findings.js';

const SPEEDS = [0.25, 0.5, 1, 2, 4];
// Inline SVG icons: the system fonts may lack the media-control glyphs.
const PLAY_ICON = '<svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M4 2v12l10-6z" fill="currentColor"/></svg>';
const PAUSE_ICON = '<svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M3 2h4v12H3zM9 2h4v12H9z" fill="currentColor"/></svg>';

function preventFaviconRequest() {
  // The shell has no icon; without this the browser asks the server for /favicon.ico.
  if (!document.querySelector('link[rel~="icon"]')) {
    const l = document.createElement('link');
    l.rel = 'icon';
    l.href = 'data:,';
    document.head.appendChild(l);
  }
}

function appRoot() {
  let app = document.getElementById('app');
  if (!app) {
    app = document.createElement('div');
    app.id = 'app';
    document.body.appendChild(app);
  }
  return app;
}

function showMessage(app, title, detail) {
  app.innerHTML = `<header class="topbar"><div class="brand">ergocell <span>review</span></div></header><div class="message-card"><h1>${esc(title)}</h1><p>${esc(detail)}</p></div>`;
}

/** The legend's swatches: RULA scores 1 … 7 in their colours, each labelled. */
function scoreRampHtml() {
  const cells = [];
  for (let k = 1; k <= RULA_TOP; k++) {
    const [r, g, b] = strainRgb((k - 1) / (RULA_TOP - 1));
    const dark = 0.299 * r + 0.587 * g + 0.114 * b > 140;
    cells.push(`<span style="background:${scoreCss(k)};color:${dark ? '#111' : '#fff'}">${k}</span>`);
  }
  return `<div class="score-ramp" aria-label="score 1 deep blue to score 7 deep red">${cells.join('')}</div>`;
}

function layout(sessions) {
  const cmp = sessions.length > 1;
  const problems = sessions.flatMap((s, i) => s.source.problems.map((p) => (cmp ? `${'AB'[i]} · ${s.label}: ${p}` : p)));
  const selector = cmp
    ? `<div class="seg-select" id="session-select" role="tablist" aria-label="Session shown in 3D">${sessions
        .map((s, i) => `<button role="tab" data-i="${i}"><span class="sess-dot" style="background:${SESSION_COLORS[i]}"></span>${'AB'[i]} · ${esc(s.label)}</button>`)
        .join('')}</div>`
    : '';
  const title = cmp ? `${esc(sessions[0].label)} <span class="vs">vs</span> ${esc(sessions[1].label)}` : esc(sessions[0].label);
  return `
<header class="topbar">
  <div class="brand">ergocell <span>review</span></div>
  <div class="title" title="${esc(sessions.map((s) => s.label).join(' vs '))}">${title}</div>
  ${selector}
  <button class="tool" id="findings-toggle" aria-pressed="false" title="The findings: the printed report's first page">Findings</button>
  <button class="tool" id="print" title="Print, or save as PDF: the findings first, then the session facts, warnings, robot and state changes, the timeline, body regions and task segments, and the joint angles">Print report</button>
</header>
<section class="card findings" id="findings"></section>
${sessions
  .filter((s) => s.overview)
  .map((s) => {
    const o = s.overview;
    const win = o.windows.reduce((sum, [a, b]) => sum + (b - a), 0);
    return `<div class="banner note" id="overview-note"><b>${cmp ? `${esc(s.label)}: ` : ''}Overview of a long recording.</b> This page holds ${o.kept.toLocaleString('en')} of its ${o.recorded.toLocaleString('en')} frames: every frame of the worst moments (${o.windows.length} stretch${o.windows.length === 1 ? '' : 'es'}, ${Math.round(win / 60)} min: action level 3 or more, and warnings, with 30 s either side), elsewhere the worst frame of each ${o.bucketS.toFixed(1)} s. The body-region rows, shares, exposure and angle distributions are over every frame.</div>`;
  })
  .join('')}
${problems.length ? `<div class="banner" role="alert"><b>${problems.length === 1 ? 'Problem with the recording' : `${problems.length} problems with the recordings`}</b> — only what could be read is shown.<ul>${problems.map((p) => `<li>${esc(p)}</li>`).join('')}</ul></div>` : ''}
<main class="layout${cmp ? ' compare' : ''}">
  <section class="card viewer">
    <div class="viewport" id="viewport">
      <div class="overlay top-left"><span class="session-badge" id="session-badge"></span></div>
      <div class="overlay legend" aria-label="Strain colour legend">
        <div class="legend-title">RULA score of each joint's region</div>
        ${scoreRampHtml()}
        <div class="ramp-note">One colour per score, the same in every region. A region's scale ends at its own top: legs 2, forearm 3, wrist 4, upper arm, neck and trunk 6 (7: the grand score only).</div>
        <div class="legend-keys"><span><i class="dot grey"></i>not scored</span><span><i class="dot tcp"></i>robot TCP</span><span><i class="dot handover"></i>handover point</span></div>
      </div>
      <div class="overlay bottom-left readout" id="readout"></div>
      <div class="overlay bottom-right hint">drag to orbit · right-drag to pan · wheel to zoom</div>
      <div class="view-message" id="view-empty" hidden><span class="msg">No frames were recorded in this session.</span></div>
    </div>
    <div class="transport">
      <button id="step-back" title="Step back (←)" aria-label="Step back"><svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M3 2h2v12H3zM14 2v12L6 8z" fill="currentColor"/></svg></button>
      <button id="play" class="primary" title="Play / pause (space)" aria-label="Play">${PLAY_ICON}</button>
      <button id="step-forward" title="Step forward (→)" aria-label="Step forward"><svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M11 2h2v12h-2zM2 2v12l8-6z" fill="currentColor"/></svg></button>
      <input type="range" id="scrubber" min="0" max="0" step="1" value="0" aria-label="Time">
      <label class="speed">speed <select id="speed">${SPEEDS.map((v) => `<option value="${v}"${v === 1 ? ' selected' : ''}>${v}×</option>`).join('')}</select></label>
      <span id="frame-counter" class="counter">frame 0 / 0 · 0.00 s</span>
    </div>
  </section>
  <aside class="side">
    <section class="card" id="facts"></section>
    <section class="card" id="warnings"></section>
    <section class="card" id="robot"></section>
    <section class="card" id="states"></section>
  </aside>
  <section class="card timeline-card">
    <h2>Timeline <span class="hint">RULA grand score per side and action level · dashed flags are warnings (hover)${sessions.some((s) => s.hasUncertain) ? " · hatched band at the bottom: a side's score is uncertain" : ''}${sessions.some((s) => s.robotLegs.length || s.robotHolds.length || s.robotEvents.length || s.partsTaken.length) ? ' · strip at the top: robot legs (dashed end: planned, not reported), red ticks: holds, diamonds: controller events and parts taken' : ''} · click to jump</span></h2>
    <div id="timeline"></div>
  </section>
  <section class="card" id="regions"></section>
  <section class="card" id="segments"></section>
  <section class="card" id="angles"></section>
</main>
<footer class="foot">ergocell review · RULA scores per frame from the fused 3D skeleton · lengths in metres, angles in degrees</footer>`;
}

const ACTION_TEXT = ['not scored', 'acceptable', 'investigate further', 'investigate, change soon', 'investigate, change now'];

const BAND_REGIONS = ['upper arm', 'lower arm', 'wrist', 'neck', 'trunk'];

/** How sure a side's region bands are at one frame: the least sure one in words, every one in the tooltip. */
function bandsHtml(name, bands) {
  const known = (bands || []).map((p, i) => [BAND_REGIONS[i], p]).filter(([r, p]) => r && p != null);
  if (!known.length) return '';
  const [region, p] = known.reduce((a, b) => (b[1] < a[1] ? b : a));
  const tip = `${name} side, probability that each region's band is right: ${known.map(([r, v]) => `${r} ${Math.round(v * 100)} %`).join(', ')}`;
  return `<span class="sure${p < 0.9 ? ' near' : ''}" title="${esc(tip)}">${esc(region)} ${Math.round(p * 100)} % sure</span>`;
}

/** The RULA scores and session state at frame f, for the 3D view's corner. */
function readoutHtml(s, f) {
  const g = (v) => (v == null ? '–' : v);
  const a = s.actionLevel[f];
  const t = s.t[f];
  let state = null;
  for (const st of s.facts.states) if (Number(st.t) <= t + 1e-9) state = st.state;
  const al = a == null ? '' : `<span class="al al${a}">action level ${a}${ACTION_TEXT[a] ? ` · ${ACTION_TEXT[a]}` : ''}</span>`;
  const side = (name, letter, color, v, unc, bands) => {
    const q = unc && v != null;
    const tip = q ? ` title="${name} score ${v} rests on low-confidence landmarks or held inputs (uncertain)"` : '';
    return `<span class="gs${q ? ' unc' : ''}"${tip}><i style="background:${color}"></i>${letter} ${g(v)}${q ? '<span class="q">?</span>' : ''}</span>${v == null ? '' : bandsHtml(name, bands)}`;
  };
  const leg = legAt(s.robotLegs, t);
  const robot = leg ? `<span class="rl"><i style="background:${legColor(leg)}"></i>robot ${esc(leg.leg || 'leg')}</span>` : '';
  const reba = s.hasReba ? `<span class="st" title="REBA score (Hignett &amp; McAtamney 2000) per side, 1–15">REBA L ${g(s.rebaLeft[f])} · R ${g(s.rebaRight[f])}</span>` : '';
  return `${side('Left', 'L', SERIES_COLORS.left, s.grandLeft[f], s.uncertainLeft[f], s.bandLeft[f])}${side('Right', 'R', SERIES_COLORS.right, s.grandRight[f], s.uncertainRight[f], s.bandRight[f])}${al}${reba}${state ? `<span class="st">${esc(String(state).replace(/_/g, ' '))}</span>` : ''}${robot}`;
}

function start(app, raw) {
  const sessionsRaw = raw && Array.isArray(raw.sessions) ? raw.sessions : null;
  if (!sessionsRaw) {
    showMessage(app, 'The review data is not in the expected format', 'Expected an object with a "sessions" list.');
    return;
  }
  if (!sessionsRaw.length) {
    showMessage(app, 'Nothing to review', 'The recording contains no session: no frames, facts or warnings could be read from it.');
    return;
  }
  const sessions = sessionsRaw.slice(0, 2).map(normalizeSession);
  app.innerHTML = layout(sessions);
  document.title = document.title && document.title !== '…' ? document.title : `ergocell review · ${sessions.map((s) => s.label).join(' vs ')}`;

  const $ = (id) => document.getElementById(id);
  const playBtn = $('play');
  const scrubber = $('scrubber');
  const counter = $('frame-counter');
  const speedSel = $('speed');
  const view = new SkeletonView($('viewport'));
  const readout = $('readout');

  const state = { si: 0, frame: 0, playing: false, time: 0, last: 0, raf: 0 };
  const cur = () => sessions[state.si];

  function cursorTimeFor(si) {
    return () => (si === state.si && sessions[si].n ? sessions[si].t[state.frame] : null);
  }

  // Timelines, one per session.
  const tlHost = $('timeline');
  const timelines = sessions.map((s, si) => {
    const wrap = document.createElement('div');
    wrap.className = 'tl';
    if (sessions.length > 1) {
      const h = document.createElement('div');
      h.className = 'tl-head';
      h.innerHTML = `<span class="sess-dot" style="background:${SESSION_COLORS[si]}"></span>${'AB'[si]} · ${esc(s.label)}`;
      wrap.appendChild(h);
    }
    const plot = document.createElement('div');
    plot.className = 'tl-plot';
    wrap.appendChild(plot);
    tlHost.appendChild(wrap);
    return { wrap, plot, s, si };
  });
  // Build the plots after layout so they get their real width.
  timelines.forEach((tl) => {
    tl.chart = createTimeline(tl.plot, tl.s, {
      height: sessions.length > 1 ? 150 : 190,
      cursorTime: cursorTimeFor(tl.si),
      onSeek: (t) => seek(tl.si, t),
    });
  });

  const onSeekList = (si, t) => seek(si, t);
  renderFindings($('findings'), sessions);
  $('findings-toggle').addEventListener('click', () => {
    const on = document.body.classList.toggle('show-findings');
    $('findings-toggle').setAttribute('aria-pressed', String(on));
  });
  $('print').addEventListener('click', () => window.print());
  renderFacts($('facts'), sessions);
  renderWarnings($('warnings'), sessions, onSeekList);
  renderRobot($('robot'), sessions, onSeekList);
  renderStates($('states'), sessions, onSeekList);
  renderRegions($('regions'), sessions);
  renderSegments($('segments'), sessions);
  renderAngles($('angles'), sessions);

  function update() {
    const s = cur();
    const n = s.n;
    const f = n ? state.frame : 0;
    view.setFrame(f);
    scrubber.max = String(Math.max(0, n - 1));
    scrubber.value = String(f);
    const t = n ? s.t[f] : 0;
    counter.textContent = `frame ${n ? f + 1 : 0} / ${n} · ${t.toFixed(2)} s`;
    readout.innerHTML = n ? readoutHtml(s, f) : '';
    // Only when it changes: update() runs every frame while playing, and a click whose mousedown
    // landed on an icon replaced before mouseup is no click at all (the pause was lost).
    const label = state.playing ? 'Pause' : 'Play';
    if (playBtn.getAttribute('aria-label') !== label) {
      playBtn.innerHTML = state.playing ? PAUSE_ICON : PLAY_ICON;
      playBtn.setAttribute('aria-label', label);
    }
    playBtn.classList.toggle('active', state.playing);
    for (const tl of timelines) tl.chart.redraw();
  }

  function selectSession(si, keepTime = true) {
    const t = cur().n ? cur().t[state.frame] : 0;
    state.si = si;
    const s = cur();
    view.setSession(s);
    state.frame = keepTime && s.n ? nearestFrame(s.t, t) : 0;
    const disabled = s.n === 0;
    for (const id of ['play', 'step-back', 'step-forward', 'scrubber']) $(id).disabled = disabled;
    $('view-empty').hidden = !disabled;
    $('session-badge').innerHTML = sessions.length > 1 ? `<span class="sess-dot" style="background:${SESSION_COLORS[si]}"></span>${'AB'[si]} · ${esc(s.label)}` : esc(s.label);
    document.querySelectorAll('#session-select button').forEach((b) => b.classList.toggle('active', Number(b.dataset.i) === si));
    timelines.forEach((tl) => tl.wrap.classList.toggle('active', tl.si === si));
    update();
  }

  function setFrame(i) {
    const n = cur().n;
    state.frame = n ? Math.min(n - 1, Math.max(0, i)) : 0;
    update();
  }

  function seek(si, t) {
    pause();
    if (si !== state.si) selectSession(si, false);
    const s = cur();
    if (s.n) setFrame(nearestFrame(s.t, t));
  }

  function tick(now) {
    if (!state.playing) return;
    const s = cur();
    const dt = Math.min(0.25, Math.max(0, (now - state.last) / 1000));
    state.last = now;
    state.time += dt * Number(speedSel.value || 1);
    const end = s.t[s.n - 1];
    if (state.time >= end) {
      state.frame = s.n - 1;
      state.playing = false;
      update();
      return;
    }
    const f = frameAtOrBefore(s.t, state.time);
    if (f !== state.frame) {
      state.frame = f;
      update();
    }
    state.raf = requestAnimationFrame(tick);
  }

  function play() {
    const s = cur();
    if (!s.n || state.playing) return;
    if (state.frame >= s.n - 1) state.frame = 0; // at the end: play from the start
    state.playing = true;
    state.time = s.t[state.frame];
    state.last = performance.now();
    update();
    state.raf = requestAnimationFrame(tick);
  }

  function pause() {
    if (!state.playing) return;
    state.playing = false;
    cancelAnimationFrame(state.raf);
    update();
  }

  const toggle = () => (state.playing ? pause() : play());
  const step = (d) => {
    pause();
    setFrame(state.frame + d);
  };

  playBtn.addEventListener('click', toggle);
  $('step-back').addEventListener('click', () => step(-1));
  $('step-forward').addEventListener('click', () => step(1));
  scrubber.addEventListener('input', () => {
    pause();
    setFrame(Number(scrubber.value));
  });
  speedSel.addEventListener('change', () => {
    if (state.playing) state.time = cur().t[state.frame];
  });
  document.querySelectorAll('#session-select button').forEach((b) => b.addEventListener('click', () => {
    pause();
    selectSession(Number(b.dataset.i));
  }));

  const isTyping = (el) => el && (el.tagName === 'SELECT' || el.tagName === 'TEXTAREA' || (el.tagName === 'INPUT' && el.type !== 'range'));
  window.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
    if (e.code === 'Space' || e.key === ' ') {
      e.preventDefault();
      if (!e.repeat) toggle();
    } else if (e.key === 'ArrowLeft' || e.key === 'ArrowRight') {
      e.preventDefault();
      step(e.key === 'ArrowLeft' ? -1 : 1);
    }
  });
  // A focused button would also "click" on the space key's release.
  window.addEventListener('keyup', (e) => {
    if ((e.code === 'Space' || e.key === ' ') && !isTyping(e.target)) e.preventDefault();
  });

  window.ergocellReview = {
    frame: () => state.frame,
    frameCount: () => cur().n,
    playing: () => state.playing,
    session: () => state.si,
    time: () => (cur().n ? cur().t[state.frame] : 0),
    timeOf: (i) => (cur().n ? cur().t[Math.min(cur().n - 1, Math.max(0, i))] : 0),
    seek: (t, si = state.si) => seek(si, t),
  };

  selectSession(0, false);
}

async function main() {
  preventFaviconRequest();
  const app = appRoot();
  app.innerHTML = '<div class="message-card"><p>Loading the recording…</p></div>';
  let raw;
  try {
    raw = await loadData();
  } catch (e) {
    showMessage(app, 'Could not load the review data', e.message || String(e));
    return;
  }
  try {
    start(app, raw);
  } catch (e) {
    // Keep the page readable rather than blank; the message says what broke.
    showMessage(app, 'The review page could not show this recording', e.message || String(e));
    throw e;
  }
}

main();
