//! common.js: The run's data (D, from the page's gfec-data element), the frame shown, and helpers every
//! module uses: valueAt (a change list's value at a tick), el (an SVG element), fmt (a number).
  var D = JSON.parse(document.getElementById('gfec-data').textContent);
  var SVGNS = 'http://www.w3.org/2000/svg';
  var frames = D.frames;               // frames 0 .. frames-1
  var period = D.period;
  var rows = D.rows || [];
  var events = D.events || [];
  var frame = 0, playing = false, clock = 0, lastStamp = null;
  var following = false;  // a live page showing each tick as it arrives (live.js)
  // The tick a frame shows, as logs and tests count them: frame 0 is tick 1, the first tick
  // after _init (which runs no statement of the chart and is no frame). A live stream joined late
  // or with lost ticks says its engine's tick numbers: D.ticks, a change list of tick - frame - 1.
  function tickOf(k) { return k + 1 + (D.ticks ? valueAt(D.ticks, k, 0) : 0); }

  // ---- change lists: [[tick, value], ...], a value holds until the next entry ----
  function valueAt(list, k, fallback) {
    var lo = 0, hi = list.length - 1, found = -1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (list[mid][0] <= k) { found = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return found < 0 ? fallback : list[found][1];
  }
  function el(name, attrs, parent) {
    var e = document.createElementNS(SVGNS, name);
    for (var a in attrs) e.setAttribute(a, attrs[a]);
    if (parent) parent.appendChild(e);
    return e;
  }
  function fmt(v, n) { return (Math.round(v * Math.pow(10, n)) / Math.pow(10, n)).toFixed(n); }

