// The map view: the map frame in metres (x right, y up), pan by dragging, zoom with the wheel,
// metres on the axes. Drawn from `state`: reflectors with ids, occluders, the scan's points
// coloured by RSSI, detections, detection -> map reflector lines, poses, trails, the goal,
// POSE's covariance ellipse (3 sigma, times the chosen scale, stated in the legend).

const COLORS = { POSE: '#1565c0', LASER_POSE: '#ef6c00', GROUND_TRUTH: '#2e7d32' };
const MARGIN = 44;  // px for the axes

export function rssiColor(fraction) {
  const f = Math.min(1, Math.max(0, fraction));
  return `hsl(${Math.round(240 - 240 * f)}, 90%, 45%)`;  // blue (dim) -> red (bright)
}

/// A laser-frame point (x, y) in the map frame through map_T_laser [x, y, theta].
export function laserToMap(p, x, y) {
  const c = Math.cos(p[2]), s = Math.sin(p[2]);
  return [p[0] + c * x - s * y, p[1] + s * x + c * y];
}

/// The ellipse of a 2x2 covariance [a b; b d]: semi-axes (1 sigma) and the major axis' angle.
export function covarianceEllipse(a, b, d) {
  const mean = (a + d) / 2, diff = Math.sqrt(((a - d) / 2) ** 2 + b * b);
  return { major: Math.sqrt(Math.max(mean + diff, 0)), minor: Math.sqrt(Math.max(mean - diff, 0)),
           angle: 0.5 * Math.atan2(2 * b, a - d) };
}

function niceStep(raw) {
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
}

export class MapView {
  constructor(canvas, state, onGoal) {
    this.canvas = canvas; this.state = state; this.onGoal = onGoal;
    this.scale = 40; this.originX = 0; this.originY = 0;  // px per m; screen px of map (0, 0)
    this.clickMode = null;  // 'goal' or 'pose': the next click on the map is one
    this.ellipseScale = 100;
    canvas.addEventListener('wheel', (e) => this.zoom(e), { passive: false });
    canvas.addEventListener('mousedown', (e) => this.down(e));
    window.addEventListener('mousemove', (e) => this.move(e));
    window.addEventListener('mouseup', (e) => this.up(e));
  }
  toScreen(x, y) { return [this.originX + x * this.scale, this.originY - y * this.scale]; }
  toMap(px, py) { return [(px - this.originX) / this.scale, (this.originY - py) / this.scale]; }
  local(e) { const r = this.canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; }

  fit() {
    const m = this.state.map;
    if (!m || m.reflectors.length === 0) return;
    const xs = m.reflectors.map((r) => r.x), ys = m.reflectors.map((r) => r.y);
    const w = this.canvas.clientWidth - 2 * MARGIN, h = this.canvas.clientHeight - 2 * MARGIN;
    const spanX = Math.max(...xs) - Math.min(...xs) + 1, spanY = Math.max(...ys) - Math.min(...ys) + 1;
    this.scale = Math.max(1, Math.min(w / spanX, h / spanY));
    this.originX = MARGIN + w / 2 - this.scale * (Math.max(...xs) + Math.min(...xs)) / 2;
    this.originY = MARGIN + h / 2 + this.scale * (Math.max(...ys) + Math.min(...ys)) / 2;
  }
  zoom(e) {
    e.preventDefault();
    const [px, py] = this.local(e);
    const [mx, my] = this.toMap(px, py);
    this.scale = Math.min(20000, Math.max(0.5, this.scale * (e.deltaY < 0 ? 1.2 : 1 / 1.2)));
    this.originX = px - mx * this.scale;
    this.originY = py + my * this.scale;
    this.draw();
  }
  down(e) { this.drag = { start: this.local(e), last: this.local(e) }; }
  move(e) {
    if (!this.drag || this.clickMode) return;
    const [px, py] = this.local(e);
    this.originX += px - this.drag.last[0];
    this.originY += py - this.drag.last[1];
    this.drag.last = [px, py];
    this.draw();
  }
  up(e) {
    if (!this.drag) return;
    const start = this.drag.start, end = this.local(e);
    this.drag = null;
    const mode = this.clickMode;
    if (!mode) return;
    this.clickMode = null;
    const [x, y] = this.toMap(start[0], start[1]);
    const dragged = Math.hypot(end[0] - start[0], end[1] - start[1]) > 10;
    const theta = dragged ? Math.atan2(-(end[1] - start[1]), end[0] - start[0]) : 0;
    this.onGoal(mode, x, y, theta);
  }

