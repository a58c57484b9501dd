//! chart.js: The chart's picture: gfec's SVG placed in #chart, `nodeOf` from a node id (the rows' `node`,
//! support/chart_nodes.h) to its <g class="node">; a note where there is no picture.
  // ---- the chart's diagram ----
  var chartBox = document.getElementById('chart');
  var nodeOf = {};           // node id (the dot name, in <title>) -> <g class="node">
  if (D.svg) {
    var text = D.svg.slice(D.svg.indexOf('<svg'));
    chartBox.innerHTML = text;
    var svg = chartBox.querySelector('svg');
    svg.removeAttribute('width'); svg.removeAttribute('height');
    svg.setAttribute('preserveAspectRatio', 'xMidYMid meet');
    var nodes = svg.querySelectorAll('g.node');
    for (var n = 0; n < nodes.length; ++n) {
      var t = nodes[n].querySelector('title');
      if (!t) continue;
      nodeOf[t.textContent] = nodes[n];
      nodes[n].setAttribute('data-node', t.textContent);  // the id stays readable for scripts
      t.textContent = '';   // no tooltips over the lit places
    }
  } else {
    chartBox.innerHTML = '<p class="note"></p>';
    chartBox.firstChild.textContent = D.svg_note || 'no diagram';
  }

