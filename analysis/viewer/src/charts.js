// Charts of the dashboard, drawn on canvases by this file: box plots of groups of runs with
// every run as a point, a scatter of a metric against a swept key, and bars of success rates.
// Each point knows its run: hovering shows it, a click opens its page.
import { element, format, highest, lowest, quantile } from './data.js';

const PAD = { left: 64, right: 16, top: 16, bottom: 58 };

function niceTicks(low, high, count) {
  const span = high - low || 1;
  const step0 = span / Math.max(1, count);
  const power = Math.pow(10, Math.floor(Math.log10(step0)));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * power).find((s) => s >= step0) || step0;
  const ticks = [];
  for (let v = Math.ceil(low / step) * step; v <= high + 1e-9 * span; v += step) ticks.push(Math.abs(v) < 1e-12 * span ? 0 : v);
  return ticks;
}

// `text` cut to `width` pixels with an ellipsis in its middle (variant names side by side must
// not run into each other; their ends are what tells them apart); the whole name is in the
// tooltip of what it labels.
export function fitText(g, text, width) {
  if (g.measureText(text).width <= width) return text;
  const cut = (keep) => text.slice(0, Math.ceil(keep / 2)) + '…' + text.slice(text.length - Math.floor(keep / 2));
  let keep = text.length - 1;
  while (keep > 0 && g.measureText(cut(keep)).width > width) keep -= 1;
  return keep > 0 ? cut(keep) : '…';
}

// A canvas that fills its container's width, with hit-testing of the points drawn on it.
export class Chart {
  constructor(container, height, onOpen) {
    this.root = element('div', { class: 'chart' });
    this.canvas = element('canvas');
    this.root.append(this.canvas);
    container.append(this.root);
    this.height = height;
    this.onOpen = onOpen;
    this.points = [];
    this.tip = document.querySelector('.tip') || document.body.appendChild(element('div', { class: 'tip' }));
    this.canvas.addEventListener('mousemove', (event) => {
      const hit = this.hit(event);
      this.canvas.style.cursor = hit && hit.run !== undefined ? 'pointer' : 'default';
      if (hit) {
        this.tip.textContent = hit.label;
        this.tip.style.display = 'block';
        this.tip.style.left = event.clientX + 12 + 'px';
        this.tip.style.top = event.clientY + 12 + 'px';
      } else this.tip.style.display = 'none';
    });
    this.canvas.addEventListener('mouseleave', () => { this.tip.style.display = 'none'; });
    this.canvas.addEventListener('click', (event) => {
      const hit = this.hit(event);
      if (hit && hit.run !== undefined) this.onOpen(hit.run);
    });
  }

  hit(event) {
    const box = this.canvas.getBoundingClientRect();
    const x = event.clientX - box.left;
    const y = event.clientY - box.top;
    let best = null;
    let distance = 8;
    for (const p of this.points) {
      const d = p.rect ? (x >= p.rect[0] && x <= p.rect[2] && y >= p.rect[1] && y <= p.rect[3] ? 0 : Infinity) : Math.hypot(p.x - x, p.y - y);
      if (d <= distance) { best = p; distance = d; }
    }
    return best;
  }

  begin() {
    const ratio = window.devicePixelRatio || 1;
    this.width = Math.max(200, this.root.clientWidth);
    this.canvas.width = Math.round(this.width * ratio);
    this.canvas.height = Math.round(this.height * ratio);
    this.canvas.style.height = this.height + 'px';
    const g = this.canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, this.width, this.height);
    g.font = '11px system-ui, sans-serif';
    this.points = [];
    return g;
  }

  // The y axis of [low, high] with its label; returns the value -> pixel function.
  yAxis(g, low, high, label, logScale = false) {
    const top = PAD.top;
    const bottom = this.height - PAD.bottom;
    const f = logScale ? Math.log10 : (v) => v;
    const [a, b] = [f(low), f(high)];
    const y = (v) => bottom - ((f(v) - a) / (b - a || 1)) * (bottom - top);
    g.strokeStyle = '#e2e6ec';
    g.fillStyle = '#4b5563';
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    const ticks = logScale
      ? niceTicks(a, b, 4).filter((v) => Number.isInteger(v)).map((v) => Math.pow(10, v))
      : niceTicks(low, high, 5);
    for (const v of ticks) {
      const py = Math.round(y(v)) + 0.5;
      g.beginPath(); g.moveTo(PAD.left, py); g.lineTo(this.width - PAD.right, py); g.stroke();
      g.fillText(format(v, 3), PAD.left - 6, py);
    }
    g.save();
    g.translate(14, (top + bottom) / 2);
    g.rotate(-Math.PI / 2);
    g.textAlign = 'center';
    g.fillText(label, 0, 0);
    g.restore();
    return y;
  }
}

