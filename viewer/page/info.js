//! info.js: The info pane: the fired readout (plans only) and the events list, each event a jump.
  if (D.chart.kind !== 'plan') {
    document.getElementById('r-fired-label').style.display = 'none';
    document.getElementById('r-fired').style.display = 'none';
  }

  if (!(D.vars || []).length && !D.vars_note) document.getElementById('vars-block').style.display = 'none';

  // ---- events list ----
  var evList = document.getElementById('events'), evItems = [];
  // One event's entry; a live page adds those that arrive (live.js).
  function addEventItem(e) {
    var li = document.createElement('li');
    li.textContent = fmt((tickOf(e[0]) - 1) * period, 2) + ' s  ' + e[2];
    li.title = 'tick ' + tickOf(e[0]) + ' (' + e[1] + ')';
    li.addEventListener('click', function () { pause(); seek(e[0]); });
    evList.appendChild(li);
    evItems.push(li);
  }
  events.forEach(addEventItem);

