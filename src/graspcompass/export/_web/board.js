/* graspcompass web explorer — the board: JSXGraph's board with every object of the
 * construction of §3.3, each registered with the step of the protocol that makes it (the
 * axes, the friction cones, X_n, the perpendiculars, Y_n, the signed lengths, V_n, the
 * circles on O V_n, the break points, the envelope, F_e, H, worst and best, O, P1, P2),
 * the labels' text set in the font the placement measured, and the zoomed insets
 * (inset.js).  window.GCBoard(ctx) draws them and adds to ctx what the other modules read.
 */
window.GCBoard = function (ctx) {
  "use strict";

  const { DATA, state, shapeNow } = ctx;
  const { TWO_PI } = window.GCModel;

  // ------------------------------------------------------------------------------------
  // The board (JSXGraph)
  // ------------------------------------------------------------------------------------
  const COL = DATA.colors;
  // the one label placement of every picture (graspcompass.labelling, ported in labelling.js)
  const LSPEC = DATA.labelling;
  const GL = window.GCLabelling;
  JXG.Options.text.display = "internal";
  // no CSS transitions (JSXGraph animates a marker's size over 100 ms by default): what a
  // redraw draws is at once the picture that stays, the one the labels were placed for and
  // the tick numbers give way to
  JXG.Options.elements.transitionDuration = 0;
  const board = JXG.JSXGraph.initBoard("gc-board", {
    boundingbox: [-4, 4, 4, -4], keepaspectratio: true, axis: false, grid: false,
    showCopyright: false, showNavigation: true, showFullscreen: false, showScreenshot: false,
    pan: { enabled: true, needShift: true }, zoom: { wheel: true, needShift: true },
    renderer: "svg", resize: { enabled: true, throttle: 100 },
  });
  // colours at once: JSXGraph's SVG renderer sets a changed colour 1 ms after the redraw
  // (window.setTimeout, for its CSS transitions, off here), so the inset copied the board
  // before it had the current step's highlight and kept the last step's
  board.renderer._setAttribute = (set) => set();
  // the zoomed inset of the crowded region, beside the board (inset.js)
  const insets = Array.from(document.querySelectorAll(".gc-inset"))
    .map((holder) => window.GCInset.create(board, holder, COL.axis));
  // one inset in sight at a time, the tabs above them choosing which (when two or more)
  const insetTabs = document.querySelector(".gc-inset-tabs");
  const tabButtons = insetTabs ? Array.from(insetTabs.querySelectorAll("button")) : [];
  let activeInset = 0; // the index among the insets shown
  /** Show the chosen inset of those shown, the others laid out under it unseen, and a tab
   * per inset shown (none for one); its dashed square on the board drawn bolder. */
  function arrangeInsets(choose) {
    const shown = insets.filter((i) => i.shown);
    if (Number.isInteger(choose)) activeInset = choose;
    if (!(activeInset >= 0 && activeInset < shown.length)) activeInset = 0;
    insets.forEach((ins) => {
      const k = shown.indexOf(ins);
      ins.holder.classList.toggle("gc-inset-away", k >= 0 && k !== activeInset);
      ins.setActive(k === activeInset);
    });
    if (insetTabs) {
      insetTabs.hidden = shown.length < 2;
      tabButtons.forEach((b, k) => {
        b.hidden = k >= shown.length;
        if (k < shown.length) b.textContent = String(insets.indexOf(shown[k]) + 1);
        b.setAttribute("aria-selected", String(k === activeInset));
      });
    }
    return activeInset;
  }
  tabButtons.forEach((b, k) => b.addEventListener("click", () => arrangeInsets(k)));
  let insetFrame = null;
  function redrawInset() {
    if (insetFrame !== null) cancelAnimationFrame(insetFrame);
    insetFrame = null;
    for (const ins of insets) if (ins.shown) ins.redraw();
  }
  /** Redraw the shown insets in the next frame (once, however many updates come first). */
  function scheduleInsetRedraw() {
    if (insets.some((i) => i.shown) && insetFrame === null) {
      insetFrame = requestAnimationFrame(redrawInset);
    }
  }
  board.on("update", scheduleInsetRedraw);
  // O_M's subscript: the renderer writes the label's plain text into one text node; where
  // it holds the marker SUB_M, the <text> gets text nodes and <tspan> subscripts instead
  const SVG_NS = "http://www.w3.org/2000/svg";
  const drawSub = board.renderer.updateInternalText.bind(board.renderer);
  // a label placed by GCLabelling.fit (t.gcFit) is set as the SVG sets it: in the font the
  // placement measured (scene.metrics: DejaVu Sans Oblique, subscripts at SUB_SCALE of the
  // size, their baseline SUB_SHIFT lower), its text starting at its box's left side, the
  // baseline ASCENT below the box's top (the label's anchor: left, top)
  const SUBS = "₀₁₂₃₄₅₆₇₈₉ₓ" + "\u2098";
  const PLAIN = "0123456789xM";
  /** A label's text in the font the placement measured, subscripts as <tspan>s. */
  function setFitFont(node, f) {
    node.setAttribute("font-family", DATA.fit.metrics.family);
    node.setAttribute("font-style", "italic");
    node.setAttribute("font-size", `${f}px`);
    node.setAttribute("text-anchor", "start");
    node.setAttribute("dy", "0");
  }
  function setFitText(node, text, f) {
    const m = DATA.fit.metrics;
    setFitFont(node, f);
    while (node.firstChild) node.removeChild(node.firstChild);
    let run = "", sub = false;
    const flush = () => {
      if (!run) return;
      if (sub) {
        const ts = document.createElementNS(SVG_NS, "tspan");
        ts.setAttribute("baseline-shift", `${-m.sub_shift * f}px`);
        ts.setAttribute("font-size", `${m.sub_scale * f}px`);
        ts.textContent = run;
        node.appendChild(ts);
      } else node.appendChild(document.createTextNode(run));
      run = "";
    };
    for (const c of Array.from(text)) {
      const k = SUBS.indexOf(c);
      if ((k >= 0) !== sub) { flush(); sub = k >= 0; }
      run += k >= 0 ? PLAIN[k] : c;
    }
    flush();
  }
  board.renderer.updateInternalText = function (t) {
    drawSub(t);
    const node = t.rendNode, text = t.plaintext;
    if (!node || typeof text !== "string") return;
    if (t.gcFit) {
      setFitFont(node, t.gcFont);
      node.setAttribute("y", `${t.coords.scrCoords[2] + DATA.fit.metrics.ascent * t.gcFont}px`);
      if (t.gcSubShown === text + "|fit" + t.gcFont) return;
      t.gcSubShown = text + "|fit" + t.gcFont;
      setFitText(node, text, t.gcFont);
      return;
    }
    if (t.gcSubShown === text) return;
    t.gcSubShown = text;
    while (node.firstChild) node.removeChild(node.firstChild);
    if (text.indexOf(SUB_M) < 0) {
      node.appendChild(t.rendNodeText);
      return;
    }
    text.split(SUB_M).forEach((part, i) => {
      if (i > 0) {
        const sub = document.createElementNS(SVG_NS, "tspan");
        sub.setAttribute("baseline-shift", "-0.12em"); // within the line box
        sub.setAttribute("font-size", "70%");
        sub.textContent = "M";
        node.appendChild(sub);
      }
      if (part) node.appendChild(document.createTextNode(part));
    });
  };
  // labels in the font of the other pictures: labelling.FONT_PT in a frame FRAME_PT wide
  // (at least 10 px: a page opened in a hidden frame starts with a board 0 px wide)
  const LFONT = Math.max(10, Math.round(LSPEC.font * board.canvasWidth / LSPEC.frame));
  const withFont = (attrs) => Object.assign({}, attrs,
    { label: Object.assign({ fontSize: LFONT }, attrs && attrs.label) });
  // Colours, widths and dashes are applied to the SVG only in the redraws after a change of
  // visibility or highlight (JSXGraph's "enhanced rendering"), not on every parameter change.
  ctx.visualsDirty = true; // set by the modules that change visibility or highlight
  function setVisualPass() {
    board.renderer.enhancedRendering = ctx.visualsDirty;
    ctx.visualsDirty = false;
  }

  const entries = []; // {el, step, always, exists}
  function reg(el, step, opts) {
    const e = Object.assign({ el, step, always: false, exists: null, shown: true, hl: null },
      opts || {});
    entries.push(e);
    return el;
  }
  const num = (name, i) => () => (state.num && state.num[name] ? state.num[name][i] : NaN);

  // Unicode has no subscript capital M: the label text carries U+2098 (ₘ) as a marker and
  // the SVG shows a subscript "M" in its place (subscriptM, after each text update)
  const SUB_M = "\u2098";
  const LABEL = (s) => s.replace(/(\d)/g, (d) => "₀₁₂₃₄₅₆₇₈₉"[+d])
    .replace("_M", SUB_M).replace(/x$/, "ₓ");

  const labelled = []; // points whose labels are merged where they coincide ("O = Oₘ")
  const markers = []; // {name, el}: the unlabelled break points, which labels avoid
  const extras = []; // {el, text}: H, placed after the paper's points
  const unlabelled = []; // {name, el}: the worst and best markers, which H's label avoids
  function point(name, step, attrs) {
    const el = reg(board.create("point", [num(name, 0), num(name, 1)], Object.assign({
      name: LABEL(name), size: 2, strokeColor: COL.point, fillColor: COL.point,
      fixed: true, showInfobox: false, highlight: false,
    }, withFont(attrs))), step, {
      exists: () => !!(state.num && state.num[name]),
      hl: { size: 5, strokeColor: COL.highlight, fillColor: COL.highlight },
    });
    if (name === "H") extras.push({ el, text: "H" });
    else if (el.hasLabel) labelled.push({ name, el, text: LABEL(name), shownText: LABEL(name) });
    else markers.push({ name, el });
    return el;
  }

  /** A line c + a x + b y = 0 through P along d, from a function giving {P, d}. */
  function lineFrom(get, step, attrs, hl) {
    return reg(board.create("line", [
      () => { const g = get(); return g ? -(-g.d[1] * g.P[0] + g.d[0] * g.P[1]) : 0; },
      () => { const g = get(); return g ? -g.d[1] : 0; },
      () => { const g = get(); return g ? g.d[0] : 1; },
    ], Object.assign({ fixed: true, highlight: false, strokeWidth: 1.2 }, attrs)), step,
    { hl: hl || { strokeWidth: 3, strokeColor: COL.highlight } });
  }

  const outline = reg(board.create("curve", [[0], [0]], {
    strokeColor: COL.object, fillColor: COL.objectfill, fillOpacity: 0.6, strokeWidth: 1.2,
    highlight: false, fixed: true,
  }), "O", { always: true, exists: () => !!state.shape });
  outline.updateDataArray = function () {
    const sh = shapeNow();
    this.dataX = [];
    this.dataY = [];
    if (!sh) return;
    if (sh[0] === "circle") {
      for (let j = 0; j <= 128; j++) {
        this.dataX.push(sh[1] + sh[2] * Math.cos(TWO_PI * j / 128));
        this.dataY.push(sh[2] * Math.sin(TWO_PI * j / 128));
      }
    } else if (sh[0] === "rectangle") {
      const hh = sh[3] / 2;
      this.dataX = [sh[1], sh[2], sh[2], sh[1], sh[1]];
      this.dataY = [-hh, -hh, hh, hh, -hh];
    }
  };

  const xAxis = reg(board.create("axis", [[0, 0], [1, 0]], {
    strokeColor: COL.axis, highlight: false, needsRegularUpdate: false,
    ticks: { strokeColor: COL.tick, needsRegularUpdate: false, label: {
      fontSize: 10, strokeColor: COL.ticklabel } },
  }), "x-axis", { always: true });
  const yAxis = reg(board.create("axis", [[0, 0], [0, 1]], {
    strokeColor: COL.axis, highlight: false, needsRegularUpdate: false,
    ticks: { strokeColor: COL.tick, needsRegularUpdate: false, label: {
      fontSize: 10, strokeColor: COL.ticklabel } },
  }), "y-axis", { always: true });

  // friction cones (the given data of Fig. 2): wedges of half angle ξ about the normals
  for (const i of [1, 2]) {
    const cone = reg(board.create("curve", [[0], [0]], {
      strokeColor: "none", fillColor: COL.cone, fillOpacity: 0.35, highlight: false,
      fixed: true,
    }), i === 1 ? "side3" : "side4", {});
    cone.updateDataArray = function () {
      const q = state.num;
      this.dataX = [];
      this.dataY = [];
      if (!q) return;
      const P = q["P" + i], phi = state.p["phi" + i], xi = Math.atan(state.p["mu" + i]);
      const reach = 0.6 * Math.hypot(q.P1[0] - q.P2[0], q.P1[1] - q.P2[1]);
      const sgn = i === 1 ? -1 : 1;
      this.dataX.push(P[0]);
      this.dataY.push(P[1]);
      for (let j = 0; j <= 24; j++) {
        const a = phi - xi + 2 * xi * j / 24;
        this.dataX.push(P[0] + reach * sgn * Math.sin(a));
        this.dataY.push(P[1] - reach * Math.cos(a));
      }
      this.dataX.push(P[0]);
      this.dataY.push(P[1]);
    };
  }

  for (const n of [1, 3, 2, 4]) {
    lineFrom(() => state.num && state.num.sides[n], "side" + n,
      { strokeColor: COL.side, strokeWidth: 1.3 });
  }

  /** A polyline (a JSXGraph curve: no helper points) through the points ``get()`` gives. */
  function poly(get, step, attrs, hl) {
    const c = board.create("curve", [[0], [0]], Object.assign({ highlight: false, fixed: true,
      strokeWidth: 1 }, attrs));
    c.updateDataArray = function () {
      const pts = state.num ? get(state.num) : null;
      this.dataX = pts ? pts.map((q) => q[0]) : [];
      this.dataY = pts ? pts.map((q) => q[1]) : [];
    };
    return reg(c, step, { exists: () => !!state.num, hl: hl || null });
  }

  // feet of the contacts and O_M (§3.3)
  for (const i of [1, 2]) {
    poly((q) => [q["P" + i], q[`P${i}x`]], `P${i}x`, { strokeColor: COL.perp, dash: 2 });
    point(`P${i}x`, `P${i}x`);
  }
  point("O_M", "O_M", { face: "x", size: 4 });

  // the signed lengths are drawn beside their axis, 1.2 % of the view's width per n (as the
  // SVG/TikZ scene draws them): O_M X_n below the x-axis, O Y_n right of the y-axis
  const off = (n) => {
    const b = board.getBoundingBox();
    return 0.012 * (b[2] - b[0]) * (n + 0.5);
  };
  for (const n of [1, 2, 3, 4]) {
    point("X" + n, "X" + n);
    lineFrom(() => state.num && state.num.perps[n], "perp" + n,
      { strokeColor: COL.perp, dash: 2, strokeWidth: 1 });
    point("Y" + n, "Y" + n);
    const lengthAttrs = { strokeColor: COL.length, strokeWidth: 1.6,
      lastArrow: { type: 2, size: 6 } };
    const lit = { strokeWidth: 3.5, strokeColor: COL.highlight };
    // O_M X_n along the x-axis, drawn just below it; O Y_n along the y-axis, just left of it
    poly((q) => [[q.O_M[0], -off(n)], [q["X" + n][0], -off(n)]], "OMX" + n,
      lengthAttrs, lit);
    poly((q) => [[off(n), 0], [off(n), q["Y" + n][1]]], "OY" + n,
      lengthAttrs, lit);
    // V_n = (−O_M X_n, −O Y_n): the lengths carried to O and reversed
    poly((q) => [[q.V[n - 1][0], 0], q.V[n - 1], [0, q.V[n - 1][1]]], "V" + n,
      { strokeColor: COL["circle" + n], dash: 1 });
    point("V" + n, "V" + n, { size: 3.5, strokeColor: COL["circle" + n],
      fillColor: COL["circle" + n], label: { strokeColor: COL["circle" + n] } });
  }

  // the circles on the diameters O V_n: the polar graphs of k_n (eq. (31), Fig. 3)
  for (const n of [1, 2, 3, 4]) {
    const c = board.create("point", [num("circle" + n, 0), num("circle" + n, 1)],
      { visible: false, withLabel: false, fixed: true });
    reg(board.create("circle", [c, () => (state.num ? state.num["circle" + n][2] : 0)], {
      strokeColor: COL["circle" + n], strokeWidth: 1.4, dash: 2, fillColor: "none",
      highlight: false, fixed: true,
    }), "circle" + n, { exists: () => !!state.num,
      hl: { strokeWidth: 3.5, dash: 0 } });
  }
  for (const [n, m] of [[1, 2], [1, 3], [1, 4], [2, 3], [2, 4], [3, 4]]) {
    // the envelope's break points: small and unlabelled, as in the PNG, the SVG and the TikZ
    point(`B${n}${m}`, `B${n}${m}`, { size: 2, strokeColor: COL.breakpoint,
      fillColor: COL.breakpointfill,
      withLabel: false });
  }

  // the outer envelope k_grasp (eq. (25), Fig. 5), worst and best orientation, F_e at θ
  const env = reg(board.create("curve", [[0], [0]], {
    strokeColor: COL.envelope, strokeWidth: 3, fillColor: COL.fill, fillOpacity: 0.3,
    highlight: false, fixed: true,
  }), "envelope", { exists: () => !!state.num, hl: { strokeWidth: 4.5 } });
  env.updateDataArray = function () {
    this.dataX = state.num ? state.num.envX : [];
    this.dataY = state.num ? state.num.envY : [];
  };
  const reachFe = () => {
    const q = state.num;
    return q ? 1.15 * Math.max(q.worst.k, 0.25 * Math.hypot(q.P1[0] - q.P2[0], 0)) : 1;
  };
  // the direction e(θ) of the external force F_e at O (26)
  poly(() => [[0, 0], [reachFe() * Math.sin(state.p.theta),
    -reachFe() * Math.cos(state.p.theta)]], "envelope",
  { strokeColor: COL.force, strokeWidth: 1.5, dash: 3, lastArrow: { type: 1, size: 5 } });
  point("H", "envelope", { name: "H", size: 4, face: "o", strokeColor: COL.marker,
    fillColor: COL.markerfill });
  const specialPoint = (which, attrs) => {
    const el = reg(board.create("point", [
      () => (state.num ? state.num[which].point[0] : NaN),
      () => (state.num ? state.num[which].point[1] : NaN)], Object.assign({
      fixed: true, highlight: false, showInfobox: false,
    }, withFont(attrs))), "envelope", { exists: () => !!state.num });
    unlabelled.push({ name: which, el });
  };
  // the worst and best orientation: a magenta square and a cyan diamond, named in the panel
  // beside the same marks in the same colours, not on the crowded board
  specialPoint("worst", { name: "worst", face: "[]", size: 6, strokeColor: COL.worst,
    fillColor: COL.worst, withLabel: false });
  specialPoint("best", { name: "best", face: "<>", size: 6, strokeColor: COL.best,
    fillColor: COL.best, withLabel: false });

  // O and the draggable contacts
  labelled.unshift({ name: "O", text: "O", shownText: "O", el: reg(board.create("point", [0, 0],
    withFont({ name: "O", size: 2, fixed: true, strokeColor: COL.point, fillColor: COL.point,
      highlight: false, showInfobox: false })),
  "O", { always: true }) });
  const dragAttrs = withFont({ size: 6, strokeColor: COL.contact, fillColor: COL.contactfill,
    showInfobox: false, highlight: true, highlightFillColor: COL.contacthover });
  const P1 = reg(board.create("point", [state.p.x1, state.p.y],
    Object.assign({ name: "P₁" }, dragAttrs)), "P1", { always: true });
  const P2 = reg(board.create("point", [-state.p.x2, state.p.y],
    Object.assign({ name: "P₂" }, dragAttrs)), "P2", { always: true });
  labelled.push({ name: "P1", el: P1, text: "P₁", shownText: "P₁" },
    { name: "P2", el: P2, text: "P₂", shownText: "P₂" });

  Object.assign(ctx, {
    board, COL, LSPEC, GL, LFONT, insets, redrawInset, scheduleInsetRedraw, setFitText,
    arrangeInsets,
    setVisualPass, entries, labelled, markers, extras, unlabelled, P1, P2,
    ticks: [xAxis.defaultTicks, yAxis.defaultTicks],
  });
};
