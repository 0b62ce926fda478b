// Writes synthetic review data in the contract `ergocell review` serves (version 1):
// an operator (~1.75 m) standing at the station, z up, facing +x (towards the robot),
// reaching forward with one arm every few seconds; the robot's TCP moves to a handover point.
//
//   node dev/sample-data.mjs out.json [--frames N] [--compare] [--problems] [--no-robot] [--null-strain] [--empty]
//     [--legacy]  (without the fields added later: frames.uncertain_left/right, angles[].score_edges_deg,
//                  robot.legs/holds/events, facts.parts_taken)
import { writeFileSync } from 'node:fs';

const args = process.argv.slice(2);
const out = args.find((a) => !a.startsWith('--') && !/^\d+$/.test(a)) || 'dev/sample.json';
const flag = (f) => args.includes(f);
const opt = (f, d) => {
  const i = args.indexOf(f);
  return i >= 0 ? Number(args[i + 1]) : d;
};

export const LANDMARKS = [
  'nose', 'left_eye_inner', 'left_eye', 'left_eye_outer', 'right_eye_inner', 'right_eye', 'right_eye_outer',
  'left_ear', 'right_ear', 'mouth_left', 'mouth_right', 'left_shoulder', 'right_shoulder', 'left_elbow',
  'right_elbow', 'left_wrist', 'right_wrist', 'left_pinky', 'right_pinky', 'left_index', 'right_index',
  'left_thumb', 'right_thumb', 'left_hip', 'right_hip', 'left_knee', 'right_knee', 'left_ankle', 'right_ankle',
  'left_heel', 'right_heel', 'left_foot_index', 'right_foot_index',
];
export const BONES = [
  [11, 12], [11, 13], [13, 15], [15, 17], [15, 19], [15, 21], [17, 19], [12, 14], [14, 16], [16, 18], [16, 20],
  [16, 22], [18, 20], [11, 23], [12, 24], [23, 24], [23, 25], [24, 26], [25, 27], [26, 28], [27, 29], [28, 30],
  [29, 31], [30, 32], [27, 31], [28, 32], [0, 1], [1, 2], [2, 3], [3, 7], [0, 4], [4, 5], [5, 6], [6, 8], [9, 10],
];

// Deterministic pseudo-random numbers (mulberry32).
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const deg = Math.PI / 180;
const r2 = (v) => Math.round(v * 1e4) / 1e4;

function band(v, edges) {
  // score 1 + number of edges v is above
  let s = 1;
  for (const e of edges) if (v > e) s++;
  return s;
}

// Where each sample angle's RULA score changes (ergonomics::assess::score_edges_deg).
const SCORE_EDGES = { 'trunk flexion': [0, 20, 60], 'neck flexion': [0, 10, 20], 'upper arm flexion': [-20, 20, 45, 90], 'elbow flexion': [60, 100] };

