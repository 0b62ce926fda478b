// Strain colormap: 0 = RULA score 1 (deep blue) … 1 = score 7, RULA's highest (deep red): one
// scale for every region, so one colour means one score everywhere.
// Stops of ColorBrewer's RdYlBu, reversed (diverging, readable for most colour-vision deficiencies).
const STOPS = [
  [0x31, 0x36, 0x95], [0x45, 0x75, 0xb4], [0x74, 0xad, 0xd1], [0xab, 0xd9, 0xe9], [0xe0, 0xf3, 0xf8],
  [0xff, 0xff, 0xbf], [0xfe, 0xe0, 0x90], [0xfd, 0xae, 0x61], [0xf4, 0x6d, 0x43], [0xd7, 0x30, 0x27],
  [0xa5, 0x00, 0x26],
];

export const NULL_RGB = [0x6b, 0x72, 0x80];

/** [r, g, b] in 0..255 for s in 0..1; NULL_RGB for null/NaN. */
export function strainRgb(s) {
  if (s == null || !Number.isFinite(s)) return NULL_RGB;
  const x = Math.min(1, Math.max(0, s)) * (STOPS.length - 1);
  const i = Math.min(STOPS.length - 2, Math.floor(x));
  const f = x - i;
  const a = STOPS[i];
  const b = STOPS[i + 1];
  return [0, 1, 2].map((k) => Math.round(a[k] + (b[k] - a[k]) * f));
}

export function strainCss(s) {
  const [r, g, b] = strainRgb(s);
  return `rgb(${r},${g},${b})`;
}

/** RULA's highest score (the grand score's top); a region's scores sit on the same scale. */
export const RULA_TOP = 7;

/** Colour of RULA score k (1-based): the same in every region (the 3D view's colours). */
export function scoreCss(k) {
  return strainCss((k - 1) / (RULA_TOP - 1));
}

/** Colour of level k (1-based) of a scale with `levels` levels that is not RULA's (REBA, action levels). */
export function levelCss(k, levels) {
  return strainCss(levels > 1 ? (k - 1) / (levels - 1) : 0);
}
