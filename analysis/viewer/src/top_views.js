// Top views of runs for the dashboard: the obstacles (amber: unknown to the planner), their
// margins (dashed), the goal and its tolerance, and the CoM path of each run (one colour per
// variant; the end marked ● when the run reached its goal or succeeded, ✕ otherwise).
// Hovering names the nearest path, a click opens its run.
import { COLOURS, element, floats } from './data.js';

export function boundsOf(items) {
  let [x0, x1, y0, y1] = [Infinity, -Infinity, Infinity, -Infinity];
  const add = (x, y) => { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); };
  for (const item of items) {
    const path = item.path || floats(item.top.path);
    for (let i = 0; i < path.length; i += 2) add(path[i], path[i + 1]);
    const top = item.top;
    for (const o of top.obstacles) {
      const r = o.radius + o.margin;
      if (o.outline.length) for (const [x, y] of o.outline) { add(x - o.margin, y - o.margin); add(x + o.margin, y + o.margin); }
      else { add(o.center[0] - r, o.center[1] - r); add(o.center[0] + r, o.center[1] + r); }
    }
    if (top.goal) { add(top.goal[0] - top.goal[2], top.goal[1] - top.goal[2]); add(top.goal[0] + top.goal[2], top.goal[1] + top.goal[2]); }
  }
  const pad = 0.08 * Math.max(x1 - x0, y1 - y0, 0.5);
  return [x0 - pad, x1 + pad, y0 - pad, y1 + pad];
}

// items: [{top, colour, run, name}]; the obstacles and goal are those of the first item
// (the runs of one world and seed share them).
// `bounds` [x0, x1, y0, y1]: a scale shared by several views (default: fitted to the items).
export function topView(container, items, caption, onOpen, bounds = null) {
  const canvas = element('canvas');
  const box = element('div', { class: 'top-view' }, [canvas, caption]);
  container.append(box);
  for (const item of items) item.path = floats(item.top.path);
  const draw = () => {
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth || 230;
    const height = canvas.clientHeight || 172;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    const g = canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = '#f8fafc';
    g.fillRect(0, 0, width, height);
    const [x0, x1, y0, y1] = bounds || boundsOf(items);
    const scale = Math.min(width / (x1 - x0), height / (y1 - y0));
    const ox = (width - scale * (x1 - x0)) / 2;
    const oy = (height - scale * (y1 - y0)) / 2;
    const px = (x) => ox + (x - x0) * scale;
    const py = (y) => height - oy - (y - y0) * scale;
    const first = items[0].top;
    for (const o of first.obstacles) {
      const colour = o.known ? COLOURS.obstacle : COLOURS.unknownObstacle;
      g.fillStyle = colour;
      g.strokeStyle = colour;
      g.beginPath();
      if (o.type === 'circle') g.arc(px(o.center[0]), py(o.center[1]), o.radius * scale, 0, 2 * Math.PI);
      else o.outline.forEach(([x, y], k) => (k ? g.lineTo(px(x), py(y)) : g.moveTo(px(x), py(y))));
      g.closePath();
      g.globalAlpha = 0.75;
      g.fill();
      g.globalAlpha = 1;
      if (o.margin > 0) {
        g.setLineDash([3, 3]);
        g.beginPath();
        if (o.type === 'circle') g.arc(px(o.center[0]), py(o.center[1]), (o.radius + o.margin) * scale, 0, 2 * Math.PI);
        else {
          // The outline grown by the margin, drawn as its offset corners joined by arcs.
          const [cx, cy] = o.outline.reduce(([a, b], [x, y]) => [a + x / o.outline.length, b + y / o.outline.length], [0, 0]);
          o.outline.forEach(([x, y], k) => {
            const d = Math.hypot(x - cx, y - cy) || 1;
            const gx = x + ((x - cx) / d) * o.margin;
            const gy = y + ((y - cy) / d) * o.margin;
            if (k) g.lineTo(px(gx), py(gy)); else g.moveTo(px(gx), py(gy));
          });
          g.closePath();
        }
        g.stroke();
        g.setLineDash([]);
      }
    }
    if (first.goal) {
      const [gx, gy, tolerance] = first.goal;
      g.fillStyle = COLOURS.goal + '88';
      g.strokeStyle = '#a16207';
      g.beginPath(); g.arc(px(gx), py(gy), Math.max(3, tolerance * scale), 0, 2 * Math.PI); g.fill(); g.stroke();
    }
    for (const item of items) {
      const p = item.path;
      g.strokeStyle = item.colour;
      g.lineWidth = 1.6;
      g.beginPath();
      for (let i = 0; i < p.length; i += 2) (i ? g.lineTo(px(p[i]), py(p[i + 1])) : g.moveTo(px(p[i]), py(p[i + 1])));
      g.stroke();
      const end = [px(p[p.length - 2]), py(p[p.length - 1])];
      g.fillStyle = item.colour;
      g.strokeStyle = item.colour;
      if (item.top.reached) { g.beginPath(); g.arc(end[0], end[1], 3, 0, 2 * Math.PI); g.fill(); } else if (item.top.blocked) {
        g.fillRect(end[0] - 3.5, end[1] - 3.5, 7, 7);  // stuck: the run ended blocked
      } else {
        g.beginPath();
        g.moveTo(end[0] - 4, end[1] - 4); g.lineTo(end[0] + 4, end[1] + 4);
        g.moveTo(end[0] + 4, end[1] - 4); g.lineTo(end[0] - 4, end[1] + 4);
        g.stroke();
      }
      item.screen = [];
      for (let i = 0; i < p.length; i += 2) item.screen.push([px(p[i]), py(p[i + 1])]);
    }
  };
  const nearest = (event) => {
    const r = canvas.getBoundingClientRect();
    const x = event.clientX - r.left;
    const y = event.clientY - r.top;
    let best = null;
    let distance = 14;
    for (const item of items) {
      for (const [sx, sy] of item.screen || []) {
        const d = Math.hypot(sx - x, sy - y);
        if (d < distance) { distance = d; best = item; }
      }
    }
    return best || (items.length === 1 ? items[0] : null);
  };
  canvas.addEventListener('mousemove', (event) => { const item = nearest(event); canvas.title = item ? item.name : ''; });
  canvas.addEventListener('click', (event) => { const item = nearest(event); if (item) onOpen(item.run); });
  // Drawn when it comes into view: a study of hundreds of runs lays out at once.
  new IntersectionObserver((entries, observer) => {
    if (entries.some((e) => e.isIntersecting)) { draw(); observer.disconnect(); }
  }).observe(canvas);
  return box;
}
