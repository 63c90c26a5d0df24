// Plots against time under the scene (drawn on canvases by this file: no plotting library):
// CoM and CoP x, CoM and CoP y, and the NMPC solve time per iteration coloured by status, with
// the support phases shaded. The curves are drawn once; the cursor (the current time, with the
// values there) on an overlay canvas at every frame. A click or a drag on a plot seeks.
import { COLOURS, STATUS_STYLE, element, format, highest, quantile, sampleAt } from './data.js';

const PAD = { left: 54, right: 12, top: 24, bottom: 22 };

function niceTicks(low, high, count) {
  const span = high - low || 1;
  const step0 = span / Math.max(1, count);
  const power = Math.pow(10, Math.floor(Math.log10(step0)));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * power).find((s) => s >= step0) || step0;
  const ticks = [];
  for (let v = Math.ceil(low / step) * step; v <= high + 1e-9 * span; v += step) ticks.push(Math.abs(v) < 1e-12 * span ? 0 : v);
  return ticks;
}

class TimePlot {
  // series: [{label, colour, time, values, stride, offset, unit, width, dash}]
  constructor(container, options) {
    this.options = options;
    this.root = element('div', { class: 'plot' });
    this.header = element('div', { class: 'plot-header' }, [element('span', { class: 'plot-title', text: options.title })]);
    this.readout = element('span', { class: 'plot-readout' });
    this.header.append(this.readout);
    this.base = element('canvas');
    this.overlay = element('canvas', { class: 'overlay' });
    const stack = element('div', { class: 'plot-canvas' }, [this.base, this.overlay]);
    this.root.append(this.header, stack);
    container.append(this.root);
    this.stack = stack;
    let dragging = false;
    const seek = (event) => {
      const box = this.overlay.getBoundingClientRect();
      const x = event.clientX - box.left;
      options.onSeek(this.timeAt(x));
    };
    this.overlay.addEventListener('pointerdown', (event) => { dragging = true; this.overlay.setPointerCapture(event.pointerId); seek(event); });
    this.overlay.addEventListener('pointermove', (event) => { if (dragging) seek(event); });
    this.overlay.addEventListener('pointerup', () => { dragging = false; });
    new ResizeObserver(() => this.layout()).observe(stack);
  }

  layout() {
    const ratio = window.devicePixelRatio || 1;
    const width = this.stack.clientWidth;
    const height = this.stack.clientHeight;
    if (!width || !height) return;
    for (const canvas of [this.base, this.overlay]) {
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
      canvas.style.width = width + 'px';
      canvas.style.height = height + 'px';
    }
    this.width = width;
    this.height = height;
    this.ratio = ratio;
    this.drawBase();
    if (this.cursorTime !== undefined) this.setCursor(this.cursorTime, true);
  }

  x(t) { const [t0, t1] = this.options.timeRange; return PAD.left + ((t - t0) / (t1 - t0 || 1)) * (this.width - PAD.left - PAD.right); }
  y(v) { const [v0, v1] = this.range; return this.height - PAD.bottom - ((v - v0) / (v1 - v0 || 1)) * (this.height - PAD.top - PAD.bottom); }
  timeAt(x) { const [t0, t1] = this.options.timeRange; return t0 + ((x - PAD.left) / (this.width - PAD.left - PAD.right)) * (t1 - t0); }

  drawBase() {
    const o = this.options;
    const g = this.base.getContext('2d');
    g.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
    g.clearRect(0, 0, this.width, this.height);
    this.range = o.range();
    const [t0, t1] = o.timeRange;
    const top = PAD.top;
    const bottom = this.height - PAD.bottom;
    for (const [s0, s1, state] of o.spans || []) {
      g.fillStyle = state === 1 ? 'rgba(31,119,180,0.08)' : 'rgba(214,39,40,0.08)';
      g.fillRect(this.x(s0), top, this.x(s1) - this.x(s0), bottom - top);
    }
    g.strokeStyle = '#d5dae1';
    g.fillStyle = '#4b5563';
    g.font = '11px system-ui, sans-serif';
    g.lineWidth = 1;
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    for (const v of niceTicks(this.range[0], this.range[1], 4)) {
      const y = Math.round(this.y(v)) + 0.5;
      g.beginPath(); g.moveTo(PAD.left, y); g.lineTo(this.width - PAD.right, y); g.stroke();
      g.fillText(format(v * (o.scale || 1), 3), PAD.left - 6, y);
    }
    g.textAlign = 'center';
    g.textBaseline = 'top';
    for (const t of niceTicks(t0, t1, Math.max(2, Math.floor(this.width / 90)))) {
      const x = Math.round(this.x(t)) + 0.5;
      g.beginPath(); g.moveTo(x, top); g.lineTo(x, bottom); g.stroke();
      g.fillText(format(t, 3) + (t === 0 ? ' s' : ''), x, bottom + 4);
    }
    g.save();
    g.translate(12, (top + bottom) / 2);
    g.rotate(-Math.PI / 2);
    g.textAlign = 'center';
    g.textBaseline = 'middle';
    g.fillText(o.yLabel, 0, 0);
    g.restore();
    g.save();
    g.beginPath();
    g.rect(PAD.left, top - 2, this.width - PAD.left - PAD.right, bottom - top + 4);
    g.clip();
    for (const s of o.series) this.drawSeries(g, s);
    g.restore();
    if (o.drawExtra) o.drawExtra(g, this);
  }

