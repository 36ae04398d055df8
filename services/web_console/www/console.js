// The console page: one WebSocket to web_console, frames kept in `state`, three views redrawn
// on the next animation frame. No build step, no download: plain ES modules and Canvas.
import { MapView } from './map_view.js';
import { drawSensor, clusterSummary } from './sensor_view.js';
import { renderHealth } from './health_view.js';

const TRAIL_POINTS = 2000;  // points kept per trail in the page
const state = {
  map: null, scan: null, detections: null, clusters: null, matches: null, goal: null, navStatus: null,
  mapHealth: null, poses: {}, trails: { POSE: [], LASER_POSE: [], GROUND_TRUTH: [] },
  heartbeats: new Map(), console: { control_enabled: false }, localization: null,
};

const mapView = new MapView(document.getElementById('map'), state, sendClick);
// For diagnostics from the browser's console, and for the browser test (tests/web_console), which
// computes the map point of the pixel it clicks with the view's own transform.
// timing: performance.now() [ms since navigation] of the WebSocket's open and of each frame
// type's first arrival, to tell a slow page from a slow service.
// poseShownMs / legendShownMs: when an OK POSE line and the map's reflector count were first drawn.
const timing = { socketOpenMs: null, firstFrameMs: {}, poseShownMs: null, legendShownMs: null };
window.refloc = { state, mapView, timing };
const $ = (id) => document.getElementById(id);
let socket = null;
let redrawPending = false;

function redraw() {
  if (redrawPending) return;
  redrawPending = true;
  requestAnimationFrame(() => {
    redrawPending = false;
    mapView.draw();
    if (timing.legendShownMs === null && state.map && state.map.reflectors.length > 0) timing.legendShownMs = performance.now();
    drawSensor($('sensor'), state);
    renderHealth($('health').tBodies[0], $('map-health'), state);
    renderLines();
  });
}

function renderLines() {
  const p = state.poses.POSE;
  $('pose-line').textContent = p
    ? `POSE ${p.status} x ${p.x.toFixed(3)} y ${p.y.toFixed(3)} m θ ${(p.theta * 180 / Math.PI).toFixed(2)}° ` +
      `σxy ${(1000 * Math.sqrt(Math.max(p.covariance[0], p.covariance[4]))).toFixed(1)} mm, ${p.reflectors_used} reflectors`
    : 'no POSE yet';
  if (timing.poseShownMs === null && p && p.status === 'OK') timing.poseShownMs = performance.now();
  const n = state.navStatus;
  $('nav-line').textContent = n
    ? `navigator ${n.state}` + (n.waypoints > 0 ? ` goal ${n.goal_id} waypoint ${n.waypoint_index + 1}/${n.waypoints}` +
      ` ${n.distance_to_waypoint.toFixed(3)} m` : '') + ` ${n.reason}`
    : '';
  const s = state.scan;
  $('scan-line').textContent = s ? `${s.ranges_mm.length} beams, ${s.rssi_bits}-bit RSSI, page ≤ ${state.console.scan_rate_hz} Hz` : '';
  $('cluster-line').textContent = s ? clusterSummary(state) : '';
}

function hasPose(f) { return f.channel !== 'LASER_POSE' || f.status === 'OK' || f.status === 'DEGRADED'; }

function addTrailPoint(channel, x, y) {
  const trail = state.trails[channel];
  const last = trail[trail.length - 1];
  if (last && Math.hypot(x - last[0], y - last[1]) < 0.02) return;
  trail.push([x, y]);
  if (trail.length > TRAIL_POINTS) trail.splice(0, trail.length - TRAIL_POINTS);
}

const handlers = {
  console: (f) => { state.console = f; $('controls').hidden = !f.control_enabled; },
  map: (f) => { const first = !state.map; state.map = f; if (first) mapView.fit(); },
  scan: (f) => { state.scan = f; },
  detections: (f) => { state.detections = f; },
  clusters: (f) => { state.clusters = f; },
  matches: (f) => { state.matches = f; },
  // LASER_POSE without a pose (LOST, AMBIGUOUS, INITIALIZING) carries zeros: neither drawn nor trailed.
  pose: (f) => {
    if (!hasPose(f)) { delete state.poses[f.channel]; return; }
    state.poses[f.channel] = f;
    addTrailPoint(f.channel, f.x, f.y);
  },
  trail: (f) => { if (state.trails[f.channel].length === 0) state.trails[f.channel] = f.points; },
  goal: (f) => { state.goal = f; },
  nav_status: (f) => { state.navStatus = f; },
  heartbeat: (f) => {  // at most 64 services, as the console keeps
    if (state.heartbeats.has(f.service) || state.heartbeats.size < 64) {
      state.heartbeats.set(f.service, { ...f, received_ms: performance.now() });
    }
  },
  map_health: (f) => { state.mapHealth = f; },
  localization: (f) => { state.localization = f; },
  // The service's answer to this page's last command: sent, or refused and why.
  command_result: (f) => {
    $('command-result').textContent = f.ok ? `${f.command.replace('_', ' ')} sent` : `refused: ${f.reason}`;
    $('command-result').className = f.ok ? 'ok' : 'bad';
  },
};

function connect() {
  socket = new WebSocket(`ws://${location.host}/`);
  socket.onopen = () => {
    if (timing.socketOpenMs === null) timing.socketOpenMs = performance.now();
    $('connection').textContent = 'live'; $('connection').className = 'ok';
  };
  socket.onclose = () => {
    $('connection').textContent = 'disconnected, retrying…';
    $('connection').className = 'bad';
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => {
    const frame = JSON.parse(event.data);
    if (!(frame.type in timing.firstFrameMs)) timing.firstFrameMs[frame.type] = performance.now();
    const handle = handlers[frame.type];
    if (handle) { handle(frame); redraw(); }
  };
}

function sendCommand(command) {
  if (!socket || socket.readyState !== WebSocket.OPEN) return;
  socket.send(JSON.stringify({ ...command, token: $('token').value }));
}

// A click in 'goal' mode is a goal (NAV_GOAL); in 'pose' mode "the robot is here" (INITIAL_POSE,
// a prior reflector_matcher verifies against the scans before it trusts it).
function sendClick(mode, x, y, theta) {
  sendCommand({ type: mode === 'pose' ? 'initial_pose' : 'goal', x, y, theta });
  armClick(null);
}

function armClick(mode) {
  mapView.clickMode = mode;
  $('goal-mode').classList.toggle('armed', mode === 'goal');
  $('pose-mode').classList.toggle('armed', mode === 'pose');
}

$('goal-mode').onclick = () => armClick(mapView.clickMode === 'goal' ? null : 'goal');
$('pose-mode').onclick = () => armClick(mapView.clickMode === 'pose' ? null : 'pose');
$('stop').onclick = () => sendCommand({ type: 'stop' });
$('fit').onclick = () => { mapView.fit(); redraw(); };
$('ellipse-scale').onchange = (e) => { mapView.ellipseScale = Number(e.target.value); redraw(); };
window.onresize = redraw;
setInterval(redraw, 1000);  // heartbeat ages
connect();
