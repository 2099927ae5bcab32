// The stage: the robot on its world, drawn as the HTML replay page draws it (the same scene
// shapes, from rootlang.sim.render's page data: world millimetres, y up, painted by the same
// shapes.js, loaded before this file), but fed live.
"use strict";

const Stage = (() => {
  class Stage {
    constructor(canvas) {
      this.canvas = canvas;
      this.data = null;      // the page data: view, below, robot outline, LED ring index
      this.strokes = [];     // live ink: {kind, color, w, p: [x, y, ...]}
      this.pose = null;      // {x, y, h, led}
      this.path = [];        // where the robot went (faint, under the ink)
      new ResizeObserver(() => this.draw()).observe(canvas);
    }
    // A new run (or a finished one): the scene's shapes; `final` also carries its ink and path.
    show(data, final) {
      this.data = data;
      const f = data.frames, last = f.t.length - 1;
      this.pose = {x: f.x[last], y: f.y[last], h: f.h[last], led: data.leds[f.led[last]]};
      if (final) {
        this.strokes = data.ink.map(s => ({kind: s.k === "erase" ? "erase" : "marker",
                                           color: s.s || "#000", w: s.w, p: s.p}));
        this.path = data.path ? data.path.p.slice() : [];
      } else {
        this.strokes = []; this.path = [this.pose.x, this.pose.y];
      }
      this.draw();
    }
    frame(f) {
      for (const s of f.ink) {
        const stroke = this.strokes[s.i] || (this.strokes[s.i] = {kind: s.kind, color: s.color, w: s.w, p: []});
        stroke.p.splice(2 * s.from, Infinity, ...s.p);
      }
      const p = f.pose;
      if (!p || !this.data) return;    // on a robot: no pose to show
      this.pose = {x: p.x, y: p.y, h: p.h, led: {color: p.led || "", mode: p.led_mode}};
      const n = this.path.length;
      if (n < 2 || this.path[n - 2] !== p.x || this.path[n - 1] !== p.y) this.path.push(p.x, p.y);
      this.grow(p.x, p.y);
      this.draw();
    }
    grow(x, y) {             // the robot left the view: widen it (kept square-ish by the fit)
      const v = this.data.view, margin = 250;
      if (x - margin < v[0] || x + margin > v[2] || y - margin < v[1] || y + margin > v[3]) {
        this.data.view = [Math.min(v[0], x - margin), Math.min(v[1], y - margin),
                          Math.max(v[2], x + margin), Math.max(v[3], y + margin)];
      }
    }
    draw() {
      if (!this.data) return;
      const canvas = this.canvas, r = canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
      canvas.width = Math.max(1, Math.round(r.width * dpr));
      canvas.height = Math.max(1, Math.round(r.height * dpr));
      const v = this.data.view;
      const k = Math.min(canvas.width / (v[2] - v[0]), canvas.height / (v[3] - v[1]));
      const dx = (canvas.width - (v[2] - v[0]) * k) / 2, dy = (canvas.height - (v[3] - v[1]) * k) / 2;
      const ctx = canvas.getContext("2d");
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.fillStyle = this.data.background; ctx.fillRect(0, 0, canvas.width, canvas.height);
      ctx.setTransform(k, 0, 0, -k, dx - v[0] * k, dy + v[3] * k);   // world mm, y up
      ctx.lineCap = "round"; ctx.lineJoin = "round";
      this.data.below.forEach(s => paint(ctx, s));
      if (this.path.length > 2) {
        paint(ctx, {k: "line", p: this.path, s: "#2563eb", w: 2 / k * dpr, o: 0.45});
      }
      const ink = this.inkLayer(canvas, ctx.getTransform());
      ctx.save(); ctx.setTransform(1, 0, 0, 1, 0, 0); ctx.drawImage(ink, 0, 0); ctx.restore();
      const p = this.pose, led = p.led || {mode: "off"};
      ctx.save(); ctx.translate(p.x, p.y); ctx.rotate(p.h * Math.PI / 180);
      this.data.robot.forEach((s, i) => paint(ctx, i === this.data.led && led.mode !== "off"
        ? Object.assign({}, s, {s: led.color}) : s));
      ctx.restore();
      const state = document.getElementById("state");
      if (state) {
        state.dataset.x = p.x.toFixed(1); state.dataset.y = p.y.toFixed(1);
        state.dataset.h = (((p.h % 360) + 360) % 360).toFixed(1);
        state.dataset.strokes = this.strokes.filter(s => s && s.p.length > 2).length;
      }
    }
    inkLayer(canvas, transform) {   // marker ink; an eraser clears the ink under it
      const layer = document.createElement("canvas");
      layer.width = canvas.width; layer.height = canvas.height;
      const ink = layer.getContext("2d");
      ink.setTransform(transform); ink.lineCap = "round"; ink.lineJoin = "round";
      for (const s of this.strokes) {
        if (!s || s.p.length < 2) continue;
        ink.globalCompositeOperation = s.kind === "erase" || s.kind === "eraser" ? "destination-out" : "source-over";
        ink.beginPath(); trace(ink, s.p, s.p.length / 2);
        if (s.p.length === 2) ink.lineTo(s.p[0], s.p[1] + 0.01);   // a dot
        ink.strokeStyle = s.color; ink.lineWidth = s.w; ink.stroke();
      }
      return layer;
    }
  }
  return Stage;
})();
