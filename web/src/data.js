// Loading and normalising the review JSON (contract version 1, produced by the Rust side).

export async function loadData() {
  if (typeof window.ERGOCELL_REVIEW_DATA !== 'undefined') return window.ERGOCELL_REVIEW_DATA;
  if (location.protocol === 'file:') {
    // A report carries its data inline; a page opened from disk without it has nothing to fetch.
    throw new Error('this file holds no review data (write reports with `ergocell report`, or open the page `ergocell review` serves)');
  }
  let res;
  try {
    res = await fetch('api/review.json', { cache: 'no-store' });
  } catch (e) {
    throw new Error(`could not reach the review server (${e.message})`);
  }
  if (!res.ok) throw new Error(`api/review.json answered ${res.status} ${res.statusText}`);
  try {
    return await res.json();
  } catch (e) {
    throw new Error(`api/review.json is not valid JSON (${e.message})`);
  }
}

const arr = (a) => (Array.isArray(a) ? a : []);
const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);

/** Per-frame flags: true only where the data says `true` (missing or shorter lists read as false). */
function flags(a, n) {
  const src = arr(a);
  const out = new Uint8Array(n);
  for (let i = 0; i < n; i++) out[i] = src[i] === true ? 1 : 0;
  return out;
}

/** An angle's score edges: finite numbers, ascending, no duplicates (missing in older data: none). */
function scoreEdges(a) {
  const v = arr(a).map(num).filter((x) => x !== null).sort((x, y) => x - y);
  return v.filter((x, i) => i === 0 || x !== v[i - 1]);
}

const str = (v) => (v == null ? '' : String(v));

/** Robot legs (added later): finite times only, the end never before the start, by start. */
function robotLegs(a) {
  return arr(a)
    .filter((l) => l && num(l.t_start) !== null && num(l.t_end) !== null)
    .map((l) => ({
      t_start: l.t_start,
      t_end: Math.max(l.t_start, l.t_end),
      planned_s: num(l.planned_s),
      leg: str(l.leg),
      // ergocell_msgs/ControllerEvent's LEG_* constant (0: not known)
      leg_id: Number.isInteger(l.leg_id) ? l.leg_id : 0,
      outcome: str(l.outcome),
      end_known: l.end_known !== false,
      feedback_count: num(l.feedback_count),
      max_error: num(l.max_error),
      text: str(l.text),
    }))
    .sort((a, b) => a.t_start - b.t_start);
}

/** Controller events (added later; feedback is folded into the legs, never listed). */
function robotEvents(a) {
  return arr(a)
    .filter((e) => e && num(e.t) !== null && e.kind !== 'feedback')
    .map((e) => ({ t: e.t, kind: str(e.kind), leg: str(e.leg), status: str(e.status), error_code: num(e.error_code), text: str(e.text), max_error: num(e.max_error) }))
    .sort((a, b) => a.t - b.t);
}

/** The parts the operator took (added later), by time. */
function partsTaken(a) {
  return arr(a)
    .filter((p) => p && num(p.t) !== null)
    .map((p) => ({ t: p.t, part: num(p.part), hand: p.hand == null ? null : String(p.hand), distance_m: num(p.distance_m), reason: str(p.reason) }))
    .sort((a, b) => a.t - b.t);
}

/** The robot leg under way at time `time` (the latest one started), or null. */
export function legAt(legs, time) {
  let found = null;
  for (const l of legs) {
    if (l.t_start > time + 1e-9) break;
    if (time < l.t_end) found = l;
  }
  return found;
}

/** Per frame, a row of band probabilities (numbers in 0..1 or null); a missing or malformed row: []. */
function bandRows(a, n) {
  const src = arr(a);
  const out = new Array(n);
  for (let i = 0; i < n; i++) {
    const row = Array.isArray(src[i]) ? src[i] : [];
    out[i] = row.map((v) => {
      const x = num(v);
      return x !== null && x >= 0 && x <= 1 ? x : null;
    });
  }
  return out;
}

function column(a, n) {
  const src = arr(a);
  const out = new Array(n);
  for (let i = 0; i < n; i++) out[i] = num(src[i]);
  return out;
}

