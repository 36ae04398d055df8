// The sensor view: the latest scan's range and RSSI per beam against angle, the extractor's energy
// threshold as a line on the RSSI plot, and every bright cluster of that scan (REFLECTOR_CLUSTERS)
// as a band: green accepted, red rejected with its reason written above it.

export const OUTCOME_COLOURS = {
  accepted: '#2e7d32', too_few_beams: '#8e24aa', too_wide: '#c62828', too_narrow: '#ad1457',
  not_round: '#d84315', radius: '#6d4c41', occluded: '#455a64', fit_failed: '#000000',
};
const SHORT = {
  too_few_beams: 'few', too_wide: 'wide', too_narrow: 'narrow', not_round: 'shape',
  radius: 'radius', occluded: 'occl', fit_failed: 'fit',
};

function axes(g, x0, y0, w, h, label, max) {
  g.strokeStyle = '#999'; g.strokeRect(x0, y0, w, h);
  g.fillStyle = '#444'; g.font = '11px sans-serif';
  g.fillText(label, x0 + 4, y0 + 12);
  g.fillText(String(max), x0 - 40, y0 + 10);
  g.fillText('0', x0 - 12, y0 + h);
}

/// The clusters of the scan on screen (the console decimates both by the scan's stamp, so they
/// arrive for the same scans), or null.
export function clustersOfScan(state) {
  const c = state.clusters;
  return c && state.scan && c.utime === state.scan.utime ? c : null;
}

/// "3 accepted, 2 rejected (wide 1, few 1), threshold 180 (8-bit)" for the line under the title.
export function clusterSummary(state) {
  const c = clustersOfScan(state);
  if (!c) return state.clusters ? 'clusters: none for this scan yet' : 'clusters: none received (REFLECTOR_CLUSTERS)';
  const rejected = {};
  let accepted = 0;
  for (const k of c.clusters) {
    if (k.outcome === 'accepted') accepted++;
    else rejected[k.outcome] = (rejected[k.outcome] || 0) + 1;
  }
  const reasons = Object.entries(rejected).map(([r, n]) => `${r} ${n}`).join(', ');
  const nRejected = c.clusters.length - accepted;
  return `clusters: ${accepted} accepted, ${nRejected} rejected${reasons ? ` (${reasons})` : ''}; ` +
    `threshold ${c.energy_threshold_8bit.toFixed(0)} (8-bit)` + (c.rssi_read_as_8bit ? ', 16-bit channel read as 8-bit' : '');
}

export function drawSensor(canvas, state) {
  const dpr = window.devicePixelRatio || 1;
  canvas.width = canvas.clientWidth * dpr; canvas.height = canvas.clientHeight * dpr;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, canvas.clientWidth, canvas.clientHeight);
  const scan = state.scan;
  if (!scan) return;
  const x0 = 44, top = 14, w = canvas.clientWidth - x0 - 6, h = (canvas.clientHeight - 50) / 2;
  const n = scan.ranges_mm.length;
  const maxRange = Math.max(1, ...scan.ranges_mm) / 1000;
  const fullRssi = scan.rssi_bits === 16 ? 65535 : 255;
  const bx = (i) => x0 + (i / Math.max(1, n - 1)) * w;
  const rssiTop = top + h + 10;
  const clusters = clustersOfScan(state);
  if (clusters) {  // bands behind the points, the reason above each rejected one
    g.font = '10px sans-serif';
    for (const k of clusters.clusters) {
      const colour = OUTCOME_COLOURS[k.outcome] || '#000';
      const x = bx(k.first_beam), width = Math.max(2, bx(k.last_beam + 1) - x);
      g.globalAlpha = 0.18; g.fillStyle = colour; g.fillRect(x, top, width, 2 * h + 10);
      g.globalAlpha = 1; g.fillRect(x, top - 4, width, 3);
      if (k.outcome !== 'accepted') g.fillText(SHORT[k.outcome] || k.outcome, x, top - 6);
    }
  }
  axes(g, x0, top, w, h, 'range [m]', maxRange.toFixed(1));
  axes(g, x0, rssiTop, w, h, `RSSI (${scan.rssi_bits}-bit)`, fullRssi);
  g.fillStyle = '#1565c0';
  scan.ranges_mm.forEach((mm, i) => { if (mm > 2) g.fillRect(bx(i), top + h - (mm / 1000 / maxRange) * h, 1.5, 1.5); });
  g.fillStyle = '#e65100';
  scan.rssi.forEach((v, i) => g.fillRect(bx(i), rssiTop + h - (v / fullRssi) * h, 1.5, 1.5));
  if (clusters && clusters.energy_threshold_raw > 0 && clusters.energy_threshold_raw <= fullRssi) {
    const y = rssiTop + h - (clusters.energy_threshold_raw / fullRssi) * h;
    g.strokeStyle = '#b71c1c'; g.setLineDash([6, 4]);
    g.beginPath(); g.moveTo(x0, y); g.lineTo(x0 + w, y); g.stroke(); g.setLineDash([]);
    g.fillStyle = '#b71c1c'; g.fillText(`energy threshold ${clusters.energy_threshold_8bit.toFixed(0)}`, x0 + w - 130, y - 3);
  }
  const deg = (a) => (a * 180 / Math.PI).toFixed(0);
  const end = scan.start_angle + (n - 1) * scan.angle_increment;
  g.fillStyle = '#444'; g.font = '11px sans-serif';
  g.fillText(`${deg(scan.start_angle)}°`, x0, 2 * h + 44);
  g.fillText('angle (laser frame)', x0 + w / 2 - 40, 2 * h + 44);
  g.fillText(`${deg(end)}°`, x0 + w - 24, 2 * h + 44);
}
