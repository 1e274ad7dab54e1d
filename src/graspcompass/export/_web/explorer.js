/* graspcompass web explorer: the internal force diagram of a two-point grasp
 * (Ito, Tanaka, Sasaki, Robotica 30(5), 2012), live in the browser with JSXGraph.
 *
 * The page embeds its data as JSON (#gc-data): the start parameters, the steps of the
 * construction protocol (numbered as `graspcompass steps` prints them), the palette and
 * the paper's presets.  Everything is computed here from the closed form of the paper,
 * eqs. (27)-(39), ported from graspcompass.grasp / graspcompass.grasp._floatpath:
 *
 *   tan(φ ± ξ) = (sin φ ± μ cos φ) / (cos φ ∓ μ sin φ)                       (23)
 *   S_n = ∓(x1 + x2)/2 ± y tan(φ ± ξ),  C_n = x_{2|1} tan(φ ± ξ)       (28)-(39)
 *   V_n = (S_n, C_n),  k_n(θ) = S_n sin θ − C_n cos θ                  (30)-(33)
 *   k_grasp(θ) = max(0, k_1, .., k_4),  F_int = k / (x1 + x2) · F_e       (25), (17)
 *
 * The drawing follows §3.3: X_n where the extended cone side meets the x-axis, the
 * perpendicular from P2x (n = 1, 3) or P1x (n = 2, 4) to that side meets the y-axis at
 * Y_n, V_n = (−O_M X_n, −O Y_n); the circle on the diameter O V_n is the polar graph of
 * k_n (Thales, eq. (31)); the outer envelope of the circles is k_grasp (Fig. 5).
 *
 * window.graspcompass: set({x1: .., mu2: ..}), get(name), step(i), toScreen(name),
 * lastUpdateMs, timings(), envelope(), kGrasp(θ), error() (see the docs page "Explore").
 */
