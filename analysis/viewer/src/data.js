// The page's data: the JSON that `wpg view` embeds in <script id="wpg-data">, whose large
// arrays are base64 strings of little-endian float32 (or uint8) values, and small helpers
// shared by the views.

// Decodes a base64 string into the bytes it holds.
function bytesOf(text) {
  const binary = atob(text || '');
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// A base64 string of float32 values -> Float32Array (empty for a missing array).
export function floats(text) {
  if (!text) return new Float32Array(0);
  const bytes = bytesOf(text);
  return new Float32Array(bytes.buffer, 0, bytes.length >> 2);
}

export function uint8s(text) {
  return text ? bytesOf(text) : new Uint8Array(0);
}

export function readPageData() {
  const element = document.getElementById('wpg-data');
  if (!element) throw new Error('the page holds no data (no <script id="wpg-data">)');
  return JSON.parse(element.textContent);
}

// Index of the last time <= t in a sorted array (0 before the first).
export function sampleAt(times, t) {
  let low = 0;
  let high = times.length - 1;
  if (high < 0 || t <= times[0]) return 0;
  if (t >= times[high]) return high;
  while (high - low > 1) {
    const mid = (low + high) >> 1;
    if (times[mid] <= t) low = mid; else high = mid;
  }
  return low;
}

export function format(value, digits = 3) {
  if (value === null || value === undefined || Number.isNaN(value)) return '–';
  if (typeof value !== 'number') return String(value);
  const magnitude = Math.abs(value);
  if (magnitude !== 0 && (magnitude >= 1e5 || magnitude < 1e-3)) return value.toExponential(digits - 1);
  return Number(value.toPrecision(digits)).toString();
}

// The value at quantile q (0..1) of the finite numbers of `values` (linear interpolation, as
// numpy's default), NaN when there is none.
export function quantile(values, q) {
  const sorted = values.filter((v) => v !== null && Number.isFinite(v)).sort((a, b) => a - b);
  if (!sorted.length) return NaN;
  const position = (sorted.length - 1) * q;
  const below = Math.floor(position);
  const above = Math.min(sorted.length - 1, below + 1);
  return sorted[below] + (sorted[above] - sorted[below]) * (position - below);
}

// The least and the greatest of `values` (any iterable), by a loop: Math.min(...values) passes
// every value as an argument and throws RangeError beyond about 10^5 of them (an 800 s walk has
// 160 000 NMPC iterations). Infinity / -Infinity when there is none.
export function lowest(values) {
  let low = Infinity;
  for (const v of values) if (v < low) low = v;
  return low;
}
export function highest(values) {
  let high = -Infinity;
  for (const v of values) if (v > high) high = v;
  return high;
}

export function element(tag, attributes = {}, children = []) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'text') node.textContent = value;
    else if (key === 'class') node.className = value;
    else if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else node.setAttribute(key, value);
  }
  for (const child of children) node.append(child);
  return node;
}

// Colours shared by the 3-D scene, the plots and the dashboard: the CoP never takes the
// colour of a route, the left foot is blue and the right red as in the PNG figures.
export const COLOURS = {
  left: '#1f77b4',
  right: '#d62728',
  com: '#111111',
  cop: '#2ca02c',
  zmp: '#ff7f0e',
  route: ['#9467bd', '#17becf', '#8c564b', '#e377c2', '#bcbd22'],
  obstacle: '#6b7280',
  unknownObstacle: '#d97706',
  goal: '#f5c518',
  push: '#e11d48',
  preview: '#0d9488',
};

export const STATUS_STYLE = {
  0: ['solved', '#8a8a8a'],
  1: ['relaxed obstacle', '#ff7f0e'],
  2: ['fallback', '#d62728'],
  3: ['iteration limit', '#9467bd'],
  4: ['fallen', '#000000'],
  5: ['not converged', '#bcbd22'],
  6: ['relaxed kinematics', '#8c564b'],
  7: ['relaxed balance', '#e377c2'],
};

export const VARIANT_COLOURS = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b',
  '#e377c2', '#7f7f7f', '#bcbd22', '#17becf'];