  drawSeries(g, s) {
    const n = s.time.length;
    if (s.dots) {
      for (let i = 0; i < n; ++i) {
        const v = s.values[i * (s.stride || 1) + (s.offset || 0)];
        g.fillStyle = s.colourOf ? s.colourOf(i) : s.colour;
        const clipped = v > this.range[1];
        const x = this.x(s.time[i]);
        const y = clipped ? PAD.top + 4 : this.y(v);
        g.beginPath();
        if (clipped) { g.moveTo(x, y - 5); g.lineTo(x - 5, y + 4); g.lineTo(x + 5, y + 4); g.closePath(); }
        else g.arc(x, y, s.radius ? s.radius(i) : 2.2, 0, 2 * Math.PI);
        g.fill();
      }
      return;
    }
    // One vertex per pixel column at most: min and max of the samples that fall in it.
    g.strokeStyle = s.colour;
    g.lineWidth = s.width || 1.4;
    g.setLineDash(s.dash || []);
    g.beginPath();
    let column = -Infinity;
    let low = 0;
    let high = 0;
    let started = false;
    const flush = () => {
      if (column === -Infinity) return;
      if (!started) { g.moveTo(column, this.y(low)); started = true; } else g.lineTo(column, this.y(low));
      if (high !== low) g.lineTo(column, this.y(high));
    };
    for (let i = 0; i < n; ++i) {
      const x = Math.round(this.x(s.time[i]));
      const v = s.values[i * (s.stride || 1) + (s.offset || 0)];
      if (x !== column) { flush(); column = x; low = v; high = v; } else { low = Math.min(low, v); high = Math.max(high, v); }
    }
    flush();
    g.stroke();
    g.setLineDash([]);
  }

  setCursor(t, force = false, text = true) {
    if (!this.width || (!force && t === this.cursorTime)) { this.cursorTime = t; return; }
    this.cursorTime = t;
    const g = this.overlay.getContext('2d');
    g.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
    g.clearRect(0, 0, this.width, this.height);
    const x = Math.round(this.x(t)) + 0.5;
    g.strokeStyle = '#0f172a';
    g.lineWidth = 1.2;
    g.beginPath(); g.moveTo(x, PAD.top - 4); g.lineTo(x, this.height - PAD.bottom); g.stroke();
    const parts = [];
    for (const s of this.options.series) {
      if (!text && s.dots) continue;
      if (!s.time.length || s.noReadout) continue;
      const i = sampleAt(s.time, t);
      const v = s.values[i * (s.stride || 1) + (s.offset || 0)];
      if (!s.dots && v >= this.range[0] && v <= this.range[1]) {
        g.fillStyle = s.colour;
        g.beginPath(); g.arc(this.x(s.time[i]), this.y(v), 3.2, 0, 2 * Math.PI); g.fill();
      }
      if (!text) continue;
      parts.push(`<b style="color:${s.readoutColour || s.colour}">${s.label}</b> ${readout(v, s.unit)}`);
    }
    if (!text) return;
    if (this.options.extraReadout) parts.push(this.options.extraReadout(t));
    this.readout.innerHTML = parts.join(' · ');
  }
}

// A value of the readout: metres to the millimetre, microseconds to the unit.
function readout(value, unit) {
  const digits = unit === 'm' ? 3 : 0;
  const text = (Math.abs(value) < 0.5 * Math.pow(10, -digits) ? 0 : value).toFixed(digits);
  return text + (unit ? ' ' + unit : '');
}