// Box plots: groups (e.g. worlds) of boxes (e.g. variants). boxes: [{group, label, colour,
// values: [{value, run, name}]}]. A box is the quartiles, the median line, whiskers to the
// farthest value within 1.5 IQR, and every run as a jittered point; runs without a value are
// counted under the box ("n/a k").
export function drawBoxPlots(chart, boxes, groups, yLabel, logScale) {
  const g = chart.begin();
  const finite = boxes.flatMap((b) => b.values.map((v) => v.value)).filter((v) => Number.isFinite(v) && (!logScale || v > 0));
  let low = finite.length ? lowest(finite) : 0;
  let high = finite.length ? highest(finite) : 1;
  if (logScale) { low /= 1.3; high *= 1.3; } else {
    const pad = 0.06 * (high - low || Math.abs(high) || 1);
    low -= pad; high += pad;
  }
  const y = chart.yAxis(g, low, high, yLabel, logScale);
  const slots = boxes.length + Math.max(0, groups.length - 1);  // one empty slot between groups
  const slot = (chart.width - PAD.left - PAD.right) / Math.max(1, slots);
  const drawn = [];
  let index = 0;
  let previousGroup = null;
  const groupSpans = {};
  for (const box of boxes) {
    if (previousGroup !== null && box.group !== previousGroup) index += 1;
    previousGroup = box.group;
    const cx = PAD.left + (index + 0.5) * slot;
    index += 1;
    (groupSpans[box.group] = groupSpans[box.group] || []).push(cx);
    const values = box.values.filter((v) => Number.isFinite(v.value) && (!logScale || v.value > 0));
    const half = Math.min(26, 0.32 * slot);
    if (values.length) {
      const numbers = values.map((v) => v.value);
      const [q1, median, q3] = [0.25, 0.5, 0.75].map((q) => quantile(numbers, q));
      const iqr = q3 - q1;
      const lowWhisker = lowest(numbers.filter((v) => v >= q1 - 1.5 * iqr));
      const highWhisker = highest(numbers.filter((v) => v <= q3 + 1.5 * iqr));
      g.strokeStyle = box.colour;
      g.fillStyle = box.colour + '33';
      g.lineWidth = 1.4;
      g.fillRect(cx - half, y(q3), 2 * half, y(q1) - y(q3));
      g.strokeRect(cx - half, y(q3), 2 * half, y(q1) - y(q3));
      g.beginPath();
      g.moveTo(cx - half, y(median)); g.lineTo(cx + half, y(median));
      g.moveTo(cx, y(q3)); g.lineTo(cx, y(highWhisker));
      g.moveTo(cx, y(q1)); g.lineTo(cx, y(lowWhisker));
      g.moveTo(cx - half / 2, y(highWhisker)); g.lineTo(cx + half / 2, y(highWhisker));
      g.moveTo(cx - half / 2, y(lowWhisker)); g.lineTo(cx + half / 2, y(lowWhisker));
      g.stroke();
      values.forEach((v, k) => {
        // Deterministic jitter: the same page draws the same points.
        const px = cx + ((((k * 2654435761) >>> 0) % 1000) / 1000 - 0.5) * half * 1.2;
        const py = y(v.value);
        g.fillStyle = box.colour;
        g.beginPath(); g.arc(px, py, 3, 0, 2 * Math.PI); g.fill();
        chart.points.push({ x: px, y: py, run: v.run, label: `${v.name}\n${format(v.value, 4)}` });
      });
    }
    const missing = box.values.length - values.length;
    g.fillStyle = '#4b5563';
    g.textAlign = 'center';
    g.textBaseline = 'top';
    const shown = fitText(g, `${box.label}`, slot - 4);
    g.fillText(shown, cx, chart.height - PAD.bottom + 6);
    chart.points.push({ rect: [cx - slot / 2, chart.height - PAD.bottom + 4, cx + slot / 2, chart.height - PAD.bottom + 30], label: `${box.group ? box.group + ' ' : ''}${box.label}\nn=${values.length}` });
    g.fillStyle = '#94a3b8';
    g.fillText(fitText(g, `n=${values.length}${missing ? ` · n/a ${missing}` : ''}`, slot - 4), cx, chart.height - PAD.bottom + 20);
    drawn.push({ group: box.group, label: box.label, n: values.length, missing, labelWidth: g.measureText(shown).width, slot });
  }
  g.fillStyle = '#0f172a';
  g.font = '600 12px system-ui, sans-serif';
  for (const [group, xs] of Object.entries(groupSpans)) {
    if (groups.length > 1 || group) g.fillText(fitText(g, group, highest(xs) - lowest(xs) + slot - 4), (lowest(xs) + highest(xs)) / 2, chart.height - PAD.bottom + 36);
  }
  return drawn;
}

