//! frame.js: Showing one frame (render): the lit nodes, the readouts, the tick's calls and events, the poses.
  // ---- showing one frame ----
    var lastLit = [], lastFired = null;
  function activeRows(k) { return valueAt(D.active || [], k, []); }
  // Several robots: which robots the picture shows ('all', or one robot's number).
  function shownRobot() { return robotSelect ? robotSelect.value : 'all'; }
  // Lights the nodes of several robots' active rows, each in its first robot's colour, with a badge
  // per robot in it (its number in its colour); `data-robots` names them for scripts.
  function lightTeam(act) {
    var sel = shownRobot(), at = {}, order = [];
    act.forEach(function (r) {
      var row = rows[r];
      if (sel !== 'all' && String(row.robot) !== sel) return;
      var g = nodeOf[row.node];
      if (!g) return;
      if (!at[row.node]) { at[row.node] = []; order.push(row.node); }
      at[row.node].push(row.robot);
    });
    order.forEach(function (id) {
      var g = nodeOf[id], who = at[id];
      g.classList.add('lit', 'team');
      g.style.setProperty('--robot', D.robots[who[0]].colour);
      g.setAttribute('data-robots', who.join(' '));
      var bb = g.getBBox(), badges = el('g', { 'class': 'badges' }, g);
      who.forEach(function (i, n) {
        var cx = bb.x + bb.width - 6 - (who.length - 1 - n) * 15, cy = bb.y + 2;
        el('circle', { cx: cx, cy: cy, r: 7, fill: D.robots[i].colour, stroke: '#fff', 'stroke-width': 1 }, badges);
        var t = el('text', { x: cx, y: cy + 3.5, 'text-anchor': 'middle' }, badges);
        t.textContent = String(i);
      });
      lastLit.push(g);
    });
  }
  function unlight() {
    lastLit.forEach(function (g) {
      g.classList.remove('lit', 'team');
      g.style.removeProperty('--robot');
      g.removeAttribute('data-robots');
      var b = g.querySelector('g.badges');
      if (b) b.parentNode.removeChild(b);
    });
    lastLit = [];
  }
  function rowState(r) { return rows[r].name.slice(rows[r].name.indexOf('/') + 1); }
  // The chart's vars after this tick (as the picture's note declares them), a changed one marked.
  function showVars() {
    var ul = document.getElementById('vars');
    ul.textContent = '';
    (D.vars || []).forEach(function (v) {
      var now = valueAt(v.values, frame, v.init), before = frame > 0 ? valueAt(v.values, frame - 1, v.init) : v.init;
      var li = document.createElement('li');
      li.textContent = v.type + ' ' + v.name + ' = ' + now;
      li.setAttribute('data-var', v.name);
      if (now !== before) { li.className = 'changed'; li.title = 'was ' + before; }
      ul.appendChild(li);
    });
    if (D.vars_note) {
      var note = document.createElement('li');
      note.className = 'note';
      note.textContent = D.vars_note;
      ul.appendChild(note);
    }
  }
  // A zoomed picture scrolls: when the last lit node - the innermost instance's place, rows being
  // the chart's then its instances' depth first - is out of sight, it is brought to the pane's
  // centre; a picture the reader scrolled stays put while that node shows.
  function keepLitInView() {
    if (!lastLit.length || !natural) return;
    var pane = chartBox.getBoundingClientRect(), r = lastLit[lastLit.length - 1].getBoundingClientRect();
    if (r.right > pane.left && r.left < pane.right && r.bottom > pane.top && r.top < pane.bottom) return;
    chartBox.scrollLeft += (r.left + r.width / 2) - (pane.left + pane.width / 2);
    chartBox.scrollTop += (r.top + r.height / 2) - (pane.top + pane.height / 2);
  }
  function render() {
    var act = activeRows(frame);
    unlight();
    if (team) lightTeam(act);
    else act.forEach(function (r) {
      var g = nodeOf[rows[r].node];
      if (g) { g.classList.add('lit'); lastLit.push(g); }
    });
    keepLitInView();
    // Several robots: one line per robot, "robot 0: Grab".
    var stateOf = {};
    if (team) act.forEach(function (r) { (stateOf[rows[r].robot] = stateOf[rows[r].robot] || []).push(rowState(r)); });
    document.getElementById('r-active').textContent = team
      ? bots.map(function (b) { return b.name + ': ' + ((stateOf[b.index] || []).join(', ') || '\u2013'); }).join('\n')
      : act.map(function (r) { return rows[r].name; }).join(', ') || '\u2013';
    // a plan: the supervisor that fired last, lit for one second after it fired
    if (lastFired) { lastFired.classList.remove('fired'); lastFired = null; }
    if (D.fired && D.fired.length) {
      var fi = valueAt(D.fired.map(function (f, i) { return [f[0], i]; }), frame, -1);
      if (fi >= 0) {
        var f = D.fired[fi];
        document.getElementById('r-fired').textContent = f[2] + ' at ' + fmt((tickOf(f[0]) - 1) * period, 2) + ' s';
        if (frame - f[0] < 1 / period && nodeOf[f[1]]) { lastFired = nodeOf[f[1]]; lastFired.classList.add('fired'); }
      } else document.getElementById('r-fired').textContent = '\u2013';
    } else document.getElementById('r-fired').textContent = '\u2013';
    // Time from the engine's tick: a live stream's first tick may be its thousandth.
    var seconds = (tickOf(frame) - 1) * period;
    document.getElementById('r-tick').textContent = frames ? tickOf(frame) + ' / ' + tickOf(frames - 1) : '\u2013';
    document.getElementById('r-time').textContent = frames ? fmt(seconds, 3) + ' s' : '\u2013';
    document.getElementById('r-status').textContent = valueAt(D.status || [], frame, 'running') + (team
      ? '\n' + bots.map(function (b) { return b.name + ': ' + valueAt(b.status, frame, 'running'); }).join('\n') : '');
    document.getElementById('readout').textContent = frames ? 'tick ' + tickOf(frame) + '   t = ' + fmt(seconds, 2) + ' s' : 'no tick yet';
    scrub.value = String(frame);
    showVars();
    var ul = document.getElementById('calls');
    ul.textContent = '';
    if (D.calls_note) {
      var note = document.createElement('li');
      note.textContent = D.calls_note;
      note.className = 'note';
      ul.appendChild(note);
    }
    function listCalls(calls) {
      valueAt(calls.ticks, frame, []).forEach(function (c) {
        var li = document.createElement('li'), t = calls.texts[c];
        li.textContent = t;
        if (/= true$/.test(t)) li.className = 'true'; else if (/= false$/.test(t)) li.className = 'false';
        ul.appendChild(li);
      });
    }
    if (D.calls) listCalls(D.calls);
    // Several robots: each shown robot's calls under its name and state, in its colour.
    if (team) bots.forEach(function (b) {
      if (shownRobot() !== 'all' && shownRobot() !== String(b.index)) return;
      var li = document.createElement('li');
      li.className = 'robot';
      li.style.color = b.colour;
      li.textContent = b.name + ' (' + ((stateOf[b.index] || []).join(', ') || '\u2013') + ')';
      ul.appendChild(li);
      listCalls(b.calls);
    });
    evItems.forEach(function (li, i) {
      li.className = events[i][0] === frame ? 'now' : events[i][0] < frame ? 'past' : '';
    });
    if (D.world && bots.length && frame < bots[0].x.length) {
      var poses = [];
      bots.forEach(function (b) {
        b.body.setAttribute('transform', 'translate(' + b.x[frame] + ',' + b.y[frame] + ') rotate(' + b.h[frame] + ')');
        if (b.label) { b.label.setAttribute('x', b.x[frame]); b.label.setAttribute('y', -b.y[frame]); }
        var total = b.pathLength[b.pathLength.length - 1] || 1;
        b.travelled.setAttribute('stroke-dasharray', b.pathLength[frame] + ' ' + (total + 1));
        var text = 'x ' + fmt(b.x[frame], 3) + ' m, y ' + fmt(b.y[frame], 3) + ' m, ' + fmt(b.h[frame], 1) + '\u00B0';
        if (!team || shownRobot() === 'all' || shownRobot() === String(b.index)) poses.push(team ? b.index + ': ' + text : text);
      });
      document.getElementById('r-pose').textContent = poses.join('\n');
      // A held item sits at its robot's gripper (a team's track names the robot: [1, robot]).
      var R = D.robot || { gripper: 0.29 };
      itemMarks.forEach(function (m) {
        var st = valueAt(m.item.track, frame, [0, m.item.at[0], m.item.at[1]]);
        var b = st[0] ? bots[st.length > 1 ? st[1] : 0] : null, rad = b ? b.h[frame] * Math.PI / 180 : 0;
        var x = b ? b.x[frame] + R.gripper * Math.cos(rad) : st[1];
        var y = b ? b.y[frame] + R.gripper * Math.sin(rad) : st[2];
        m.mark.setAttribute('cx', x); m.mark.setAttribute('cy', y);
      });
    }
    drawTimeline();
    if (D.live) showLink();  // following or paused, as this move left it
  }
