// The dashboard of a study, in the spirit of OMPL's Planner Arena: pick any metric of the
// summary table and see it per world × variant (box plots, every run a point) or against a
// swept key; the success rates; a top view of every run (every seed of every world); the table
// of runs. Every run opens its page (PAGE_runs/<run>.html, written beside the dashboard).
import { VARIANT_COLOURS, element, format, quantile } from './data.js';
import { Chart, drawBoxPlots, drawHeatmap, drawRates, drawScatter } from './charts.js';
import { parseFragment } from './player.js';
import { boundsOf, topView } from './top_views.js';

// Columns that are bookkeeping, not metrics of a run.
const NOT_METRICS = new Set(['index', 'done']);
const FIRST_METRICS = ['time_to_goal', 'path_length', 'distance', 'velocity_error_rms', 'cop_margin_min',
  'step_centre_clearance_min', 'steps', 'nmpc_time_p99'];
// A batch sweeps walking keys on a velocity command: how well it tracked and balanced first
// (its path length mostly repeats the commanded speed).
const FIRST_BATCH_METRICS = ['velocity_error_rms', 'cop_margin_min', 'steady_tracking', 'step_feasibility_margin_min',
  'nmpc_time_p99', 'path_length'];
const SHOWN_TOP_VIEWS = 240;  // more are drawn on request: a canvas each
const SHOWN_TABLE_ROWS = 500;  // rows of the runs table, in its order; more on request

function card(title, note) {
  const body = element('div');
  const node = element('section', { class: 'card' }, [element('h2', { text: title })]);
  if (note) node.append(element('p', { class: 'note', text: note }));
  node.append(body);
  return [node, body];
}

function select(label, options, value, onChange) {
  const node = element('select', {}, options.map(([v, text]) => element('option', { value: v, text })));
  node.value = value;
  node.addEventListener('change', () => onChange(node.value));
  return element('label', {}, [label + ' ', node]);
}