// A scatter of points [{x, y, colour, run, name}] with its axes.
export function drawScatter(chart, points, xLabel, yLabel, logScale) {
  const g = chart.begin();
  const ok = points.filter((p) => Number.isFinite(p.x) && Number.isFinite(p.y) && (!logScale || p.y > 0));
  const xs = ok.map((p) => p.x);
  const ys = ok.map((p) => p.y);
  let [x0, x1] = xs.length ? [lowest(xs), highest(xs)] : [0, 1];
  let [y0, y1] = ys.length ? [lowest(ys), highest(ys)] : [0, 1];
  const xp = 0.05 * (x1 - x0 || Math.abs(x1) || 1);
  x0 -= xp; x1 += xp;
  if (logScale) { y0 /= 1.3; y1 *= 1.3; } else {
    const yp = 0.06 * (y1 - y0 || Math.abs(y1) || 1);
    y0 -= yp; y1 += yp;
  }
  const y = chart.yAxis(g, y0, y1, yLabel, logScale);
  const x = (v) => PAD.left + ((v - x0) / (x1 - x0)) * (chart.width - PAD.left - PAD.right);
  g.fillStyle = '#4b5563';
  g.textAlign = 'center';
  g.textBaseline = 'top';
  for (const v of niceTicks(x0, x1, Math.max(2, Math.floor(chart.width / 110)))) g.fillText(format(v, 3), x(v), chart.height - PAD.bottom + 6);
  g.fillText(xLabel, (PAD.left + chart.width - PAD.right) / 2, chart.height - PAD.bottom + 24);
  for (const p of ok) {
    g.fillStyle = p.colour;
    g.beginPath(); g.arc(x(p.x), y(p.y), 3.5, 0, 2 * Math.PI); g.fill();
    chart.points.push({ x: x(p.x), y: y(p.y), run: p.run, label: `${p.name}\n${xLabel} ${format(p.x, 4)}\n${format(p.y, 4)}` });
  }
  const missing = points.length - ok.length;
  if (missing) {
    g.fillStyle = '#94a3b8';
    g.textAlign = 'right';
    g.fillText(`${missing} run${missing > 1 ? 's' : ''} without a value`, chart.width - PAD.right, PAD.top);
  }
}

