// The header line of every page: what is shown, and who wrote the page, where and when (the
// provenance that every file of wpg carries: version, commit, machine, date).
import { element } from './data.js';

export function showProvenance(data) {
  const header = document.getElementById('top');
  if (!header) return;
  const p = data.provenance || {};
  const parts = [element('h1', { text: data.title || 'wpg view' })];
  if (data.subtitle) parts.push(element('span', { class: 'subtitle', text: data.subtitle }));
  if (data.back) parts.push(element('a', { class: 'back', href: data.back, text: '← ' + (data.back_label || 'back') }));
  parts.push(element('span', {
    class: 'provenance',
    text: `${p.source || ''} · wpg ${p.version || '?'} (${p.commit || 'unknown'}) · ${p.machine || '?'} · ${p.date || '?'}`,
  }));
  for (const part of parts) header.append(part);
  document.title = data.title || 'wpg view';
}
