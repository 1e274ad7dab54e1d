/* graspcompass web explorer — the model: condition (1) and the closed form of the paper
 * (Ito, Tanaka, Sasaki, Robotica 30(5), 2012), eqs. (27)-(39), ported from
 * graspcompass.grasp / graspcompass.grasp._floatpath, and the numbers printed as Python
 * prints them (the messages of graspcompass.grasp):
 *
 *   tan(φ ± ξ) = (sin φ ± μ cos φ) / (cos φ ∓ μ sin φ)                       (23)
 *   S_n = ∓(x1 + x2)/2 ± y tan(φ ± ξ),  C_n = x_{2|1} tan(φ ± ξ)       (28)-(39)
 *   V_n = (S_n, C_n),  k_n(θ) = S_n sin θ − C_n cos θ                  (30)-(33)
 *   k_grasp(θ) = max(0, k_1, .., k_4),  F_int = k / (x1 + x2) · F_e       (25), (17)
 *
 * No page, no board: window.GCModel, read by explorer.js and its modules (board.js,
 * placement.js, controls.js).
 */
(function (root) {
  "use strict";

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

  root.GCModel = {
    PI, TWO_PI, NAMES, fmtG, sympyFloat, decimalStr, fmtValue, fmtAngle, pyRepr, validate,
    sideOf, kOf, thetaOf, mod2pi, envelopeOf, kGraspOf, compute,
  };
})(window);