  draw() {
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    c.width = c.clientWidth * dpr; c.height = c.clientHeight * dpr;
    const g = c.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, c.clientWidth, c.clientHeight);
    this.canvas.classList.toggle('goal', this.clickMode !== null);
    this.drawGrid(g);
    const s = this.state;
    if (s.map) this.drawMap(g, s.map);
    for (const [channel, trail] of Object.entries(s.trails)) this.drawTrail(g, trail, COLORS[channel]);
    if (s.scan && s.scan.map_T_laser) this.drawScan(g, s.scan);
    if (s.detections && s.detections.map_T_laser) this.drawDetections(g, s.detections);
    if (s.matches && s.matches.status === 'OK') this.drawMatches(g, s.matches);
    if (s.goal) this.drawGoal(g, s.goal);
    for (const [channel, pose] of Object.entries(s.poses)) this.drawPose(g, pose, COLORS[channel]);
    this.legend();
  }
  drawGrid(g) {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    const step = niceStep(80 / this.scale);
    const [x0, y1] = this.toMap(0, 0), [x1, y0] = this.toMap(w, h);
    g.font = '11px sans-serif'; g.lineWidth = 1;
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
      const [px] = this.toScreen(x, 0);
      g.strokeStyle = '#eee'; g.beginPath(); g.moveTo(px, 0); g.lineTo(px, h - MARGIN / 2); g.stroke();
      g.fillStyle = '#444'; g.fillText(`${+x.toFixed(3)}`, px + 2, h - 4);
    }
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
      const [, py] = this.toScreen(0, y);
      g.strokeStyle = '#eee'; g.beginPath(); g.moveTo(MARGIN / 2, py); g.lineTo(w, py); g.stroke();
      g.fillStyle = '#444'; g.fillText(`${+y.toFixed(3)}`, 2, py - 2);
    }
    g.fillText('x [m]', w - 40, h - 16); g.fillText('y [m]', 4, 12);
  }
  drawMap(g, map) {
    g.strokeStyle = '#777'; g.lineWidth = 2;
    for (const o of map.occluders) {
      g.beginPath();
      o.points.forEach(([x, y], i) => { const [px, py] = this.toScreen(x, y); i ? g.lineTo(px, py) : g.moveTo(px, py); });
      if (o.closed) g.closePath();
      g.stroke();
    }
    g.font = '11px sans-serif';
    for (const r of map.reflectors) {
      const [px, py] = this.toScreen(r.x, r.y);
      g.fillStyle = '#9e9e9e'; g.strokeStyle = '#212121'; g.lineWidth = 1;
      g.beginPath(); g.arc(px, py, Math.max(3, r.r * this.scale), 0, 2 * Math.PI); g.fill(); g.stroke();
      g.fillStyle = '#212121'; g.fillText(String(r.id), px + 5, py - 5);
    }
  }
  drawTrail(g, trail, color) {
    if (trail.length < 2) return;
    g.strokeStyle = color; g.globalAlpha = 0.6; g.lineWidth = 1.5; g.beginPath();
    trail.forEach(([x, y], i) => { const [px, py] = this.toScreen(x, y); i ? g.lineTo(px, py) : g.moveTo(px, py); });
    g.stroke(); g.globalAlpha = 1;
  }
  drawScan(g, scan) {
    const full = scan.rssi_bits === 16 ? 65535 : 255;
    scan.ranges_mm.forEach((mm, i) => {
      if (mm <= 2) return;  // 0 no echo, 1 dazzled
      const a = scan.start_angle + i * scan.angle_increment, r = mm / 1000;
      const [x, y] = laserToMap(scan.map_T_laser, r * Math.cos(a), r * Math.sin(a));
      const [px, py] = this.toScreen(x, y);
      g.fillStyle = scan.rssi.length ? rssiColor(scan.rssi[i] / full) : '#555';
      g.fillRect(px - 1.5, py - 1.5, 3, 3);
    });
  }
  drawDetections(g, d) {
    g.strokeStyle = '#d81b60'; g.lineWidth = 2;
    for (const det of d.detections) {
      const [x, y] = laserToMap(d.map_T_laser, det.x, det.y), [px, py] = this.toScreen(x, y);
      g.beginPath(); g.arc(px, py, Math.max(6, det.radius * this.scale + 3), 0, 2 * Math.PI); g.stroke();
    }
  }
  drawMatches(g, m) {
    g.strokeStyle = '#00c853'; g.lineWidth = 1.5;
    for (const pair of m.matches) {
      const [x, y] = laserToMap(m.map_T_laser, pair.x, pair.y);
      const [ax, ay] = this.toScreen(x, y), [bx, by] = this.toScreen(pair.map_x, pair.map_y);
      g.beginPath(); g.moveTo(ax, ay); g.lineTo(bx, by); g.stroke();
    }
  }
  drawGoal(g, goal) {
    g.strokeStyle = '#6a1b9a'; g.lineWidth = 2;
    for (const [x, y, t] of goal.waypoints) {
      const [px, py] = this.toScreen(x, y);
      g.beginPath(); g.moveTo(px - 8, py - 8); g.lineTo(px + 8, py + 8); g.moveTo(px - 8, py + 8); g.lineTo(px + 8, py - 8);
      g.moveTo(px, py); g.lineTo(px + 20 * Math.cos(t), py - 20 * Math.sin(t)); g.stroke();
    }
  }
  drawPose(g, p, color) {
    const [px, py] = this.toScreen(p.x, p.y);
    if (p.channel === 'POSE') {
      const e = covarianceEllipse(p.covariance[0], p.covariance[1], p.covariance[4]);
      const k = 3 * this.ellipseScale * this.scale;
      g.strokeStyle = color; g.lineWidth = 1;
      g.beginPath(); g.ellipse(px, py, Math.max(1, e.major * k), Math.max(1, e.minor * k), -e.angle, 0, 2 * Math.PI); g.stroke();
    }
    const size = 12, t = p.theta;
    g.fillStyle = color; g.globalAlpha = p.status === 'OK' ? 1 : 0.4;
    g.beginPath();
    g.moveTo(px + size * Math.cos(t), py - size * Math.sin(t));
    g.lineTo(px + size * 0.6 * Math.cos(t + 2.5), py - size * 0.6 * Math.sin(t + 2.5));
    g.lineTo(px + size * 0.6 * Math.cos(t - 2.5), py - size * 0.6 * Math.sin(t - 2.5));
    g.closePath(); g.fill(); g.globalAlpha = 1;
  }
  legend() {
    const el = document.getElementById('map-legend');
    const m = this.state.map;
    const n = m ? m.reflectors.length : 0;
    el.innerHTML = `map ${m ? m.map_id || '(format 1)' : '…'}: <b>${n}</b> reflectors · ` +
      Object.entries(COLORS).map(([k, c]) => `<span style="color:${c}">■</span> ${k}`).join(' ') +
      ` · POSE ellipse: 3σ × ${this.ellipseScale} · scan points by RSSI (blue dim → red bright)` +
      ` · <span style="color:#d81b60">○</span> detections · <span style="color:#00c853">—</span> matches`;
  }
}
