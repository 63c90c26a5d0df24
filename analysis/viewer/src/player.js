// Time of the page: play / pause, speed, the scrubber, and the URL fragment.
//
// The fragment is a contract (tests and users link to an instant): `#t=SECONDS` opens the page
// paused at that time of the walk (clamped to the walk). Without `t=` the walk plays from its
// start. More keys, joined with '&': `speed=X` (playback speed), `play` (play from t), and
// `measure=SECONDS`: count the animation frames drawn while playing for that long, then write
// the frames per second into #wpg-fps (its data-fps attribute) and the console
// ("wpg-fps <value>"), and pause.
import { element, format } from './data.js';

const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4];

export function parseFragment(hash) {
  const keys = {};
  for (const part of (hash || '').replace(/^#/, '').split('&')) {
    if (!part) continue;
    const [key, value] = part.split('=');
    keys[decodeURIComponent(key)] = value === undefined ? true : decodeURIComponent(value);
  }
  return keys;
}

export class Player {
  constructor(container, start, end, onTime, render, adapt = () => {}) {
    this.adapt = adapt;
    this.start = start;
    this.end = end;
    this.onTime = onTime;
    this.render = render;
    this.t = start;
    this.speed = 1;
    this.playing = false;
    this.playButton = element('button', { class: 'play', title: 'play / pause (space)', onclick: () => this.toggle() });
    this.scrubber = element('input', { type: 'range', min: String(start), max: String(end), step: 'any', value: String(start), 'aria-label': 'time' });
    this.scrubber.addEventListener('input', () => { this.pause(); this.seek(Number(this.scrubber.value)); });
    this.clock = element('span', { class: 'clock' });
    const speed = element('select', { title: 'playback speed', 'aria-label': 'speed' },
      SPEEDS.map((s) => element('option', { value: String(s), text: s + '×' })));
    speed.value = '1';
    speed.addEventListener('change', () => { this.speed = Number(speed.value); });
    this.speedSelect = speed;
    this.fps = element('span', { id: 'wpg-fps', class: 'fps' });
    container.append(this.playButton, this.clock, this.scrubber, speed, this.fps);
    document.addEventListener('keydown', (event) => {
      if (event.target instanceof HTMLInputElement && event.target.type !== 'range') return;
      if (event.code === 'Space') { event.preventDefault(); this.toggle(); }
      if (event.code === 'ArrowRight') { this.pause(); this.seek(this.t + 0.1); }
      if (event.code === 'ArrowLeft') { this.pause(); this.seek(this.t - 0.1); }
    });
    window.addEventListener('hashchange', () => this.applyFragment());
    this.frame = this.frame.bind(this);
  }

  applyFragment() {
    const keys = parseFragment(window.location.hash);
    if (keys.speed && Number(keys.speed) > 0) {
      this.speed = Number(keys.speed);
      if (SPEEDS.includes(this.speed)) this.speedSelect.value = String(this.speed);
    }
    const t = Number(keys.t);
    if (keys.t !== undefined && Number.isFinite(t)) {
      this.seek(t);
      if (keys.play) this.play(); else this.pause();
    } else {
      this.seek(this.start);
      this.play();
    }
    if (keys.measure) this.startMeasure(Number(keys.measure) || 3);
  }

  startMeasure(seconds) {
    this.measure = { seconds, frames: 0, since: null };
    if (!this.playing) this.play();
  }

  seek(t) {
    this.t = Math.min(this.end, Math.max(this.start, t));
    this.show();
  }

  // The scene follows every frame; the text (clock, scrubber, the plots' readouts) at most 15
  // times a second while playing: a layout per frame costs more than the drawing.
  show(now = null) {
    const text = now === null || !this.lastText || now - this.lastText > 66;
    if (text) {
      this.lastText = now;
      this.scrubber.value = String(this.t);
      this.clock.textContent = `${format(this.t, 4).padStart(5)} s / ${format(this.end, 4)} s`;
    }
    this.onTime(this.t, text);
  }

  play() {
    if (this.t >= this.end) this.t = this.start;
    this.playing = true;
    this.last = null;
    this.playButton.textContent = '❚❚';
    this.playButton.classList.add('playing');
  }

  pause() {
    this.playing = false;
    this.playButton.textContent = '▶';
    this.playButton.classList.remove('playing');
  }

  toggle() { if (this.playing) this.pause(); else this.play(); }

  run() {
    this.applyFragment();
    requestAnimationFrame(this.frame);
  }

  frame(now) {
    if (this.playing) {
      if (this.last !== null) {
        // At most 0.1 s of walk per frame: a stalled tab does not jump to the end.
        this.t += Math.min(0.1, (now - this.last) / 1000) * this.speed;
        this.adapt(now - this.last);
        if (this.t >= this.end) {
          this.t = this.end;
          if (!this.measure) this.pause();
          else this.t = this.start;  // measuring: loop
        }
        this.show(now);
      }
      this.last = now;
    }
    const drawn = this.render();
    if (this.measure && this.playing && drawn) {
      const m = this.measure;
      if (m.warmup === undefined) m.warmup = now;  // 1 s to settle the render scale first
      else if (now - m.warmup < 1000) { /* warming up */ } else if (m.since === null) m.since = now;
      else m.frames += 1;
      if (m.since !== null && now - m.since >= 1000 * m.seconds) {
        const fps = (1000 * m.frames) / (now - m.since);
        const scale = this.scale ? this.scale() : 1;
        this.fps.textContent = `${fps.toFixed(1)} frames/s (render scale ${scale.toFixed(2)})`;
        this.fps.dataset.fps = fps.toFixed(2);
        this.fps.dataset.scale = scale.toFixed(3);
        console.log(`wpg-fps ${fps.toFixed(2)} scale ${scale.toFixed(3)}`);
        this.measure = null;
        this.pause();
      }
    }
    requestAnimationFrame(this.frame);
  }
}
