// Drawing the scene's shapes (world mm, y up) on a canvas: the one copy the HTML replay page
// (inlined by rootlang/sim/render/html.py) and the studio's stage (served as a file) both use.
function paint(ctx, s) {
  ctx.globalAlpha = s.o === undefined ? 1 : s.o;
  if (s.k === "label") {
    ctx.save(); ctx.translate(s.at[0], s.at[1]); ctx.scale(1, -1);
    ctx.font = s.size + "px sans-serif"; ctx.fillStyle = s.color;
    ctx.textAlign = {start: "left", middle: "center", end: "right"}[s.anchor];
    ctx.fillText(s.text, 0, 0); ctx.restore(); ctx.globalAlpha = 1; return;
  }
  ctx.beginPath();
  if (s.k === "circle") ctx.arc(s.c[0], s.c[1], s.r, 0, 2 * Math.PI);
  else trace(ctx, s.p, s.p.length / 2);
  if (s.k === "polygon") ctx.closePath();
  if (s.f && s.k !== "line") { ctx.fillStyle = s.f; ctx.fill(); }
  if (s.s) { ctx.strokeStyle = s.s; ctx.lineWidth = s.w; ctx.stroke(); }
  ctx.globalAlpha = 1;
}
function trace(ctx, p, count, end) {   // a polyline's first `count` points, then `end` if given
  ctx.moveTo(p[0], p[1]);
  for (let i = 1; i < count; i++) ctx.lineTo(p[2 * i], p[2 * i + 1]);
  if (end) ctx.lineTo(end[0], end[1]);
}
