//! world.js: The world (walls, boxes, line, items, paths, bumps, contacts, robot bodies), when the run has one.
  // ---- the world ----
  var itemMarks = [];
  if (D.world) {
    document.getElementById('main').classList.remove('no-world');
    var W = D.world, w = W.size[0], h = W.size[1];
    var box = document.getElementById('world');
    var svgW = el('svg', { viewBox: (-w / 2 - 0.1) + ' ' + (-h / 2 - 0.1) + ' ' + (w + 0.2) + ' ' + (h + 0.2),
                           preserveAspectRatio: 'xMidYMid meet' }, box);
    var g = el('g', { transform: 'scale(1,-1)' }, svgW);   // y up, as in the world file
    el('rect', { x: -w / 2, y: -h / 2, width: w, height: h, fill: '#fbfaf6', stroke: '#999', 'stroke-width': 0.01 }, g);
    for (var gx = Math.ceil(-w / 2 / 0.5) * 0.5; gx <= w / 2 + 1e-9; gx += 0.5)
      el('line', { x1: gx, y1: -h / 2, x2: gx, y2: h / 2, stroke: '#e6e6e6', 'stroke-width': 0.005 }, g);
    for (var gy = Math.ceil(-h / 2 / 0.5) * 0.5; gy <= h / 2 + 1e-9; gy += 0.5)
      el('line', { x1: -w / 2, y1: gy, x2: w / 2, y2: gy, stroke: '#e6e6e6', 'stroke-width': 0.005 }, g);
    if (W.line && W.line.points) {
      var pts = W.line.points.map(function (p) { return p[0] + ',' + p[1]; }).join(' ');
      el(W.line.closed ? 'polygon' : 'polyline', { points: pts, fill: 'none', stroke: '#333',
         'stroke-width': W.line.width || 0.05, 'stroke-linejoin': 'round' }, g);
    }
    (W.walls || []).forEach(function (wl) {
      el('line', { x1: wl.from[0], y1: wl.from[1], x2: wl.to[0], y2: wl.to[1], stroke: '#5d4037',
                   'stroke-width': wl.thickness || 0.05, 'stroke-linecap': 'square' }, g);
    });
    (W.boxes || []).forEach(function (b) {
      var low = (b.height || 0.3) < 0.2;
      el('rect', { x: b.center[0] - b.size[0] / 2, y: b.center[1] - b.size[1] / 2, width: b.size[0], height: b.size[1],
                   fill: low ? '#d7ccc8' : '#8d6e63', stroke: '#4e342e', 'stroke-width': 0.01,
                   'stroke-dasharray': low ? '0.03 0.02' : 'none' }, g);
    });
    (D.items || []).forEach(function (it) {
      el('circle', { cx: it.destination[0], cy: it.destination[1], r: 0.1, fill: 'none', stroke: '#2e7d32',
                     'stroke-width': 0.01, 'stroke-dasharray': '0.03 0.02' }, g);
      var mark = el('circle', { r: 0.04, fill: '#fb8c00', stroke: '#e65100', 'stroke-width': 0.01 }, g);
      itemMarks.push({ item: it, mark: mark });
    });
    bots.forEach(function (b) {
      if (!b.x.length) return;
      var pp = [];
      for (var k = 0; k < b.x.length; ++k) pp.push(fmt(b.x[k], 3) + ',' + fmt(b.y[k], 3));
      var all = pp.join(' ');
      el('polyline', { points: all, fill: 'none', stroke: team ? b.colour : '#90caf9', 'stroke-opacity': team ? 0.3 : 1,
                       'stroke-width': 0.012 }, g);
      b.travelled = el('polyline', { points: all, fill: 'none', stroke: team ? b.colour : '#1565c0', 'stroke-width': 0.02,
                                     'stroke-linejoin': 'round' }, g);
    });
    (D.bumps || []).forEach(function (b) {
      var c = el('g', { transform: 'translate(' + b[1] + ',' + b[2] + ')' }, g);
      el('line', { x1: -0.04, y1: -0.04, x2: 0.04, y2: 0.04, stroke: '#d32f2f', 'stroke-width': 0.015 }, c);
      el('line', { x1: -0.04, y1: 0.04, x2: 0.04, y2: -0.04, stroke: '#d32f2f', 'stroke-width': 0.015 }, c);
    });
    // Where two robots touched: a diamond in the picture's contact colour.
    (D.contacts || []).forEach(function (c) {
      el('polygon', { points: [[0, 0.05], [0.05, 0], [0, -0.05], [-0.05, 0]].map(function (p) {
        return (c[3] + p[0]) + ',' + (c[4] + p[1]); }).join(' '), fill: '#b8860b', stroke: '#6d4c00', 'stroke-width': 0.008 }, g);
    });
    var R = D.robot || { length: 0.4, width: 0.35, gripper: 0.29 };
    bots.forEach(function (b) {
      var fill = team ? b.colour : 'rgba(255,213,79,0.85)', edge = team ? b.colour : '#e65100';
      b.body = el('g', { id: team ? 'robot-' + b.index : 'robot' }, g);
      el('rect', { x: -R.length / 2, y: -R.width / 2, width: R.length, height: R.width, rx: 0.03,
                   fill: fill, 'fill-opacity': team ? 0.35 : 1, stroke: edge, 'stroke-width': 0.012 }, b.body);
      el('polygon', { points: (R.length / 2 - 0.1) + ',-0.07 ' + (R.length / 2 - 0.01) + ',0 ' + (R.length / 2 - 0.1) + ',0.07',
                      fill: edge }, b.body);
      if (team) {
        // The robot's number, upright whatever the heading (the world is drawn y up).
        b.label = el('text', { x: 0, y: 0, 'font-size': 0.16, 'font-weight': 'bold', fill: b.colour, 'text-anchor': 'middle',
                               'dominant-baseline': 'central', transform: 'scale(1,-1)' }, el('g', {}, g));
        b.label.textContent = String(b.index);
      }
    });
  } else {
    document.getElementById('r-pose-label').style.display = 'none';
    document.getElementById('r-pose').style.display = 'none';
  }
