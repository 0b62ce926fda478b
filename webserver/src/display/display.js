// ergocell operator display: renders each snapshot the cell pushes on /events (server-sent events).
// Every message is the whole picture, so a reload or a reconnect needs nothing but the next one.
"use strict";
(function () {
  const STATES = {
    waiting_for_operator: "Waiting for the operator",
    measuring_height: "Measuring your height — please stand straight",
    class_decided: "Height measured",
    trajectory_locked: "Robot path locked for your height",
    working: "Working",
    held: "ROBOT HELD",
    session_ended: "Session ended",
  };
  const LEVELS = {
    1: "Posture acceptable",
    2: "Posture: investigate, change may be needed",
    3: "Posture: change soon",
    4: "Posture: change now",
  };
  // MediaPipe BlazePose connections (the body only: face points are left out).
  const BONES = [[11, 12], [11, 13], [13, 15], [12, 14], [14, 16], [11, 23], [12, 24], [23, 24],
    [23, 25], [25, 27], [24, 26], [26, 28], [27, 29], [29, 31], [27, 31], [28, 30], [30, 32], [28, 32],
    [15, 17], [15, 19], [17, 19], [16, 18], [16, 20], [18, 20], [0, 11], [0, 12]];
  const $ = (id) => document.getElementById(id);
  window.__latencies = [];
  // per warning first shown: from the capture stamp of the frame that raised it to the screen
  window.__warningLatencies = [];
  const shownWarnings = new Set();
  window.__snapshots = 0;
  let lastRaised = 0;

  function render(s) {
    const state = $("state");
    let text = STATES[s.state] || s.state;
    if (s.state === "held" && s.held_reason) text += " — " + s.held_reason;
    // the integrator's words for the same hold, on hover
    state.title = s.state === "held" && s.held_detail ? s.held_detail : "";
    if (s.state === "working" && s.class) text += " — class " + s.class;
    state.textContent = text;
    state.className = s.state;
    state.dataset.state = s.state;

    const level = $("level");
    // While the operator is asked to stand straight for the height measurement, a coloured band
    // ("change may be needed") contradicts the instruction: the band waits for work to start,
    // unless a posture warning is up (warnings always run).
    const measuring = s.state === "waiting_for_operator" || s.state === "measuring_height";
    const al = measuring && !s.warnings.length ? 0 : s.action_level || 0;
    level.dataset.level = String(al);
    level.textContent = al
      ? `${LEVELS[al]} (RULA score ${s.grand_score} of 7, action level ${al})`
      : measuring ? "Posture: shown once your height is measured" : "Posture: —";

    const list = $("warnings");
    list.textContent = "";
    const fresh = s.latest_raised && s.latest_raised[0] > lastRaised ? s.latest_raised[1] : null;
    if (s.latest_raised) lastRaised = Math.max(lastRaised, s.latest_raised[0]);
    for (const w of s.warnings) {
      const li = document.createElement("li");
      li.dataset.level = String(w.action_level);
      li.dataset.region = w.region;
      li.textContent = w.message;
      if (w.near_limit) {
        // the band is less than 90 % sure: the posture is close to the band's edge
        const near = document.createElement("span");
        near.className = "near";
        near.textContent = " — near the limit";
        li.appendChild(near);
        li.dataset.near = "true";
      }
      if (fresh && w.message === fresh) li.className = "fresh";
      list.appendChild(li);
    }
    $("none").style.display = s.warnings.length ? "none" : "";
    let cls = s.class ? "height class " + s.class : "";
    if (s.class && s.class_probability != null) {
      cls += ` (probability ${s.class_probability.toFixed(2)}` + (s.across_boundary ? ", near a class boundary)" : ")");
    }
    $("class").textContent = cls;
    $("seq").textContent = "update " + s.seq;
    drawSkeleton(s.skeleton || []);
  }

  // Seen from the operator's right: they face the world's +x (the reference cell's robot), drawn to the right, so
  // a bent trunk or a raised arm shows as RULA scores it (in the sagittal plane); centred on the hips.
  function drawSkeleton(points) {
    const svg = $("skeleton");
    const lh = points[23], rh = points[24];
    const cx = lh && rh ? (lh[0] + rh[0]) / 2 : 0;
    const p = (i) => points[i] && [points[i][0] - cx, -points[i][2]];
    let d = "";
    for (const [a, b] of BONES) {
      const pa = p(a), pb = p(b);
      if (pa && pb) d += `M${pa[0].toFixed(3)} ${pa[1].toFixed(3)}L${pb[0].toFixed(3)} ${pb[1].toFixed(3)}`;
    }
    svg.innerHTML = d ? `<path d="${d}" stroke="#e0e0e0" stroke-width="0.035" stroke-linecap="round" fill="none"/>` : "";
  }

  function connect() {
    const source = new EventSource("/events");
    source.onopen = () => { $("conn").textContent = "live"; $("conn").className = ""; };
    source.onmessage = (m) => {
      let s;
      try { s = JSON.parse(m.data); } catch (e) { return; }
      render(s);
      window.__snapshots += 1;
      // on screen: after the next paint
      const fresh = (s.warnings || []).filter((w) => {
        const key = `${w.region}|${w.side}|${w.stamp_ms}`;
        if (shownWarnings.has(key)) return false;
        shownWarnings.add(key);
        return true;
      });
      requestAnimationFrame(() => setTimeout(() => {
        const now = Date.now();
        window.__latencies.push(now - s.sent_unix_ms);
        for (const w of fresh) window.__warningLatencies.push({ region: w.region, side: w.side, ms: now - w.stamp_ms });
      }, 0));
    };
    source.onerror = () => {
      // EventSource reconnects by itself (the server restarting, a network hiccup)
      $("conn").textContent = "connection lost — reconnecting";
      $("conn").className = "lost";
    };
  }
  connect();
})();