(function () {
  "use strict";

  const DATA = JSON.parse(document.getElementById("gc-data").textContent);
  const PI = Math.PI;
  const TWO_PI = 2 * Math.PI;
  const NAMES = ["x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "theta"];
  const FLOAT_MARGIN = 1e-12; // graspcompass.grasp._floatpath.FLOAT_MARGIN
  const MERGE = 1e-13; // break angles closer than this are one (envelope._FLOAT_MERGE)

  // ------------------------------------------------------------------------------------
  // Number formatting as Python prints it (the error messages of graspcompass.grasp)
  // ------------------------------------------------------------------------------------
  function stripZeros(s) {
    return s.indexOf(".") < 0 ? s : s.replace(/0+$/, "").replace(/\.$/, "");
  }

  /** Python's format(x, ".{p}g"). */
  function fmtG(x, p) {
    if (Number.isNaN(x)) return "nan";
    if (!Number.isFinite(x)) return x > 0 ? "inf" : "-inf";
    if (x === 0) return Object.is(x, -0) ? "-0" : "0";
    const [m, ex] = x.toExponential(p - 1).split("e");
    const e = parseInt(ex, 10);
    if (e < -4 || e >= p) {
      const a = Math.abs(e);
      return stripZeros(m) + "e" + (e < 0 ? "-" : "+") + (a < 10 ? "0" + a : String(a));
    }
    return stripZeros(x.toFixed(Math.max(0, p - 1 - e)));
  }

  /** str(sympy.Float(x)): 15 significant digits, fixed for 1e-5 < |x| < 1e15. */
  function sympyFloat(x) {
    if (x === 0) return "0.0";
    const e = parseInt(x.toExponential(14).split("e")[1], 10);
    if (e > -5 && e < 15) return x.toPrecision(15);
    return x.toExponential(14);
  }

  /** str(decimal.Decimal(s)) of a number's text (as sympy's Float.__format__ prints). */
  function decimalStr(s) {
    const m = s.match(/^(-?)(\d*)\.?(\d*)(?:e([+-]?\d+))?$/i);
    if (!m) return s;
    let digits = (m[2] + m[3]).replace(/^0+(?=\d)/, "");
    const exp = (m[4] ? parseInt(m[4], 10) : 0) - m[3].length;
    if (digits === "") digits = "0";
    const adjusted = exp + digits.length - 1;
    let body;
    if (exp <= 0 && adjusted >= -6) {
      if (exp === 0) body = digits;
      else if (digits.length > -exp) {
        body = digits.slice(0, digits.length + exp) + "." + digits.slice(digits.length + exp);
      } else body = "0." + "0".repeat(-exp - digits.length) + digits;
    } else {
      body = digits[0] + (digits.length > 1 ? "." + digits.slice(1) : "") + "E" +
        (adjusted >= 0 ? "+" : "-") + Math.abs(adjusted);
    }
    return m[1] + body;
  }

  /** graspcompass.grasp._fmt of a float parameter: f"{Float(x)} ≈ {x:.4g}". */
  function fmtValue(x) {
    return decimalStr(sympyFloat(x)) + " ≈ " + fmtG(x, 4);
  }

  /** graspcompass.grasp._fmt_angle: the angle as a multiple of π. */
  function fmtAngle(v) {
    const f = v / PI;
    return Number.isFinite(f) && Math.abs(f) < 1e6 ? fmtG(f, 3) + "π" : v + " rad";
  }

  /** Python's repr of a float (shortest round trip). */
  function pyRepr(x) {
    if (Number.isInteger(x) && Math.abs(x) < 1e16) return x.toFixed(1);
    let s = String(x);
    const m = s.match(/^(-?[\d.]+)e([+-])(\d+)$/);
    if (m) s = m[1] + "e" + m[2] + (m[3].length < 2 ? "0" + m[3] : m[3]);
    return s;
  }

  // ------------------------------------------------------------------------------------
  // The model: condition (1) and the closed form (27)-(39)
  // ------------------------------------------------------------------------------------
  /** The first check of graspcompass.Grasp that ``p`` fails, as its message; else null. */
  function validate(p) {
    for (const k of NAMES) {
      if (typeof p[k] !== "number" || !Number.isFinite(p[k])) {
        const v = p[k];
        const shown = typeof v !== "number" ? String(v)
          : Number.isNaN(v) ? "nan" : v > 0 ? "inf" : "-inf";
        return `${k}: expected a finite number, got ${shown}`;
      }
    }
    for (const i of [1, 2]) {
      const mu = p["mu" + i];
      if (mu <= 0) {
        return `contact ${i}: the friction coefficient μ${i} = ${fmtValue(mu)} must be positive`;
      }
    }
    if (!(p.x1 + p.x2 > 0)) {
      return `x1 + x2 = ${fmtValue(p.x1 + p.x2)} must be positive: P1 = (x1, y) lies right ` +
        "of P2 = (-x2, y) (x1 <= 0 or x2 <= 0 alone is allowed: the centre of mass then " +
        "projects onto the line through the contacts beyond a contact)";
    }
    if (p.y < 0) {
      return `y = ${fmtValue(p.y)} must be non-negative (the frame of §2.2.1 puts y >= 0)`;
    }
    for (const i of [1, 2]) {
      const phi = p["phi" + i];
      if (!(phi > 0)) {
        return `contact ${i}: φ${i} = ${fmtAngle(phi)} must be positive (0 < φ ≤ π)`;
      }
      if (phi > PI) {
        return `contact ${i}: φ${i} = ${fmtAngle(phi)} must not exceed π (0 < φ ≤ π)`;
      }
    }
    // floats within rounding of a bound of condition (1) (Grasp._check_float_margins)
    for (const i of [1, 2]) {
      const phi = p["phi" + i], xi = Math.atan(p["mu" + i]);
      const lo = phi - xi, up = phi + xi;
      const rows = [
        [lo, "−", -PI / 2, "−π/2", ">"], [lo, "−", PI / 2, "π/2", "<"],
        [up, "+", PI / 2, "π/2", ">"], [up, "+", 3 * PI / 2, "3π/2", "<"],
      ];
      for (const [value, sign, bound, b, rel] of rows) {
        const margin = rel === ">" ? value - bound : bound - value;
        if (Math.abs(margin / Math.abs(bound)) >= FLOAT_MARGIN) continue;
        const where = margin > 0 ? "within" : "on the wrong side of, and within";
        return `contact ${i}: φ${i} ${sign} ξ${i} ${rel} ${b} of condition (1) is within ` +
          `rounding of its bound: φ${i} ${sign} ξ${i} = ${pyRepr(value)} rad is ${where} ` +
          `${fmtG(Math.abs(margin), 2)} rad of ${b}, below the 1e-12·|${b}| that double ` +
          "precision resolves here (the cone side is nearly horizontal and X_n, Y_n, V_n " +
          `scale like 1/cos(φ${i} ${sign} ξ${i})). Give the parameters exactly, as text such ` +
          "as 'pi/2', '3*pi/4' or '1/3', to use the exact path";
      }
    }
    for (const i of [1, 2]) {
      const phi = p["phi" + i], xi = Math.atan(p["mu" + i]);
      const lo = phi - xi, up = phi + xi;
      const who = `the friction cone at P${i}`, other = `P${3 - i}`;
      const pre = `contact ${i}: `;
      if (!(lo + PI / 2 > 0)) {
        return pre + `φ${i} − ξ${i} = ${fmtAngle(lo)} must exceed −π/2 — ${who} turns past ` +
          "the contact's tangent line (condition (1))";
      }
      if (!(PI / 2 - lo > 0)) {
        return pre + `φ${i} − ξ${i} = ${fmtAngle(lo)} must be below π/2 — ${who} does not ` +
          `contain ${other} (its lower side passes above ${other}; condition (1))`;
      }
      if (!(up - PI / 2 > 0)) {
        return pre + `φ${i} + ξ${i} = ${fmtAngle(up)} must exceed π/2 — ${who} does not ` +
          `contain ${other} (its upper side passes below ${other}; condition (1))`;
      }
      if (!(3 * PI / 2 - up > 0)) {
        return pre + `φ${i} + ξ${i} = ${fmtAngle(up)} must be below 3π/2 — ${who} turns past ` +
          "the contact's tangent line (condition (1))";
      }
    }
    return null;
  }

  /** ``[sin(φ ± ξ), cos(φ ± ξ)] / cos ξ`` of cone side n = 1..4 (μ form of (23)). */
  function sideOf(p, n) {
    const i = n === 1 || n === 3 ? 1 : 2;
    const phi = p["phi" + i], mu = p["mu" + i];
    const s = Math.sin(phi), c = Math.cos(phi), sg = n <= 2 ? 1 : -1;
    return [s + sg * c * mu, c - sg * s * mu];
  }

  /** k_n(θ) = S_n sin θ − C_n cos θ, eq. (32). */
  function kOf(V, theta) {
    const s = Math.sin(theta), c = Math.cos(theta);
    return V.map((v) => v[0] * s - v[1] * c);
  }

  /** θ in [0, 2π) with e(θ) = (sin θ, −cos θ) along (wx, wy). */
  function thetaOf(wx, wy) {
    const t = Math.atan2(wx, -wy);
    return t < 0 ? t + TWO_PI : t;
  }

  function mod2pi(t) {
    const r = t % TWO_PI;
    return r < 0 ? r + TWO_PI : r;
  }

  /** The outer envelope of the circles on O V_n (eq. (25), Fig. 5), as arcs in θ.
   *
   * A port of graspcompass.construction.envelope: candidate break angles where
   * e(θ) ⊥ V_n (k_n = 0) or e(θ) ⊥ V_n − V_m (k_n = k_m); between two neighbours the
   * winner is the largest k at the midpoint (ties: the lowest index, 0 for k_grasp = 0).
   */
  function envelopeOf(V) {
    const cands = [];
    const keys = [[0], [1], [2], [3], [0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
    for (const key of keys) {
      const wx = V[key[0]][0] - (key.length === 2 ? V[key[1]][0] : 0);
      const wy = V[key[0]][1] - (key.length === 2 ? V[key[1]][1] : 0);
      if (wx || wy) {
        const t = thetaOf(-wy, wx);
        cands.push(t, mod2pi(t + PI));
      }
    }
    cands.sort((a, b) => a - b);
    const cuts = [];
    for (const t of cands) {
      if (!cuts.length || t - cuts[cuts.length - 1] > MERGE) cuts.push(t);
    }
    if (cuts.length > 1 && cuts[0] + TWO_PI - cuts[cuts.length - 1] <= MERGE) cuts.pop();
    const arcs = [];
    if (!cuts.length) {
      arcs.push({ n: 0, theta0: 0, theta1: TWO_PI });
    } else {
      const win = cuts.map((t, i) => {
        const b = i + 1 < cuts.length ? cuts[i + 1] : cuts[0] + TWO_PI;
        const ks = [0, ...kOf(V, (t + b) / 2)];
        let best = 0;
        for (let n = 1; n <= 4; n++) if (ks[n] > ks[best]) best = n;
        return best;
      });
      const m = cuts.length;
      const breaks = [];
      for (let i = 0; i < m; i++) {
        const before = win[(i - 1 + m) % m];
        if (before !== win[i]) breaks.push([cuts[i], win[i]]);
      }
      if (!breaks.length) {
        arcs.push({ n: win[0], theta0: 0, theta1: TWO_PI });
      } else {
        for (let j = 0; j < breaks.length; j++) {
          const t1 = j + 1 < breaks.length ? breaks[j + 1][0] : breaks[0][0] + TWO_PI;
          arcs.push({ n: breaks[j][1], theta0: breaks[j][0], theta1: t1 });
        }
      }
    }
    return arcs;
  }

  /** k_grasp(θ) = max(0, k_1, .., k_4), eq. (25). */
  function kGraspOf(V, theta) {
    return Math.max(0, ...kOf(V, theta));
  }

  /** Every number of the construction for the parameters ``p`` (valid by condition (1)). */
  function compute(p) {
    const P1 = [p.x1, p.y], P2 = [-p.x2, p.y];
    const P1x = [p.x1, 0], P2x = [-p.x2, 0], OM = [(p.x1 - p.x2) / 2, 0];
    const h = (p.x1 + p.x2) / 2;
    const out = {
      O: [0, 0], P1, P2, P1x, P2x, O_M: OM, sides: {}, perps: {}, S: [], C: [], V: [],
    };
    for (let n = 1; n <= 4; n++) {
      const [sx, cx] = sideOf(p, n);
      const odd = n === 1 || n === 3;
      const P = odd ? P1 : P2, F = odd ? P2x : P1x;
      const d = [odd ? -sx : sx, -cx]; // the side's direction (graspcompass side_direction)
      const t = sx / cx; // tan(φ ± ξ), eq. (23)
      const S = odd ? -h + p.y * t : h - p.y * t; // eqs. (28), (34), (36), (38)
      const C = (odd ? p.x2 : p.x1) * t; // eqs. (29), (35), (37), (39)
      out.S.push(S);
      out.C.push(C);
      out.V.push([S, C]); // eq. (30)/(33)
      out.sides[n] = { P, d };
      out.perps[n] = { P: F, d: [-d[1], d[0]] };
      out["X" + n] = [P[0] - P[1] * d[0] / d[1], 0]; // the side meets the x-axis
      out["Y" + n] = [0, F[0] * d[0] / d[1]]; // the perpendicular meets the y-axis
      out["OMX" + n] = out["X" + n][0] - OM[0]; // signed length O_M X_n = −S_n
      out["OY" + n] = out["Y" + n][1]; // signed length O Y_n = −C_n
      out["V" + n] = [S, C];
      out["circle" + n] = [S / 2, C / 2, Math.hypot(S, C) / 2]; // eq. (31)
    }
    const scale = Math.max(1e-300, ...out.V.map((v) => Math.abs(v[0]) + Math.abs(v[1])));
    for (let n = 1; n <= 4; n++) {
      for (let m = n + 1; m <= 4; m++) {
        // second intersection of the circles on O V_n and O V_m: B · (V_n − V_m) = 0
        const [vn, vm] = [out.V[n - 1], out.V[m - 1]];
        const u = [-(vn[1] - vm[1]), vn[0] - vm[0]];
        const uu = u[0] * u[0] + u[1] * u[1];
        let B = null;
        if (uu > 1e-24 * scale * scale) {
          const lam = (u[0] * vn[0] + u[1] * vn[1]) / uu;
          B = [lam * u[0], lam * u[1]];
          if (Math.hypot(B[0], B[1]) < 1e-12 * scale) B = null;
        }
        out[`B${n}${m}`] = B;
      }
    }
    out.arcs = envelopeOf(out.V);
    // the worst case: the largest |V_n|, at the θ of V_n; the local maxima of k_grasp
    let worst = null;
    out.maxima = [];
    for (const a of out.arcs) {
      if (!a.n) continue;
      const v = out.V[a.n - 1], tv = thetaOf(v[0], v[1]);
      if (mod2pi(tv - a.theta0) <= a.theta1 - a.theta0) {
        const mx = { n: a.n, theta: tv, k: Math.hypot(v[0], v[1]), point: [v[0], v[1]] };
        out.maxima.push(mx);
        if (!worst || mx.k > worst.k) worst = mx;
      }
    }
    if (!worst) worst = { n: 0, theta: 0, k: 0, point: [0, 0] };
    // the best case: 0 in the middle of the longest zero region, else the lowest break
    let best = null;
    for (const a of out.arcs) {
      if (a.n === 0) {
        if (!best || best.k > 0 || a.theta1 - a.theta0 > best.span) {
          best = { n: 0, theta: mod2pi((a.theta0 + a.theta1) / 2), k: 0, point: [0, 0],
            span: a.theta1 - a.theta0 };
        }
      } else if (!best || best.k > 0) {
        const k = kOf(out.V, a.theta0)[a.n - 1];
        if (!best || k < best.k) {
          best = { n: a.n, theta: a.theta0, k, point: [k * Math.sin(a.theta0),
            -k * Math.cos(a.theta0)] };
        }
      }
    }
    delete best.span;
    out.worst = worst;
    out.best = best;
    const D = p.x1 + p.x2;
    out.worst.Fint = worst.k / D; // eq. (17), per unit F_e
    out.best.Fint = best.k / D;
    out.k = kOf(out.V, p.theta);
    out.kgrasp = Math.max(0, ...out.k);
    out.Fint = out.kgrasp / D;
    out.H = [out.kgrasp * Math.sin(p.theta), -out.kgrasp * Math.cos(p.theta)];
    // the envelope as a polyline: each arc sampled at least every half degree
    const xs = [], ys = [];
    for (const a of out.arcs) {
      if (!a.n) {
        xs.push(0, 0);
        ys.push(0, 0);
        continue;
      }
      const v = out.V[a.n - 1];
      const steps = Math.max(2, Math.ceil((a.theta1 - a.theta0) / (PI / 360)));
      for (let j = 0; j <= steps; j++) {
        const t = a.theta0 + (a.theta1 - a.theta0) * j / steps;
        const s = Math.sin(t), c = Math.cos(t), k = v[0] * s - v[1] * c;
        xs.push(k * s);
        ys.push(-k * c);
      }
    }
    out.envX = xs;
    out.envY = ys;
    return out;
  }

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

  // ------------------------------------------------------------------------------------
  // The board (JSXGraph)
  // ------------------------------------------------------------------------------------
  const COL = DATA.colors;
  // the one label placement of every picture (graspcompass.labelling, ported in labelling.js)
  const LSPEC = DATA.labelling;
  const GL = window.GCLabelling;
  JXG.Options.text.display = "internal";
  const board = JXG.JSXGraph.initBoard("gc-board", {
    boundingbox: [-4, 4, 4, -4], keepaspectratio: true, axis: false, grid: false,
    showCopyright: false, showNavigation: true, showFullscreen: false, showScreenshot: false,
    pan: { enabled: true, needShift: true }, zoom: { wheel: true, needShift: true },
    renderer: "svg", resize: { enabled: true, throttle: 100 },
  });
  // the zoomed inset of the crowded region, beside the board (inset.js)
  const insets = Array.from(document.querySelectorAll(".gc-inset"))
    .map((holder) => window.GCInset.create(board, holder, COL.axis));
  let insetFrame = null;
  function redrawInset() {
    if (insetFrame !== null) cancelAnimationFrame(insetFrame);
    insetFrame = null;
    for (const ins of insets) if (ins.shown) ins.redraw();
  }
  board.on("update", () => {
    if (insets.some((i) => i.shown) && insetFrame === null) {
      insetFrame = requestAnimationFrame(redrawInset);
    }
  });
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
  let visualsDirty = true;
  function setVisualPass() {
    board.renderer.enhancedRendering = visualsDirty;
    visualsDirty = false;
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

  reg(board.create("axis", [[0, 0], [1, 0]], {
    strokeColor: COL.axis, highlight: false, needsRegularUpdate: false,
    ticks: { strokeColor: COL.tick, needsRegularUpdate: false, label: {
      fontSize: 10, strokeColor: COL.ticklabel } },
  }), "x-axis", { always: true });
  reg(board.create("axis", [[0, 0], [0, 1]], {
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
  // the worst and best orientation: a red square and a green diamond, named in the panel
  // (■ worst, ◆ best) in the same colours, not on the crowded board
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
      const bad = idx.filter((i, k) => !fitted[k] || spaced[k] ||
        nearerOther(fitted[k].box, k, every, lastInputs.markerSizes,
          across(groups[i].e.el)));
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
      .map((f, k) => (f && !nearerOther(f.box, k, hAnchors.concat(hObst), hSizes) ? f
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
   * (sizes: the markers' sizes; own0: the size of the label's own point's marker, where
   * it names a group), by NEAR_MARGIN: the rule a reader checks by eye. */
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
  const INSET_ZOOMS = [1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 48, 64];
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
      if (!plan) {
        ins.hide();
        return;
      }
      insetStates.push(plan);
      rest = rest.filter((g) => !plan.named.has(g));
      showInset(ins, plan);
    });
    if (insetFrame === null && insets.some((i) => i.shown)) {
      insetFrame = requestAnimationFrame(redrawInset);
    }
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
      const ok = fits.map((f, k) => !!f && !spaced[k] &&
        !nearerOther(f.box, k, every, sizes, across(gs[k].e.el)));
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

  function setLabel(e, text) {
    if (text === e.shownText || !e.el.label) return;
    if (text === null) {
      e.el.label.setAttribute({ visible: false });
    } else {
      if (e.shownText === null) e.el.label.setAttribute({ visible: "inherit" });
      e.el.label.setText(text);
    }
    e.shownText = text;
    visualsDirty = true;
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
        visualsDirty = true;
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
        visualsDirty = true;
      }
    }
    groupLabels();
    placeLabels();
  }

  // ------------------------------------------------------------------------------------
  // Controls: sliders, step navigator, readouts
  // ------------------------------------------------------------------------------------
  const $ = (id) => document.getElementById(id);
  const DEG = PI / 180;
  const rangeMax = (v) => Math.max(4, Math.ceil(2 * v));
  const SLIDERS = [
    { name: "x1", label: "x₁", unit: 1, min: 0.05, max: rangeMax(state.p.x1), step: 0.001 },
    { name: "x2", label: "x₂", unit: 1, min: 0.05, max: rangeMax(state.p.x2), step: 0.001 },
    { name: "y", label: "y", unit: 1, min: 0, max: rangeMax(state.p.y), step: 0.001 },
    { name: "phi1", label: "φ₁ (°)", unit: DEG, min: 1, max: 180, step: 0.1 },
    { name: "phi2", label: "φ₂ (°)", unit: DEG, min: 1, max: 180, step: 0.1 },
    { name: "mu1", label: "μ₁", unit: 1, min: 0.02, max: rangeMax(state.p.mu1), step: 0.001 },
    { name: "mu2", label: "μ₂", unit: 1, min: 0.02, max: rangeMax(state.p.mu2), step: 0.001 },
    { name: "theta", label: "θ (°)", unit: DEG, min: 0, max: 360, step: 0.5 },
  ];
  const sliderBox = $("gc-sliders");
  for (const s of SLIDERS) {
    const row = document.createElement("div");
    row.className = "gc-slider";
    row.innerHTML = `<label for="gc-slider-${s.name}">${s.label}</label>` +
      `<input type="range" id="gc-slider-${s.name}" data-param="${s.name}" min="${s.min}" ` +
      `max="${s.max}" step="${s.step}">` +
      `<input type="number" id="gc-num-${s.name}" data-param="${s.name}" step="any" ` +
      `aria-label="${s.label}">`;
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
      // (y < 0 from a drag below the x-axis, a large x1), it is never clamped
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

  /** Decimals that give 4 significant digits at ``scale`` (0 to 10). */
  function decimalsFor(scale) {
    if (!(scale > 0) || !Number.isFinite(scale)) return 3;
    return Math.min(10, Math.max(0, 3 - Math.floor(Math.log10(scale))));
  }
  /** ``x`` to ``d`` decimals; a value within 1e-12·scale of 0 (zero to double precision,
   * as C_4 = x_1 tan(φ_2 − ξ_2) of Fig. 6, where φ_2 = ξ_2) prints 0, and −0.000 prints 0.000. */
  function fixed(x, d, scale) {
    if (!Number.isFinite(x)) return "–";
    if (Math.abs(x) <= 1e-12 * scale) return "0";
    const t = x.toFixed(d);
    return /^-0(\.0*)?$/.test(t) ? t.slice(1) : t.replace(/^-/, "−");
  }
  const deg = (t) => fixed(t / DEG, 1, 360) + "°";
  // the readouts: built once, then only their texts change
  const SUB = "₀₁₂₃₄";
  $("gc-info").innerHTML =
    "<p id=\"gc-invalid-note\" hidden>The parameters violate the conditions of §2.2 (see " +
    "the message): the diagram shows the last valid grasp.</p><div id=\"gc-readout\">" +
    "<p>θ = <span data-r=\"theta\"></span>: k<sub>grasp</sub> = <span data-r=\"kgrasp\"></span>, " +
    "F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"Fint\"></span> " +
    "<small>(eqs. (25), (17))</small></p>" +
    `<p class="gc-worst" style="color:${COL.worst}">■ worst: θ = ` +
    "<span data-r=\"wtheta\"></span>, k = " +
    "<span data-r=\"wk\"></span>, F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"wF\"></span>" +
    "<span data-r=\"wn\"></span></p>" +
    `<p class="gc-best" style="color:${COL.best}">◆ best: θ = ` +
    "<span data-r=\"btheta\"></span>, k = " +
    "<span data-r=\"bk\"></span>, F<sub>int</sub>/F<sub>e</sub> = <span data-r=\"bF\"></span></p>" +
    "<table class=\"gc-v\"><tr><th></th><th>S<sub>n</sub></th><th>C<sub>n</sub></th>" +
    "<th>k<sub>n</sub>(θ)</th></tr>" +
    [1, 2, 3, 4].map((n) => `<tr style="color:${COL["circle" + n]}"><td>V${SUB[n]}</td>` +
      `<td data-r="S${n}"></td><td data-r="C${n}"></td><td data-r="k${n}"></td></tr>`).join("") +
    "</table><p class=\"gc-small\" data-r=\"prec\"></p></div>";
  const readout = {};
  for (const el of $("gc-info").querySelectorAll("[data-r]")) {
    readout[el.getAttribute("data-r")] = { el, text: null };
  }
  function put(key, text) {
    const r = readout[key];
    if (r.text !== text) {
      r.el.textContent = text;
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
  let shownError;
  function renderInfo() {
    const q = state.num;
    if (state.error !== shownError) {
      $("gc-error").hidden = !state.error;
      $("gc-error-text").textContent = state.error ? roundedMessage(state.error) : "";
      $("gc-invalid-note").hidden = !state.error;
      $("gc-readout").hidden = !!state.error;
      shownError = state.error;
    }
    if (state.error) return;
    // lengths to 4 significant digits of the diagram's scale (the largest |V_n|, |P_i|),
    // forces per unit F_e to 4 digits of scale / (x1 + x2): the precision the note states
    const scale = Math.max(...q.V.map((v) => Math.hypot(v[0], v[1])), Math.hypot(...q.P1),
      Math.hypot(...q.P2));
    const D = state.p.x1 + state.p.x2;
    const dl = decimalsFor(scale), df = decimalsFor(scale / D);
    const len = (x) => fixed(x, dl, scale), force = (x) => fixed(x, df, scale / D);
    put("prec", `Lengths to ${dl} decimal${dl === 1 ? "" : "s"}, forces to ${df}, angles ` +
      "to 0.1°; a value within 10⁻¹² of the drawing's scale (the largest |V| or |P|) " +
      "is zero to double precision and prints 0.");
    put("theta", deg(state.p.theta));
    put("kgrasp", len(q.kgrasp));
    put("Fint", force(q.Fint));
    put("wtheta", deg(q.worst.theta));
    put("wk", len(q.worst.k));
    put("wF", force(q.worst.Fint));
    put("wn", q.worst.n ? ` (V${SUB[q.worst.n]}, k = |V${SUB[q.worst.n]}|)` : "");
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
  /** The heading: the given title until a parameter is changed, then the grasp's values. */
  function renderHeading() {
    const p = state.p;
    const text = !state.follow && !(DATA.untitled && state.title === DATA.title) ? state.title
      : `Your grasp: x₁ = ${g3(p.x1)}, x₂ = ${g3(p.x2)}, y = ${g3(p.y)}, ` +
        `φ₁ = ${g3(p.phi1 / DEG)}°, φ₂ = ${g3(p.phi2 / DEG)}°, μ₁ = ${g3(p.mu1)}, ` +
        `μ₂ = ${g3(p.mu2)}`;
    const h = document.querySelector(".gc-header h1");
    if (h && h.textContent !== text) h.textContent = text;
  }

  /** Put ``text`` into ``el`` with "k_grasp", "O_M", "X_{1}" as subscripts (DOM nodes,
   * never HTML parsing): captions read as the paper prints them, not with underscores. */
  function setSubscripted(el, text) {
    el.textContent = "";
    const re = /([A-Za-z])_(\{[^}]*\}|[A-Za-z0-9]+)/g;
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

  /** Recompute after a parameter change and redraw; ``t0`` from performance.now(). */
  function refresh(t0, fromSlider) {
    recompute();
    renderHeading();
    P1.setPositionDirectly(JXG.COORDS_BY_USER, [state.p.x1, state.p.y]);
    P2.setPositionDirectly(JXG.COORDS_BY_USER, [-state.p.x2, state.p.y]);
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
    visualsDirty = true;
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
    if (key === "P1") return [state.p.x1, state.p.y];
    if (key === "P2") return [-state.p.x2, state.p.y];
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
    /** Viewport coordinates [px, py] of a named point (as page.mouse expects). */
    toScreen(name) {
      const xy = getValue(name);
      if (!Array.isArray(xy)) throw new Error(`${name} is not a point here`);
      const c = new JXG.Coords(JXG.COORDS_BY_USER, xy, board).scrCoords;
      const r = board.containerObj.getBoundingClientRect();
      return [r.left + c[1], r.top + c[2]];
    },
    /** The labels as placed: [{names, direction, offset, box}] (points, y up). */
    labels: () => JSON.parse(JSON.stringify(lastPlacement)),
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
      return insets.filter((i) => i.shown).map((ins, k) => Object.assign(ins.rects(),
        { zoom: ins.zoom, region: insetStates[k] && insetStates[k].region }));
    },
    /** The board's rectangle (client pixels). */
    boardRect: () => { const r = board.containerObj.getBoundingClientRect();
      return [r.left, r.top, r.right, r.bottom]; },
    /** What the last placement was given: {anchors, texts, opts} (points, y up). */
    labelInputs: () => JSON.parse(JSON.stringify(lastInputs)),
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