// Bars of rates in [0, 1]: [{group, label, colour, rate, count, total}].
export function drawRates(chart, bars, groups) {
  const g = chart.begin();
  const y = chart.yAxis(g, 0, 1.05, 'success rate');
  const slots = bars.length + Math.max(0, groups.length - 1);
  const slot = (chart.width - PAD.left - PAD.right) / Math.max(1, slots);
  let index = 0;
  let previous = null;
  const spans = {};
  for (const bar of bars) {
    if (previous !== null && bar.group !== previous) index += 1;
    previous = bar.group;
    const cx = PAD.left + (index + 0.5) * slot;
    index += 1;
    (spans[bar.group] = spans[bar.group] || []).push(cx);
    const half = Math.min(24, 0.34 * slot);
    g.fillStyle = bar.colour;
    g.fillRect(cx - half, y(bar.rate), 2 * half, y(0) - y(bar.rate));
    chart.points.push({ rect: [cx - half, y(1.05), cx + half, y(0)], label: `${bar.group} ${bar.label}\n${bar.count} / ${bar.total}` });
    g.fillStyle = '#0f172a';
    g.textAlign = 'center';
    g.textBaseline = 'bottom';
    g.fillText(`${bar.count}/${bar.total}`, cx, y(bar.rate) - 2);
    g.textBaseline = 'top';
    g.fillStyle = '#4b5563';
    g.fillText(fitText(g, bar.label, slot - 4), cx, chart.height - PAD.bottom + 6);
  }
  g.fillStyle = '#0f172a';
  g.font = '600 12px system-ui, sans-serif';
  for (const [group, xs] of Object.entries(spans)) g.fillText(fitText(g, group, highest(xs) - lowest(xs) + slot - 4), (lowest(xs) + highest(xs)) / 2, chart.height - PAD.bottom + 22);
}

// A heatmap of a metric over two swept keys: a cell per pair of values (xs by ys, in the
// study's order), coloured by the median of its runs' finite values (light low, dark high),
// the median written in it. cells: [{x, y, median, n}]. Returns the cells drawn.
export function drawHeatmap(chart, xValues, yValues, cells, xLabel, yLabel, valueLabel) {
  const g = chart.begin();
  const left = PAD.left + 30;
  const width = (chart.width - left - PAD.right) / Math.max(1, xValues.length);
  const height = (chart.height - PAD.top - PAD.bottom) / Math.max(1, yValues.length);
  const finite = cells.filter((c) => Number.isFinite(c.median)).map((c) => c.median);
  const [low, high] = finite.length ? [lowest(finite), highest(finite)] : [0, 1];
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  for (const c of cells) {
    const x0 = left + xValues.indexOf(c.x) * width;
    const y0 = PAD.top + (yValues.length - 1 - yValues.indexOf(c.y)) * height;
    const f = Number.isFinite(c.median) ? (c.median - low) / (high - low || 1) : null;
    g.fillStyle = f === null ? '#f1f5f9' : `hsl(215, 70%, ${Math.round(92 - 57 * f)}%)`;
    g.fillRect(x0 + 1, y0 + 1, width - 2, height - 2);
    g.fillStyle = f !== null && f > 0.55 ? '#ffffff' : '#0f172a';
    g.fillText(fitText(g, format(c.median, 3), width - 4), x0 + width / 2, y0 + height / 2);
    chart.points.push({ rect: [x0, y0, x0 + width, y0 + height], label: `${xLabel} ${format(c.x, 4)}, ${yLabel} ${format(c.y, 4)}\n${valueLabel}: median ${format(c.median, 4)} (${c.n} runs)` });
  }
  g.fillStyle = '#4b5563';
  xValues.forEach((v, i) => g.fillText(fitText(g, format(v, 3), width - 4), left + (i + 0.5) * width, chart.height - PAD.bottom + 12));
  g.textAlign = 'right';
  yValues.forEach((v, i) => g.fillText(fitText(g, format(v, 3), left - 8), left - 4, PAD.top + (yValues.length - 0.5 - i) * height));
  g.textAlign = 'center';
  g.fillText(xLabel, (left + chart.width - PAD.right) / 2, chart.height - PAD.bottom + 32);
  g.save();
  g.translate(14, (PAD.top + chart.height - PAD.bottom) / 2);
  g.rotate(-Math.PI / 2);
  g.fillText(yLabel, 0, 0);
  g.restore();
  return cells;
}
