//! timeline.js: The timeline: a row per place, grouped by instance or robot, the active intervals as bars, the
//! events above; drawn once to a backdrop, the current tick's cursor over it; a click seeks.
  // ---- timeline ----
  var tl = document.getElementById('timeline');
  var ROW = 16, TOP = 20, LABEL = 150;
  // Rows of one sub-chart instance (same `group`, its path) come together, under a header line
  // naming the instance and its chart: lineOf[r] is row r's line, headers [{line, text}].
  var lineOf = [], headers = [], lines = 0;
  (function () {
    var chartOf = {};
    (D.instances || []).forEach(function (i) { chartOf[i.path] = i.chart; });
    (D.robots || []).forEach(function (r) { chartOf[r.name] = D.chart.name; });
    rows.forEach(function (row, r) {
      var g = row.group || '';
      if (g && (r === 0 || (rows[r - 1].group || '') !== g))
        headers.push({ line: lines++, text: g + (chartOf[g] ? ': ' + chartOf[g] : '') });
      lineOf.push(lines++);
    });
  })();
  // Per row: the closed intervals [from, to) of frames it was active, and the frame its open one
  // began (-1: none), which lasts to the last frame. extendIntervals reads the change list's
  // entries not read yet: a live page calls it as frames arrive (live.js).
  var intervals = rows.map(function () { return []; }), openAt = rows.map(function () { return -1; }), readTo = 0;
  function extendIntervals() {
    var list = D.active || [];
    for (; readTo < list.length; ++readTo) {
      var at = list[readTo][0], set = {};
      list[readTo][1].forEach(function (r) { set[r] = true; });
      for (var r = 0; r < rows.length; ++r) {
        var on = !!set[r];
        if (openAt[r] >= 0 && !on) { intervals[r].push([openAt[r], at]); openAt[r] = -1; }
        if (on && openAt[r] < 0) openAt[r] = at;
      }
    }
  }
  extendIntervals();
  var EVCOLOR = { bump: '#d32f2f', item: '#fb8c00', status: '#6a1b9a', note: '#00838f', supervisor: '#c62828',
                  state: '#455a64', actor: '#455a64', contact: '#b8860b', lost: '#e53935',
                  fail: '#b71c1c' };
  var backdrop = null;
  function drawBackdrop() {
    var dpr = window.devicePixelRatio || 1, cw = tl.clientWidth, ch = TOP + ROW * lines + 18;
    tl.style.height = ch + 'px';
    tl.width = Math.round(cw * dpr); tl.height = Math.round(ch * dpr);
    backdrop = document.createElement('canvas');
    backdrop.width = tl.width; backdrop.height = tl.height;
    var c = backdrop.getContext('2d');
    c.scale(dpr, dpr);
    c.fillStyle = '#fff'; c.fillRect(0, 0, cw, ch);
    c.font = '11px DejaVu Sans, Helvetica, Arial, sans-serif';
    c.textBaseline = 'middle';
    var x0 = LABEL, x1 = cw - 8, span = Math.max(1, frames - 1);
    function xOf(f) { return x0 + (x1 - x0) * f / span; }
    // time axis
    c.fillStyle = '#666'; c.strokeStyle = '#ddd';
    var seconds = span * period;
    var step = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 30, 60, 120, 300, 600, 1800, 3600]
      .find(function (s) { return seconds / s <= 12; }) || 7200;
    for (var m = 0; m * step <= seconds + 1e-9; ++m) {
      var x = xOf(m * step / period);
      c.beginPath(); c.moveTo(x, 12); c.lineTo(x, ch - 16); c.stroke();
      if (x + 40 < cw) c.fillText(String(Math.round(m * step * 100) / 100) + ' s', x + 2, ch - 8);
    }
    c.fillText('events', 6, 10);
    events.forEach(function (e) {
      c.fillStyle = EVCOLOR[e[1]] || '#333';
      c.fillRect(xOf(e[0]) - 1, 3, 2.5, 14);
    });
    headers.forEach(function (h) {
      var y = TOP + h.line * ROW;
      c.fillStyle = '#e3e8ee'; c.fillRect(0, y + 1, cw, ROW - 2);
      c.fillStyle = '#37474f';
      c.fillText(h.text.length > 60 ? h.text.slice(0, 59) + '\u2026' : h.text, 6, y + ROW / 2);
    });
    rows.forEach(function (row, r) {
      var y = TOP + lineOf[r] * ROW;
      if (r % 2 === 0) { c.fillStyle = '#f7f9fb'; c.fillRect(0, y, cw, ROW); }
      c.fillStyle = '#222';
      // An instance's row is named by its place under the instance's header.
      var name = row.group ? '  ' + row.name.slice(row.name.lastIndexOf('/') + 1) : row.name;
      c.fillText(name.length > 22 ? name.slice(0, 21) + '\u2026' : name, 6, y + ROW / 2);
      // Several robots: each robot's bars in its colour, a success or failure state's paler.
      c.fillStyle = team ? D.robots[row.robot].colour : row.terminal ? '#8e24aa' : '#f9a825';
      c.globalAlpha = team && row.terminal ? 0.45 : 1;
      intervals[r].concat(openAt[r] >= 0 ? [[openAt[r], frames]] : []).forEach(function (iv) {
        var a = xOf(iv[0]), b = Math.max(a + 1.5, xOf(iv[1]));
        c.fillRect(a, y + 3, b - a, ROW - 6);
      });
      c.globalAlpha = 1;
    });
  }
  function drawTimeline() {
    if (!backdrop) drawBackdrop();
    var c = tl.getContext('2d'), dpr = window.devicePixelRatio || 1;
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.drawImage(backdrop, 0, 0);
    c.scale(dpr, dpr);
    var cw = tl.clientWidth, x = LABEL + (cw - 8 - LABEL) * frame / Math.max(1, frames - 1);
    c.strokeStyle = '#1565c0'; c.lineWidth = 2;
    c.beginPath(); c.moveTo(x, 0); c.lineTo(x, tl.clientHeight); c.stroke();
  }
  tl.addEventListener('click', function (ev) {
    var rect = tl.getBoundingClientRect(), cw = tl.clientWidth;
    var f = Math.round((ev.clientX - rect.left - LABEL) / (cw - 8 - LABEL) * (frames - 1));
    seek(Math.max(0, Math.min(frames - 1, f)));
  });
  window.addEventListener('resize', function () { backdrop = null; drawTimeline(); });

