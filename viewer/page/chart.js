//! chart.js: The chart's picture: gfec's SVG placed in #chart, `nodeOf` from a node id (the rows' `node`,
//! support/chart_nodes.h) to its <g class="node">; a note where there is no picture. The zoom: the
//! picture is drawn at a scale (1 = Graphviz's own size, 1 pt = 4/3 px) and scrolls in its pane.
//! `showPicture` draws a picture; a run page draws its one picture once, the editor's preview
//! (preview.js) draws again each time the text changes.
  // ---- the chart's diagram ----
  var chartBox = document.getElementById('chart');
  var svg = null;            // the picture's <svg>, or null for none
  var natural = null;        // the picture's own size in points, or null for none
  var nodeOf = {};           // node id (the dot name, in <title>) -> <g class="node">
  // keepZoom: a picture that replaces one stays at the reader's zoom and scroll (the preview's
  // redraw while typing) instead of going back to the first scale.
  function showPicture(svgText, note, keepZoom) {
    var had = natural !== null;
    svg = null; natural = null; nodeOf = {};
    if (svgText) {
      var scroll = { left: chartBox.scrollLeft, top: chartBox.scrollTop };
      chartBox.innerHTML = svgText.slice(svgText.indexOf('<svg'));
      svg = chartBox.querySelector('svg');
      // The picture's own size in points (Graphviz writes width="726pt"): the zoom scales it.
      natural = { w: parseFloat(svg.getAttribute('width')) || 400, h: parseFloat(svg.getAttribute('height')) || 300 };
      svg.removeAttribute('width'); svg.removeAttribute('height');
      svg.setAttribute('preserveAspectRatio', 'xMidYMin meet');
      var nodes = svg.querySelectorAll('g.node');
      for (var n = 0; n < nodes.length; ++n) {
        var t = nodes[n].querySelector('title');
        if (!t) continue;
        nodeOf[t.textContent] = nodes[n];
        nodes[n].setAttribute('data-node', t.textContent);  // the id stays readable for scripts
        t.textContent = '';   // no tooltips over the lit places
      }
      document.getElementById('zoom').style.display = '';
      if (keepZoom && had) {
        setZoom(zoom, false);
        chartBox.scrollLeft = scroll.left; chartBox.scrollTop = scroll.top;
      } else resetZoom();
    } else {
      chartBox.innerHTML = '<p class="note"></p>';
      chartBox.firstChild.textContent = note || 'no diagram';
      document.getElementById('zoom').style.display = 'none';
    }
  }

  // ---- zoom ----
  // The first scale fits the picture to the pane's width, but never draws the places' text
  // (Graphviz's 11 pt) smaller than MIN_TEXT_PX nor larger than 1.5 times its own size: a large
  // chart then scrolls instead of shrinking to unreadable text. The buttons, Ctrl+wheel and the
  // keys + - 0 change it; "fit" (0) goes back to the first scale.
  var MIN_TEXT_PX = 12, PT = 4 / 3, zoom = 1, fitZoom = 1;
  var zoomLabel = document.getElementById('z-level');
  function fitScale() {
    if (!natural) return 1;
    var byWidth = (chartBox.clientWidth - 16) / (natural.w * PT);
    return Math.min(1.5, Math.max(MIN_TEXT_PX / (11 * PT), byWidth));
  }
  function setZoom(z, keepCentre) {
    if (!natural) return;
    z = Math.max(0.1, Math.min(8, z));
    var cx = (chartBox.scrollLeft + chartBox.clientWidth / 2) / (zoom || 1);
    var cy = (chartBox.scrollTop + chartBox.clientHeight / 2) / (zoom || 1);
    zoom = z;
    svg.style.width = (natural.w * PT * z) + 'px';
    svg.style.height = (natural.h * PT * z) + 'px';
    if (keepCentre) {
      chartBox.scrollLeft = cx * z - chartBox.clientWidth / 2;
      chartBox.scrollTop = cy * z - chartBox.clientHeight / 2;
    }
    zoomLabel.textContent = Math.round(z * 100) + '%';
  }
  function resetZoom() { fitZoom = fitScale(); setZoom(fitZoom, false); chartBox.scrollLeft = 0; chartBox.scrollTop = 0; }
  document.getElementById('z-in').addEventListener('click', function () { setZoom(zoom * 1.25, true); });
  document.getElementById('z-out').addEventListener('click', function () { setZoom(zoom / 1.25, true); });
  document.getElementById('z-fit').addEventListener('click', resetZoom);
  chartBox.addEventListener('wheel', function (ev) {
    if (!natural || (!ev.ctrlKey && !ev.metaKey)) return;  // a plain wheel scrolls the picture
    ev.preventDefault();
    setZoom(zoom * (ev.deltaY < 0 ? 1.1 : 1 / 1.1), true);
  }, { passive: false });
  showPicture(D.svg, D.svg_note, false);
