/* graspcompass web explorer: the internal force diagram of a two-point grasp
 * (Ito, Tanaka, Sasaki, Robotica 30(5), 2012), live in the browser with JSXGraph.
 *
 * The page embeds its data as JSON (#gc-data): the start parameters, the steps of the
 * construction protocol (numbered as `graspcompass steps` prints them), the palette and
 * the paper's presets.  Everything is computed in the page from the closed form of the
 * paper, eqs. (27)-(39) (model.js, window.GCModel).
 *
 * The drawing follows §3.3: X_n where the extended cone side meets the x-axis, the
 * perpendicular from P2x (n = 1, 3) or P1x (n = 2, 4) to that side meets the y-axis at
 * Y_n, V_n = (−O_M X_n, −O Y_n); the circle on the diameter O V_n is the polar graph of
 * k_n (Thales, eq. (31)); the outer envelope of the circles is k_grasp (Fig. 5).
 *
 * This file holds the page's state, wires its modules (each a function of one shared
 * context, inlined before this file into the page's one script, in this order):
 *   model.js      GCModel: condition (1), the closed form, the envelope, Python's numbers
 *   board.js      GCBoard: the JSXGraph board and every object, registered by step
 *   placement.js  GCPlacement: what each step shows, the labels' places, the insets
 *   controls.js   GCControls: sliders, readouts, heading, step navigator, drags, view
 * and exposes window.graspcompass: set({x1: .., mu2: ..}), get(name), step(i),
 * toScreen(name), lastUpdateMs, timings(), envelope(), kGrasp(θ), error() (see the docs
 * page "Explore").
 */
