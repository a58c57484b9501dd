//! preview.js: The editor's live preview (preview.html, editors/vscode). The editor posts messages;
//! the page answers with messages of its own (through VS Code's acquireVsCodeApi):
//!   in  {type: 'picture', svg, note, title, elements}  draw again (elements: the gfec/chartPicture
//!                                                       result's, each {node, kind, name, uri, range})
//!   in  {type: 'problems', note, problems: [{uri, range, message}]}  the text does not compile:
//!                                                       keep the last good picture, list the errors
//!   in  {type: 'cursor', uri, position: {line, character}}  light the element under the cursor
//!                                                       (a node, or a sub-chart instance's frame)
//!   out {type: 'ready'}                                  the page can take messages
//!   out {type: 'reveal', uri, range}                     a click on an element or an error
//! Pan: drag the picture; zoom: chart.js's buttons, Ctrl+wheel, the keys + - 0.
  var vscodeApi = typeof acquireVsCodeApi === 'function' ? acquireVsCodeApi() : null;
  function post(message) { if (vscodeApi) vscodeApi.postMessage(message); }
  var mainEl = document.getElementById('main');
  var problemsBox = document.getElementById('problems');
  var elements = [];         // the last good picture's elements
  var byNode = {};           // node id -> element
  var frameOf = {};          // a sub-chart instance's frame id ("cluster_s0") -> its <g class="cluster">
  // The drawn group of an element: a node, or the frame of a sub-chart instance (a "chart").
  function shapeOf(id) { return nodeOf[id] || frameOf[id]; }
  var cursorAt = null;       // the editor's last cursor: {uri, position}
  var cursorNode = null;     // the node lit for it
  var pictures = 0;          // pictures drawn, for scripts and tests

  function contains(range, pos) {
    var s = range.start, e = range.end;
    if (pos.line < s.line || pos.line > e.line) return false;
    if (pos.line === s.line && pos.character < s.character) return false;
    if (pos.line === e.line && pos.character > e.character) return false;
    return true;
  }
  function size(range) { return (range.end.line - range.start.line) * 100000 + range.end.character - range.start.character; }

  // The innermost drawn element whose range holds the cursor: a transition's line inside its
  // chart, a place's block rather than the chart around it.
  function elementAt(at) {
    var best = null;
    for (var i = 0; i < elements.length; ++i) {
      var e = elements[i];
      if (!shapeOf(e.node) || e.uri !== at.uri || !contains(e.range, at.position)) continue;
      if (!best || size(e.range) < size(best.range)) best = e;
    }
    return best;
  }
  function showCursor() {
    if (cursorNode) cursorNode.classList.remove('cursor');
    cursorNode = null;
    var e = cursorAt && elementAt(cursorAt);
    if (!e) return;
    cursorNode = shapeOf(e.node);
    cursorNode.classList.add('cursor');
    // Bring it into sight when it is out of the pane; leave the reader's scroll alone otherwise.
    var pane = chartBox.getBoundingClientRect(), r = cursorNode.getBoundingClientRect();
    if (r.right < pane.left || r.left > pane.right || r.bottom < pane.top || r.top > pane.bottom) {
      chartBox.scrollLeft += (r.left + r.width / 2) - (pane.left + pane.width / 2);
      chartBox.scrollTop += (r.top + r.height / 2) - (pane.top + pane.height / 2);
    }
  }

  function picture(m) {
    showPicture(m.svg, m.note, true);
    ++pictures;
    frameOf = {};
    var frames = svg ? svg.querySelectorAll('g.cluster') : [];
    for (var f = 0; f < frames.length; ++f) {
      var ft = frames[f].querySelector('title');
      if (ft) { frameOf[ft.textContent] = frames[f]; frames[f].setAttribute('data-node', ft.textContent); }
    }
    elements = m.elements || [];
    byNode = {};
    for (var i = 0; i < elements.length; ++i) {
      var e = elements[i];
      byNode[e.node] = e;
      var g = shapeOf(e.node);
      if (!g) continue;
      g.classList.add('linked');
      var t = g.querySelector('title');
      if (t) t.textContent = e.kind + ' ' + e.name;   // the tooltip says what a click opens
    }
    if (m.title !== undefined) document.getElementById('chart-heading').textContent = m.title;
    mainEl.classList.remove('stale');
    problemsBox.hidden = true;
    showCursor();
  }

  function problems(m) {
    mainEl.classList.toggle('stale', !!svg);
    document.getElementById('problems-note').textContent = m.note || 'the text does not compile';
    var list = document.getElementById('problems-list');
    list.innerHTML = '';
    (m.problems || []).forEach(function (p) {
      var li = document.createElement('li');
      li.textContent = (p.range ? (p.range.start.line + 1) + ':' + (p.range.start.character + 1) + ': ' : '') + p.message;
      if (p.uri && p.range) li.addEventListener('click', function () { post({ type: 'reveal', uri: p.uri, range: p.range }); });
      list.appendChild(li);
    });
    problemsBox.hidden = false;
  }

  window.addEventListener('message', function (ev) {
    var m = ev.data || {};
    if (m.type === 'picture') picture(m);
    else if (m.type === 'problems') problems(m);
    else if (m.type === 'cursor') { cursorAt = { uri: m.uri, position: m.position }; showCursor(); }
  });

  // Pan by dragging; a drag that moved is not a click on the node it started on.
  var drag = null, dragged = false;
  chartBox.addEventListener('mousedown', function (ev) {
    if (ev.button !== 0) return;
    drag = { x: ev.clientX, y: ev.clientY, left: chartBox.scrollLeft, top: chartBox.scrollTop };
    dragged = false;
  });
  window.addEventListener('mousemove', function (ev) {
    if (!drag) return;
    var dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (!dragged && Math.abs(dx) + Math.abs(dy) < 4) return;
    dragged = true;
    chartBox.classList.add('panning');
    chartBox.scrollLeft = drag.left - dx; chartBox.scrollTop = drag.top - dy;
    ev.preventDefault();
  });
  window.addEventListener('mouseup', function () { drag = null; chartBox.classList.remove('panning'); });
  chartBox.addEventListener('click', function (ev) {
    if (dragged) { dragged = false; return; }
    var g = ev.target.closest ? ev.target.closest('g.node, g.cluster') : null;
    var e = g && byNode[g.getAttribute('data-node')];
    if (e) post({ type: 'reveal', uri: e.uri, range: e.range });
  });
  document.addEventListener('keydown', function (ev) {
    if (!svg) return;
    if (ev.key === '+' || ev.key === '=') setZoom(zoom * 1.25, true);
    else if (ev.key === '-') setZoom(zoom / 1.25, true);
    else if (ev.key === '0') resetZoom();
    else return;
    ev.preventDefault();
  });

  // For scripts and tests: what the page shows.
  window.gfecPreview = {
    pictures: function () { return pictures; },
    elements: function () { return elements; },
    highlighted: function () { return cursorNode ? cursorNode.getAttribute('data-node') : null; },
    stale: function () { return mainEl.classList.contains('stale'); },
    zoom: function () { return zoom; },
    setZoom: function (z) { setZoom(z, true); }
  };
  post({ type: 'ready' });