export function dashboardPage(app, data) {
  const columns = {};
  for (const c of data.columns) columns[c.name] = c;
  const runs = data.runs;
  const rows = runs.length;
  const names = columns.name ? columns.name.values : runs.map((_, i) => String(i));
  const open = (row) => { if (runs[row]) window.location.href = runs[row].page; };
  const swept = data.columns.filter((c) => c.name.startsWith('sweep.'));
  const metrics = data.columns.filter((c) => !NOT_METRICS.has(c.name) && !c.name.startsWith('sweep.') &&
    c.values.every((v) => v === null || typeof v === 'number'));
  const comparison = data.comparison;
  const worldOf = (row) => (comparison ? columns['sweep.world'].values[row] : '');
  const variantOf = (row) => (comparison ? columns['sweep.variant'].values[row] : '');
  const variantColour = (variant) => VARIANT_COLOURS[Math.max(0, (data.variants || []).indexOf(variant)) % VARIANT_COLOURS.length];
  const reachedOf = (row) => {
    if (columns.goal_reached) return columns.goal_reached.values[row] === 1;
    if (columns.exit_status) return columns.exit_status.values[row] === 0;
    return runs[row] ? runs[row].top.success : false;
  };
  // What the tests read: the world × variant cells each chart drew.
  const published = (window.wpgDashboard = { rows, boxCells: [], rateCells: [], topViews: 0 });

  const dashboard = element('div', { class: 'dashboard' });
  app.append(dashboard);

  // --- the metric -------------------------------------------------------------------------
  const [metricCard, metricBody] = card('Metric', comparison
    ? 'Every run is a point (a click opens it); the box spans the quartiles, the whiskers 1.5 IQR.'
    : 'Every run is a point (a click opens it).');
  dashboard.append(metricCard);
  // The first metric of FIRST_METRICS that varies between the runs, else the first that does.
  const varies = (c) => new Set(c.values.filter((v) => Number.isFinite(v))).size > 1;
  const preferred = (comparison ? FIRST_METRICS : FIRST_BATCH_METRICS).find((name) => columns[name] && varies(columns[name])) ||
    (metrics.find(varies) || {}).name;
  const axisOptions = [];
  if (comparison) axisOptions.push(['cells', 'world × variant']);
  const sweptKeys = swept.filter((c) => c.name !== 'sweep.world' && c.name !== 'sweep.variant');
  for (const c of sweptKeys) axisOptions.push([c.name, 'against ' + c.name.slice(6)]);
  // Two swept keys at once: a heatmap of the metric's median per pair of values.
  for (let i = 0; i < sweptKeys.length; ++i) {
    for (let j = i + 1; j < sweptKeys.length; ++j) {
      axisOptions.push([`heatmap:${sweptKeys[i].name}:${sweptKeys[j].name}`, `heatmap ${sweptKeys[i].name.slice(6)} × ${sweptKeys[j].name.slice(6)}`]);
    }
  }
  axisOptions.push(['index', 'against the run index']);
  // The metric and the view are in the URL (#metric=...&view=...): a link opens the same chart.
  const fragment = parseFragment(window.location.hash);
  const state = {
    metric: columns[fragment.metric] && metrics.includes(columns[fragment.metric]) ? fragment.metric : preferred || (metrics[0] && metrics[0].name),
    axis: axisOptions.some(([v]) => v === fragment.view) ? fragment.view : comparison ? 'cells' : (swept[0] ? swept[0].name : 'index'),
    log: fragment.log === '1',
  };
  const remember = () => {
    const hash = `#metric=${encodeURIComponent(state.metric)}&view=${encodeURIComponent(state.axis)}${state.log ? '&log=1' : ''}`;
    window.history.replaceState(null, '', hash);
  };
  const pickers = element('div', { class: 'pickers' }, [
    select('metric', metrics.map((c) => [c.name, `${c.name}${c.unit && c.unit !== '1' ? ' [' + c.unit + ']' : ''}`]), state.metric, (v) => { state.metric = v; drawMetric(); }),
    select('view', axisOptions, state.axis, (v) => { state.axis = v; drawMetric(); }),
  ]);
  const log = element('label', {}, [element('input', { type: 'checkbox' }), ' log scale']);
  log.firstChild.checked = state.log;
  log.firstChild.addEventListener('change', () => { state.log = log.firstChild.checked; drawMetric(); });
  pickers.append(log);
  metricBody.append(pickers);
  const metricChart = new Chart(metricBody, 340, open);

  function drawMetric() {
    const column = columns[state.metric];
    if (!column) return;
    remember();
    published.metric = state.metric;
    published.view = state.axis;
    const label = `${column.name}${column.unit && column.unit !== '1' ? ' [' + column.unit + ']' : ''}`;
    const done = (row) => runs[row] !== null;
    if (state.axis.startsWith('heatmap:')) {
      const [, xKey, yKey] = state.axis.split(':');
      const xs = columns[xKey].values;
      const ys = columns[yKey].values;
      const xValues = [...new Set(xs)];
      const yValues = [...new Set(ys)];
      const groups = new Map();
      for (let row = 0; row < rows; ++row) {
        if (!done(row)) continue;
        const key = xValues.indexOf(xs[row]) + ',' + yValues.indexOf(ys[row]);
        if (!groups.has(key)) groups.set(key, { x: xs[row], y: ys[row], values: [] });
        groups.get(key).values.push(column.values[row]);
      }
      const cells = [...groups.values()].map((c) => ({ x: c.x, y: c.y, median: quantile(c.values, 0.5), n: c.values.length }));
      published.heatCells = drawHeatmap(metricChart, xValues, yValues, cells, xKey.slice(6), yKey.slice(6), label)
        .map((c) => ({ x: c.x, y: c.y, median: c.median, n: c.n }));
    } else if (state.axis === 'cells') {
      const boxes = [];
      for (const world of data.worlds) {
        for (const variant of data.variants) {
          const values = [];
          for (let row = 0; row < rows; ++row) {
            if (done(row) && worldOf(row) === world && variantOf(row) === variant) values.push({ value: column.values[row], run: row, name: names[row] });
          }
          boxes.push({ group: world, label: variant, colour: variantColour(variant), values });
        }
      }
      published.boxCells = drawBoxPlots(metricChart, boxes, data.worlds, label, state.log);
    } else {
      const xs = state.axis === 'index' ? names.map((_, i) => i) : columns[state.axis].values;
      const distinct = [...new Set(xs)];
      const numeric = xs.every((v) => typeof v === 'number');
      const colourOf = (row) => (comparison ? variantColour(variantOf(row)) : reachedOf(row) ? '#2563eb' : '#d62728');
      if (!numeric || (distinct.length <= 12 && state.axis !== 'index')) {
        // Few values (or text): a box per value.
        const boxes = distinct.map((x) => ({
          group: '', label: String(x), colour: '#2563eb',
          values: xs.map((v, row) => ({ v, row })).filter(({ v, row }) => v === x && done(row)).map(({ row }) => ({ value: column.values[row], run: row, name: names[row] })),
        }));
        drawBoxPlots(metricChart, boxes, [''], label, state.log);
      } else {
        const points = [];
        for (let row = 0; row < rows; ++row) if (done(row)) points.push({ x: xs[row], y: column.values[row], colour: colourOf(row), run: row, name: names[row] });
        drawScatter(metricChart, points, state.axis === 'index' ? 'run index' : state.axis.slice(6), label, state.log);
      }
    }
  }

  // --- success rates ----------------------------------------------------------------------
  const [rateCard, rateBody] = card('Success rates', comparison
    ? 'Runs that reached the goal, per world and variant.'
    : 'Runs whose walk succeeded (exit status 0)' + (swept[0] ? ', per value of ' + swept[0].name.slice(6) : '') + '.');
  dashboard.append(rateCard);
  const rateChart = new Chart(rateBody, 260, open);
  function drawSuccess() {
    const bars = [];
    if (comparison) {
      for (const world of data.worlds) {
        for (const variant of data.variants) {
          let count = 0;
          let total = 0;
          for (let row = 0; row < rows; ++row) {
            if (runs[row] && worldOf(row) === world && variantOf(row) === variant) { total += 1; count += reachedOf(row) ? 1 : 0; }
          }
          bars.push({ group: world, label: variant, colour: variantColour(variant), rate: total ? count / total : 0, count, total });
        }
      }
      published.rateCells = bars.map((b) => ({ group: b.group, label: b.label, total: b.total }));
      drawRates(rateChart, bars, data.worlds);
    } else {
      const key = swept[0] ? swept[0].name : null;
      const values = key ? [...new Set(columns[key].values)] : ['all runs'];
      for (const value of values.slice(0, 40)) {
        let count = 0;
        let total = 0;
        for (let row = 0; row < rows; ++row) {
          if (runs[row] && (!key || columns[key].values[row] === value)) { total += 1; count += reachedOf(row) ? 1 : 0; }
        }
        bars.push({ group: '', label: typeof value === 'number' ? format(value, 3) : String(value), colour: '#2563eb', rate: total ? count / total : 0, count, total });
      }
      drawRates(rateChart, bars, ['']);
    }
  }

  // --- top views --------------------------------------------------------------------------
  const [topCard, topBody] = card('Top views', comparison
    ? 'Every seed of every world: the CoM path of each variant (● reached the goal, ■ ended blocked, ✕ did not reach it otherwise). A click opens the run nearest to it.'
    : 'Every run: its CoM path (● succeeded, ■ ended blocked, ✕ failed otherwise). A click opens it.');
  dashboard.append(topCard);
  if (comparison) {
    const key = element('div', { class: 'variant-key' }, data.variants.map((v) => element('span', {}, [element('span', { class: 'swatch', style: `background:${variantColour(v)}` }), v])));
    topBody.append(key);
    for (const world of data.worlds) {
      topBody.append(element('div', { class: 'world-title', text: world }));
      const grid = element('div', { class: 'tops' });
      topBody.append(grid);
      for (const seed of data.seeds) {
        const items = [];
        for (let row = 0; row < rows; ++row) {
          const rowSeed = columns['sweep.seed'].values[row];
          if (runs[row] && worldOf(row) === world && (rowSeed === seed || Number(rowSeed) === Number(seed))) {
            items.push({ top: runs[row].top, colour: variantColour(variantOf(row)), run: row, name: names[row] });
          }
        }
        if (!items.length) continue;
        const reached = items.filter((i) => i.top.reached).length;
        const blocked = items.filter((i) => i.top.blocked).length;
        const seedText = Number.isFinite(Number(seed)) ? format(Number(seed), 6) : seed;
        // One text, words apart: the caption reads the same aloud or copied as on the screen.
        const caption = `seed ${seedText} · ${reached}/${items.length} reached` + (blocked ? ` · ${blocked} blocked` : '');
        topView(grid, items, element('div', { class: 'caption' }, [element('span', { text: caption })]), open);
        published.topViews += 1;
      }
    }
  } else {
    const grid = element('div', { class: 'tops small' });
    topBody.append(grid);
    // One scale for every run: their lengths compare at a glance.
    const bounds = boundsOf(runs.filter((r) => r).map((r) => ({ top: r.top })));
    let shown = 0;
    const more = element('button', { class: 'link' });
    const showMore = () => {
      const until = Math.min(rows, shown + SHOWN_TOP_VIEWS);
      for (; shown < until; ++shown) {
        if (!runs[shown]) continue;
        const caption = [names[shown], ...swept.map((c) => `${c.name.slice(6)} ${format(c.values[shown], 3)}`)];
        const top = runs[shown].top;
        const colour = top.success ? '#2563eb' : top.blocked ? '#d97706' : '#d62728';
        topView(grid, [{ top, colour, run: shown, name: names[shown] }],
          element('div', { class: 'caption', title: caption.join('\n') }, [element('span', { text: caption[0] })]), open, bounds);
        published.topViews += 1;
      }
      more.textContent = shown < rows ? `show ${Math.min(SHOWN_TOP_VIEWS, rows - shown)} more of ${rows - shown}` : '';
    };
    more.addEventListener('click', showMore);
    topBody.append(more);
    showMore();
  }

  // --- the runs ---------------------------------------------------------------------------
  const [tableCard, tableBody] = card('Runs', 'A click on a header sorts; a click on a run opens it.');
  dashboard.append(tableCard);
  const shownColumns = ['name', ...swept.map((c) => c.name), ...(columns.goal_reached ? ['goal_reached'] : ['exit_status']),
    'blocked', 'blocked_since'];
  const table = element('table', { class: 'runs' });
  const tableBox = element('div', { class: 'table-box' }, [table]);
  tableBody.append(tableBox);
  let sortKey = null;
  let sortDown = false;
  let shownRows = SHOWN_TABLE_ROWS;
  const moreRows = element('button', { class: 'link' });
  moreRows.addEventListener('click', () => { shownRows += SHOWN_TABLE_ROWS; drawTable(); });
  tableBody.append(moreRows);
  function drawTable() {
    const keys = [...shownColumns, state.metric].filter((k, i, all) => columns[k] && all.indexOf(k) === i);
    const order = [];
    for (let row = 0; row < rows; ++row) if (runs[row]) order.push(row);
    if (sortKey) {
      const values = columns[sortKey].values;
      order.sort((a, b) => {
        const [x, y] = [values[a], values[b]];
        const c = typeof x === 'number' && typeof y === 'number' ? (Number.isFinite(x) ? x : Infinity) - (Number.isFinite(y) ? y : Infinity) : String(x).localeCompare(String(y));
        return sortDown ? -c : c;
      });
    }
    table.replaceChildren(element('tr', {}, keys.map((k) => element('th', {
      text: k.replace(/^sweep\./, '') + (sortKey === k ? (sortDown ? ' ▼' : ' ▲') : ''),
      onclick: () => { sortDown = sortKey === k ? !sortDown : false; sortKey = k; drawTable(); },
    }))));
    for (const row of order.slice(0, shownRows)) {
      const cells = keys.map((k, i) => {
        const v = columns[k].values[row];
        if (i === 0) return element('td', {}, [element('a', { href: runs[row].page, text: String(v) })]);
        return element('td', { text: v === null || typeof v === 'number' ? format(v, 4) : String(v) });
      });
      table.append(element('tr', { class: reachedOf(row) ? '' : 'failed' }, cells));
    }
    const hidden = order.length - Math.min(shownRows, order.length);
    moreRows.textContent = hidden ? `show ${Math.min(SHOWN_TABLE_ROWS, hidden)} more of ${hidden}` : '';
  }

  const drawAll = () => { drawMetric(); drawSuccess(); drawTable(); };
  drawAll();
  const originalMetric = drawMetric;
  // The table shows the chosen metric too.
  pickers.addEventListener('change', () => drawTable());
  window.addEventListener('resize', () => { originalMetric(); drawSuccess(); });
  document.body.dataset.wpgReady = '1';
}
