// The health view: one row per service from HEARTBEAT (state with its reason, age, rates from
// consecutive heartbeats, p99, decode errors, non-zero counters) and the map health summary.

const STALE_S = 3;  // a heartbeat older than this is shown STALE (refloc-status' default)
const previous = new Map();  // service -> {messages_in, messages_out, uptime_s}

function rates(h) {
  const p = previous.get(h.service);
  let r = p && p.uptime_s < h.uptime_s && h.utime !== p.utime
    ? [(h.messages_in - p.messages_in) / (h.uptime_s - p.uptime_s), (h.messages_out - p.messages_out) / (h.uptime_s - p.uptime_s)]
    : (p ? p.rates : ['', '']);
  if (!p || h.utime !== p.utime) previous.set(h.service, { ...h, rates: r });
  return r.map((v) => (v === '' ? '' : v.toFixed(1)));
}

function cell(row, text, cls) {
  const td = row.insertCell();
  td.textContent = text;
  if (cls) td.className = cls;
}

export function renderHealth(tbody, mapHealthEl, state) {
  const l = state.localization;
  document.getElementById('localization').textContent = l
    ? `localization: POSE ${l.pose_status}, matcher ${l.matches_status}, fixes ${l.ok_fixes_per_s.toFixed(1)}/s OK ` +
      `of ${l.fixes_per_s.toFixed(1)}/s (LASER_POSE)`
    : '';
  tbody.replaceChildren();
  const now = performance.now();
  for (const h of [...state.heartbeats.values()].sort((a, b) => a.service.localeCompare(b.service))) {
    const age = (now - h.received_ms) / 1000;
    const shown = age > STALE_S ? 'STALE' : h.state;
    const [inRate, outRate] = rates(h);
    const row = tbody.insertRow();
    cell(row, h.service);
    cell(row, shown, `state-${shown}`);
    cell(row, age.toFixed(1), 'num');
    cell(row, inRate, 'num');
    cell(row, outRate, 'num');
    cell(row, Math.round(h.processing_p99_us), 'num');
    cell(row, h.decode_errors, 'num');
    const counters = Object.entries(h.counters).filter(([, v]) => v !== 0).map(([k, v]) => `${k} ${v}`).join(', ');
    const td = row.insertCell();
    td.textContent = h.detail;
    const small = document.createElement('div');
    small.className = 'counters';
    small.textContent = counters;
    td.appendChild(small);
  }
  const m = state.mapHealth;
  if (!m) { mapHealthEl.textContent = 'map health: not published'; return; }
  const count = (s) => m.reflectors.filter((r) => r.state === s).length;
  const flagged = m.reflectors.filter((r) => r.state === 'missing' || r.state === 'moved')
    .map((r) => `${r.id} ${r.state}`).join(', ');
  mapHealthEl.textContent = `map health (${m.map_id ? `${m.map_id} v${m.map_version}` : 'format-1 map'}, ${m.scans_used} scans): ` +
    `${count('ok')} ok, ${count('missing')} missing, ${count('moved')} moved, ${count('unconfirmed')} unconfirmed, ` +
    `${m.candidates.length} candidates${flagged ? ' — ' + flagged : ''}`;
}
