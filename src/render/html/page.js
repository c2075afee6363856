// contact-lab page script: one step at a time (← → keys, buttons, the
// list), predict before you look (graded like the app's predict mode), and
// on resolve pages Enter on a contact row opens its worked stages. Without
// this script the page reads top to bottom.
(function () {
  'use strict';
  var steps = Array.prototype.slice.call(document.querySelectorAll('[data-step]'));
  var controls = document.querySelector('.controls');
  if (!steps.length || !controls) { return; }
  document.body.classList.add('js');
  controls.hidden = false;
  var where = controls.querySelector('.where');
  var prev = controls.querySelector('[data-go="prev"]');
  var next = controls.querySelector('[data-go="next"]');
  var links = Array.prototype.slice.call(document.querySelectorAll('nav.steps a[href^="#"]'));
  var at = 0;

  function show(i, focus) {
    at = Math.max(0, Math.min(steps.length - 1, i));
    steps.forEach(function (s, k) { s.classList.toggle('current', k === at); });
    var s = steps[at];
    where.textContent = (s.getAttribute('data-title') || s.id) + ' (' + (at + 1) + ' of ' + steps.length + ')';
    prev.disabled = at === 0;
    next.disabled = at === steps.length - 1;
    links.forEach(function (a) {
      if (a.getAttribute('href') === '#' + s.id) { a.setAttribute('aria-current', 'step'); }
      else { a.removeAttribute('aria-current'); }
    });
    if (history.replaceState) { history.replaceState(null, '', '#' + s.id); }
    if (focus) { s.focus(); }
  }
  function indexOf(id) {
    for (var k = 0; k < steps.length; k++) { if (steps[k].id === id) { return k; } }
    return -1;
  }
  prev.addEventListener('click', function () { show(at - 1); });
  next.addEventListener('click', function () { show(at + 1); });
  links.forEach(function (a) {
    a.addEventListener('click', function (e) {
      var k = indexOf(a.getAttribute('href').slice(1));
      if (k >= 0) { e.preventDefault(); show(k, true); }
    });
  });
  document.addEventListener('keydown', function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey) { return; }
    var t = e.target;
    if (t && t.closest && t.closest('input, textarea, select')) { return; }
    if (e.key === 'ArrowRight') { show(at + 1); e.preventDefault(); }
    else if (e.key === 'ArrowLeft') { show(at - 1); e.preventDefault(); }
    else if (e.key === 'Home') { show(0); e.preventDefault(); }
    else if (e.key === 'End') { show(steps.length - 1); e.preventDefault(); }
  });

  // Resolve: Enter (or a click) on a contact row opens that contact's stages.
  Array.prototype.slice.call(document.querySelectorAll('tr[data-open]')).forEach(function (row) {
    var target = document.getElementById(row.getAttribute('data-open'));
    if (!target) { return; }
    function toggle() {
      var open = target.hidden;
      target.hidden = !open;
      row.classList.toggle('open', open);
      row.setAttribute('aria-expanded', open ? 'true' : 'false');
    }
    row.addEventListener('click', toggle);
    row.addEventListener('keydown', function (e) {
      if (e.key === 'Enter' || e.key === ' ') { toggle(); e.preventDefault(); }
    });
    target.hidden = true;
  });

  // Predict before you look: the same reading and tolerance as the app's
  // predict mode; the tolerance's numbers come from the app, in the page's
  // data (<body data-tolerance>), never restated here.
  function decimalsOf(t) {
    var parts = t.split(/[eE]/);
    var exp = parts.length > 1 ? (parseInt(parts[1], 10) || 0) : 0;
    var frac = parts[0].indexOf('.') >= 0 ? parts[0].split('.')[1].length : 0;
    return Math.max(frac - exp, 0);
  }
  function isUnit(t) { return /^[\p{L}\/·°²⁻¹*^\-0-9]+$/u.test(t) && /[\p{L}°]/u.test(t); }
  function parseAnswer(s) {
    var tokens = s.replace(/[−–]/g, '-').replace(/[()\[\]{};]/g, ' ').split(/[,\s]+/).filter(Boolean);
    var nums = [];
    for (var k = 0; k < tokens.length; k++) {
      var t = tokens[k];
      if (/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(t)) {
        var x = Number(t);
        if (!isFinite(x)) { return { problem: '«' + t + '» is not a finite number' }; }
        nums.push({ value: x, decimals: decimalsOf(t.replace(/^[+-]+/, '')) });
      } else if (nums.length && isUnit(t)) {
        continue;
      } else {
        return { problem: '«' + t.slice(0, 16) + '» is not a number' };
      }
    }
    if (!nums.length) { return { problem: 'no number in the answer' }; }
    return { nums: nums };
  }
  var rule = JSON.parse(document.body.getAttribute('data-tolerance'));
  function tolerance(n) {
    return rule.last_digit_units * Math.pow(10, -Math.max(n.decimals, rule.min_decimals)) +
      rule.relative * Math.abs(n.value);
  }
  function grade(answer, formula) {
    var word = formula.getAttribute('data-word');
    if (word !== null) {
      var given = answer.trim().toLowerCase();
      var alias = { sticks: 'static', stick: 'static', sticking: 'static', slides: 'dynamic',
        slide: 'dynamic', sliding: 'dynamic', kinetic: 'dynamic' }[given] || given;
      return { correct: alias === word };
    }
    var want = JSON.parse(formula.getAttribute('data-answer'));
    var got = parseAnswer(answer);
    if (got.problem) { return { correct: false, problem: got.problem }; }
    if (got.nums.length !== want.length) {
      return { correct: false, problem: 'the answer has ' + got.nums.length + ' number(s); ' +
        (want.length === 1 ? 'one number' : want.length + ' numbers') + ' expected' };
    }
    var ok = got.nums.every(function (n, k) { return Math.abs(want[k] - n.value) <= tolerance(n); });
    return { correct: ok };
  }
  var toggle = document.getElementById('predict');
  var score = controls.querySelector('.score');
  var right = 0, graded = 0;
  Array.prototype.slice.call(document.querySelectorAll('.formula[data-answer], .formula[data-word]')).forEach(function (f, n) {
    var form = document.createElement('form');
    form.className = 'guess';
    var id = 'guess-' + n;
    var name = f.getAttribute('data-name') || 'the result';
    var unit = f.getAttribute('data-unit');
    form.innerHTML = '<label for="' + id + '"></label> <input id="' + id + '" type="text" autocomplete="off" spellcheck="false">' +
      ' <button type="submit">Check</button> <button type="button" class="reveal">Show</button> <output role="status"></output>';
    form.querySelector('label').textContent = 'Your ' + name + (unit ? ' (' + unit + ')' : '') + ':';
    form.querySelector('input').setAttribute('aria-label', 'your value of ' + name);
    var out = form.querySelector('output');
    form.addEventListener('submit', function (e) {
      e.preventDefault();
      var g = grade(form.querySelector('input').value, f);
      var shown = f.getAttribute('data-shown') || '';
      graded += 1; if (g.correct) { right += 1; }
      out.className = g.correct ? 'right' : 'wrong';
      out.textContent = (g.correct ? '✓ right' : '✗ wrong') + (g.problem ? ' (' + g.problem + ')' : '') + ': ' + name + ' = ' + shown;
      f.classList.add('revealed');
      if (score) { score.textContent = 'score ' + right + '/' + graded; }
    });
    form.querySelector('.reveal').addEventListener('click', function () { f.classList.add('revealed'); });
    f.parentNode.insertBefore(form, f.nextSibling);
  });
  if (toggle) {
    toggle.addEventListener('change', function () { document.body.classList.toggle('predict', toggle.checked); });
  }

  var start = indexOf(decodeURIComponent(location.hash.slice(1)));
  show(start >= 0 ? start : 0);
})();