(function () {
  "use strict";

  const DATA = JSON.parse(document.getElementById("gc-data").textContent);
  const { NAMES, validate, compute, envelopeOf, kOf, kGraspOf, fmtG, sympyFloat } =
    window.GCModel;

  // ------------------------------------------------------------------------------------
  // State
  // ------------------------------------------------------------------------------------
  const state = {
    p: Object.assign({}, DATA.params),
    error: null,
    num: null,
    step: DATA.initial_step,
    timings: [],
    last: NaN,
    pendingT0: null,
    playing: null,
    follow: false, // true once a parameter is changed in the page (heading, outline follow)
    title: DATA.title,
    validP: null,
  };
  const stepIndex = {};
  DATA.steps.forEach((s) => { stepIndex[s.name] = s.index; });
  const lastStep = DATA.steps.length - 1;

  /** Validate and compute; an invalid grasp keeps the last valid one drawn (state.num),
   * while the API's model values (get, kGrasp, envelope) are null until it is valid again. */
  function recompute() {
    state.error = validate(state.p);
    if (!state.error) {
      state.num = compute(state.p);
      state.validP = Object.assign({}, state.p);
    }
  }

  /** The object's outline now: as given until the parameters are changed in the page; then
   * it follows the contacts (a circle: centred on the x-axis at O_M through P1 and P2; a
   * rectangle: its sides through P1 and P2, tall enough to hold them), for the last valid
   * grasp.  Returns ["circle", cx, r] or ["rectangle", xmin, xmax, h], or null. */
  function shapeNow() {
    const sh = state.shape;
    if (!sh) return null;
    const p = state.validP || state.p;
    if (sh[0] === "circle") {
      if (!state.follow) return ["circle", 0, sh[1]];
      return ["circle", (p.x1 - p.x2) / 2, Math.hypot((p.x1 + p.x2) / 2, p.y)];
    }
    if (sh[0] === "rectangle") {
      if (!state.follow) return ["rectangle", -sh[1] / 2, sh[1] / 2, sh[2]];
      return ["rectangle", -p.x2, p.x1, Math.max(sh[2], 2.5 * p.y)];
    }
    return null;
  }

  // the modules: the board, what each step shows, the controls (each adds to ctx)
  const ctx = { DATA, state, stepIndex, lastStep, recompute, shapeNow, drawValue, getValue };
  window.GCBoard(ctx);
  window.GCPlacement(ctx);
  window.GCControls(ctx);
  const { board, GL, LSPEC, insets, redrawInset, entries, labelled, markers } = ctx;
  const { entryOf, applyVisibility, refresh, setStep, stopPlay, play, fit, viewBox,
    userChanged, roundedMessage, syncControls, renderInfo, renderStep, renderHeading,
    record } = ctx;

  // ------------------------------------------------------------------------------------
  // The API for tests and embedding
  // ------------------------------------------------------------------------------------
  const PARAM_ALIASES = { θ: "theta", φ1: "phi1", φ2: "phi2", μ1: "mu1", μ2: "mu2" };
  /** Where a named point is drawn: the last valid grasp's, also while the parameters are
   * invalid (getValue then gives null for the model's points). */
  function drawValue(name) {
    return getValue(name, true);
  }
  function getValue(name, drawing) {
    const key = PARAM_ALIASES[name] || name;
    if (NAMES.indexOf(key) >= 0) return state.p[key];
    if (key === "xi1" || key === "xi2") return Math.atan(state.p["mu" + key[2]]);
    if (key === "step") return state.step;
    if (key === "error") return state.error;
    // the contacts drawn stay those of the last valid grasp while the parameters are not
    // a grasp; get() gives the parameters' own
    const p = drawing && state.error && state.validP ? state.validP : state.p;
    if (key === "P1") return [p.x1, p.y];
    if (key === "P2") return [-p.x2, p.y];
    if (key === "O") return [0, 0];
    const q = state.error && !drawing ? null : state.num;
    const known = /^(P[12]x|O_M|[XYVB]\d+|circle[1-4]|[SCk][1-4]|OMX[1-4]|OY[1-4]|H|worst|best|kgrasp|Fint)$/;
    if (!known.test(key)) throw new Error(`unknown name ${JSON.stringify(name)}`);
    if (!q) return null;
    if (key === "worst" || key === "best") return q[key].point.slice();
    if (/^[SCk][1-4]$/.test(key)) return q[key[0]][+key[1] - 1];
    const v = q[key];
    if (v === undefined) throw new Error(`unknown name ${JSON.stringify(name)}`);
    return Array.isArray(v) ? v.slice() : v;
  }

  const api = {
    /** The protocol's steps: [{index, name, caption, ref, instrument, key}]. */
    steps: DATA.steps.map((s) => Object.assign({}, s)),
    version: DATA.version,
    board,
    /** Set parameters (x1, x2, y, phi1, phi2 in radians, mu1, mu2, theta) and redraw. */
    set(values) {
      const t0 = performance.now();
      for (const k of Object.keys(values)) {
        const key = PARAM_ALIASES[k] || k;
        if (NAMES.indexOf(key) < 0) {
          throw new Error(`unknown parameter ${JSON.stringify(k)}; use ${NAMES.join(", ")}`);
        }
      }
      for (const [k, v] of Object.entries(values)) state.p[PARAM_ALIASES[k] || k] = Number(v);
      userChanged();
      refresh(t0, null);
      return state.error;
    },
    /** A parameter's value, or the coordinates [x, y] of a named point (null if invalid). */
    get: getValue,
    /** Show the construction up to step i (negative counts from the end). */
    step: (i) => {
      stopPlay();
      return setStep(i);
    },
    /** Viewport coordinates [px, py] of a named point where it is drawn (as page.mouse
     * expects; the last valid grasp's while the parameters are not a grasp). */
    toScreen(name) {
      const xy = drawValue(name);
      if (!Array.isArray(xy)) throw new Error(`${name} is not a point here`);
      const c = new JXG.Coords(JXG.COORDS_BY_USER, xy, board).scrCoords;
      const r = board.containerObj.getBoundingClientRect();
      return [r.left + c[1], r.top + c[2]];
    },
    /** The labels as placed: [{names, direction, offset, box}] (points, y up). */
    labels: () => JSON.parse(JSON.stringify(ctx.lastPlacement())),
    /** As drawn (getBoundingClientRect): per shown point of the paper and break point, its
     * marker's rectangle and its label's (null: none), for the checks of the label rules. */
    labelRects: () => {
      const rect = (n) => { const r = n.getBoundingClientRect(); return [r.left, r.top,
        r.right, r.bottom]; };
      const [x0, y1, x1, y0] = board.getBoundingBox();
      const inside = (p) => p && p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1;
      const out = [];
      for (const e of labelled) {
        if (!e.el.rendNode || !entryOf.get(e.el).shown || !inside(drawValue(e.name))) continue;
        const l = e.el.label;
        const shown = l && l.rendNode && l.visPropCalc.visible && e.group;
        out.push({ id: e.name, m: rect(e.el.rendNode), t: shown ? rect(l.rendNode) : null });
      }
      for (const m of markers) {
        if (!m.el.rendNode || !entryOf.get(m.el).shown || !inside(drawValue(m.name))) continue;
        out.push({ id: m.name, m: rect(m.el.rendNode), t: null });
      }
      return out;
    },
    /** The zoomed insets as drawn (those shown): [{board: its rectangle, pts: per
     * marker in it and label, as labelRects, zoom: over the board, region}]. */
    insetRects: () => {
      redrawInset();
      const insetStates = ctx.insetStates();
      return insets.filter((i) => i.shown).map((ins, k) => Object.assign(ins.rects(),
        { zoom: ins.zoom, region: insetStates[k] && insetStates[k].region }));
    },
    /** The inset in sight, among those shown (0 for the first); ``k`` chooses it, as its
     * tab does. */
    insetTab: (k) => ctx.arrangeInsets(k),
    /** The board's rectangle (client pixels). */
    boardRect: () => { const r = board.containerObj.getBoundingClientRect();
      return [r.left, r.top, r.right, r.bottom]; },
    /** What the last placement was given: {anchors, texts, opts} (points, y up). */
    labelInputs: () => JSON.parse(JSON.stringify(ctx.lastInputs())),
    /** The one label placement (labelling.place) on any data, for checks. */
    placeLabels: (anchors, texts, opts) => GL.place(anchors, texts,
      Object.assign({ spec: LSPEC }, opts || {})),
    /** The view box [xmin, xmax, ymin, ymax] of the one rule (layout.view_box). */
    viewBox: () => viewBox(),
    /** The object's outline as drawn: ["circle", cx, r], ["rectangle", xmin, xmax, h] or
     * null (it follows the contacts once a parameter is changed in the page). */
    outline: () => shapeNow(),
    /** Whether the objects of the step named ``name`` (e.g. "envelope", "V1") are drawn. */
    drawn: (name) => entries.some((e) => e.step === name && e.shown),
    /** The failing inequality when the parameters are not a valid grasp, else null. */
    error: () => state.error,
    /** k_grasp(θ) (eq. (25)) and the four k_n(θ) (eq. (32)) for the current grasp. */
    kGrasp: (theta) => (state.num && !state.error ? kGraspOf(state.num.V, theta) : null),
    k: (theta) => (state.num && !state.error ? kOf(state.num.V, theta) : null),
    /** The envelope: arcs, local maxima (the V_n on it, k = |V_n|), worst and best case. */
    envelope() {
      const q = state.error ? null : state.num;
      if (!q) return null;
      return JSON.parse(JSON.stringify({ arcs: q.arcs, maxima: q.maxima, worst: q.worst,
        best: q.best }));
    },
    /** Time of the last update (ms, performance.now() in the page). */
    get lastUpdateMs() {
      return state.last;
    },
    timings: () => state.timings.slice(),
    resetTimings() {
      state.timings = [];
    },
    play,
    pause: stopPlay,
    fit,
    /** The model alone (no drawing), for checks: validate(p), compute(p). */
    model: { validate, compute, envelopeOf, fmtG, sympyFloat, roundedMessage },
  };
  window.graspcompass = api;

  // first drawing
  state.shape = DATA.shape;
  const t0 = performance.now();
  recompute();
  syncControls(null);
  applyVisibility();
  renderInfo();
  renderStep();
  renderHeading();
  fit();
  record(t0);
  document.body.setAttribute("data-ready", "1");
})();