// Shaded single-support spans [(t0, t1, 1 left | 2 right)] of the support codes.
function supportSpans(time, support) {
  const spans = [];
  let start = 0;
  for (let i = 1; i <= time.length; ++i) {
    if (i === time.length || support[i] !== support[start]) {
      if (support[start] === 1 || support[start] === 2) spans.push([time[start], time[Math.min(i, time.length - 1)], support[start]]);
      start = i;
    }
  }
  return spans;
}

// [min, max] of the columns of the series, padded by 8 %.
function rangeOf(series) {
  let low = Infinity;
  let high = -Infinity;
  for (const s of series) {
    for (let i = 0; i < s.time.length; ++i) {
      const v = s.values[i * (s.stride || 1) + (s.offset || 0)];
      if (v < low) low = v;
      if (v > high) high = v;
    }
  }
  if (!(high > low)) { low -= 0.05; high += 0.05; }
  const pad = 0.08 * (high - low);
  return [low - pad, high + pad];
}

export function buildTimePlots(container, walk, onSeek) {
  const timeRange = [walk.time[0], walk.time[walk.time.length - 1]];
  const spans = supportSpans(walk.time, walk.support);
  const plots = [];
  for (const [axis, column] of [['x', 0], ['y', 1]]) {
    const series = [
      { label: 'CoP ' + axis, colour: COLOURS.cop, time: walk.time, values: walk.cop, stride: 2, offset: column, unit: 'm', width: 1.2 },
      { label: 'CoM ' + axis, colour: COLOURS.com, time: walk.time, values: walk.com, stride: 3, offset: column, unit: 'm', width: 1.8 },
    ];
    if (walk.zmpMultibody.length) {
      series.push({ label: 'multibody ZMP ' + axis, colour: COLOURS.zmp, time: walk.time, values: walk.zmpMultibody, stride: 2, offset: column, unit: 'm', width: 1, dash: [4, 3] });
    }
    plots.push(new TimePlot(container, {
      title: `CoM and CoP ${axis} [m]` + (walk.zmpMultibody.length ? ', multibody ZMP before the filter' : ''),
      yLabel: axis + ' [m]', series, spans, timeRange, onSeek, range: () => rangeOf(series),
    }));
  }
  if (walk.mpc.time.length) plots.push(solveTimePlot(container, walk, spans, timeRange, onSeek));
  return plots;
}

// The NMPC solve time: a scale that shows the typical iteration, the iterations above it drawn
// as triangles on the top edge, counted in the title.
function solveTimePlot(container, walk, spans, timeRange, onSeek) {
  const mpc = walk.mpc;
  const micro = Array.from(mpc.solveTime, (s) => 1e6 * s);
  // As the PNG figure (analysis/run_figure/time_panels.py): 1.5 times the largest iteration,
  // unless it is above twice the 98th percentile; then twice that percentile.
  const p98 = quantile(micro, 0.98);
  const typicalTop = Math.max(highest(micro) <= 2 * p98 ? 1.5 * highest(micro) : 2 * p98, 1e-3);
  const largest = highest(micro);
  const outliers = micro.filter((v) => v > typicalTop).length;
  const counts = {};
  mpc.status.forEach((code) => { counts[code] = (counts[code] || 0) + 1; });
  const legend = Object.entries(counts).map(([code, count]) => {
    const [name, colour] = STATUS_STYLE[code] || ['status ' + code, '#000'];
    return `<span class="swatch" style="background:${colour}"></span>${name} ${count}`;
  }).join(' ');
  const series = [{
    label: 'solve', colour: '#64748b', time: mpc.time, values: micro, unit: 'µs', dots: true,
    colourOf: (i) => (STATUS_STYLE[mpc.status[i]] || ['', '#000'])[1],
    radius: (i) => (mpc.status[i] === 0 ? 2.2 : 3.6), readoutColour: '#334155',
  }];
  const plot = new TimePlot(container, {
    title: `NMPC solve time per iteration [µs]: median ${format(quantile(micro, 0.5), 3)}, max ${format(largest, 3)}` +
      (outliers ? ` (${outliers} above the scale, ▲)` : ''),
    yLabel: 'solve [µs]', series, spans, timeRange, onSeek, range: () => [0, typicalTop],
    extraReadout: (t) => (STATUS_STYLE[mpc.status[sampleAt(mpc.time, t)]] || ['status'])[0],
  });
  const status = element('span', { class: 'plot-legend' });
  status.innerHTML = legend;
  plot.header.insertBefore(status, plot.readout);
  return plot;
}
