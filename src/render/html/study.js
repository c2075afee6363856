// contact-lab study page: each column heading of a table sorts it (a
// button in the heading; again to reverse), by the cell's data-sort number
// where it has one (the numbers the cells show), else by its text. Without
// this script the tables are plain.
(function () {
  'use strict';
  document.body.classList.add('js');
  function key(td) {
    var v = td.getAttribute('data-sort');
    if (v === null) { return { text: td.textContent.trim() }; }
    var x = Number(v);
    return { num: isFinite(x) ? x : Infinity };
  }
  function compare(a, b) {
    if (a.num !== undefined && b.num !== undefined) { return a.num - b.num; }
    var na = Number(a.text), nb = Number(b.text);
    if (a.text !== undefined && isFinite(na) && isFinite(nb) && a.text !== '' && b.text !== '') { return na - nb; }
    return String(a.text).localeCompare(String(b.text));
  }
  Array.prototype.slice.call(document.querySelectorAll('table.sortable')).forEach(function (table) {
    var heads = Array.prototype.slice.call(table.querySelectorAll('thead th'));
    var body = table.tBodies[0];
    heads.forEach(function (th, col) {
      var button = document.createElement('button');
      button.type = 'button';
      button.className = 'sort';
      button.textContent = th.textContent;
      button.setAttribute('aria-label', 'sort by ' + th.textContent);
      th.textContent = '';
      th.appendChild(button);
      button.addEventListener('click', function () {
        var up = th.getAttribute('aria-sort') !== 'ascending';
        heads.forEach(function (h) { h.removeAttribute('aria-sort'); });
        th.setAttribute('aria-sort', up ? 'ascending' : 'descending');
        var rows = Array.prototype.slice.call(body.rows);
        rows.sort(function (a, b) {
          var c = compare(key(a.cells[col]), key(b.cells[col]));
          return up ? c : -c;
        });
        rows.forEach(function (r) { body.appendChild(r); });
      });
    });
  });
})();
