//! live.js: Live mode (docs/viewer.md "Live mode"): a page served by `gfec monitor --http` polls for the
//! frames that arrived since it last asked and appends them to D, the same data the other sections
//! read; it follows the newest tick until the reader moves, and says when the link is silent, lost
//! ticks or ended. A recorded page (no D.live) does nothing here.
  var link = D.live ? D.live.link : null, banner = document.getElementById('live-banner');
  var liveButton = document.getElementById('b-live'), lostSeen = 0, lostAt = 0, answered = Date.now();
  // Shows the newest frame, and each one that arrives after it until the reader moves.
  function follow() {
    following = true;
    pause();
    frame = Math.max(0, frames - 1);
    clock = frame * period;
    render();
    showLink();
  }
  // The banner: silence or the end of the stream, recent losses, a monitor that does not answer.
  function showLink() {
    if (!D.live || !link) return;  // (render runs once before this section's variables are set)
    var text = '', kind = '';
    var unit = link.unit || 'tick';  // a plan's stream loses events
    var lost = link.lost_ticks ? link.lost_ticks + ' ' + unit + (link.lost_ticks === 1 ? '' : 's') + ' lost'
                               : link.losses ? unit + 's lost' : '';
    if (link.losses > lostSeen) { lostSeen = link.losses; lostAt = Date.now(); }
    if (Date.now() - answered > 3000) { text = 'the monitor does not answer: the page shows what arrived before'; kind = 'silent'; }
    else if (link.state === 'ended') { text = 'the stream ended: ' + (link.ended || 'end of stream'); kind = 'ended'; }
    else if (link.state === 'waiting') { text = 'waiting for the stream\u2019s first ' + unit; kind = 'waiting'; }
    else if (link.silent > 0) { text = 'the link is silent: nothing for ' + fmt(link.silent, 1) + ' s'; kind = 'silent'; }
    else if (lost && Date.now() - lostAt < 10000) { text = lost + ' (' + (link.last_loss || 'garbled bytes') + ')'; kind = 'lost'; }
    banner.textContent = text;
    banner.className = kind;
    banner.hidden = !text;
    liveButton.classList.toggle('on', following);
    liveButton.title = following ? 'following the ticks as they arrive' : 'back to the newest tick, following them (End)';
    document.getElementById('live-state').textContent =
      (following ? 'live' : 'paused') + (lost ? ' \u00b7 ' + lost : '') + (link.waiting ? ' \u00b7 ' + link.waiting + ' held back' : '');
  }
  // Appends an update (LiveRecording::update): change lists grow at their end, call texts at
  // texts_from, events by count; then the scrubber, the timeline and the frame shown follow.
  function append(list, more) { (more || []).forEach(function (e) { list.push(e); }); }
  function appendCalls(calls, more) {
    if (!calls || !more) return;
    calls.texts.length = more.texts_from;
    append(calls.texts, more.texts);
    append(calls.ticks, more.ticks);
  }
  function applyUpdate(u) {
    // Fewer frames than the page holds: another monitor answers now; its run starts afresh.
    if (u.frames < frames) { location.reload(); return; }
    append(D.active, u.active);
    append(D.status, u.status);
    append(D.ticks, u.ticks);
    if (D.fired) append(D.fired, u.fired);
    appendCalls(D.calls, u.calls);
    (u.robots || []).forEach(function (r, i) { appendCalls(bots[i].calls, r.calls); append(bots[i].status, r.status); });
    (u.events || []).forEach(function (e) { events.push(e); addEventItem(e); });
    var grew = u.frames !== frames || (u.events || []).length;
    frames = D.frames = u.frames;
    scrub.max = String(Math.max(0, frames - 1));
    link = u.link;
    if (grew) {
      extendIntervals();
      backdrop = null;
      if (following) { frame = Math.max(0, frames - 1); clock = frame * period; }
      render();
    }
    showLink();
  }
  function poll() {
    var texts = [D.calls ? D.calls.texts.length : 0].concat(bots.map(function (b) { return b.calls.texts.length; }));
    var url = D.live.update + '?frames=' + frames + '&events=' + events.length + '&texts=' + texts.join(',');
    fetch(url, { cache: 'no-store' }).then(function (r) {
      if (!r.ok) throw new Error('HTTP ' + r.status);
      return r.json();
    }).then(function (u) {
      answered = Date.now();
      applyUpdate(u);
      setTimeout(poll, POLL_MS);
    }).catch(function () {
      showLink();
      setTimeout(poll, 1000);
    });
  }
  // Polling: a request at most every POLL_MS, the next only once the last is answered, so a
  // slow page or link never piles requests up; a monitor restarted or gone is retried each second.
  var POLL_MS = 200;
  if (D.live) {
    document.body.classList.add('live');
    liveButton.hidden = false;
    liveButton.addEventListener('click', follow);
    window.gfecViewer.live = {
      following: function () { return following; },
      follow: follow,
      frames: function () { return frames; },
      link: function () { return link; },
      banner: function () { return banner.hidden ? '' : banner.textContent; }
    };
    follow();
    setInterval(showLink, 1000);
    poll();
  }