function session(label, { frames = 300, seed = 1, reachScale = 1, robot = true, nullStrain = false, problems = [], legacy = false } = {}) {
  const rand = rng(seed);
  const noise = () => (rand() - 0.5) * 0.006;
  const dt = 0.1;
  const t = [], positions = [], strain = [];
  const gl = [], gr = [], al = [], ar = [], act = [], ul = [], ur = [];
  const angleSamples = { 'trunk flexion|': [], 'neck flexion|': [], 'upper arm flexion|left': [], 'upper arm flexion|right': [], 'elbow flexion|left': [], 'elbow flexion|right': [] };
  const regionScores = { 'upper arm|left': [], 'upper arm|right': [], 'lower arm|left': [], 'lower arm|right': [], 'wrist|left': [], 'wrist|right': [], 'neck|': [], 'trunk|': [], 'legs|': [] };
  const maxScore = { 'upper arm': 6, 'lower arm': 3, wrist: 4, neck: 6, trunk: 6, legs: 2 };
  const measuringUntil = 2.2;

  for (let i = 0; i < frames; i++) {
    const time = i * dt;
    t.push(r2(time));
    // A reach every 5 s, alternating arms; 2.2 s forward and back.
    const cycle = 5.0;
    const k = Math.floor(time / cycle);
    const ph = (time - k * cycle) / 2.2;
    const reach = ph < 1 ? Math.sin(Math.PI * ph) ** 2 : 0;
    const leftArm = k % 2 === 0;
    const big = k % 3 === 1 ? 1.12 : 0.85; // every third reach goes overhead
    const flexL = (14 + (leftArm ? reach * 90 * big * reachScale : 4 * Math.sin(time))) * deg;
    const flexR = (12 + (!leftArm ? reach * 82 * big * reachScale : 4 * Math.cos(time))) * deg;
    const elbowL = (70 - (leftArm ? reach * 55 : 0)) * deg;
    const elbowR = (75 - (!leftArm ? reach * 55 : 0)) * deg;
    const trunk = (4 + reach * 14 * reachScale + Math.sin(time * 0.7) * 2) * deg;
    const neck = (8 + reach * 10 + Math.sin(time * 0.5) * 4) * deg;

    const P = new Array(33);
    // Lower body fixed; hips at 0.95 m.
    const hipZ = 0.95;
    P[23] = [0, 0.1, hipZ]; P[24] = [0, -0.1, hipZ];
    P[25] = [0.02, 0.1, 0.52]; P[26] = [0.02, -0.1, 0.52];
    P[27] = [0, 0.1, 0.09]; P[28] = [0, -0.1, 0.09];
    P[29] = [-0.05, 0.1, 0.04]; P[30] = [-0.05, -0.1, 0.04];
    P[31] = [0.16, 0.11, 0.02]; P[32] = [0.16, -0.11, 0.02];
    // Upper body rotates forward about the hip axis by the trunk angle.
    const bend = (x, z, a) => [x * Math.cos(a) + (z - hipZ) * Math.sin(a), hipZ - x * Math.sin(a) + (z - hipZ) * Math.cos(a)];
    const up = (x, y, z, a = trunk) => { const [bx, bz] = bend(x, z, a); return [bx, y, bz]; };
    P[11] = up(0, 0.19, 1.44); P[12] = up(0, -0.19, 1.44);
    const headA = trunk + neck;
    const head = (x, y, z) => { const sx = P[11][0] / 2 + P[12][0] / 2; const sz = P[11][2]; const dx = x, dz = z - 1.44; return [sx + dx * Math.cos(neck) + dz * Math.sin(headA), y, sz - dx * Math.sin(neck) + dz * Math.cos(headA)]; };
    P[0] = head(0.1, 0, 1.62);
    P[1] = head(0.085, 0.015, 1.665); P[2] = head(0.083, 0.032, 1.667); P[3] = head(0.078, 0.048, 1.665);
    P[4] = head(0.085, -0.015, 1.665); P[5] = head(0.083, -0.032, 1.667); P[6] = head(0.078, -0.048, 1.665);
    P[7] = head(0.0, 0.075, 1.64); P[8] = head(0.0, -0.075, 1.64);
    P[9] = head(0.088, 0.025, 1.585); P[10] = head(0.088, -0.025, 1.585);
    // Arms in the sagittal plane: upper arm 0.30 m, forearm 0.26 m, hand 0.08 m.
    const arm = (s, flex, elbow, side) => {
      const a1 = flex + trunk * 0.3;
      const e = [s[0] + 0.3 * Math.sin(a1), s[1] + side * 0.02, s[2] - 0.3 * Math.cos(a1)];
      const a2 = a1 + elbow;
      const w = [e[0] + 0.26 * Math.sin(a2), e[1] + side * 0.01, e[2] - 0.26 * Math.cos(a2)];
      const h = (d, dy) => [w[0] + d * Math.sin(a2), w[1] + dy, w[2] - d * Math.cos(a2)];
      return [e, w, h(0.08, side * 0.02), h(0.085, 0), h(0.05, -side * 0.02)];
    };
    const [eL, wL, pL, iL, thL] = arm(P[11], flexL, elbowL, 1);
    const [eR, wR, pR, iR, thR] = arm(P[12], flexR, elbowR, -1);
    P[13] = eL; P[15] = wL; P[17] = pL; P[19] = iL; P[21] = thL;
    P[14] = eR; P[16] = wR; P[18] = pR; P[20] = iR; P[22] = thR;

    const row = [];
    const occludedLeftHand = i % 47 === 13 || i % 47 === 14; // the left hand drops out now and then
    for (let j = 0; j < 33; j++) {
      if (occludedLeftHand && (j === 17 || j === 19 || j === 21)) row.push(null, null, null);
      else row.push(r2(P[j][0] + noise()), r2(P[j][1] + noise()), r2(P[j][2] + noise()));
    }
    positions.push(row);

    // RULA-like scores (upper arm, lower arm, wrist, neck, trunk, legs).
    const scored = time >= measuringUntil && !nullStrain;
    const fl = flexL / deg, fr = flexR / deg;
    const uaL = band(fl, [20, 45, 90]), uaR = band(fr, [20, 45, 90]);
    const laL = (elbowL / deg >= 60 && elbowL / deg <= 100) ? 1 : 2, laR = (elbowR / deg >= 60 && elbowR / deg <= 100) ? 1 : 2;
    const wrL = 2, wrR = 2;
    const nk = band(neck / deg, [10, 20]);
    const tr = band(trunk / deg, [0, 20, 60]);
    const lg = 1;
    const grand = (ua, la) => Math.min(7, Math.max(1, Math.round(ua + la * 0.5 + (nk + tr) / 2 - 0.5)));
    const action = (g) => (g <= 2 ? 1 : g <= 4 ? 2 : g <= 6 ? 3 : 4);
    if (scored) {
      const gL = grand(uaL, laL), gR = grand(uaR, laR);
      gl.push(gL); gr.push(gR); al.push(action(gL)); ar.push(action(gR)); act.push(Math.max(action(gL), action(gR)));
      // Uncertain: the left side around the hand's drop-outs (held inputs), the right side while
      // tracking degrades before the 'held' state at 18 s.
      ul.push(i % 47 >= 12 && i % 47 <= 17);
      ur.push(i >= 165 && i < 180);
      const st = new Array(33).fill(null);
      // One scale for every region, as the Rust side writes it: score 1 → 0 … score 7 → 1.
      const norm = (s) => (s - 1) / 6;
      st[11] = norm(uaL); st[12] = norm(uaR);
      st[13] = norm(laL); st[14] = norm(laR);
      for (const j of [15, 17, 19, 21]) st[j] = norm(wrL);
      for (const j of [16, 18, 20, 22]) st[j] = norm(wrR);
      st[0] = norm(nk); st[7] = st[0]; st[8] = st[0];
      st[23] = norm(tr); st[24] = st[23];
      for (const j of [25, 26, 27, 28, 29, 30, 31, 32]) st[j] = norm(lg);
      strain.push(st.map((v) => (v == null ? null : r2(v))));
      angleSamples['trunk flexion|'].push(trunk / deg);
      angleSamples['neck flexion|'].push(neck / deg);
      angleSamples['upper arm flexion|left'].push(fl);
      angleSamples['upper arm flexion|right'].push(fr);
      angleSamples['elbow flexion|left'].push(elbowL / deg);
      angleSamples['elbow flexion|right'].push(elbowR / deg);
      regionScores['upper arm|left'].push(uaL); regionScores['upper arm|right'].push(uaR);
      regionScores['lower arm|left'].push(laL); regionScores['lower arm|right'].push(laR);
      regionScores['wrist|left'].push(wrL); regionScores['wrist|right'].push(wrR);
      regionScores['neck|'].push(nk); regionScores['trunk|'].push(tr); regionScores['legs|'].push(lg);
    } else {
      gl.push(null); gr.push(null); al.push(null); ar.push(null); act.push(0); ul.push(false); ur.push(false);
      strain.push(null);
    }
  }

  const regions = Object.entries(regionScores).map(([key, v]) => {
    const [name, side] = key.split('|');
    const max = maxScore[name];
    const share = new Array(max).fill(0);
    for (const s of v) share[s - 1] += 1 / v.length;
    return { name, side, max_score: max, mean: v.length ? r2(v.reduce((a, b) => a + b, 0) / v.length) : null, time_share: share.map(r2) };
  });
  const angles = Object.entries(angleSamples).map(([key, v]) => {
    const [name, side] = key.split('|');
    const lo = name.startsWith('upper arm') ? -20 : name.startsWith('elbow') ? 0 : -30;
    const hi = name.startsWith('upper arm') ? 140 : name.startsWith('elbow') ? 160 : 90;
    const edges = [];
    for (let e = lo; e <= hi; e += 10) edges.push(e);
    const counts = new Array(edges.length - 1).fill(0);
    for (const x of v) counts[Math.min(counts.length - 1, Math.max(0, Math.floor((x - lo) / 10)))]++;
    const sorted = [...v].sort((a, b) => a - b);
    return {
      name, side, unit: 'deg', bin_edges: edges, counts,
      mean: v.length ? r2(v.reduce((a, b) => a + b, 0) / v.length) : null,
      p95: v.length ? r2(sorted[Math.min(sorted.length - 1, Math.floor(0.95 * sorted.length))]) : null,
      samples: v.length,
      ...(legacy ? {} : { score_edges_deg: SCORE_EDGES[name] || [] }),
    };
  });

  // Warnings: the first overhead reach raises the left upper arm warning, and it clears.
  const warnings = [];
  const firstHigh = gl.findIndex((g) => g != null && g >= 5);
  if (firstHigh >= 0) {
    const clear = gl.findIndex((g, i) => i > firstHigh && g != null && g < 5);
    warnings.push({ t: t[firstHigh], kind: 'raised', region: 'upper arm', side: 'left', score: 4, action_level: 3, message: `Left upper arm raised ${Math.round(90 * 1.12 * reachScale + 14)}° above the shoulder: grand score ${gl[firstHigh]}, action level 3 — investigate and change soon` });
    if (clear > 0) warnings.push({ t: t[clear], kind: 'cleared', region: 'upper arm', side: 'left', score: 2, action_level: 2, message: 'Left upper arm back below 45°; warning cleared' });
  }

  // Robot TCP at 20 Hz: waits at home, moves to the handover point during reaches.
  let tcp = null;
  const handover = [0.52, 0.08, 1.12];
  if (robot && frames > 0) {
    const tt = [], pp = [];
    const home = [0.95, -0.25, 1.35];
    const T = (frames - 1) * dt;
    for (let k = 0; k * 0.05 <= T + 1e-9; k++) {
      const time = k * 0.05;
      const c = (time % 10) / 10;
      const s = c < 0.3 ? 0 : c < 0.5 ? (1 - Math.cos(Math.PI * (c - 0.3) / 0.2)) / 2 : c < 0.7 ? 1 : c < 0.9 ? (1 + Math.cos(Math.PI * (c - 0.7) / 0.2)) / 2 : 0;
      tt.push(r2(time));
      pp.push([0, 1, 2].map((j) => r2(home[j] + (handover[j] - home[j]) * s + (j === 2 ? 0.08 * Math.sin(Math.PI * s) : 0))));
    }
    tcp = { t: tt, positions: pp };
  }

  // The cell's cycle, as `ergocell run` records it in action mode: a leg home → handover, the
  // operator takes the part, the leg home, the next part… Held at 18.0 s (the leg home canceled),
  // the last leg's end not reported (the recording ends).
  const cycle = robot && frames > 0 && !legacy;
  const HO = 'home → handover', HH = 'handover → home';
  const legs = cycle ? [
    { t_start: 3.0, t_end: 5.08, planned_s: 2.0, leg: HO, leg_id: 1, outcome: 'succeeded', end_known: true, feedback_count: 21, max_error: 0.0021, text: '' },
    { t_start: 7.0, t_end: 9.06, planned_s: 2.0, leg: HH, leg_id: 2, outcome: 'succeeded', end_known: true, feedback_count: 21, max_error: 0.0034, text: '' },
    { t_start: 13.0, t_end: 15.1, planned_s: 2.0, leg: HO, leg_id: 1, outcome: 'succeeded', end_known: true, feedback_count: 22, max_error: 0.0019, text: '' },
    { t_start: 17.0, t_end: 18.05, planned_s: 2.0, leg: HH, leg_id: 2, outcome: 'canceled', end_known: true, feedback_count: 11, max_error: 0.0022, text: '' },
    { t_start: 23.0, t_end: 25.4, planned_s: 2.0, leg: HO, leg_id: 1, outcome: 'aborted', end_known: true, feedback_count: 24, max_error: 0.0412, text: 'PATH_TOLERANCE_VIOLATED (-4): a4 beyond its path tolerance' },
    { t_start: 27.0, t_end: 29.0, planned_s: 2.0, leg: HH, leg_id: 2, outcome: 'sent', end_known: false, feedback_count: null, max_error: null, text: '' },
  ] : [];
  const ev = (t, kind, leg = '', extra = {}) => ({ t, kind, leg, status: '', error_code: 0, text: '', max_error: null, ...extra });
  const events = cycle ? [
    ev(0.4, 'driver', '', { status: 'ready', text: 'configured and controlling' }),
    ...legs.flatMap((l) => [
      ev(l.t_start, 'goal_sent', l.leg, { text: '6 points over 2.00 s; path tolerances 0.0187, 0.0194, 0.0201, 0.0188, 0.0210, 0.0230 rad' }),
      ev(l.t_start + 0.02, 'accepted', l.leg),
      ...(l.end_known ? [ev(l.t_end, 'finished', l.leg, { status: l.outcome, error_code: l.outcome === 'aborted' ? -4 : 0, text: l.text })] : []),
    ]),
    ev(18.0, 'cancel_requested', HH),
    ev(25.3, 'monitor', '', { text: 'a4 is 0.041 rad off the locked path (tolerance 0.023 rad) at 2.30 s into home → handover', max_error: 1.78 }),
  ].sort((a, b) => a.t - b.t) : [];
  const holds = cycle ? [18.0, 25.3] : [];
  const partTaken = (n, t, hand) => ({ t, part: n, hand, distance_m: 0.041 + n * 0.01, reason: `part ${n} taken: the operator's ${hand} hand came to ${(0.041 + n * 0.01).toFixed(3)} m of the handover point and left it; robot going home for the next part` });
  const parts = cycle ? [partTaken(1, 7.0, 'left'), partTaken(2, 17.0, 'right'), partTaken(3, 27.0, 'left')] : [];

  const states = frames > 0 ? [
    { t: 0.0, state: 'waiting_for_operator', reason: 'session started' },
    { t: 0.3, state: 'measuring_height', reason: 'operator tracked at the station' },
    { t: 2.0, state: 'class_decided', reason: 'stature 1.746 ± 0.023 m → c2 (1.68–1.82 m)' },
    { t: 2.1, state: 'trajectory_locked', reason: 'trajectories/c2.toml verified against its approval' },
    { t: 2.2, state: 'working', reason: '' },
    { t: Math.min(18.0, t[t.length - 1]), state: 'held', reason: 'camera cam3 stale for 0.5 s; fewer than one stereo pair' },
    { t: Math.min(19.1, t[t.length - 1]), state: 'working', reason: 'tracking back for 0.5 s, lock verified, robot at home' },
    ...parts.map((p) => ({ t: p.t, state: 'working', reason: p.reason })),
  ].sort((a, b) => a.t - b.t) : [];

  return {
    label,
    source: { file: label, bytes: 1048576 + seed * 12345, messages: frames * 14 + 40, complete: problems.length === 0, problems },
    facts: {
      height_m: 1.746, height_uncertainty_m: 0.023, height_class: 'c2',
      decision_basis: 'interval', class_probability: 0.98, expected_rula_cost: 0,
      trajectory_sha256: '3f6c1a9e0b7d4c2f8a5e6b1d9c0f7a2e4b8d6c3a1f0e9d8c7b6a5f4e3d2c1b0a',
      approved_by: ['M. Keller (EHS)'], states,
      ...(legacy ? {} : { parts_taken: parts }),
    },
    landmarks: LANDMARKS,
    bones: BONES,
    up: [0, 0, 1],
    frames: { t, positions, strain, grand_left: gl, grand_right: gr, action_left: al, action_right: ar, ...(legacy ? {} : { uncertain_left: ul, uncertain_right: ur }), action_level: act },
    robot: { tcp, handover_point: robot ? handover : null, ...(legacy ? {} : { legs, holds, events }) },
    warnings,
    regions,
    angles,
  };
}

const frames = opt('--frames', 300);
const problems = flag('--problems') ? ['truncated after 29.4 s: the last chunk ends mid-record (offset 1048321 of 1048576 bytes)'] : [];
const common = { frames, robot: !flag('--no-robot'), nullStrain: flag('--null-strain'), legacy: flag('--legacy') };
let data;
if (flag('--empty')) data = { version: 1, sessions: [] };
else if (flag('--compare'))
  data = {
    version: 1,
    sessions: [
      session('before-adaptation.mcap', { ...common, seed: 1, reachScale: 1, problems }),
      session('after-adaptation.mcap', { ...common, seed: 2, reachScale: 0.72 }),
    ],
  };
else data = { version: 1, sessions: [session('ergocell-demo.mcap', { ...common, seed: 1, problems })] };

writeFileSync(out, JSON.stringify(data));
console.log(`wrote ${out}`);
