/* graspcompass n-contact web page: the internal force diagram of n >= 2 planar point
 * contacts with Coulomb friction, live in the browser with JSXGraph (issue 25).
 *
 * The page embeds its data as JSON (#gc-data): the contacts (x, y, angle of the inward
 * normal, μ, floats), the centre of mass O, the effort's name, θ and the palette.  The
 * polygon Q is computed here by the same float algorithm as graspcompass.ncontact's float
 * path (ported from ncontact/_dual.py, maxnormal.py, polygon.py and _hull.py):
 *
 *   edges d = n ± μ J n, wrenches g = (d, (p - O) × d), costs c = w_i · d;
 *   linear effort: the dual {u : rows·u <= rhs}, every d-subset of its rows solved,
 *     kept when feasible (relative tolerance 1e-9): q = -u_f; the paper's k >= 0 adds
 *     the column c_j and the row -z <= 0;
 *   "max-normal": the ties of each contact, q = -d / f(d) for d = ±h_a × h_b (g+ × g- for
 *     two ties of one contact: their three pairs give one point, bit for bit);
 *   candidates closer than 1e-9 relative to the first met are one (polygon._float_close);
 *   recession directions: the extreme rays of {r : rows·r <= 0}, q-rays -r_f;
 *   Q = the hull of the q (Andrew's chain, relative orientation 1e-12); its vertices are
 *   the hull points whose normal cone meets the open cone of loads that can be held;
 *   v(θ) = max_q q·e(θ) with e(θ) = (sin θ, -cos θ) (eq. (26)), +inf where e·r > 0.
 *
 * The picture: contacts (drag the square) with normal handles (drag the dot) and their
 * friction cones, Q's vertices q_i, the Thales circles on O q_i (dashed grey for the
 * redundant dual vertices, whose circles never reach the envelope), the envelope (the
 * polar plot of v(θ), Fig. 5), the load at θ and, on request, the construction of one
 * vertex (cost lines, A12 A13 / A'12 A'13, R, quarter turn).  A drag to a grasp that cannot hold any
 * load keeps the last valid drawing and says why.
 *
 * window.graspcompass: set({contacts, effort, theta}), state(), drawn(), compute(state),
 * support(Q, θ), arcOf(Q), constructOf(Q, k, com), construct(k), showConstruction(k), vertices(), redundant(), rays(), arc(), k(θ), error(), board, lastUpdateMs.
 */
