// contact-lab player: the recorded frames (drawn by the app: each frame's
// SVG is in the page's data) played, paused, stepped and scrubbed, at a
// speed; the energy chart's cursor follows; the events go to their frames;
// the recorded step's iterations open one at a time. Without this script
// the page shows the summary, the events and the film strip.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('frames').textContent);
  var frames = data.frames;
  var player = document.getElementById('player');
  if (!frames.length || !player) { return; }
  document.body.classList.add('js', 'player-page');
  var moving = player.querySelector('svg.stage g.moving');
  var cursor = player.querySelector('svg.energy line.cursor');
  var counter = player.querySelector('.frame-counter');
  var scrub = player.querySelector('.scrub');
  var speed = player.querySelector('.speed');
  var play = player.querySelector('[data-do="play"]');
  var pause = player.querySelector('[data-do="pause"]');
  var back = player.querySelector('[data-do="back"]');
  var step = player.querySelector('[data-do="step"]');
  var at = 0, playing = false, clock = 0, last = 0;

  function cursorX(t) {
    var c = data.chart;
    return c.left + (t - c.lo) / Math.max(c.hi - c.lo, 1e-300) * (c.right - c.left);
  }
  function show(k) {
    at = Math.max(0, Math.min(frames.length - 1, k));
    var f = frames[at];
    moving.innerHTML = f.svg;
    counter.textContent = f.label;
    scrub.value = String(at);
    var x = cursorX(f.t).toFixed(1);
    cursor.setAttribute('x1', x);
    cursor.setAttribute('x2', x);
    back.disabled = at === 0;
    step.disabled = at === frames.length - 1;
    player.setAttribute('data-frame', String(at));
  }
  function stop() {
    playing = false;
    play.disabled = false;
    pause.disabled = true;
    counter.setAttribute('aria-live', 'polite');
  }
  function tick(now) {
    if (!playing) { return; }
    clock += (now - last) / 1000 * Number(speed.value);
    last = now;
    var k = at;
    while (k + 1 < frames.length && frames[k + 1].t <= clock) { k += 1; }
    if (k !== at) { show(k); }
    if (at === frames.length - 1) { stop(); return; }
    requestAnimationFrame(tick);
  }
  function start() {
    if (at === frames.length - 1) { show(0); }
    playing = true;
    play.disabled = true;
    pause.disabled = false;
    counter.setAttribute('aria-live', 'off');
    clock = frames[at].t;
    last = performance.now();
    requestAnimationFrame(tick);
  }
  play.addEventListener('click', function () { start(); pause.focus(); });
  pause.addEventListener('click', function () { stop(); play.focus(); });
  back.addEventListener('click', function () { stop(); show(at - 1); });
  step.addEventListener('click', function () { stop(); show(at + 1); });
  scrub.addEventListener('input', function () { stop(); show(Number(scrub.value)); });
  player.querySelector('svg.energy').addEventListener('click', function (e) {
    var svg = e.currentTarget, box = svg.getBoundingClientRect();
    var x = (e.clientX - box.left) * svg.viewBox.baseVal.width / box.width;
    var c = data.chart, t = c.lo + (x - c.left) / (c.right - c.left) * (c.hi - c.lo);
    var k = 0;
    while (k + 1 < frames.length && frames[k + 1].t <= t) { k += 1; }
    stop(); show(k);
  });
  document.addEventListener('keydown', function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey) { return; }
    var t = e.target;
    // A field keeps its keys (the scrub bar moves itself); a button or a
    // link keeps Space and Enter.
    if (t && t.closest && t.closest('input, textarea, select')) { return; }
    if (e.key === ' ' && t && t.closest && t.closest('button, summary, a')) { return; }
    if (e.key === 'ArrowRight') { stop(); show(at + 1); e.preventDefault(); }
    else if (e.key === 'ArrowLeft') { stop(); show(at - 1); e.preventDefault(); }
    else if (e.key === ' ') { if (playing) { stop(); } else { start(); } e.preventDefault(); }
    else if (e.key === 'Home') { stop(); show(0); e.preventDefault(); }
    else if (e.key === 'End') { stop(); show(frames.length - 1); e.preventDefault(); }
  });

  // The recorded step's iterations, one at a time.
  var trace = document.getElementById('trace');
  var its = trace ? Array.prototype.slice.call(trace.querySelectorAll('[data-step]')) : [];
  var it = 0;
  function showIteration(k) {
    it = Math.max(0, Math.min(its.length - 1, k));
    its.forEach(function (s, j) { s.classList.toggle('current', j === it); });
    trace.querySelector('.it-where').textContent =
      (its[it].getAttribute('data-title') || its[it].id) + ' (' + (it + 1) + ' of ' + its.length + ')';
    trace.querySelector('[data-it="prev"]').disabled = it === 0;
    trace.querySelector('[data-it="next"]').disabled = it === its.length - 1;
  }
  if (its.length) {
    trace.querySelector('[data-it="prev"]').addEventListener('click', function () { showIteration(it - 1); });
    trace.querySelector('[data-it="next"]').addEventListener('click', function () { showIteration(it + 1); });
    showIteration(0);
  }
  function openTrace() {
    if (!trace) { return; }
    trace.open = true;
    trace.scrollIntoView();
    trace.querySelector('summary').focus();
  }

  // The events (and the open button): to their frames.
  Array.prototype.slice.call(document.querySelectorAll('[data-frame]')).forEach(function (a) {
    if (a === player) { return; }
    a.addEventListener('click', function (e) {
      e.preventDefault();
      stop();
      show(Number(a.getAttribute('data-frame')));
      if (a.getAttribute('data-do') === 'open' || a.getAttribute('data-open')) { openTrace(); }
      else { player.scrollIntoView(); }
    });
  });

  show(0);
})();