/** A session with every optional part filled in, typed arrays for the per-frame data. */
export function normalizeSession(s, index) {
  s = s || {};
  const frames = s.frames || {};
  const tRaw = arr(frames.t);
  // Frames without a finite time cannot be placed on the timeline; keep the valid prefix.
  let n = 0;
  while (n < tRaw.length && num(tRaw[n]) !== null) n++;
  const t = Float64Array.from(tRaw.slice(0, n));

  const landmarks = arr(s.landmarks).map(String);
  const posRows = arr(frames.positions);
  let nl = landmarks.length;
  if (!nl) for (const r of posRows) if (Array.isArray(r)) { nl = Math.floor(r.length / 3); break; }
  if (!nl) nl = 33;

  const positions = new Array(n);
  const strain = new Array(n);
  const strainRows = arr(frames.strain);
  for (let i = 0; i < n; i++) {
    const p = new Float64Array(nl * 3).fill(NaN);
    const r = posRows[i];
    if (Array.isArray(r)) {
      for (let k = 0; k < nl; k++) {
        const x = num(r[3 * k]), y = num(r[3 * k + 1]), z = num(r[3 * k + 2]);
        if (x !== null && y !== null && z !== null) { p[3 * k] = x; p[3 * k + 1] = y; p[3 * k + 2] = z; }
      }
    }
    positions[i] = p;
    const sr = strainRows[i];
    const st = new Float64Array(nl).fill(NaN);
    if (Array.isArray(sr)) for (let k = 0; k < nl; k++) { const v = num(sr[k]); if (v !== null) st[k] = v; }
    strain[i] = st;
  }

  const bones = arr(s.bones).filter((b) => Array.isArray(b) && b.length === 2 && b.every((k) => Number.isInteger(k) && k >= 0 && k < nl));
  const upRaw = arr(s.up).map(Number);
  let up = upRaw.length === 3 && upRaw.every(Number.isFinite) ? upRaw : [0, 0, 1];
  const ul = Math.hypot(...up);
  up = ul > 0 ? up.map((v) => v / ul) : [0, 0, 1];

  let tcp = null;
  const robot = s.robot || {};
  if (robot.tcp && Array.isArray(robot.tcp.t)) {
    const tt = [], pp = [];
    const rows = arr(robot.tcp.positions);
    robot.tcp.t.forEach((tv, i) => {
      const r = arr(rows[i]).map(num);
      if (num(tv) !== null && r.length === 3 && r.every((v) => v !== null)) { tt.push(tv); pp.push(r); }
    });
    if (tt.length) tcp = { t: Float64Array.from(tt), positions: pp };
  }
  const hp = arr(robot.handover_point).map(num);
  const handover = hp.length === 3 && hp.every((v) => v !== null) ? hp : null;

  const source = s.source || {};
  const facts = s.facts || {};
  return {
    index,
    label: String(s.label ?? source.file ?? `session ${index + 1}`),
    source: {
      file: source.file ?? null,
      bytes: num(source.bytes),
      messages: num(source.messages),
      complete: source.complete !== false,
      problems: arr(source.problems).map(String),
    },
    facts: {
      height_m: num(facts.height_m),
      height_uncertainty_m: num(facts.height_uncertainty_m),
      height_class: facts.height_class ?? null,
      // The class decision's basis, probability and expected RULA cost (absent in older data).
      decision_basis: facts.decision_basis ?? null,
      class_probability: num(facts.class_probability),
      expected_rula_cost: num(facts.expected_rula_cost),
      trajectory_sha256: facts.trajectory_sha256 ?? null,
      approved_by: arr(facts.approved_by).map(String),
      states: arr(facts.states).filter((x) => x && typeof x === 'object'),
    },
    // The cell's cycle (added later; absent in older data: no parts, no legs, no events).
    partsTaken: partsTaken(facts.parts_taken),
    hasPartsTaken: Array.isArray(facts.parts_taken),
    robotLegs: robotLegs(robot.legs),
    robotHolds: arr(robot.holds).map(num).filter((v) => v !== null).sort((a, b) => a - b),
    robotEvents: robotEvents(robot.events),
    landmarks,
    nl,
    bones,
    up,
    n,
    t,
    positions,
    strain,
    grandLeft: column(frames.grand_left, n),
    grandRight: column(frames.grand_right, n),
    actionLeft: column(frames.action_left, n),
    actionRight: column(frames.action_right, n),
    actionLevel: column(frames.action_level, n),
    // REBA beside RULA (absent in recordings made before it).
    rebaLeft: column(frames.reba_left, n),
    rebaRight: column(frames.reba_right, n),
    hasReba: Array.isArray(frames.reba_left) && frames.reba_left.some((v) => v != null),
    // The side's score rests on low-confidence landmarks or held inputs (absent in older data).
    uncertainLeft: flags(frames.uncertain_left, n),
    uncertainRight: flags(frames.uncertain_right, n),
    hasUncertain: Array.isArray(frames.uncertain_left) || Array.isArray(frames.uncertain_right),
    // How sure each region's band is, per frame (upper arm, lower arm, wrist, neck, trunk; absent in older data).
    bandLeft: bandRows(frames.band_left, n),
    bandRight: bandRows(frames.band_right, n),
    tcp,
    handover,
    warnings: arr(s.warnings).filter((w) => w && num(w.t) !== null).sort((a, b) => a.t - b.t),
    regions: arr(s.regions).filter((r) => r && typeof r === 'object'),
    // The session summary: task segments, static postures, REBA (absent in older data).
    summary: s.summary && typeof s.summary === 'object' ? s.summary : {},
    angles: arr(s.angles)
      .filter((a) => a && typeof a === 'object')
      .map((a) => ({ ...a, score_edges_deg: scoreEdges(a.score_edges_deg) })),
    overview: overview(s.overview),
    // The report's first page (absent in data written before it: no findings page).
    findings: findings(s.findings),
  };
}

