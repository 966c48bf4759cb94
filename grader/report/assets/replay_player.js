(function () {
  function decode(b64) {
    var s = atob(b64), n = s.length >> 1, a = new Int16Array(n);
    for (var i = 0; i < n; i++) {
      var u = s.charCodeAt(2 * i) | (s.charCodeAt(2 * i + 1) << 8);
      a[i] = u > 32767 ? u - 65536 : u;
    }
    return a;
  }
  function prepare(run) {
    run.pts = decode(run.data);
    run.shapePts = run.shapes.reduce(function (n, s) { return n + s[1]; }, 0);
    run.at = [];
    var at = 0;
    run.counts.forEach(function (c) { run.at.push(at); at += 2 * (c[0] + run.shapePts + 4 * c[1]); });
  }
  function draw(ctx, run, f, color, background) {
    var W = ctx.canvas.width, H = ctx.canvas.height, v = run.view, s = H / v[2], u = run.unit;
    if (background) {
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
      ctx.strokeStyle = '#999'; ctx.fillStyle = '#eee'; ctx.lineWidth = 1.5;
      run.planes.forEach(function (p) {
        var cx = p[0] * p[2], cy = p[1] * p[2], tx = -p[1] * 4 * v[2], ty = p[0] * 4 * v[2];
        ctx.beginPath();
        ctx.moveTo(W / 2 + (cx - tx - v[0]) * s, H / 2 - (cy - ty - v[1]) * s);
        ctx.lineTo(W / 2 + (cx + tx - v[0]) * s, H / 2 - (cy + ty - v[1]) * s);
        ctx.stroke();
      });
      run.circles.forEach(function (c) {
        ctx.beginPath();
        ctx.arc(W / 2 + (c[0] - v[0]) * s, H / 2 - (c[1] - v[1]) * s, c[2] * s, 0, 2 * Math.PI);
        ctx.fill(); ctx.stroke();
      });
    }
    if (f >= run.counts.length) return;
    var d = run.pts, base = run.at[f], n = run.counts[f][0], m = run.counts[f][1];
    function pt(i) {
      var x = d[base + 2 * i], y = d[base + 2 * i + 1];
      if (x === -32768 || y === -32768) return null;
      return [W / 2 + x * u * s, H / 2 - y * u * s];
    }
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.globalAlpha = 0.55; ctx.lineWidth = 1;
    ctx.beginPath();
    for (var k = 0; k + 2 < run.springs.length; k += 3) {
      var a = run.springs[k], b = run.springs[k + 1];
      if (a >= n || b >= n) continue;
      var pa = pt(a), pb = pt(b);
      if (pa && pb) { ctx.moveTo(pa[0], pa[1]); ctx.lineTo(pb[0], pb[1]); }
    }
    ctx.stroke();
    ctx.globalAlpha = 1;
    var r = Math.max(1.5, Math.min(6, run.radius * s));
    for (var i = 0; i < n; i++) {
      var p = pt(i);
      if (p) { ctx.beginPath(); ctx.arc(p[0], p[1], r, 0, 2 * Math.PI); ctx.fill(); }
    }
    var at = n;
    ctx.lineWidth = 2;
    run.shapes.forEach(function (sh) {
      ctx.beginPath();
      if (sh[0] === 0) {
        var c = pt(at), rim = pt(at + 1);
        if (c && rim) {
          ctx.arc(c[0], c[1], sh[2] * s, 0, 2 * Math.PI);
          ctx.moveTo(c[0], c[1]); ctx.lineTo(rim[0], rim[1]);
        }
      } else {
        for (var q = 0; q < sh[1]; q++) {
          var pq = pt(at + q);
          if (pq) { if (q === 0) ctx.moveTo(pq[0], pq[1]); else ctx.lineTo(pq[0], pq[1]); }
        }
        if (sh[0] === 1) ctx.closePath();
      }
      ctx.stroke();
      at += sh[1];
    });
    ctx.setLineDash([4, 3]);
    for (var j = 0; j < m; j++) {
      ctx.beginPath();
      for (var e = 0; e < 4; e++) {
        var pj = pt(at + 4 * j + e);
        if (pj) { if (e === 0) ctx.moveTo(pj[0], pj[1]); else ctx.lineTo(pj[0], pj[1]); }
      }
      ctx.stroke();
    }
    ctx.setLineDash([]);
  }
  document.querySelectorAll('.replay').forEach(function (box) {
    var data = JSON.parse(box.querySelector('script.replay-data').textContent);
    var mine = data.student, ref = data.reference;
    prepare(mine); prepare(ref);
    var canvases = box.querySelectorAll('canvas'), left = canvases[0].getContext('2d'),
        right = canvases[1].getContext('2d');
    var slider = box.querySelector('input[type=range]'), label = box.querySelector('.time'),
        overlay = box.querySelector('input.overlay'), play = box.querySelector('.play');
    var last = mine.frames.length - 1, f = 0, timer = null;
    slider.max = last;
    function show(k) {
      f = Math.max(0, Math.min(last, k));
      slider.value = f;
      var both = overlay.checked;
      if (both) { draw(left, ref, f, '#1a73e8', true); draw(left, mine, f, '#e8710a', false); }
      else { draw(left, mine, f, '#e8710a', true); draw(right, ref, f, '#1a73e8', true); }
      canvases[1].parentNode.style.display = both ? 'none' : '';
      box.querySelector('.cap-left').textContent = both ? 'yours (orange) over the reference (blue)' : 'your run';
      var t = (mine.frames[f] * mine.frameDt).toFixed(2);
      label.textContent = 't = ' + t + ' s, frame ' + mine.frames[f] +
          (data.parted >= 0 && f >= data.parted ? '  (parted)' : '');
    }
    function stop() { if (timer) { clearInterval(timer); timer = null; } play.textContent = '\u25B6 play'; }
    play.onclick = function () {
      if (timer) { stop(); return; }
      if (f >= last) show(0);
      play.textContent = '\u23F8 pause';
      timer = setInterval(function () { if (f >= last) stop(); else show(f + 1); }, 100);
    };
    box.querySelector('.prev').onclick = function () { stop(); show(f - 1); };
    box.querySelector('.next').onclick = function () { stop(); show(f + 1); };
    var parted = box.querySelector('.parted');
    if (parted) parted.onclick = function () { stop(); show(data.parted); };
    slider.oninput = function () { stop(); show(+slider.value); };
    overlay.onchange = function () { show(f); };
    show(data.parted >= 0 ? data.parted : 0);
  });
})();
