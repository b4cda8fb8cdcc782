// The course page of embed.html: two BSV Playground drills in iframes, driven through the
// postMessage API that docs/embed.md describes. `BsvFrame` is a small client of that API that
// another page may copy: `call(method, ...args)` resolves with the reply's result (or rejects
// with its error), and `on(event, f)` hears the drill's events.

/** The app's address: `?app=` of this page, else the one `make serve` serves. */
const APP = new URL(new URLSearchParams(location.search).get('app') ?? 'http://127.0.0.1:8000/');

/** One embedded drill. */
export class BsvFrame {
  /** Loads `route` (e.g. `ik-2r`) embedded in `iframe`. */
  constructor(iframe, route) {
    this.iframe = iframe;
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = new Map();
    this.ready = new Promise((resolve) => this.on('ready', resolve));
    window.addEventListener('message', (e) => this.receive(e));
    iframe.src = new URL(`#/${route}?embed=1`, APP).href;
  }

  /** Asks the drill for `method(...args)`: resolves with the result, rejects with the error
   * (its `reply` holds the whole reply, e.g. the keys a setState did not use). */
  call(method, ...args) {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.post({ namespace: 'bsv', id, method, args });
    });
  }

  /** Posts any message to the drill (the API answers malformed ones with an error). */
  post(message) {
    this.iframe.contentWindow.postMessage(message, APP.origin);
  }

  /** Calls `f(message)` on each event `name` (`ready`, `statechange`, `readouts`). */
  on(name, f) {
    if (!this.listeners.has(name)) this.listeners.set(name, []);
    this.listeners.get(name).push(f);
  }

  receive(e) {
    if (e.source !== this.iframe.contentWindow || e.origin !== APP.origin) return;
    const message = e.data;
    if (message?.namespace !== 'bsv') return;
    if (message.event) {
      for (const f of this.listeners.get(message.event) ?? []) f(message);
      return;
    }
    const waiting = this.pending.get(message.id);
    if (!waiting) return;
    this.pending.delete(message.id);
    if ('error' in message) {
      const error = new Error(message.error);
      error.reply = message;
      waiting.reject(error);
    } else {
      waiting.resolve(message.result);
    }
  }
}

/** Shows a drill's readouts (`{key: {value, unit}}`) in `table`. */
function showReadouts(table, readouts) {
  const body = table.tBodies[0];
  body.replaceChildren(...Object.entries(readouts).filter(([, r]) => r.value !== null).map(([key, r]) => {
    const row = document.createElement('tr');
    for (const text of [key, String(r.value), r.unit]) {
      row.insertCell().textContent = text;
    }
    return row;
  }));
}

/** Appends a line to a drill's log. */
function log(section, text) {
  const pre = section.querySelector('.log');
  pre.textContent += `${text}\n`;
  pre.scrollTop = pre.scrollHeight;
}

/** Wires one section: its frame, its readouts table, its log; returns its BsvFrame. */
function drill(section) {
  const iframe = section.querySelector('iframe');
  const frame = new BsvFrame(iframe, iframe.dataset.drill);
  const table = section.querySelector('.readouts');
  frame.on('ready', (m) => {
    log(section, `ready: ${m.page}`);
    frame.call('getReadouts').then((r) => showReadouts(table, r));
  });
  frame.on('statechange', (m) => log(section, `statechange: ${JSON.stringify(m.state)}`));
  frame.on('readouts', (m) => showReadouts(table, m.readouts));
  const run = (promise) => promise
    .then((result) => log(section, `→ ${JSON.stringify(result)}`))
    .catch((error) => log(section, `error: ${error.message}`));
  section.addEventListener('click', (e) => {
    const button = e.target.closest('button');
    if (!button) return;
    const { pose, start, step, call } = button.dataset;
    if (pose) {
      const [q1, q2] = pose.split(',').map(Number);
      run(frame.call('setState', { q1, q2, elbow: 'down' }));
    } else if (start) {
      run(frame.call('setState', { 'angle-deg': Number(start), timestep: 0.01, t: 0 }));
    } else if (step) {
      run(frame.call('step', Number(step)));
    } else if (call) {
      run(frame.call(call));
    }
  });
  return frame;
}

/** The two drills, for a console (and the browser tests). */
window.bsvDemo = {
  ik: drill(document.getElementById('ik')),
  pendulum: drill(document.getElementById('pendulum')),
};
