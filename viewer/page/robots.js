//! robots.js: The robots' paths, decoded from delta-coded integers: `bots` (none without a world), `team`.
  // ---- poses: delta-coded integers; one robot (D.pose) or several (D.robots[i].pose) ----
  function decodePose(P) {
    var b = { x: [], y: [], h: [], pathLength: [0] };
    var s = P.scale, sh = P.heading_scale, ax = 0, ay = 0, ah = 0;
    for (var i = 0; i < P.x.length; ++i) {
      ax += P.x[i]; ay += P.y[i]; ah += P.h[i];
      b.x.push(ax / s); b.y.push(ay / s); b.h.push(ah / sh);
      if (i > 0) b.pathLength.push(b.pathLength[i - 1] + Math.hypot(b.x[i] - b.x[i - 1], b.y[i] - b.y[i - 1]));
    }
    return b;
  }
  var team = !!(D.robots && D.robots.length);
  var bots = team ? D.robots.map(function (r, i) {
    // A live team has no poses: no world, no path.
    var b = decodePose(r.pose || { scale: 1, heading_scale: 1, x: [], y: [], h: [] });
    b.index = i; b.name = r.name; b.colour = r.colour; b.calls = r.calls; b.status = r.status;
    return b;
  }) : D.pose ? [decodePose(D.pose)] : [];

