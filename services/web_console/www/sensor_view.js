// The sensor view: the latest scan's range and RSSI per beam against angle, with the detected
// clusters' beams marked. (The extractor's energy threshold and rejected clusters are not on
// the bus yet: see the README.)

function axes(g, x0, y0, w, h, label, max) {
  g.strokeStyle = '#999'; g.strokeRect(x0, y0, w, h);
  g.fillStyle = '#444'; g.font = '11px sans-serif';
  g.fillText(label, x0 + 4, y0 + 12);
  g.fillText(String(max), x0 - 40, y0 + 10);
  g.fillText('0', x0 - 12, y0 + h);
}

export function drawSensor(canvas, state) {
  const dpr = window.devicePixelRatio || 1;
  canvas.width = canvas.clientWidth * dpr; canvas.height = canvas.clientHeight * dpr;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, canvas.clientWidth, canvas.clientHeight);
  const scan = state.scan;
  if (!scan) return;
  const x0 = 44, w = canvas.clientWidth - x0 - 6, h = (canvas.clientHeight - 40) / 2;
  const n = scan.ranges_mm.length;
  const maxRange = Math.max(1, ...scan.ranges_mm) / 1000;
  const fullRssi = scan.rssi_bits === 16 ? 65535 : 255;
  axes(g, x0, 4, w, h, 'range [m]', maxRange.toFixed(1));
  axes(g, x0, h + 14, w, h, `RSSI (${scan.rssi_bits}-bit)`, fullRssi);
  const bx = (i) => x0 + (i / Math.max(1, n - 1)) * w;
  if (state.detections) {  // the detected clusters' beams
    g.fillStyle = '#f8bbd0';
    for (const d of state.detections.detections) g.fillRect(bx(d.first_beam), 4, Math.max(2, bx(d.beams) - x0), 2 * h + 10);
  }
  g.fillStyle = '#1565c0';
  scan.ranges_mm.forEach((mm, i) => { if (mm > 2) g.fillRect(bx(i), 4 + h - (mm / 1000 / maxRange) * h, 1.5, 1.5); });
  g.fillStyle = '#e65100';
  scan.rssi.forEach((v, i) => g.fillRect(bx(i), h + 14 + h - (v / fullRssi) * h, 1.5, 1.5));
  const deg = (a) => (a * 180 / Math.PI).toFixed(0);
  const end = scan.start_angle + (n - 1) * scan.angle_increment;
  g.fillStyle = '#444';
  g.fillText(`${deg(scan.start_angle)}°`, x0, 2 * h + 34);
  g.fillText('angle (laser frame)', x0 + w / 2 - 40, 2 * h + 34);
  g.fillText(`${deg(end)}°`, x0 + w - 24, 2 * h + 34);
}
