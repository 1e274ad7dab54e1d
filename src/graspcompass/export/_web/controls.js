/* graspcompass web explorer — the controls: the sliders and their boxes, the readouts
 * (k_grasp, F_int, worst and best, the table of S_n, C_n, k_n), the heading, the error
 * box, the step navigator and its keys, play, the drags of P1 and P2, the view (the one
 * view-box rule, fit view) and the presets.  window.GCControls(ctx) wires them and adds
 * to ctx what the API and the first drawing call.
 */
window.GCControls = function (ctx) {
  "use strict";

  const { DATA, state, lastStep, recompute, shapeNow } = ctx;
  const { board, COL, P1, P2, setVisualPass, applyVisibility, placeLabels } = ctx;
  const { PI, fmtG, compute } = window.GCModel;

  // ------------------------------------------------------------------------------------
  // Controls: sliders, step navigator, readouts
  // ------------------------------------------------------------------------------------
  const $ = (id) => document.getElementById(id);
  const DEG = PI / 180;
  const rangeMax = (v) => Math.max(4, Math.ceil(2 * v));
  const SLIDERS = [
    { name: "x1", label: "x_1", unit: 1, min: 0.05, max: rangeMax(state.p.x1), step: 0.001 },
    { name: "x2", label: "x_2", unit: 1, min: 0.05, max: rangeMax(state.p.x2), step: 0.001 },
    { name: "y", label: "y", unit: 1, min: 0, max: rangeMax(state.p.y), step: 0.001 },
    { name: "phi1", label: "φ_1 (°)", unit: DEG, min: 1, max: 180, step: 0.1 },
    { name: "phi2", label: "φ_2 (°)", unit: DEG, min: 1, max: 180, step: 0.1 },
    { name: "mu1", label: "μ_1", unit: 1, min: 0.02, max: rangeMax(state.p.mu1), step: 0.001 },
    { name: "mu2", label: "μ_2", unit: 1, min: 0.02, max: rangeMax(state.p.mu2), step: 0.001 },
    { name: "theta", label: "θ (°)", unit: DEG, min: 0, max: 360, step: 0.5 },
  ];
  const sliderBox = $("gc-sliders");
  // subscripts as <sub> of ordinary digits (x_1 -> x<sub>1</sub>): glyphs every font has
  for (const s of SLIDERS) {
    const row = document.createElement("div");
    row.className = "gc-slider";
    row.innerHTML = `<label for="gc-slider-${s.name}"></label>` +
      `<input type="range" id="gc-slider-${s.name}" data-param="${s.name}" min="${s.min}" ` +
      `max="${s.max}" step="any">` +
      `<input type="number" id="gc-num-${s.name}" data-param="${s.name}" step="any" ` +
      `aria-label="${s.label.replace("_", "")}">`;
    setSubscripted(row.querySelector("label"), s.label);
    sliderBox.appendChild(row);
    const range = row.querySelector("input[type=range]");
    const box = row.querySelector("input[type=number]");
    range.addEventListener("input", () => {
      const t0 = performance.now();
      state.p[s.name] = parseFloat(range.value) * s.unit;
      userChanged();
      refresh(t0, s.name);
    });
    range.addEventListener("change", followView);
    box.addEventListener("change", () => {
      const v = parseFloat(box.value);
      if (Number.isFinite(v)) {
        const t0 = performance.now();
        state.p[s.name] = v * s.unit;
        userChanged();
        refresh(t0, null);
        followView();
      }
    });
    s.range = range;
    s.box = box;
  }

  function syncControls(except) {
    for (const s of SLIDERS) {
      const v = state.p[s.name] / s.unit;
      // the slider shows what the box shows: its range grows to take a value beyond it
      // (y < 0 from a drag below the x-axis, a large x1), it is never clamped, and it has
      // no step grid (step="any"): a grid from a widened minimum snapped y = −306.443580
      // to −306.443857, and a dragged x1 = 0.904011 to 0.904
      if (Number.isFinite(v) && (v < s.min || v > s.max)) {
        if (v < s.min) s.range.min = String((s.min = v));
        if (v > s.max) s.range.max = String((s.max = v));
        s.lastRange = null;
      }
      const r = String(v), b = String(+v.toPrecision(6));
      if (s.name !== except && r !== s.lastRange) {
        s.range.value = r;
        s.lastRange = r;
      }
      if (document.activeElement !== s.box && b !== s.lastBox) {
        s.box.value = b;
        s.lastBox = b;
      }
    }
  }

  /** ``x`` to 4 significant digits, in plain decimals (1005, 0.4340, 0.0001234, never
   * e-notation), so that no nonzero value prints 0; a value within 1e-12·scale of 0 (zero
   * to double precision, as C_4 = x_1 tan(φ_2 − ξ_2) of Fig. 6, where φ_2 = ξ_2) prints 0.
   * (To the decimals of the drawing's scale, S_4 = 0.434 printed 0 where the largest value
   * was 1005, and k_grasp = 4.593 printed 5.) */
  const SIG = 4;
  function sig(x, scale) {
    if (!Number.isFinite(x)) return "–";
    if (x === 0 || Math.abs(x) <= 1e-12 * scale) return "0";
    let d = SIG - 1 - Math.floor(Math.log10(Math.abs(x)));
    // log10 a hair off at a power of ten, or rounding up to one (9.9996 -> 10.00)
    if (Math.abs(+x.toFixed(Math.max(0, Math.min(100, d)))) >= 10 ** (SIG - d)) d -= 1;
    const t = d >= 0 ? x.toFixed(Math.min(100, d))
      : (Math.round(x / 10 ** -d) * 10 ** -d).toFixed(0);
    return t.replace(/^-/, "−");
  }
  /** An angle in degrees to 0.1° (−0.0 prints 0.0; within 1e-12 of a turn of 0 prints 0). */
  function fixed(x, d, scale) {
    if (!Number.isFinite(x)) return "–";
    if (Math.abs(x) <= 1e-12 * scale) return "0";
    const t = x.toFixed(d);
    return /^-0(\.0*)?$/.test(t) ? t.slice(1) : t.replace(/^-/, "−");
  }
  const deg = (t) => fixed(t / DEG, 1, 360) + "°";
  // the readouts: built once, then only their texts change; the worst and best marks are
  // SVG (the red square and green diamond of the board), subscripts and superscripts
  // <sub>/<sup>: no glyph a font may lack
  const MARK = (d) => `<svg class="gc-mark" viewBox="0 0 10 10" aria-hidden="true">` +
    `<path d="${d}"/></svg>`;
  $("gc-info").innerHTML =
    "<p id=\"gc-invalid-note\" hidden>The parameters violate the conditions of §2.2 (see " +
    "the message): the diagram shows the last valid grasp.</p><div id=\"gc-readout\">" +
    "<p>θ = <span data-r=\"theta\"></span>: k<sub>grasp</sub> = <span data-r=\"kgrasp\"></span>, " +
    "F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"Fint\"></span> " +
    "<small>(eqs. (25), (17))</small></p>" +
    `<p class="gc-worst" style="color:${COL.worst}">${MARK("M1 1h8v8H1z")} worst: θ = ` +
    "<span data-r=\"wtheta\"></span>, k = " +
    "<span data-r=\"wk\"></span>, F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"wF\"></span>" +
    "<span data-r=\"wn\"></span></p>" +
    `<p class="gc-best" style="color:${COL.best}">${MARK("M5 0 10 5 5 10 0 5z")} best: θ = ` +
    "<span data-r=\"btheta\"></span>, k = " +
    "<span data-r=\"bk\"></span>, F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"bF\"></span></p>" +
    "<table class=\"gc-v\"><tr><th></th><th>S<sub>n</sub></th><th>C<sub>n</sub></th>" +
    "<th>k<sub>n</sub>(θ)</th></tr>" +
    [1, 2, 3, 4].map((n) => `<tr style="color:${COL["circle" + n]}"><td>V<sub>${n}</sub></td>` +
      `<td data-r="S${n}"></td><td data-r="C${n}"></td><td data-r="k${n}"></td></tr>`).join("") +
    "</table><p class=\"gc-small\" data-r=\"prec\">Lengths and forces to 4 significant " +
    "digits, angles to 0.1°; a value within 10<sup>−12</sup> of the drawing's scale (the " +
    "largest |V| or |P|) is zero to double precision and prints 0.</p></div>";
  const readout = {};
  for (const el of $("gc-info").querySelectorAll("[data-r]")) {
    readout[el.getAttribute("data-r")] = { el, text: null };
  }
  /** Show ``text`` in the readout ``key`` (with subscripts, "V_1", when ``sub``). */
  function put(key, text, sub) {
    const r = readout[key];
    if (r.text !== text) {
      if (sub) setSubscripted(r.el, text);
      else r.el.textContent = text;
      r.text = text;
    }
  }
  /** The message of graspcompass.Grasp for the page: its exact values "v ≈ r" as the rounded
   * r alone, long decimals to 4 significant digits, >= and <= as ≥ and ≤. */
  function roundedMessage(msg) {
    return msg.replace(/(\S+) ≈ (\S+)/g, "$2")
      .replace(/-?\d+\.\d{5,}(?:e[+-]?\d+)?/gi, (m) => fmtG(parseFloat(m), 4))
      .replace(/>=/g, "≥").replace(/<=/g, "≤");
  }
  /** The message takes the caption's place in the flow, at least as tall as the caption
   * was (the board below moves as little as can be while the pointer drags). */
  let shownError;
  function renderInfo() {
    const q = state.num;
    if (state.error !== shownError) {
      const box = $("gc-error"), caption = $("gc-caption");
      if (state.error && !shownError) box.style.minHeight = `${caption.offsetHeight}px`;
      box.hidden = !state.error;
      caption.hidden = !!state.error;
      $("gc-error-text").textContent = state.error ? roundedMessage(state.error) : "";
      $("gc-invalid-note").hidden = !state.error;
      $("gc-readout").hidden = !!state.error;
      shownError = state.error;
    }
    if (state.error) return;
    // every length and force to 4 significant digits (the note says so), zero to double
    // precision of the diagram's scale (the largest |V_n|, |P_i|; for forces per unit F_e,
    // scale / (x1 + x2)) as 0
    const scale = Math.max(...q.V.map((v) => Math.hypot(v[0], v[1])), Math.hypot(...q.P1),
      Math.hypot(...q.P2));
    const D = q.P1[0] - q.P2[0]; // x1 + x2 of the grasp shown
    const len = (x) => sig(x, scale), force = (x) => sig(x, scale / D);
    put("theta", deg(state.p.theta));
    put("kgrasp", len(q.kgrasp));
    put("Fint", force(q.Fint));
    put("wtheta", deg(q.worst.theta));
    put("wk", len(q.worst.k));
    put("wF", force(q.worst.Fint));
    put("wn", q.worst.n ? ` (V_${q.worst.n}, k = |V_${q.worst.n}|)` : "", true);
    put("btheta", deg(q.best.theta));
    put("bk", len(q.best.k));
    put("bF", force(q.best.Fint));
    for (let n = 1; n <= 4; n++) {
      put("S" + n, len(q.S[n - 1]));
      put("C" + n, len(q.C[n - 1]));
      put("k" + n, len(q.k[n - 1]));
    }
  }

  /** A parameter changed in the page: the grasp is no longer the preset or the one given. */
  function userChanged() {
    if (state.follow) return;
    state.follow = true;
    const box = document.getElementById("gc-preset");
    if (box) box.value = "";
  }
  const g3 = (x) => fmtG(x, 3).replace(/^-/, "−");
  /** The parameters of the grasp drawn: the last valid one while the parameters are not
   * a grasp (a drag below the x-axis), else the parameters. */
  const drawnParams = () => (state.error && state.validP ? state.validP : state.p);
  /** The heading: the given title until a parameter is changed, then the values of the
   * grasp drawn (their subscripts set as <sub>): never those of an invalid grasp, which
   * the board does not draw (the message gives its failing value). */
  let shownHeading = null;
  function renderHeading() {
    const p = drawnParams();
    const own = !(!state.follow && !(DATA.untitled && state.title === DATA.title));
    const text = !own ? state.title
      : `Your grasp: x_1 = ${g3(p.x1)}, x_2 = ${g3(p.x2)}, y = ${g3(p.y)}, ` +
        `φ_1 = ${g3(p.phi1 / DEG)}°, φ_2 = ${g3(p.phi2 / DEG)}°, μ_1 = ${g3(p.mu1)}, ` +
        `μ_2 = ${g3(p.mu2)}`;
    const h = document.querySelector(".gc-header h1");
    if (!h || text === shownHeading) return;
    if (own) setSubscripted(h, text);
    else h.textContent = text;
    shownHeading = text;
  }

  /** Put ``text`` into ``el`` with "k_grasp", "O_M", "X_{1}" as subscripts (DOM nodes,
   * never HTML parsing): captions read as the paper prints them, not with underscores. */
  function setSubscripted(el, text) {
    el.textContent = "";
    const re = /([A-Za-zα-ωΑ-Ω])_(\{[^}]*\}|[A-Za-z0-9]+)/g;
    let at = 0, m;
    while ((m = re.exec(text)) !== null) {
      el.appendChild(document.createTextNode(text.slice(at, m.index + 1)));
      const sub = document.createElement("sub");
      sub.textContent = m[2].replace(/^\{|\}$/g, "");
      el.appendChild(sub);
      at = m.index + m[0].length;
    }
    el.appendChild(document.createTextNode(text.slice(at)));
  }
  let shownPlaying = null;
  function renderStep() {
    const s = DATA.steps[state.step];
    $("gc-stepno").textContent = `Step ${s.index} / ${lastStep}`;
    setSubscripted($("gc-caption-text"), s.caption);
    $("gc-ref").textContent = s.ref;
    $("gc-instrument").textContent = s.instrument;
    $("gc-first").disabled = $("gc-prev").disabled = state.step === 0;
    $("gc-next").disabled = $("gc-last").disabled = state.step === lastStep;
    const playing = !!state.playing;
    if (playing !== shownPlaying) {
      // SVG icons, not glyphs (⏮, ⏭, ❚❚ are missing from many fonts)
      $("gc-play").innerHTML = `<svg class="gc-icon" viewBox="0 0 16 16" aria-hidden="true">` +
        `<path d="${playing ? "M3 2h4v12H3zM9 2h4v12H9z" : "M4 2v12l10-6z"}"/></svg>` +
        `<span>${playing ? "pause" : "play"}</span>`;
      shownPlaying = playing;
    }
  }

  /** Finish an update that began at ``t0``: record how long it took (ms). */
  function record(t0) {
    const dt = performance.now() - t0;
    state.last = dt;
    state.timings.push(dt);
    if (state.timings.length > 5000) state.timings.shift();
  }

  /** P1 and P2 where the grasp drawn has them (the last valid one's, while invalid). */
  function placeContacts() {
    const p = drawnParams();
    P1.setPositionDirectly(JXG.COORDS_BY_USER, [p.x1, p.y]);
    P2.setPositionDirectly(JXG.COORDS_BY_USER, [-p.x2, p.y]);
  }

  /** Recompute after a parameter change and redraw; ``t0`` from performance.now(). */
  function refresh(t0, fromSlider) {
    recompute();
    renderHeading();
    placeContacts();
    applyVisibility();
    setVisualPass();
    board.update();
    // the panel after the board: its layout waits for the next frame, not for JSXGraph
    syncControls(fromSlider);
    renderInfo();
    record(t0);
  }

  // dragging P1 moves x1 and y, P2 moves x2 and y (JSXGraph redraws after the handler)
  function onDrag(which) {
    state.pendingT0 = performance.now();
    userChanged();
    if (which === 1) {
      state.p.x1 = P1.X();
      state.p.y = P1.Y();
      P2.setPositionDirectly(JXG.COORDS_BY_USER, [-state.p.x2, state.p.y]);
    } else {
      state.p.x2 = -P2.X();
      state.p.y = P2.Y();
      P1.setPositionDirectly(JXG.COORDS_BY_USER, [state.p.x1, state.p.y]);
    }
    recompute();
    // an invalid drag (below the x-axis, past the other contact) leaves P1 and P2 where
    // the last valid grasp, the one drawn, has them; the pointer drags on, and the point
    // follows it again once the grasp is valid
    if (state.error) placeContacts();
    renderHeading();
    applyVisibility();
    setVisualPass();
  }
  // zoom and pan (shift + wheel / drag) move the labels' frame: place them again
  let relabel = null;
  board.on("boundingbox", () => {
    placeLabels();
    if (relabel === null) {
      relabel = requestAnimationFrame(() => {
        relabel = null;
        board.update();
      });
    }
  });
  P1.on("drag", () => onDrag(1));
  P2.on("drag", () => onDrag(2));
  // the view follows a drag once it ends (refitting under the mouse would move the point)
  P1.on("up", () => followView());
  P2.on("up", () => followView());
  board.on("update", () => {
    if (state.pendingT0 !== null) {
      const t0 = state.pendingT0;
      state.pendingT0 = null;
      syncControls(null);
      renderInfo();
      record(t0);
    }
  });

  function setStep(i) {
    const n = DATA.steps.length;
    if (!Number.isInteger(i) || i < -n || i >= n) {
      throw new RangeError(`step ${i} out of range: the protocol has ${n} steps, 0 to ${n - 1}`);
    }
    state.step = ((i % n) + n) % n;
    applyVisibility();
    renderStep();
    setVisualPass();
    board.update();
    return state.step;
  }

  function stopPlay() {
    if (state.playing) clearTimeout(state.playing);
    state.playing = null;
    renderStep();
  }
  function playNext() {
    if (state.step >= lastStep) {
      stopPlay();
      return;
    }
    setStep(state.step + 1);
    const s = DATA.steps[state.step];
    // long enough to read the caption: 2.5 s, more for a long one or a key result
    const ms = Math.max(2500, 45 * (s.caption.length + s.ref.length)) + (s.key ? 1000 : 0);
    state.playing = setTimeout(playNext, ms);
    renderStep();
  }
  function play() {
    if (state.playing) {
      stopPlay();
      return;
    }
    if (state.step >= lastStep) setStep(0);
    state.playing = setTimeout(playNext, 800);
    renderStep();
  }
  $("gc-first").addEventListener("click", () => { stopPlay(); setStep(0); });
  $("gc-prev").addEventListener("click", () => { stopPlay(); setStep(Math.max(0, state.step - 1)); });
  $("gc-next").addEventListener("click", () => {
    stopPlay();
    setStep(Math.min(lastStep, state.step + 1));
  });
  $("gc-last").addEventListener("click", () => { stopPlay(); setStep(lastStep); });
  $("gc-play").addEventListener("click", play);
  document.addEventListener("keydown", (ev) => {
    if (ev.target && /^(INPUT|SELECT|TEXTAREA)$/.test(ev.target.tagName)) return;
    if (ev.key === "ArrowRight") setStep(Math.min(lastStep, state.step + 1));
    else if (ev.key === "ArrowLeft") setStep(Math.max(0, state.step - 1));
    else if (ev.key === "Home") setStep(0);
    else if (ev.key === "End") setStep(lastStep);
  });

  /** The one view-box rule of every picture (graspcompass.layout.view_box, by roles):
   * O, the contacts, the object, X_n, Y_n and the circles (so V_n), each clipped to 3×
   * the largest of |P_i|, |V_n| and the object's size, a square, 8 % margin each side. */
  const VIEW_MARGIN = 0.08;
  function viewBox() {
    const q = state.num || compute(Object.assign({}, state.p));
    const pts = [[0, 0], q.P1, q.P2];
    let scale = Math.max(Math.hypot(...q.P1), Math.hypot(...q.P2));
    for (let n = 1; n <= 4; n++) {
      const [cx, cy, r] = q["circle" + n];
      if (Number.isFinite(r)) pts.push([cx - r, cy - r], [cx + r, cy + r]);
      scale = Math.max(scale, 2 * r);
      pts.push(q["X" + n], q["Y" + n]);
    }
    const sh = shapeNow();
    if (sh) {
      const [xa, xb, hh] = sh[0] === "circle" ? [sh[1] - sh[2], sh[1] + sh[2], sh[2]]
        : [sh[1], sh[2], sh[3] / 2];
      pts.push([xa, -hh], [xb, hh]);
      scale = Math.max(scale, (xb - xa) / 2, hh);
    }
    const lim = 3 * (scale || 1);
    const clip = (v) => Math.min(Math.max(Number.isFinite(v) ? v : 0, -lim), lim);
    const xs = pts.map((p) => clip(p[0])), ys = pts.map((p) => clip(p[1]));
    const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys),
      1e-9);
    const cx = (Math.max(...xs) + Math.min(...xs)) / 2, cy = (Math.max(...ys) + Math.min(...ys)) / 2;
    const half = span / 2 + VIEW_MARGIN * span;
    return [cx - half, cx + half, cy - half, cy + half];
  }
  /** Refit the view when the diagram's box (the one rule) leaves the view, or fills less
   * than 40 % of its width: after a drag, a slider or a typed value. */
  function followView() {
    const [x0, y1, x1, y0] = board.getBoundingBox();
    const [a, b, c, d] = viewBox();
    const w = x1 - x0, tol = 1e-6 * w;
    if (a < x0 - tol || b > x1 + tol || c < y0 - tol || d > y1 + tol || b - a < 0.4 * w) fit();
  }
  function fit() {
    const [x0, x1, y0, y1] = viewBox();
    board.setBoundingBox([x0, y1, x1, y0], true);
    placeLabels();
    ctx.visualsDirty = true;
    setVisualPass();
    board.fullUpdate();
  }
  $("gc-fit").addEventListener("click", fit);

  // presets of the paper (floats of graspcompass.grasp.PRESETS)
  const presetBox = $("gc-preset");
  for (const [key, pr] of Object.entries(DATA.presets)) {
    const o = document.createElement("option");
    o.value = key;
    o.textContent = pr.title;
    presetBox.appendChild(o);
  }
  presetBox.addEventListener("change", () => {
    const pr = DATA.presets[presetBox.value];
    if (!pr) return;
    const t0 = performance.now();
    Object.assign(state.p, pr.params);
    state.shape = pr.shape;
    state.title = pr.title;
    state.follow = false;
    refresh(t0, null);
    fit();
  });
  // the page of a preset names it in the menu: the same parameters (to rounding) and object
  const same = (a, b) => Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(a), Math.abs(b));
  for (const [key, pr] of Object.entries(DATA.presets)) {
    const params = Object.keys(pr.params).every((k) => same(pr.params[k], DATA.params[k]));
    if (params && JSON.stringify(pr.shape) === JSON.stringify(DATA.shape)) {
      presetBox.value = key;
      break;
    }
  }

  Object.assign(ctx, {
    refresh, setStep, stopPlay, play, fit, viewBox, userChanged, roundedMessage,
    syncControls, renderInfo, renderStep, renderHeading, record,
  });
};
