// Entry of the page of `wpg view`: reads the data embedded in the page and builds the run's
// scene or the study's dashboard. An error is shown on the page and thrown to the console
// (the tests read the console: a page that works logs no error).
import { element, readPageData } from './data.js';
import { dashboardPage } from './dashboard_page.js';
import { scenePage } from './scene_page.js';
import { showProvenance } from './page_header.js';

function start() {
  const app = document.getElementById('app');
  try {
    const data = readPageData();
    showProvenance(data);
    if (data.kind === 'run') scenePage(app, data);
    else if (data.kind === 'dashboard') dashboardPage(app, data);
    else throw new Error('unknown page kind ' + data.kind);
  } catch (error) {
    app.append(element('pre', { class: 'error', text: 'wpg view: ' + (error && error.stack ? error.stack : error) }));
    throw error;
  }
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