/** The first page's findings, every part checked (absent or malformed: null). */
function findings(f) {
  if (!f || typeof f !== 'object') return null;
  const secs = arr(f.action_level_secs).map(num);
  if (secs.length !== 4 || secs.some((v) => v === null)) return null;
  return {
    action_level_secs: secs,
    unscored_secs: num(f.unscored_secs) ?? 0,
    dwell_s: num(f.dwell_s) ?? 2,
    worst_moments: arr(f.worst_moments)
      .filter((m) => m && num(m.t) !== null)
      .map((m) => ({
        t: m.t,
        action_level: num(m.action_level) ?? 0,
        grand_left: num(m.grand_left),
        grand_right: num(m.grand_right),
        regions: arr(m.regions).filter((r) => r && typeof r === 'object').map((r) => ({ region: str(r.region), side: str(r.side), score: num(r.score) })),
      })),
    regions: arr(f.regions)
      .filter((r) => r && typeof r === 'object')
      .map((r) => ({
        region: str(r.region),
        side: str(r.side),
        verdict: str(r.verdict),
        warn_at: num(r.warn_at),
        highest: num(r.highest),
        top: num(r.top),
        share_at_warn: num(r.share_at_warn) ?? 0,
        secs_at_warn: num(r.secs_at_warn) ?? 0,
        episodes_at_warn: num(r.episodes_at_warn) ?? 0,
        longest_at_warn_secs: num(r.longest_at_warn_secs) ?? 0,
        warnings_raised: num(r.warnings_raised) ?? 0,
        advice_text: r.advice_text == null ? null : String(r.advice_text),
      })),
  };
}

/** A long recording's page holds only some frames (absent: every frame). */
function overview(o) {
  if (!o || typeof o !== 'object') return null;
  const recorded = num(o.frames_recorded);
  const kept = num(o.frames_kept);
  if (recorded === null || kept === null) return null;
  const windows = arr(o.windows)
    .filter((w) => Array.isArray(w) && w.length === 2 && num(w[0]) !== null && num(w[1]) !== null)
    .map((w) => [num(w[0]), num(w[1])]);
  return { recorded, kept, bucketS: num(o.bucket_s) ?? 0, windows };
}

/** Index of the frame nearest to time `time` (t sorted ascending). */
export function nearestFrame(t, time) {
  const n = t.length;
  if (!n) return 0;
  if (time <= t[0]) return 0;
  if (time >= t[n - 1]) return n - 1;
  let lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (t[mid] <= time) lo = mid; else hi = mid;
  }
  return time - t[lo] <= t[hi] - time ? lo : hi;
}

/** Index of the last frame with t <= time (0 if none). */
export function frameAtOrBefore(t, time) {
  const n = t.length;
  if (!n || time < t[0]) return 0;
  let lo = 0, hi = n;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (t[mid] <= time) lo = mid; else hi = mid;
  }
  return lo;
}
