/* graspcompass web explorer — what each step shows and where its labels go: the objects
 * made up to the current step (and valid), the current step's objects highlighted, one
 * label for coinciding points, the labels placed by the one algorithm (GCLabelling.fit of
 * labelling.js) and the labels that find no place on the board left to the zoomed insets.
 * window.GCPlacement(ctx) adds applyVisibility and placeLabels to ctx.
 */
window.GCPlacement = function (ctx) {
  "use strict";

  const { DATA, state, stepIndex, lastStep, drawValue } = ctx;
  const { board, COL, LSPEC, GL, LFONT, insets, scheduleInsetRedraw, setFitText, entries,
    labelled, markers, extras, unlabelled, ticks, arrangeInsets } = ctx;
  const { PI } = window.GCModel;

  // ------------------------------------------------------------------------------------
  // Visibility by step and validity; highlight of the current step's objects
  // ------------------------------------------------------------------------------------
  const entryOf = new Map(entries.map((e) => [e.el, e]));
  labelled.sort((a, b) => (stepIndex[a.name] ?? 1e9) - (stepIndex[b.name] ?? 1e9));

  /** One label for the shown points that coincide, within 1e-9 of the view's width, in the
   * order of the steps (layout.group_points, as every other picture groups them). */
  function groupLabels() {
    const b = board.getBoundingBox();
    const tol = 1e-9 * (b[2] - b[0]);
    const shown = labelled.filter((e) => entryOf.get(e.el).shown);
    const where = shown.map((e) => drawValue(e.name));
    const taken = new Array(shown.length).fill(false);
    for (const e of labelled) e.group = null;
    for (let a = 0; a < shown.length; a++) {
      if (taken[a]) continue;
      const names = [shown[a].name], texts = [shown[a].text];
      for (let c = a + 1; c < shown.length; c++) {
        if (!taken[c] && where[a] && where[c] &&
            Math.hypot(where[c][0] - where[a][0], where[c][1] - where[a][1]) <= tol) {
          taken[c] = true;
          names.push(shown[c].name);
          texts.push(shown[c].text);
        }
      }
      shown[a].group = names;
      setLabel(shown[a], texts.join(" = "));
    }
    shown.forEach((e, i) => { if (taken[i]) setLabel(e, null); });
    for (const e of labelled) if (!entryOf.get(e.el).shown) setLabel(e, e.text);
  }

  /** The part of p + t d (t0 <= t <= t1) inside the box, or null (layout.clip). */
  function clip(p, d, box, t0 = -Infinity, t1 = Infinity) {
    const [xmin, xmax, ymin, ymax] = box;
    for (const [pi, di, lo, hi] of [[p[0], d[0], xmin, xmax], [p[1], d[1], ymin, ymax]]) {
      if (Math.abs(di) < 1e-300) {
        if (pi < lo || pi > hi) return null;
        continue;
      }
      let ta = (lo - pi) / di, tb = (hi - pi) / di;
      if (ta > tb) [ta, tb] = [tb, ta];
      t0 = Math.max(t0, ta);
      t1 = Math.min(t1, tb);
      if (t0 > t1) return null;
    }
    if (!(Number.isFinite(t0) && Number.isFinite(t1))) return null;
    return [[p[0] + t0 * d[0], p[1] + t0 * d[1]], [p[0] + t1 * d[0], p[1] + t1 * d[1]]];
  }

  /** What the labels avoid, in user units: the drawn lines clipped to the view, the circles
   * (100 points each), the signed lengths and the envelope (export._scene._labels). */
  function drawnCurves(box, viewSpan) {
    const q = state.num;
    const out = [];
    if (!q) return out;
    const shown = (step) => entries.some((e) => e.step === step && e.shown);
    for (const d of [[1, 0], [0, 1]]) {
      const seg = clip([0, 0], d, box);
      if (seg) out.push(seg);
    }
    for (const n of [1, 2, 3, 4]) {
      for (const [step, line] of [["side" + n, q.sides[n]], ["perp" + n, q.perps[n]]]) {
        if (!line || !shown(step)) continue;
        const seg = clip(line.P, line.d, box);
        if (seg) out.push(seg);
      }
    }
    for (const n of [1, 2, 3, 4]) {
      const [cx, cy, r] = q["circle" + n];
      if (!shown("circle" + n) || !Number.isFinite(r)) continue;
      const ring = [];
      for (let j = 0; j < 100; j++) {
        const t = (2 * PI * j) / 99;
        ring.push([cx + r * Math.cos(t), cy + r * Math.sin(t)]);
      }
      out.push(ring);
    }
    const span = viewSpan || box[1] - box[0];
    for (const n of [1, 2, 3, 4]) {
      const o = 0.012 * span * (n + 0.5);
      for (const [step, a, b] of [["OMX" + n, [q.O_M[0], -o], [q["X" + n][0], -o]],
        ["OY" + n, [o, 0], [o, q["Y" + n][1]]]]) {
        if (!shown(step) || Math.hypot(b[0] - a[0], b[1] - a[1]) <= 1e-9 * span) continue;
        const seg = clip(a, [b[0] - a[0], b[1] - a[1]], box, 0, 1);
        if (seg) out.push(seg);
      }
    }
    if (shown("envelope")) out.push(envelopeSamples(q));
    return out;
  }

  /** The envelope's arcs sampled every degree of their circle, as the scene samples them
   * (export._scene._arc_points): the same curve for the labels to avoid. */
  function envelopeSamples(q) {
    const pts = [];
    const deg = (x) => (x * 180) / PI;
    for (const a of q.arcs) {
      if (!a.n) {
        pts.push([0, 0], [0, 0]);
        continue;
      }
      const [vx, vy] = q.V[a.n - 1];
      const start = ((((deg(2 * a.theta0 - PI - Math.atan2(vy, vx)) + 180) % 360) + 360) % 360)
        - 180;
      const delta = deg(2 * (a.theta1 - a.theta0));
      const m = Math.max(2, Math.trunc(Math.abs(delta)));
      const r = Math.hypot(vx, vy) / 2;
      for (let j = 0; j < m; j++) {
        const t = ((start + delta * (j === m - 1 ? 1 : j * (1 / (m - 1)))) * PI) / 180;
        pts.push([vx / 2 + r * Math.cos(t), vy / 2 + r * Math.sin(t)]);
      }
    }
    return pts;
  }

  let lastPlacement = [], lastInputs = null;
  /** Place every shown label with the one algorithm (labelling.place): the paper's points in
   * the order of labelling.LABEL_ORDER, then H, worst and best; the break points avoided. */
  function placeLabels() {
    const [x0, y1, x1, y0] = board.getBoundingBox();
    const box = [x0, x1, y0, y1];
    const s = LSPEC.frame / (x1 - x0);
    const pxPerPt = board.canvasWidth / LSPEC.frame;
    const pt = (p) => [(p[0] - x0) * s, (p[1] - y0) * s];
    const inside = (p) => p && p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1;
    const groups = labelled.filter((e) => e.group && entryOf.get(e.el).shown &&
      inside(drawValue(e.name)))
      .map((e) => ({ e, names: e.group, at: drawValue(e.name) }));
    groups.sort((a, b) => GL.labelOrder(a.names, LSPEC) - GL.labelOrder(b.names, LSPEC));
    const special = extras.filter((x) => entryOf.get(x.el).shown && inside([x.el.X(), x.el.Y()]))
      .map((x) => ({ e: x, names: [x.text], at: [x.el.X(), x.el.Y()], text: x.text }));
    const textOf = (g) => "$" + g.names.map(GL.tex).join(" = ") + "$";
    // the markers no label covers: the break points, worst, best and H
    const shownMarkers = markers.filter((m) => entryOf.get(m.el).shown &&
      inside(drawValue(m.name))).concat(unlabelled.filter((m) => entryOf.get(m.el).shown &&
      inside(drawValue(m.name))), extras.filter((x) => entryOf.get(x.el).shown &&
      inside([x.el.X(), x.el.Y()])).map((x) => ({ name: "H", el: x.el })));
    const frame = [0, 0, LSPEC.frame, (y1 - y0) * s];
    const fontSize = LFONT / pxPerPt;
    // the markers as drawn (a point of size s: 2 s + 2 px across, its stroke included; a
    // cross 2 s): points whose markers do not touch are two places, each label nearer its own
    const across = (el) => (2 * el.visProp.size + (el.visProp.face === "x" ? 0 : 2)) / pxPerPt;
    const curves = drawnCurves(box).map((c) => c.map(pt));
    // the paper's points as the SVG and TikZ place them (scene.fit); a label with no place
    // that keeps the rules, or whose centre is nearer another point than its own, is left
    // to the zoomed inset (placed again without it, its marker still avoided)
    let keep = groups.map(() => true), fitted = null, texts = null;
    for (;;) {
      const inFit = groups.filter((_, i) => keep[i]), out = groups.filter((_, i) => !keep[i]);
      texts = inFit.map(textOf);
      lastInputs = { anchors: inFit.map((g) => pt(g.at)), texts, fontSize, opts: { curves,
        frame, obstacles: shownMarkers.map((m) => pt(drawValue(m.name)))
          .concat(out.map((g) => pt(g.at))) } };
      lastInputs.markerSizes = inFit.map(groupSize)
        .concat(shownMarkers.map((m) => across(m.el)), out.map(groupSize));
      fitted = GL.fit(lastInputs.anchors, texts, Object.assign({ fitSpec: DATA.fit,
        fontSize, markerSizes: lastInputs.markerSizes, optional: texts.map(() => true) },
      lastInputs.opts));
      const every = lastInputs.anchors.concat(lastInputs.opts.obstacles);
      const idx = groups.map((_, i) => i).filter((i) => keep[i]);
      const spaced = crowdedLabels(fitted.map((f) => f && f.box), LABEL_SPACE / pxPerPt);
      const touch = inFit.map(groupTouch).concat(shownMarkers.map((m) => across(m.el)),
        out.map(groupTouch));
      const bad = idx.filter((i, k) => !fitted[k] || spaced[k] ||
        nearerOther(fitted[k].box, k, every, touch, across(groups[i].e.el)));
      if (!bad.length) break;
      for (const i of bad) keep[i] = false;
    }
    const mainGroups = groups.filter((_, i) => keep[i]);
    const leftOut = groups.filter((_, i) => !keep[i]);
    for (const g of leftOut) hideLabel(g.e.el.label);
    const obstacles = shownMarkers.map((m) => pt(drawValue(m.name)));
    const placed = fitted.map((f) => f || { offset: [0, 0], direction: [1, 1], box: null });
    // then H, under the same rules, around the paper's points' labels and markers
    const hAnchors = special.map((g) => pt(g.at));
    const notH = shownMarkers.filter((m) => m.name !== "H");
    const hObst = notH.map((m) => pt(drawValue(m.name))).concat(groups.map((g) => pt(g.at)));
    const hSizes = special.map((g) => across(g.e.el)).concat(notH.map((m) => across(m.el)),
      groups.map(groupSize));
    const more = GL.fit(hAnchors, special.map((g) => `$${g.text}$`), { fitSpec: DATA.fit,
      fontSize, markerSizes: hSizes, curves, frame, obstacles: hObst,
      optional: special.map(() => true), avoid: placed.filter((p) => p.box).map((p) => p.box) })
      .map((f, k) => (f && !nearerOther(f.box, k, hAnchors.concat(hObst),
        special.map((g) => across(g.e.el)).concat(notH.map((m) => across(m.el)),
          groups.map(groupTouch))) ? f
        : { offset: [0, 0], direction: [1, 1], box: null }));
    const all = mainGroups.concat(special);
    placed.push(...more);
    lastPlacement = all.map((g, i) => ({ names: g.names.slice(), direction: placed[i].direction,
      offset: placed[i].offset, box: placed[i].box, shown: !!placed[i].box }));
    all.forEach((g, i) => {
      const label = g.e.el.label;
      if (!label) return;
      const p = placed[i];
      const vp = label.visProp;
      { // by GCLabelling.fit: the box's top left corner
        const at = pt(g.at);
        if (!p.box) {
          hideLabel(label);
          return;
        }
        if (label.gcOff) {
          label.gcOff = false;
          label.setAttribute({ visible: "inherit" });
        }
        label.gcFit = true;
        label.gcFont = LFONT;
        vp.offset = [(p.box ? p.box[0] - at[0] : 0) * pxPerPt,
          (p.box ? p.box[3] - at[1] : 0) * pxPerPt];
        vp.anchorx = "left";
        vp.anchory = "top";
        label.needsUpdate = true;
      }
    });
    placeInset(leftOut, groups, shownMarkers);
  }

  /** A group of coinciding points' marker size in points: the largest of their markers. */
  function groupSize(g) {
    const pxPerPt = board.canvasWidth / LSPEC.frame;
    const across = (el) => (2 * el.visProp.size + (el.visProp.face === "x" ? 0 : 2)) / pxPerPt;
    return Math.max(across(g.e.el), ...labelled.filter((e) => g.names.includes(e.name))
      .map((e) => across(e.el)));
  }

  /** A group of coinciding points' smallest marker in points: a label is nearer its own
   * point than every point whose marker does not touch its own, and a group's small
   * member (P1x under P1's large marker) may not touch a marker that P1's does (a label
   * of O was nearer P1x = X1, 10 px from O, than O: P1's marker touched O's). */
  function groupTouch(g) {
    const pxPerPt = board.canvasWidth / LSPEC.frame;
    const across = (el) => (2 * el.visProp.size + (el.visProp.face === "x" ? 0 : 2)) / pxPerPt;
    return Math.min(across(g.e.el), ...labelled.filter((e) => g.names.includes(e.name))
      .map((e) => across(e.el)));
  }

  function hideLabel(label) {
    if (!label) return;
    if (label.visProp.visible !== false) label.setAttribute({ visible: false });
    label.gcOff = true;
  }

  /** Per box (null: none), whether it comes within ``space`` of an earlier one: two
   * labels that nearly touch read as one ("X₂P₂ₓ = X₄"); the later is left to the inset. */
  const LABEL_SPACE = 3; // px
  function crowdedLabels(boxes, space) {
    return boxes.map((b, k) => !!b && boxes.slice(0, k).some((o) => o &&
      Math.min(b[2], o[2]) + space > Math.max(b[0], o[0]) &&
      Math.min(b[3], o[3]) + space > Math.max(b[1], o[1])));
  }

  /** Whether the centre of label k's box (points, y up), or the box itself, is not nearer
   * its own point pts[k] than every other point whose marker does not touch its own
   * (sizes: the markers' sizes, a group's its smallest member's, groupTouch; own0: the
   * size of the label's own point's marker, where it names a group), by NEAR_MARGIN: the
   * rule a reader checks by eye. */
  const NEAR_MARGIN = 1.5;
  function nearerOther(box, k, pts, sizes, own0) {
    const mine = own0 ?? sizes[k]; // the label's own point's marker (not its group's)
    const cx = (box[0] + box[2]) / 2, cy = (box[1] + box[3]) / 2;
    const [px, py] = pts[k];
    const own = Math.hypot(cx - px, cy - py);
    const ownBox = boxDist(px, py, box);
    for (let j = 0; j < pts.length; j++) {
      if (j === k) continue;
      const [qx, qy] = pts[j];
      if (Math.hypot(qx - px, qy - py) < (sizes[j] + mine) / 2) continue;
      if (Math.hypot(cx - qx, cy - qy) <= own + NEAR_MARGIN) return true;
      // and the box itself nearer its own point (the drawn text may be a little larger)
      if (boxDist(qx, qy, box) <= ownBox + NEAR_MARGIN) return true;
    }
    return false;
  }
  function boxDist(x, y, b) {
    return Math.hypot(Math.max(b[0] - x, 0, x - b[2]), Math.max(b[1] - y, 0, y - b[3]));
  }

  /** The insets: the labels left out of the board, with every point near them, in a
   * square magnified about them, at the smallest zoom at which each finds a place keeping
   * the rules (scene.picture's inset, in the page); the labels no zoom of the first inset
   * names (a tighter crowd within the crowd) go to the next, zoomed further. */
  // up to 4096: points 0.05 apart in a view 900 units wide (x1 = x2 = 0.05, y = 4, φ1 = 2°,
  // φ2 = 178°: V_n out at 400) are 2 px apart at ×64, and O = O_M between P1x and P2x was
  // named nowhere
  const INSET_ZOOMS = [1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 48, 64, 96, 128,
    192, 256, 384, 512, 768, 1024, 1536, 2048, 3072, 4096];
  const INSET_ROOM = 30; // px of the inset kept around the points left out, for labels
  let insetStates = [];
  function placeInset(leftOut, groups, shownMarkers) {
    insetStates = [];
    let rest = leftOut;
    insets.forEach((ins) => {
      if (!rest.length) {
        ins.hide();
        return;
      }
      ins.holder.hidden = false;
      const plan = planInset(ins.side(), rest, groups, shownMarkers);
      // an inset that names none of the labels left (the same region at the largest zoom
      // again: insets 2, 3 and 4 showed one square) is not shown
      if (!plan || !plan.named.size) {
        ins.hide();
        rest = [];
        return;
      }
      insetStates.push(plan);
      rest = rest.filter((g) => !plan.named.has(g));
      showInset(ins, plan);
    });
    arrangeInsets();
    scheduleInsetRedraw();
  }

  function planInset(side, rest, groups, shownMarkers) {
    if (!(side > 0)) return null;
    const pxPerPt = board.canvasWidth / LSPEC.frame;
    const xs = rest.map((g) => g.at[0]), ys = rest.map((g) => g.at[1]);
    const cx = (Math.min(...xs) + Math.max(...xs)) / 2;
    const cy = (Math.min(...ys) + Math.max(...ys)) / 2;
    const spread = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
    const zmax = side / (spread * board.unitX + 2 * INSET_ROOM);
    const zooms = [Math.max(Math.min(zmax, INSET_ZOOMS[0]), 1)]
      .concat(INSET_ZOOMS.filter((z) => z > zmax), INSET_ZOOMS.filter((z) => z <= zmax))
      .sort((a, b) => a - b);
    // the closest pair of points left out, apart on the board (px): a zoom that leaves
    // them nearer than a label's height cannot name both
    let closest = Infinity;
    for (let i = 0; i < rest.length; i++) {
      for (let j = i + 1; j < rest.length; j++) {
        const d = Math.hypot(rest[i].at[0] - rest[j].at[0], rest[i].at[1] - rest[j].at[1]);
        if (d > 0) closest = Math.min(closest, d * board.unitX);
      }
    }
    const others = shownMarkers.map((m) => ({ at: drawValue(m.name), el: m.el }));
    const across = (el) => (2 * el.visProp.size + (el.visProp.face === "x" ? 0 : 2)) / pxPerPt;
    const [bx0, , bx1] = board.getBoundingBox();
    let best = null;
    for (const z of zooms) {
      const u = board.unitX * z; // inset px per user unit
      const half = side / u / 2;
      // too wide to hold every point left out: the square about the most of them
      let [ox, oy] = [cx, cy];
      if (z > zmax * 1.000001) {
        const reach = half - INSET_ROOM / u;
        let most = [];
        for (const p of rest) {
          const these = rest.filter((g) => Math.abs(g.at[0] - p.at[0]) <= reach &&
            Math.abs(g.at[1] - p.at[1]) <= reach);
          if (these.length > most.length) most = these;
        }
        const mx = most.map((g) => g.at[0]), my = most.map((g) => g.at[1]);
        ox = (Math.min(...mx) + Math.max(...mx)) / 2;
        oy = (Math.min(...my) + Math.max(...my)) / 2;
      } else if (closest * z < 0.75 * LFONT && z < zooms[zooms.length - 1]) continue;
      const region = [ox - half, ox + half, oy - half, oy + half];
      const within = (p) => p && p[0] >= region[0] && p[0] <= region[1] &&
        p[1] >= region[2] && p[1] <= region[3];
      // the points near the edge too: their markers reach into the inset
      const pad = 12 / u;
      const near = (p) => p && p[0] >= region[0] - pad && p[0] <= region[1] + pad &&
        p[1] >= region[2] - pad && p[1] <= region[3] + pad;
      const gs = groups.filter((g) => within(g.at));
      const os = others.filter((o) => near(o.at))
        .concat(groups.filter((g) => !within(g.at) && near(g.at))
          .map((g) => ({ at: g.at, el: g.e.el })));
      const pt = (p) => [(p[0] - region[0]) * u / pxPerPt, (p[1] - region[2]) * u / pxPerPt];
      const anchors = gs.map((g) => pt(g.at));
      const obst = os.map((o) => pt(o.at));
      const sizes = gs.map(groupSize).concat(os.map((o) => across(o.el)));
      const curves = drawnCurves(region, bx1 - bx0).map((c) => c.map(pt));
      const fits = GL.fit(anchors, gs.map((g) => "$" + g.names.map(GL.tex).join(" = ") + "$"),
        { fitSpec: DATA.fit, fontSize: LFONT / pxPerPt, markerSizes: sizes, curves,
          frame: [0, 0, side / pxPerPt, side / pxPerPt], obstacles: obst,
          optional: gs.map(() => true) });
      const every = anchors.concat(obst);
      const spaced = crowdedLabels(fits.map((f) => f && f.box), LABEL_SPACE / pxPerPt);
      const touch = gs.map(groupTouch).concat(os.map((o) => across(o.el)));
      const ok = fits.map((f, k) => !!f && !spaced[k] &&
        !nearerOther(f.box, k, every, touch, across(gs[k].e.el)));
      const named = new Set(gs.filter((g, k) => ok[k] && rest.includes(g)));
      const key = (rest.length - named.size) * 1000 + ok.filter((v) => !v).length;
      if (best === null || key < best.key) {
        best = { key, z, region, gs, os, fits, ok, u, named, side, pxPerPt };
      }
      if (key === 0) break;
    }
    return best;
  }

  function showInset(ins, best) {
    const { side, pxPerPt } = best;
    const labels = best.gs.map((g, k) => {
      const f = best.fits[k];
      if (!best.ok[k]) return { name: g.e.name, box: null };
      const text = g.e.shownText;
      const color = (g.e.el.label && g.e.el.label.rendNode &&
        g.e.el.label.rendNode.getAttribute("fill")) || COL.point;
      const left = f.box[0] * pxPerPt, top = side - f.box[3] * pxPerPt;
      let leader = null;
      if (f.leader) {
        const ax = (g.at[0] - best.region[0]) * best.u;
        const ay = side - (g.at[1] - best.region[2]) * best.u;
        const bx = Math.min(Math.max(ax, left), f.box[2] * pxPerPt);
        const by = Math.min(Math.max(ay, top), side - f.box[1] * pxPerPt);
        leader = [[ax, ay], [bx, by]];
      }
      return { name: g.e.name, text, color, box: [left, top], leader };
    });
    const points = best.gs.map((g) => ({ name: g.e.name, node: g.e.el.rendNode }));
    for (const g of best.gs) { // the points merged into a group: markers of their own
      for (const e of labelled) {
        if (e !== g.e && g.names.includes(e.name) && e.el.rendNode) {
          points.push({ name: `member:${e.name}`, node: e.el.rendNode });
        }
      }
    }
    ins.show(best.region, points, labels, (node, text, l, t) => {
      setFitText(node, text, LFONT);
      node.setAttribute("x", `${l}px`);
      node.setAttribute("y", `${t + DATA.fit.metrics.ascent * LFONT}px`);
    });
  }

  /** The axes' numbers give way to the points: after each redraw of the board, a tick
   * number that comes within LABEL_SPACE px of a shown point's marker or label (as the
   * browser lays them out) is hidden, and shown again once it is clear.  The labels are
   * placed first, by the rules of every picture; the ticks only say where the axes are. */
  const GIVE_WAY = "data-gc-give-way"; // explorer.css: hidden, its place kept
  function ticksGiveWay() {
    const near = [];
    const add = (node) => {
      const r = node.getBoundingClientRect();
      if (r.width > 0 || r.height > 0) near.push(r);
    };
    for (const el of board.objectsList) {
      if (el.elType !== "point" || !el.visPropCalc.visible || !el.rendNode) continue;
      add(el.rendNode);
      const l = el.label;
      if (l && l.visPropCalc.visible && l.rendNode) add(l.rendNode);
    }
    const s = LABEL_SPACE;
    for (const t of ticks) {
      for (const l of t.labels) {
        const node = l && l.rendNode;
        if (!node) continue;
        let off = false;
        if (l.visPropCalc.visible) {
          const r = node.getBoundingClientRect();
          off = near.some((o) => r.left - s < o.right && o.left < r.right + s &&
            r.top - s < o.bottom && o.top < r.bottom + s);
        }
        if (off !== node.hasAttribute(GIVE_WAY)) {
          if (off) node.setAttribute(GIVE_WAY, "");
          else node.removeAttribute(GIVE_WAY);
        }
      }
    }
  }
  board.on("update", ticksGiveWay);

  function setLabel(e, text) {
    if (text === e.shownText || !e.el.label) return;
    if (text === null) {
      e.el.label.setAttribute({ visible: false });
    } else {
      if (e.shownText === null) e.el.label.setAttribute({ visible: "inherit" });
      e.el.label.setText(text);
    }
    e.shownText = text;
    ctx.visualsDirty = true;
  }

  /** Show, hide and highlight without a board update per change (JSXGraph's setAttribute
   * redraws the board each time): the caller redraws once afterwards. */
  function applyVisibility() {
    const was = board.isSuspendedUpdate;
    board.isSuspendedUpdate = true;
    try {
      applyVisibilityNow();
    } finally {
      board.isSuspendedUpdate = was;
    }
  }

  function applyVisibilityNow() {
    const cur = state.step;
    const curName = DATA.steps[cur] ? DATA.steps[cur].name : null;
    for (const e of entries) {
      const idx = stepIndex[e.step];
      let show = idx !== undefined && idx <= cur;
      if (show && e.exists && !e.exists()) show = false;
      if (show !== e.shown) {
        e.el.setAttribute({ visible: show });
        e.shown = show;
        ctx.visualsDirty = true;
      }
      const hl = !!(show && e.hl && e.step === curName && cur < lastStep);
      if (e.hl && hl !== !!e.lit) {
        if (hl) {
          e.base = {};
          for (const k of Object.keys(e.hl)) e.base[k] = e.el.visProp[k.toLowerCase()];
          e.el.setAttribute(e.hl);
        } else if (e.base) {
          e.el.setAttribute(e.base);
        }
        e.lit = hl;
        ctx.visualsDirty = true;
      }
    }
    groupLabels();
    placeLabels();
  }

  Object.assign(ctx, {
    entryOf, applyVisibility, placeLabels,
    lastPlacement: () => lastPlacement,
    lastInputs: () => lastInputs,
    insetStates: () => insetStates,
  });
};
