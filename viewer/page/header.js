//! header.js: The title, the chart's name and file, the robot selector of a team run, the scrubber's range.
  // ---- header ----
  document.title = D.title;
  document.getElementById('title').textContent = D.title;
  document.getElementById('subtitle').textContent = D.subtitle || '';
  var heading = document.getElementById('chart-heading'), file = document.createElement('span');
  heading.textContent = D.chart.kind + ' ' + D.chart.name + ' ';
  file.className = 'file';
  file.textContent = D.chart.file;
  heading.appendChild(file);
  // Several robots: the picture lights every robot's state in its colour, or one robot's.
  var robotSelect = null;
  if (team) {
    robotSelect = document.createElement('select');
    robotSelect.id = 'robot-select';
    robotSelect.title = 'whose states the picture lights';
    [['all', 'all robots']].concat(D.robots.map(function (r, i) { return [String(i), r.name]; }))
      .forEach(function (o) {
        var opt = document.createElement('option');
        opt.value = o[0]; opt.textContent = o[1];
        robotSelect.appendChild(opt);
      });
    robotSelect.addEventListener('change', function () { render(); });
    heading.appendChild(robotSelect);
  }
  var scrub = document.getElementById('scrubber');
  scrub.max = String(frames - 1);

