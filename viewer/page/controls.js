//! controls.js: Moving through the run: seek, play/pause at a speed, the buttons, the keys; window.gfecViewer.
  // A move to a chosen frame; on a live page it stops following the ticks as they arrive.
  function seek(k) {
    following = false;
    frame = Math.max(0, Math.min(frames - 1, k));
    clock = frame * period;
    render();
  }
  function speed() { return parseFloat(document.getElementById('speed').value); }
  function tickAnim(stamp) {
    if (!playing) return;
    if (lastStamp !== null) {
      clock += (stamp - lastStamp) / 1000 * speed();
      var k = Math.floor(clock / period + 1e-9);
      // At the last frame: the end of a recording; a live page follows the ticks as they come.
      if (k >= frames - 1) { k = frames - 1; pause(); if (D.live) follow(); }
      if (k !== frame) { frame = k; render(); }
    }
    lastStamp = stamp;
    if (playing) requestAnimationFrame(tickAnim);
  }
  function play() {
    if (playing) return;
    if (frame >= frames - 1) seek(0);
    playing = true; lastStamp = null; clock = frame * period;
    document.getElementById('b-play').innerHTML = '&#x275A;&#x275A;';
    requestAnimationFrame(tickAnim);
  }
  function pause() {
    playing = false;
    document.getElementById('b-play').innerHTML = '&#x25B6;';
  }
  document.getElementById('b-play').addEventListener('click', function () { playing ? pause() : play(); });
  document.getElementById('b-back').addEventListener('click', function () { pause(); seek(frame - 1); });
  document.getElementById('b-fwd').addEventListener('click', function () { pause(); seek(frame + 1); });
  document.getElementById('b-start').addEventListener('click', function () { pause(); seek(0); });
  scrub.addEventListener('input', function () { pause(); seek(parseInt(scrub.value, 10)); });
  document.addEventListener('keydown', function (ev) {
    if (ev.target && ev.target.tagName === 'SELECT') return;
    var big = Math.max(1, Math.round(1 / period));
    if (ev.key === ' ') { playing ? pause() : play(); }
    else if (ev.key === 'ArrowRight') { pause(); seek(frame + (ev.shiftKey ? big : 1)); }
    else if (ev.key === 'ArrowLeft') { pause(); seek(frame - (ev.shiftKey ? big : 1)); }
    else if (ev.key === 'Home') { pause(); seek(0); }
    else if (ev.key === 'End') { pause(); if (D.live) follow(); else seek(frames - 1); }
    else if (D.svg && (ev.key === '+' || ev.key === '=')) setZoom(zoom * 1.25, true);
    else if (D.svg && ev.key === '-') setZoom(zoom / 1.25, true);
    else if (D.svg && ev.key === '0') resetZoom();
    else return;
    ev.preventDefault();
  });

  // For scripts and tests: read-only views and the same moves as the controls.
  window.gfecViewer = {
    data: D,
    frame: function () { return frame; },
    // The tick number the page shows for the current frame (logs count from 1: frame + 1).
    tick: function () { return tickOf(frame); },
    // The picture's scale (1 = Graphviz's own size) and the first, fit-to-width one.
    zoom: function () { return zoom; },
    fitZoom: function () { return fitZoom; },
    setZoom: function (z) { setZoom(z, true); },
    // Several robots: whose states the picture lights ('all' or a robot's number, as a string).
    robot: shownRobot,
    showRobot: function (v) { if (robotSelect) { robotSelect.value = String(v); render(); } },
    playing: function () { return playing; },
    seek: function (k) { pause(); seek(k); },
    play: play,
    pause: pause
  };
  seek(0);