(function () {
  "use strict";

  const DATA = JSON.parse(document.getElementById("gc-data").textContent);
  const COLORS = DATA.colors;
  const TOL = 1e-9; // ncontact._dual.TOL
  const TWO_PI = 2 * Math.PI;
  const CIRCLES = ["circle1", "circle2", "circle3", "circle4"];

  // ------------------------------------------------------------------------------------
  // Small linear algebra
  // ------------------------------------------------------------------------------------
  function norm(v) {
    let s = 0;
    for (const x of v) s += x * x;
    return Math.sqrt(s);
  }

  function det(M) { // determinant by Gaussian elimination with partial pivoting
    const n = M.length;
    const A = M.map((r) => r.slice());
    let d = 1;
    for (let c = 0; c < n; c++) {
      let p = c;
      for (let r = c + 1; r < n; r++) if (Math.abs(A[r][c]) > Math.abs(A[p][c])) p = r;
      if (A[p][c] === 0) return 0;
      if (p !== c) { [A[p], A[c]] = [A[c], A[p]]; d = -d; }
      d *= A[c][c];
      for (let r = c + 1; r < n; r++) {
        const f = A[r][c] / A[c][c];
        for (let k = c; k < n; k++) A[r][k] -= f * A[c][k];
      }
    }
    return d;
  }

  function solve(M, b) { // M u = b, Gaussian elimination with partial pivoting
    const n = M.length;
    const A = M.map((r, i) => [...r, b[i]]);
    for (let c = 0; c < n; c++) {
      let p = c;
      for (let r = c + 1; r < n; r++) if (Math.abs(A[r][c]) > Math.abs(A[p][c])) p = r;
      [A[p], A[c]] = [A[c], A[p]];
      for (let r = c + 1; r < n; r++) {
        const f = A[r][c] / A[c][c];
        for (let k = c; k <= n; k++) A[r][k] -= f * A[c][k];
      }
    }
    const u = new Array(n).fill(0);
    for (let r = n - 1; r >= 0; r--) {
      let s = A[r][n];
      for (let k = r + 1; k < n; k++) s -= A[r][k] * u[k];
      u[r] = s / A[r][r];
    }
    return u;
  }

  function combinations(R, d) {
    const out = [];
    const c = [];
    (function rec(start) {
      if (c.length === d) { out.push(c.slice()); return; }
      for (let i = start; i < R; i++) { c.push(i); rec(i + 1); c.pop(); }
    })(0);
    return out;
  }

  function cross3(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }

  function dot(a, b) {
    let s = 0;
    for (let i = 0; i < a.length; i++) s += a[i] * b[i];
    return s;
  }

  // ------------------------------------------------------------------------------------
  // The model (ncontact/contact.py, model.py, effort.py)
  // ------------------------------------------------------------------------------------
  function check(state) {
    const n = state.contacts.length;
    if (n < 2) return "contacts: expected 2 or more contacts, got " + n;
    for (let i = 0; i < n; i++) {
      const c = state.contacts[i];
      for (const k of ["x", "y", "angle", "mu"]) {
        if (!Number.isFinite(c[k])) return "contact " + (i + 1) + ": values must be finite";
      }
      if (c.mu < 0) {
        return "contact " + (i + 1) + ": the friction coefficient μ = " + c.mu + " must be >= 0";
      }
    }
    if (state.effort === "paper" && n !== 2) {
      return "effort 'paper' (the paper's k) needs exactly 2 contacts, got " + n;
    }
    const m = /^pair:(\d+),(\d+)$/.exec(state.effort);
    if (m) {
      const i = +m[1], j = +m[2];
      if (!(i >= 1 && i <= n && j >= 1 && j <= n) || i === j) {
        return "effort '" + state.effort + "': I and J must be two different contacts among 1.." + n;
      }
    } else if (!["paper", "sum-normal", "max-normal"].includes(state.effort)) {
      return "unknown effort '" + state.effort + "'";
    }
    return null;
  }

  function model(state) {
    const O = state.com;
    const contacts = state.contacts.map((c) => {
      const nx = Math.cos(c.angle), ny = Math.sin(c.angle);
      const jx = -ny, jy = nx;
      return { p: [c.x, c.y], n: [nx, ny], mu: c.mu,
        edges: [[nx + c.mu * jx, ny + c.mu * jy], [nx - c.mu * jx, ny - c.mu * jy]] };
    });
    const G = [];
    const owner = [];
    contacts.forEach((c, i) => {
      for (const d of c.edges) {
        const px = c.p[0] - O[0], py = c.p[1] - O[1];
        G.push([d[0], d[1], px * d[1] - py * d[0]]);
        owner.push(i);
      }
    });
    let weights = null;
    let nonneg = false;
    const e = state.effort;
    if (e === "sum-normal") weights = contacts.map((c) => c.n);
    else if (e === "paper") {
      const [p1, p2] = [contacts[0].p, contacts[1].p];
      weights = [[(p2[0] - p1[0]) / 2, (p2[1] - p1[1]) / 2],
        [(p1[0] - p2[0]) / 2, (p1[1] - p2[1]) / 2]];
      nonneg = true;
    } else if (e.startsWith("pair:")) {
      const [i, j] = e.slice(5).split(",").map((s) => +s - 1);
      weights = contacts.map((c, k) => (k === i || k === j ? c.n : [0, 0]));
    }
    return { contacts, G, owner, weights, nonneg };
  }

  function dualSystem(m) {
    const costs = m.G.map((g, j) => {
      const w = m.weights[m.owner[j]];
      const d = m.contacts[m.owner[j]].edges[j % 2];
      return w[0] * d[0] + w[1] * d[1];
    });
    if (!m.nonneg) return { rows: m.G.map((g) => g.slice()), rhs: costs };
    const rows = m.G.map((g, j) => [...g, costs[j]]);
    rows.push([0, 0, 0, -1]);
    return { rows, rhs: [...costs, 0] };
  }

  // the basic feasible solutions of {u : rows·u <= rhs} (_dual.float_vertices)
  function dualVertices(rows, rhs) {
    const d = rows[0].length;
    const rn = rows.map(norm);
    const out = [];
    let any = false;
    for (const B of combinations(rows.length, d)) {
      const M = B.map((r) => rows[r]);
      let scale = 1;
      for (const r of B) scale *= rn[r];
      if (!(Math.abs(det(M)) > 1e-12 * Math.max(scale, 1e-300))) continue;
      any = true;
      const u = solve(M, B.map((r) => rhs[r]));
      const un = norm(u);
      let ok = true;
      for (let k = 0; k < rows.length && ok; k++) {
        const slack = rhs[k] - dot(rows[k], u);
        if (slack < -TOL * (rn[k] * un + Math.abs(rhs[k]) + 1e-300)) ok = false;
      }
      if (ok) out.push({ q: [-u[0], -u[1]], basis: B });
    }
    if (!any) {
      throw new Error("the edge wrenches do not span the three dimensions of planar " +
        "wrenches (rank < 3)");
    }
    return out;
  }

  // extreme rays of {r : rows·r <= 0} (_dual.float_rays), as q-directions -r_f
  function qRays(A) {
    const R = A.length, d = A[0].length;
    const rn = A.map(norm);
    const found = [];
    for (const S of combinations(R, d - 1)) {
      const sub = S.map((i) => A[i]);
      let r;
      if (d === 3) r = cross3(sub[0], sub[1]);
      else {
        r = [];
        for (let t = 0; t < d; t++) {
          r.push((t % 2 ? -1 : 1) * det(sub.map((row) => row.filter((_, k) => k !== t))));
        }
      }
      const nr = norm(r);
      let scale = 1;
      for (const i of S) scale *= rn[i];
      if (!(nr > 1e-12 * scale)) continue;
      r = r.map((x) => x / nr);
      const dots = A.map((row) => dot(r, row));
      for (const sg of [1, -1]) {
        if (dots.every((v, k) => sg * v <= TOL * rn[k])) found.push([-sg * r[0], -sg * r[1]]);
      }
    }
    const unit = [];
    for (const r of found) {
      const n = Math.hypot(r[0], r[1]);
      if (n > 1e-12) unit.push([r[0] / n, r[1] / n]);
    }
    return unit;
  }

  // "max-normal": the candidates of maxnormal._float
  function maxNormalPoints(G) {
    const nc = G.length / 2;
    const ties = [];
    for (let i = 0; i < nc; i++) {
      const gp = G[2 * i], gm = G[2 * i + 1];
      ties.push({ i, name: "+0", h: gp });
      ties.push({ i, name: "-0", h: gm });
      ties.push({ i, name: "+-", h: [gp[0] - gm[0], gp[1] - gm[1], gp[2] - gm[2]] });
    }
    let scale = 0;
    for (const g of G) for (const v of g) scale = Math.max(scale, Math.abs(v));
    const tol = 1e-9 * scale;
    const out = [];
    for (let a = 0; a < ties.length; a++) {
      for (let b = a + 1; b < ties.length; b++) {
        // the three tie planes of one contact share one line (through g+ and g-): one cross
        // product for the three pairs, so they give one point bit for bit (maxnormal._float)
        const d0 = ties[a].i === ties[b].i ? cross3(G[2 * ties[a].i], G[2 * ties[a].i + 1])
          : cross3(ties[a].h, ties[b].h);
        const nd = norm(d0);
        if (nd <= 1e-12 * scale * scale) continue;
        for (const sg of [1, -1]) {
          const d = d0.map((v) => (sg * v) / nd);
          const lp = [], mx = [];
          for (let i = 0; i < nc; i++) {
            const p = dot(G[2 * i], d), m = dot(G[2 * i + 1], d);
            lp.push(p);
            mx.push(Math.max(0, p, m));
          }
          let ok = true;
          for (const t of [ties[a], ties[b]]) {
            const tied = t.name === "+0" || t.name === "+-" ? lp[t.i] : 0;
            if (tied < mx[t.i] - tol) ok = false;
          }
          if (!ok) continue;
          let f = 0;
          for (const v of mx) f += v;
          if (f <= tol) continue;
          out.push({ q: [-d[0] / f, -d[1] / f], basis: [a, b] });
        }
      }
    }
    return out;
  }

  // ------------------------------------------------------------------------------------
  // Q: hull, feasible cone, vertices (polygon._build_float, _hull)
  // ------------------------------------------------------------------------------------
  function floatHull(P) {
    const m = P.length;
    if (m <= 2) {
      return m < 2 || P[0][0] !== P[1][0] || P[0][1] !== P[1][1] ? [...Array(m).keys()] : [0];
    }
    let big = 1;
    for (const p of P) big = Math.max(big, Math.abs(p[0]), Math.abs(p[1]));
    const tol = 1e-12 * big;
    const order = [...Array(m).keys()].sort((i, j) => {
      const dx = P[i][0] - P[j][0];
      if (Math.abs(dx) > tol) return dx < 0 ? -1 : 1;
      const dy = P[i][1] - P[j][1];
      return dy === 0 ? 0 : dy < 0 ? -1 : 1;
    });
    function turn(o, a, b) {
      const u = [P[a][0] - P[o][0], P[a][1] - P[o][1]];
      const w = [P[b][0] - P[o][0], P[b][1] - P[o][1]];
      return u[0] * w[1] - u[1] * w[0] > 1e-12 * Math.hypot(...u) * Math.hypot(...w);
    }
    function chain(seq) {
      const out = [];
      for (const i of seq) {
        while (out.length >= 2 && !turn(out[out.length - 2], out[out.length - 1], i)) out.pop();
        out.push(i);
      }
      return out;
    }
    const lower = chain(order), upper = chain(order.slice().reverse());
    const h = [...lower.slice(0, -1), ...upper.slice(0, -1)];
    return h.length >= 2 ? h : [order[0], order[order.length - 1]];
  }

  function sgn(v) { return Math.abs(v) <= 1e-10 ? 0 : v > 0 ? 1 : -1; }
  const crs = (a, b) => a[0] * b[1] - a[1] * b[0];
  const dt = (a, b) => a[0] * b[0] + a[1] * b[1];

  // {e : e·r <= 0 for all r} as [start, end] ccw; [] = the whole plane; null = no interior
  function feasibleCone(rays) {
    if (!rays.length) return [];
    function first(ccw) {
      for (let i = 0; i < rays.length; i++) {
        let ok = true;
        for (let j = 0; j < rays.length && ok; j++) {
          if (i === j) continue;
          const c = sgn(crs(rays[i], rays[j])) * (ccw ? 1 : -1);
          if (c < 0 || (c === 0 && sgn(dt(rays[i], rays[j])) < 0)) ok = false;
        }
        if (ok) return i;
      }
      return -1;
    }
    const ia = first(true), ib = first(false);
    if (ia < 0 || ib < 0) return null;
    const ra = rays[ia], rb = rays[ib];
    const start = [-rb[1], rb[0]], end = [ra[1], -ra[0]];
    const c = ia === ib ? 0 : sgn(crs(ra, rb));
    if (c === 0) return ia === ib || sgn(dt(ra, rb)) > 0 ? [start, end] : null;
    return c > 0 ? [start, end] : null;
  }

  function inOpen(x, cone) {
    const [a, b] = cone;
    const ca = sgn(crs(a, x)), cb = sgn(crs(x, b));
    if (sgn(crs(a, b)) === 0) return ca > 0;
    return ca > 0 && cb > 0;
  }

  function conesMeet(c1, c2) {
    if (!c1.length || !c2.length) return true;
    return inOpen(c2[0], c1) || inOpen(c1[0], c2) ||
      (sgn(crs(c1[0], c2[0])) === 0 && sgn(dt(c1[0], c2[0])) > 0);
  }

  function normalCone(poly, k) {
    const m = poly.length;
    if (m === 1) return [];
    const edge = (a, b) => [b[0] - a[0], b[1] - a[1]];
    const unit = (v) => { const n = Math.hypot(v[0], v[1]) || 1; return [v[0] / n, v[1] / n]; };
    if (m === 2) {
      const u = edge(poly[k], poly[1 - k]);
      return [unit([-u[1], u[0]]), unit([u[1], -u[0]])];
    }
    const e1 = edge(poly[(k - 1 + m) % m], poly[k]), e2 = edge(poly[k], poly[(k + 1) % m]);
    return [unit([e1[1], -e1[0]]), unit([e2[1], -e2[0]])];
  }

  /** Q of a state: {vertices, redundant, hull, rays, cone, closure}, or throws an Error. */
  function compute(state) {
    const bad = check(state);
    if (bad) throw new Error(bad);
    const m = model(state);
    let pts, rays;
    if (m.weights === null) {
      pts = maxNormalPoints(m.G);
      if (!pts.length) throw new Error("no direction has a positive effort");
      rays = qRays(m.G);
    } else {
      const { rows, rhs } = dualSystem(m);
      pts = dualVertices(rows, rhs);
      if (!pts.length) {
        throw new Error("the effort can be made arbitrarily negative (its dual is empty): " +
          "no least effort exists");
      }
      rays = qRays(rows);
    }
    const closure = qRays(m.G).length === 0;
    // one candidate per point: closer than 1e-9 relative to the group's first point, in the
    // order met (polygon._float_close, the rule of Python's float path too), as the copies
    // of one dual vertex from its several bases are (each rounds on its own way)
    const cands = [];
    for (const p of pts) {
      const same = cands.find((c) => Math.abs(c.q[0] - p.q[0]) + Math.abs(c.q[1] - p.q[1]) <=
        1e-9 * (1 + Math.abs(c.q[0]) + Math.abs(c.q[1])));
      if (same) same.bases.push(p.basis);
      else cands.push({ q: p.q, bases: [p.basis] });
    }
    const h = floatHull(cands.map((c) => c.q));
    const cone = feasibleCone(rays);
    if (cone === null) {
      throw new Error("no load direction can be held: the recession directions of Q span " +
        "a half-plane or more (the grasp resists no open arc of loads)");
    }
    let keep = h;
    if (rays.length) {
      const hp = h.map((i) => cands[i].q);
      keep = h.filter((i, k) => conesMeet(normalCone(hp, k), cone));
    }
    const kept = new Set(keep);
    return {
      vertices: keep.map((i) => cands[i].q),
      bases: keep.map((i) => cands[i].bases),
      model: m, costs: m.weights === null ? null : dualSystem(m).rhs,
      redundant: cands.filter((_, i) => !kept.has(i)).map((c) => c.q),
      hull: h.map((i) => cands[i].q),
      rays, cone, closure, edges: m.contacts.map((c) => c.edges),
    };
  }

  /** v(θ) for a unit load: max over the hull points, +inf where e·r > 0 (_support_float). */
  function support(Q, theta) {
    const e = [Math.sin(theta), -Math.cos(theta)];
    for (const r of Q.rays) if (dt(e, r) > 0) return Infinity;
    const pts = Q.rays.length ? Q.hull : Q.vertices;
    let best = -Infinity;
    for (const q of pts) best = Math.max(best, dt(q, e));
    return best;
  }

  function arcOf(Q) { // polygon.arc
    if (Q.cone === null) return null;
    if (!Q.cone.length) return [0, TWO_PI];
    const [a, b] = Q.cone;
    let lo = Math.atan2(a[1], a[0]) + Math.PI / 2;
    const hi0 = Math.atan2(b[1], b[0]) + Math.PI / 2;
    lo = ((lo % TWO_PI) + TWO_PI) % TWO_PI;
    const w = (((hi0 - lo) % TWO_PI) + TWO_PI) % TWO_PI;
    return [lo, lo + (w || TWO_PI)];
  }

  // ------------------------------------------------------------------------------------
  // The construction of one vertex (construction/ncontact_recipe.py, notes §3): the
  // rotated dual motion r(p) = J^T u(p) is a homothety taking each line of action l_j of
  // the basis onto its cost line L'_j = {x : (J^T d_j)·x = c_j}; R = r(O) is where the
  // parallels to A12 O through A'12 and to A13 O through A'13 meet; q = R turned a
  // quarter turn clockwise about O.  Coordinates relative to O.
  // ------------------------------------------------------------------------------------
  function meet(p, d, a, b) { // line p + s d  ∩  line a + t b
    const den = crs(d, b);
    if (Math.abs(den) <= 1e-12 * Math.hypot(...d) * Math.hypot(...b)) return null;
    const s = crs([a[0] - p[0], a[1] - p[1]], b) / den;
    return [p[0] + s * d[0], p[1] + s * d[1]];
  }

  /** The steps for the vertex k of Q, or null (a sign constraint, max-normal, degenerate). */
  function construct(Q, k, com) {
    if (!Q.costs || !Q.bases[k]) return null;
    const m = Q.model;
    for (const B of Q.bases[k]) {
      if (B.some((r) => r >= m.G.length)) continue; // the paper's k >= 0: a given point
      const lines = B.map((j) => {
        const i = m.owner[j], d = m.contacts[i].edges[j % 2];
        const p = [m.contacts[i].p[0] - com[0], m.contacts[i].p[1] - com[1]];
        const w = m.weights[i];
        const T = [w[1], -w[0]]; // the cost point J^T w_i
        return { j, i, p, d, T };
      });
      for (let first = 0; first < 3; first++) {
        const [l1, l2, l3] = [lines[first], ...lines.filter((_, t) => t !== first)];
        const A12 = meet(l1.p, l1.d, l2.p, l2.d), A13 = meet(l1.p, l1.d, l3.p, l3.d);
        const C12 = meet(l1.T, l1.d, l2.T, l2.d), C13 = meet(l1.T, l1.d, l3.T, l3.d);
        if (!A12 || !A13 || !C12 || !C13) continue;
        const R = meet(C12, [-A12[0], -A12[1]], C13, [-A13[0], -A13[1]]);
        if (!R) continue;
        return { lines: [l1, l2, l3], A12, A13, C12, C13, R, q: [R[1], -R[0]] };
      }
    }
    return null;
  }

  // ------------------------------------------------------------------------------------
  // The page
  // ------------------------------------------------------------------------------------
  let state = JSON.parse(JSON.stringify(DATA.state));
  let valid = null; // {state, Q}: the last valid drawing
  let lastError = null;
  const info = document.getElementById("gc-info");
  const errBox = document.getElementById("gc-error");
  const errText = document.getElementById("gc-error-text");
  const fmt = (x) => (Number.isFinite(x) ? (Math.abs(x) < 5e-13 ? "0" : x.toPrecision(6)) : "∞");
  const deg = (t) => (t * 180 / Math.PI).toFixed(2) + "°";

  JXG.Options.text.useMathJax = false;
  const board = JXG.JSXGraph.initBoard("gc-board", {
    boundingbox: [-3, 3, 3, -3], axis: false, grid: false, keepaspectratio: true,
    showCopyright: false, showNavigation: true, pan: { enabled: true, needShift: false },
    zoom: { wheel: true, needShift: false },
  });
  board.create("axis", [[0, 0], [1, 0]], { strokeColor: "#bbbbbb", ticks: { visible: false } });
  board.create("axis", [[0, 0], [0, 1]], { strokeColor: "#bbbbbb", ticks: { visible: false } });

  const O = board.create("point", state.com, { name: "O", fixed: true, size: 3,
    fillColor: COLORS.point, strokeColor: COLORS.point, label: { offset: [-14, -12] } });
  const envelope = board.create("curve", [[0], [0]], { strokeColor: COLORS.envelope,
    strokeWidth: 3.5, highlight: false, layer: 8, doAdvancedPlot: false, RDPsmoothing: false,
    curveType: "plot" });
  let dyn = []; // circles, vertex marks, rays: redrawn on each update
  const contactPts = [], handles = [], coneLines = [];
  const L = DATA.handle;
  const load = board.create("arrow", [[0, 0], [0, -1]], { strokeColor: COLORS.highlight,
    strokeWidth: 2, fixed: true, highlight: false });
  const kPoint = board.create("point", [0, 0], { name: "", size: 3, fixed: true,
    fillColor: COLORS.highlight, strokeColor: COLORS.highlight });

  function addContact(i) {
    const c = state.contacts[i];
    const P = board.create("point", [c.x, c.y], { name: "P" + (i + 1), face: "[]", size: 5,
      fillColor: COLORS.contactfill, strokeColor: COLORS.contact, label: { offset: [8, -12] } });
    const H = board.create("point", [c.x + L * Math.cos(c.angle), c.y + L * Math.sin(c.angle)],
      { name: "", size: 3, fillColor: COLORS.contact, strokeColor: COLORS.contact });
    const N = board.create("arrow", [P, H], { strokeColor: COLORS.contact, strokeWidth: 1.5,
      fixed: true, highlight: false });
    const lines = [0, 1].map(() => board.create("segment", [[0, 0], [0, 0]], {
      strokeColor: COLORS.side, strokeWidth: 1.3, fixed: true, highlight: false }));
    P.on("drag", () => {
      const s = state.contacts[i];
      s.x = P.X(); s.y = P.Y();
      H.setPosition(JXG.COORDS_BY_USER, [s.x + L * Math.cos(s.angle), s.y + L * Math.sin(s.angle)]);
      update();
    });
    H.on("drag", () => {
      const s = state.contacts[i];
      s.angle = Math.atan2(H.Y() - P.Y(), H.X() - P.X());
      H.setPosition(JXG.COORDS_BY_USER, [s.x + L * Math.cos(s.angle), s.y + L * Math.sin(s.angle)]);
      update();
    });
    contactPts.push(P); handles.push(H); coneLines.push(lines);
    void N;
  }
  state.contacts.forEach((_, i) => addContact(i));

  function syncPoints() { // the points follow the state (after set())
    state.contacts.forEach((c, i) => {
      contactPts[i].setPosition(JXG.COORDS_BY_USER, [c.x, c.y]);
      handles[i].setPosition(JXG.COORDS_BY_USER,
        [c.x + L * Math.cos(c.angle), c.y + L * Math.sin(c.angle)]);
    });
  }

  function drawCones(st) { // the friction cones where the contacts are now (valid or not)
    st.contacts.forEach((c, i) => {
      const nx = Math.cos(c.angle), ny = Math.sin(c.angle);
      const mu = Number.isFinite(c.mu) ? Math.max(c.mu, 0) : 0;
      [[nx - mu * ny, ny + mu * nx], [nx + mu * ny, ny - mu * nx]].forEach((d, k) => {
        const n = Math.hypot(d[0], d[1]);
        coneLines[i][k].point1.setPosition(JXG.COORDS_BY_USER, [c.x, c.y]);
        coneLines[i][k].point2.setPosition(JXG.COORDS_BY_USER,
          [c.x + 1.6 * L * d[0] / n, c.y + 1.6 * L * d[1] / n]);
      });
    });
  }

  // Thales circles on O q and the marks of q, made once per slot and then moved
  const vertexPool = [], redundantPool = [];
  function place(pool, pts, com, style) {
    const [ox, oy] = com;
    pts.forEach((q, i) => {
      if (!pool[i]) {
        const [cs, ps] = style(i);
        const slot = { r: 0 };
        slot.c = board.create("point", [0, 0], { visible: false, fixed: true, name: "",
          withLabel: false });
        slot.circle = board.create("circle", [slot.c, () => slot.r], { ...cs, fixed: true,
          highlight: false });
        slot.mark = board.create("point", [0, 0], { ...ps, fixed: true, highlight: false });
        pool[i] = slot;
      }
      const slot = pool[i];
      slot.c.setPosition(JXG.COORDS_BY_USER, [ox + q[0] / 2, oy + q[1] / 2]);
      slot.r = Math.hypot(q[0], q[1]) / 2;
      slot.mark.setPosition(JXG.COORDS_BY_USER, [ox + q[0], oy + q[1]]);
      slot.circle.show(); slot.mark.show();
    });
    for (let i = pts.length; i < pool.length; i++) { pool[i].circle.hide(); pool[i].mark.hide(); }
  }

  function draw(st, Q) {
    for (const o of dyn) board.removeObject(o);
    dyn = [];
    const [ox, oy] = st.com;
    const V = Q.vertices;
    place(vertexPool, V, st.com, (i) => {
      const col = COLORS[CIRCLES[i % 4]];
      return [{ strokeColor: col, strokeWidth: 1.2, strokeOpacity: 0.85 },
        { name: "q" + (i + 1), size: 3, fillColor: col, strokeColor: col,
          label: { strokeColor: col, offset: [5, 6] } }];
    });
    if (V.length >= 3 && !Q.rays.length) {
      dyn.push(board.create("polygon", V.map((q) => [ox + q[0], oy + q[1]]), {
        fillColor: COLORS.fill, fillOpacity: 0.25, borders: { strokeColor: COLORS.fill,
          strokeWidth: 1 }, vertices: { visible: false }, fixed: true, highlight: false }));
    }
    place(redundantPool, Q.redundant, st.com, () => [
      { strokeColor: "#9a9a9a", strokeWidth: 1, dash: 2 },
      { name: "", face: "x", size: 3, strokeColor: "#9a9a9a" }]);
    drawConstruction(st, Q);
    let scale = 1;
    for (const q of V) scale = Math.max(scale, Math.hypot(...q));
    for (const r of Q.rays) {
      dyn.push(board.create("arrow", [[ox, oy], [ox + 0.5 * scale * r[0], oy + 0.5 * scale * r[1]]],
        { strokeColor: COLORS.highlight, strokeWidth: 1.5, dash: 1, fixed: true, highlight: false }));
    }
    const xs = [], ys = [];
    const N = 1440;
    for (let j = 0; j <= N; j++) {
      const t = (TWO_PI * j) / N;
      const v = support(Q, t);
      if (Number.isFinite(v)) {
        const r = Math.max(v, 0);
        xs.push(ox + r * Math.sin(t)); ys.push(oy - r * Math.cos(t));
      } else { xs.push(NaN); ys.push(NaN); }
    }
    envelope.dataX = xs; envelope.dataY = ys;
    const t = st.theta, v = support(Q, t);
    const e = [Math.sin(t), -Math.cos(t)];
    load.point1.setPosition(JXG.COORDS_BY_USER, [ox, oy]);
    const reach = 0.3 * Math.max(L / 0.3, ...V.map((q) => Math.hypot(...q)));
    load.point2.setPosition(JXG.COORDS_BY_USER, [ox + reach * e[0], oy + reach * e[1]]);
    if (Number.isFinite(v)) {
      kPoint.setPosition(JXG.COORDS_BY_USER, [ox + Math.max(v, 0) * e[0], oy + Math.max(v, 0) * e[1]]);
      kPoint.show();
    } else kPoint.hide();
    showInfo(st, Q);
  }

  const conSel = document.getElementById("gc-construct");
  const conText = document.getElementById("gc-construction");
  function drawConstruction(st, Q) {
    const k = conSel.value === "" ? -1 : +conSel.value;
    const keep = conSel.value;
    conSel.innerHTML = "<option value=''>none</option>" + Q.vertices.map((_, i) =>
      "<option value='" + i + "'>q" + (i + 1) + "</option>").join("");
    conSel.value = k < Q.vertices.length ? keep : "";
    conText.textContent = "";
    if (k < 0 || k >= Q.vertices.length) return;
    const c = construct(Q, k, st.com);
    if (!c) {
      conText.textContent = "q" + (k + 1) + " is a given point here (its basis holds a sign " +
        "constraint, the effort is max-normal, or the recipe degenerates).";
      return;
    }
    const [ox, oy] = st.com;
    const at = (p) => [ox + p[0], oy + p[1]];
    const thin = { strokeColor: COLORS.perp, strokeWidth: 1, dash: 2, fixed: true,
      highlight: false, straightFirst: true, straightLast: true };
    const mark = (p, name, col) => dyn.push(board.create("point", at(p), { name, size: 2,
      fixed: true, fillColor: col, strokeColor: col, label: { strokeColor: col } }));
    c.lines.forEach((l, t) => {
      dyn.push(board.create("line", [at(l.p), at([l.p[0] + l.d[0], l.p[1] + l.d[1]])], thin));
      dyn.push(board.create("line", [at(l.T), at([l.T[0] + l.d[0], l.T[1] + l.d[1]])],
        { ...thin, strokeColor: COLORS.side }));
      mark(l.T, "T" + (l.i + 1), COLORS.side);
      void t;
    });
    const par = { ...thin, strokeColor: COLORS.highlight, dash: 0 };
    dyn.push(board.create("line", [at(c.C12), at([c.C12[0] - c.A12[0], c.C12[1] - c.A12[1]])], par));
    dyn.push(board.create("line", [at(c.C13), at([c.C13[0] - c.A13[0], c.C13[1] - c.A13[1]])], par));
    mark(c.A12, "A12", COLORS.perp); mark(c.A13, "A13", COLORS.perp);
    mark(c.C12, "A'12", COLORS.side); mark(c.C13, "A'13", COLORS.side);
    mark(c.R, "R", COLORS.highlight);
    dyn.push(board.create("segment", [at([0, 0]), at(c.R)], { strokeColor: COLORS.highlight,
      dash: 1, fixed: true, highlight: false }));
    const names = c.lines.map((l) => "P" + (l.i + 1) + (l.j % 2 ? "−" : "+"));
    conText.textContent = "q" + (k + 1) + " from the edges " + names.join(", ") + ": 1. the " +
      "cost lines, parallel to each edge through its contact's cost point T; 2. A12 = " +
      names[0] + " ∩ " + names[1] + ", A13 = " + names[0] + " ∩ " + names[2] + " and their " +
      "images A'12, A'13 on the cost lines; 3. R = (parallel to A12 O through A'12) ∩ " +
      "(parallel to A13 O through A'13); 4. q" + (k + 1) + " = R turned a quarter turn " +
      "clockwise about O.";
  }

  function showInfo(st, Q) {
    const arc = arcOf(Q);
    const v = support(Q, st.theta);
    const rows = Q.vertices.map((q, i) => "<tr><td>q" + (i + 1) + "</td><td>" + fmt(q[0]) +
      "</td><td>" + fmt(q[1]) + "</td><td>" + fmt(Math.hypot(...q)) + "</td></tr>").join("");
    const span = arc[1] - arc[0] >= TWO_PI - 1e-12 ? "every direction"
      : "θ in [" + deg(arc[0]) + ", " + deg(arc[1]) + "]";
    info.innerHTML = (lastError ? "<p class='gc-small'>The numbers of the last valid grasp " +
      "drawn:</p>" : "") +
      "<p><b>" + st.contacts.length + " contacts</b>, effort <b>" + st.effort + "</b>; force " +
      "closure: <b>" + (Q.closure ? "yes" : "no") + "</b>; the load is held for " + span + ".</p>" +
      "<p>θ = " + deg(st.theta) + ": least effort <b>k = " + fmt(v) + "</b>" +
      (Number.isFinite(v) ? "" : " (the load cannot be held)") + "</p>" +
      "<table class='gc-v'><tr><th></th><th>x</th><th>y</th><th>|q|</th></tr>" + rows + "</table>" +
      "<p>" + Q.vertices.length + " vertices of Q; " + Q.redundant.length + " redundant dual " +
      "vertices (dashed grey circles: they never touch the envelope)" +
      (Q.rays.length ? "; " + Q.rays.length + " recession directions (red arrows)" : "") +
      ".</p><p class='gc-small'>The thick curve is the envelope of the Thales circles on " +
      "O q: the polar plot of k(θ); the red arrow at O is the load e(θ), the red dot k(θ) " +
      "e(θ).</p>";
  }

  function update() {
    const t0 = performance.now();
    board.suspendUpdate(); // one redraw for the whole change
    try {
      const Q = compute(state);
      valid = { state: JSON.parse(JSON.stringify(state)), Q };
      lastError = null;
      errBox.hidden = true;
      draw(state, Q);
    } catch (err) {
      lastError = String(err.message || err);
      errText.textContent = lastError;
      errBox.hidden = false;
      if (valid) showInfo(valid.state, valid.Q);
    }
    drawCones(state);
    board.unsuspendUpdate();
    api.lastUpdateMs = performance.now() - t0;
    syncControls();
  }

  // ---- side panel: effort, θ, μ per contact -------------------------------------------
  const panel = document.getElementById("gc-controls");
  function slider(label, min, max, step, get, put) {
    const row = document.createElement("label");
    row.className = "gc-slider";
    row.innerHTML = "<span>" + label + "</span><input type='range'><input type='number'>";
    const [range, num] = row.querySelectorAll("input");
    for (const el of [range, num]) { el.min = min; el.max = max; el.step = step; }
    const sync = () => { range.value = get(); num.value = (+get()).toFixed(3); };
    range.addEventListener("input", () => { put(+range.value); update(); });
    num.addEventListener("change", () => { put(+num.value); update(); });
    panel.appendChild(row);
    return sync;
  }
  const syncs = [];
  const effortSel = document.getElementById("gc-effort");
  function fillEfforts() {
    const n = state.contacts.length;
    const names = ["sum-normal", "max-normal", ...(n === 2 ? ["paper"] : [])];
    for (let i = 1; i <= n; i++) for (let j = i + 1; j <= n; j++) names.push("pair:" + i + "," + j);
    if (!names.includes(state.effort)) names.push(state.effort);
    effortSel.innerHTML = names.map((s) => "<option>" + s + "</option>").join("");
    effortSel.value = state.effort;
  }
  fillEfforts();
  effortSel.addEventListener("change", () => { state.effort = effortSel.value; update(); fit(); });
  function redraw() {
    if (!valid) return;
    board.suspendUpdate();
    draw(valid.state, valid.Q);
    board.unsuspendUpdate();
  }
  conSel.addEventListener("change", redraw);
  syncs.push(slider("θ (°)", 0, 360, 0.5, () => state.theta * 180 / Math.PI,
    (v) => { state.theta = v * Math.PI / 180; }));
  state.contacts.forEach((c, i) => {
    syncs.push(slider("μ" + (i + 1), 0, 1.5, 0.01, () => state.contacts[i].mu,
      (v) => { state.contacts[i].mu = v; }));
  });
  function syncControls() { for (const s of syncs) s(); effortSel.value = state.effort; }

  function fit() {
    if (!valid) return;
    const pts = [valid.state.com];
    for (const c of valid.state.contacts) pts.push([c.x, c.y]);
    const [ox, oy] = valid.state.com;
    for (const q of valid.Q.vertices) {
      const r = Math.hypot(...q);
      pts.push([ox + q[0] / 2 + r / 2, oy + q[1] / 2 + r / 2], [ox + q[0] / 2 - r / 2, oy + q[1] / 2 - r / 2]);
    }
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of pts) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
    const pad = 0.08 * Math.max(x1 - x0, y1 - y0, 1);
    const half = Math.max(x1 - x0, y1 - y0) / 2 + pad;
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    board.setBoundingBox([cx - half, cy + half, cx + half, cy - half], true);
  }
  document.getElementById("gc-fit").addEventListener("click", fit);

  const api = {
    board, compute, support, arcOf, constructOf: construct, arc: () => (valid ? arcOf(valid.Q) : null),
    state: () => JSON.parse(JSON.stringify(state)),
    drawn: () => (valid ? JSON.parse(JSON.stringify(valid.state)) : null),
    vertices: () => (valid ? valid.Q.vertices.map((q) => q.slice()) : []),
    redundant: () => (valid ? valid.Q.redundant.map((q) => q.slice()) : []),
    rays: () => (valid ? valid.Q.rays.map((r) => r.slice()) : []),
    closure: () => (valid ? valid.Q.closure : null),
    k: (t) => (valid ? support(valid.Q, t) : null),
    construct: (k) => { const c = valid ? construct(valid.Q, k, valid.state.com) : null;
      return c ? { q: c.q, R: c.R, edges: c.lines.map((l) => l.j) } : null; },
    showConstruction: (k) => { conSel.value = k === null ? "" : String(k);
      redraw(); },
    error: () => lastError,
    toScreen: (i) => { const p = contactPts[i].coords.scrCoords;
      const r = board.containerObj.getBoundingClientRect(); return [r.left + p[1], r.top + p[2]]; },
    handleToScreen: (i) => { const p = handles[i].coords.scrCoords;
      const r = board.containerObj.getBoundingClientRect(); return [r.left + p[1], r.top + p[2]]; },
    set(s) {
      if (s.contacts) {
        s.contacts.forEach((c, i) => Object.assign(state.contacts[i], c));
      }
      if (s.effort !== undefined) state.effort = s.effort;
      if (s.theta !== undefined) state.theta = s.theta;
      syncPoints();
      update();
    },
    fit, lastUpdateMs: NaN,
  };
  window.graspcompass = api;
  update();
  fit();
  document.body.dataset.ready = "1";
})();
