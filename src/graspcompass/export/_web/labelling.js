/* graspcompass — label placement in the web page: ports of graspcompass.labelling.place and
 * of graspcompass.scene.fit.fit (the hard rules of the SVG, TikZ and PNG labels: fit below).
 *
 * One algorithm for every picture (issue 12 §4): the PNG, the SVG and the TikZ place their
 * labels with graspcompass.labelling.place (Python); the page places its own with this port,
 * which reads the same constants (labelling.spec(), passed in the page's data).  Each label
 * tries eight positions around its point (NE, NW, SE, SW, N, S, E, W), close and then twice
 * as far, and takes the one with the least overlap with the labels already placed, the point
 * markers and the drawn curves.  Every arithmetic step is the Python one in the same order
 * (squared distances, numpy's pairwise summation of the overlaps, the curves' samples),
 * so that both give the same placement; tests/test_web_labels.py checks it in Chromium.
 *
 * Sizes in points of a frame whose y axis points up.
 */
(function (root) {
  "use strict";

  const SUB = /_\{([^}]*)\}|_(\w)/g;
  const chars = (s) => Array.from(s).length;
  const round9 = (x) => Number(x.toFixed(9));

  /** Estimated [width, height] of a mathtext label (labelling.text_size). */
  function textSize(text, fontSize, spec) {
    const r = spec.size;
    const body = text.split("$").join("");
    let subs = "";
    body.replace(SUB, (m, a, b) => {
      subs += a || b || "";
      return m;
    });
    const main = body.replace(SUB, "").split("\\").join("");
    const spaces = main.split(" ").length - 1;
    let width = r.char * fontSize * chars(main.split(" ").join("")) + r.space * fontSize * spaces;
    width += r.sub * fontSize * chars(subs);
    return [round9(width + r.pad), round9(r.height * fontSize)];
  }

  /** numpy's pairwise summation (add.reduce of a contiguous float64 array). */
  function pairwiseSum(a, start, n) {
    if (n < 8) {
      let res = -0.0;
      for (let i = 0; i < n; i++) res += a[start + i];
      return res;
    }
    if (n <= 128) {
      const r = a.slice(start, start + 8);
      let i = 8;
      for (; i < n - (n % 8); i += 8) {
        for (let j = 0; j < 8; j++) r[j] += a[start + i + j];
      }
      let res = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
      for (; i < n; i++) res += a[start + i];
      return res;
    }
    let n2 = Math.floor(n / 2);
    n2 -= n2 % 8;
    return pairwiseSum(a, start, n2) + pairwiseSum(a, start + n2, n - n2);
  }

  /** Total overlap area of box ``b`` with ``boxes`` (labelling._overlap). */
  function overlap(b, boxes) {
    if (boxes.length === 0) return 0.0;
    const terms = new Array(boxes.length);
    for (let i = 0; i < boxes.length; i++) {
      const o = boxes[i];
      const w = Math.max(Math.min(b[2], o[2]) - Math.max(b[0], o[0]), 0);
      const h = Math.max(Math.min(b[3], o[3]) - Math.max(b[1], o[1]), 0);
      terms[i] = w * h;
    }
    return pairwiseSum(terms, 0, terms.length);
  }

  /** The range [lo, hi) of the samples of segment a + t d (t in [0, 1], length L) that may
   * lie in ``win`` (Liang-Barsky, the window widened by ``step``): labelling._in_window. */
  function inWindow(ax, ay, dx, dy, L, step, win, count) {
    T[0] = 0;
    T[1] = 1;
    // x, then y (no arrays made: this runs for every segment of every curve per update)
    if (!clipAxis(ax, dx, win[0] - step, win[2] + step) ||
        !clipAxis(ay, dy, win[1] - step, win[3] + step)) return EMPTY;
    const t0 = T[0], t1 = T[1];
    if (!(t0 <= t1)) return EMPTY;
    const lo = Math.min(Math.max(Math.floor((t0 * L) / step) - 1, 0), count);
    const hi = Math.min(Math.max(Math.ceil((t1 * L) / step) + 2, 0), count);
    // more samples than the window holds: floats cannot space them by step there
    const cap = 4 + Math.ceil((2 * ((win[2] - win[0]) + (win[3] - win[1]))) / step);
    return Number.isFinite(lo) && Number.isFinite(hi) && hi - lo <= cap ? [lo, hi] : EMPTY;
  }

  /** Narrow T = [t0, t1] to the t where lo <= p + t q <= hi; false when q = 0 and p is
   * outside [lo, hi] (Liang-Barsky along one axis). */
  function clipAxis(p, q, lo, hi) {
    if (q === 0) return p >= lo && p <= hi;
    let ta = (lo - p) / q, tb = (hi - p) / q;
    if (ta > tb) {
      const t = ta;
      ta = tb;
      tb = t;
    }
    T[0] = Math.max(T[0], ta);
    T[1] = Math.min(T[1], tb);
    return true;
  }
  const T = new Float64Array(2);
  const EMPTY = [0, 0];

  /** Points every ``step`` along each segment of each polyline (labelling.resample): a
   * segment a -> b of length L gives a + (i step / L)(b - a) for 0 <= i step < L (a alone
   * if L = 0, nothing if L overflows), each polyline its last vertex; non-finite vertices
   * dropped; with ``win`` [x0, y0, x1, y1] only the samples that may lie in it.
   * Flat [x0, y0, x1, ...]. */
  function resample(curves, step, win) {
    const out = [];
    const finite = (p) => Number.isFinite(p[0]) && Number.isFinite(p[1]);
    for (const raw of curves) {
      const c = raw.every(finite) ? raw : raw.filter(finite);
      if (c.length < 2) {
        for (const p of c) out.push(p[0], p[1]);
        continue;
      }
      for (let j = 0; j + 1 < c.length; j++) {
        const ax = c[j][0], ay = c[j][1], dx = c[j + 1][0] - ax, dy = c[j + 1][1] - ay;
        const L = Math.sqrt(dx * dx + dy * dy);
        const count = !Number.isFinite(L) ? 0 : L > 0 ? Math.ceil(L / step) : 1;
        const [lo, hi] = win ? inWindow(ax, ay, dx, dy, L, step, win, count) : [0, count];
        // (m + lo) as in Python: lo may be too large for k++ to step by one
        for (let m = 0, n = hi - lo; m < n; m++) {
          const f = L > 0 ? ((m + lo) * step) / L : 0;
          out.push(ax + f * dx, ay + f * dy);
        }
      }
      const e = c[c.length - 1];
      out.push(e[0], e[1]);
    }
    return out;
  }

  /** The curve samples within ``win`` [x0, y0, x1, y1] (those outside can't be inside any
   * box tried), bucketed on a dense grid, to count those strictly inside a box quickly:
   * the count is the one of a scan over every sample (labelling.place's inside.sum()). */
  function sampleGrid(flat, win) {
    if (!win) return { count: (b) => countAll(flat, b) };
    const cell = 16;
    const nx = Math.max(1, Math.ceil((win[2] - win[0]) / cell));
    const ny = Math.max(1, Math.ceil((win[3] - win[1]) / cell));
    if (!(nx * ny <= 1 << 20)) return { count: (b) => countAll(flat, b) };
    const start = new Int32Array(nx * ny + 1);
    const idx = new Int32Array(flat.length / 2).fill(-1);
    for (let k = 0, m = 0; k < flat.length; k += 2, m++) {
      const x = flat[k], y = flat[k + 1];
      if (!(x >= win[0] && x <= win[2] && y >= win[1] && y <= win[3])) continue;
      const i = Math.min(nx - 1, Math.floor((x - win[0]) / cell));
      const j = Math.min(ny - 1, Math.floor((y - win[1]) / cell));
      idx[m] = j * nx + i;
      start[idx[m] + 1]++;
    }
    for (let c = 0; c < nx * ny; c++) start[c + 1] += start[c];
    const fill = start.slice(0, nx * ny);
    const pts = new Float64Array(2 * start[nx * ny]);
    for (let m = 0; m < idx.length; m++) {
      if (idx[m] < 0) continue;
      const at = fill[idx[m]]++;
      pts[2 * at] = flat[2 * m];
      pts[2 * at + 1] = flat[2 * m + 1];
    }
    return {
      count(b) {
        const i0 = Math.max(0, Math.floor((b[0] - win[0]) / cell));
        const i1 = Math.min(nx - 1, Math.floor((b[2] - win[0]) / cell));
        const j0 = Math.max(0, Math.floor((b[1] - win[1]) / cell));
        const j1 = Math.min(ny - 1, Math.floor((b[3] - win[1]) / cell));
        let n = 0;
        for (let j = j0; j <= j1; j++) {
          for (let k = start[j * nx + i0]; k < start[j * nx + i1 + 1]; k++) {
            const x = pts[2 * k], y = pts[2 * k + 1];
            if (x > b[0] && x < b[2] && y > b[1] && y < b[3]) n++;
          }
        }
        return n;
      },
    };
  }
  function countAll(flat, b) {
    let n = 0;
    for (let k = 0; k < flat.length; k += 2) {
      const x = flat[k], y = flat[k + 1];
      if (x > b[0] && x < b[2] && y > b[1] && y < b[3]) n++;
    }
    return n;
  }

  /**
   * One placement {offset: [dx, dy], direction: [sx, sy], box: [x0, y0, x1, y1]} per label
   * texts[i] of the point anchors[i] (labelling.place).  ``opts``: spec (labelling.spec()),
   * curves (polylines [[x, y], ...]), frame [x0, y0, x1, y1] or null, avoid (boxes),
   * fontSize, markerSize, gap, obstacles ([[x, y], ...]).
   */
  function place(anchors, texts, opts) {
    const spec = opts.spec;
    const wt = spec.weights;
    const font = opts.fontSize ?? spec.font;
    const marker = opts.markerSize ?? spec.marker;
    const gap = opts.gap ?? spec.gap;
    const frame = opts.frame || null;
    const r = marker / 2 + 1.0;
    const every = anchors.concat(opts.obstacles || []);
    const markers = every.map(([x, y]) => [x - r, y - r, x + r, y + r]);
    // every box tried lies within its width or height plus the far distance of its point
    // (labelling._reach): only curve samples in that window can fall in a box
    const sizes = texts.map((t) => textSize(t, font, spec));
    let reach = 0;
    for (const [w, h] of sizes) reach = Math.max(reach, w, h);
    reach = reach + (marker / 2 + gap) * Math.max(...spec.far) + 1;
    let win = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of anchors) {
      if (!(Number.isFinite(x) && Number.isFinite(y))) continue; // its boxes hold nothing
      win = [Math.min(win[0], x - reach), Math.min(win[1], y - reach),
        Math.max(win[2], x + reach), Math.max(win[3], y + reach)];
    }
    const finite = win.every(Number.isFinite);
    const flat = finite ? resample((opts.curves || []).filter((c) => c.length),
      spec.resample, win) : [];
    const grid = flat.length ? sampleGrid(flat, win) : null;
    const labels = (opts.avoid || []).map((b) => b.slice());
    const out = [];
    for (let i = 0; i < anchors.length; i++) {
      const [px, py] = anchors[i];
      const [w, h] = sizes[i];
      let best = [0.0, 0.0, 1, 1], bestScore = Infinity, bestBox = [0, 0, 0, 0];
      let rank = 0;
      for (const far of spec.far) {
        for (const [dx, dy] of spec.offsets) {
          const d = (marker / 2 + gap) * far;
          const x0 = px + dx * d - (dx < 0 ? w : dx === 0 ? w / 2 : 0);
          const y0 = py + dy * d - (dy < 0 ? h : dy === 0 ? h / 2 : 0);
          const box = [x0, y0, x0 + w, y0 + h];
          let score = wt.label * overlap(box, labels);
          score += wt.marker * overlap(box, markers);
          if (grid) score += wt.curve * grid.count(box);
          if (anchors.length > 1) {
            const cx = (box[0] + box[2]) / 2, cy = (box[1] + box[3]) / 2;
            const own = (px - cx) * (px - cx) + (py - cy) * (py - cy);
            let near = 0;
            for (let k = 0; k < anchors.length; k++) {
              if (k === i) continue;
              const ox = anchors[k][0] - cx, oy = anchors[k][1] - cy;
              if (ox * ox + oy * oy < own) near++;
            }
            score += wt.near * near;
          }
          if (frame) {
            const outW = Math.max(0.0, frame[0] - box[0]) + Math.max(0.0, box[2] - frame[2]);
            const outH = Math.max(0.0, frame[1] - box[1]) + Math.max(0.0, box[3] - frame[3]);
            score += wt.frame * (outW + outH) * h;
          }
          score += wt.rank * rank;
          rank += 1;
          if (score < bestScore) {
            best = [dx * d, dy * d, dx, dy];
            bestScore = score;
            bestBox = box;
          }
        }
      }
      labels.push(bestBox);
      out.push({ offset: [best[0], best[1]], direction: [best[2], best[3]], box: bestBox });
    }
    return out;
  }


  // -- scene.fit: labels under hard rules (the placement of the SVG, TikZ and PNG) ----------

  /** The label's [width, ascent, descent] in the font it is drawn in (scene.metrics.extent). */
  function extent(text, fontSize, m) {
    const body = text.split("$").join("").split("\\").join("");
    const re = /_\{([^}]*)\}|_(.)|([^_]+)/g;
    const w = (cs) => Array.from(cs).reduce((a, c) => {
      const k = c.codePointAt(0);
      return a + (k >= 32 && k < 127 ? m.widths[k - 32] : 2048);
    }, 0) / 2048;
    let width = 0, down = m.descent * fontSize, g;
    while ((g = re.exec(body)) !== null) {
      if (g[3]) width += w(g[3]) * fontSize;
      else if (g[1] || g[2]) {
        width += w(g[1] || g[2]) * m.sub_scale * fontSize;
        down = Math.max(down, (m.sub_shift + m.descent * m.sub_scale) * fontSize);
      }
    }
    return [width, m.ascent * fontSize, down];
  }

  function distToBox(x, y, b) {
    const dx = Math.max(Math.max(b[0] - x, 0), x - b[2]);
    const dy = Math.max(Math.max(b[1] - y, 0), y - b[3]);
    return Math.hypot(dx, dy);
  }

  function hits(b, boxes) {
    for (const o of boxes) {
      if (Math.min(b[2], o[2]) > Math.max(b[0], o[0]) &&
          Math.min(b[3], o[3]) > Math.max(b[1], o[1])) return true;
    }
    return false;
  }

  /** scene.fit.fit: one {offset, direction, box, leader, ok} per label, or null (optional
   * labels that no place suits).  opts: fitSpec (scene.fit.spec()), curves, frame,
   * obstacles, optional, avoid, fontSize, markerSize, markerSizes, gap. */
  function fit(anchors, texts, opts) {
    const sp = opts.fitSpec;
    const font = opts.fontSize ?? sp.font, msize = opts.markerSize ?? sp.marker;
    const gap = opts.gap ?? sp.gap, frame = opts.frame || null;
    const optional = opts.optional || [];
    const every = anchors.concat(opts.obstacles || []);
    const ms = every.map((_, j) => (opts.markerSizes && j < opts.markerSizes.length
      ? opts.markerSizes[j] : msize));
    const markers = every.map(([x, y], j) => {
      const r = ms[j] / 2 + sp.margin.marker;
      return [x - r, y - r, x + r, y + r];
    });
    const sizes = texts.map((t) => {
      const [w, up, down] = extent(t, font, sp.metrics);
      return [w, up + down];
    });
    const curves = (opts.curves || []).filter((c) => c.length);
    // only the samples some box tried can hold (scene.fit.fit's window)
    const fin = anchors.filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y));
    const reach = Math.max(0, ...sizes.map(([w, h]) => Math.max(w, h))) +
      (msize / 2 + gap) * Math.max(...sp.fits) + 1.0;
    const win = fin.length ? [Math.min(...fin.map((p) => p[0])) - reach,
      Math.min(...fin.map((p) => p[1])) - reach, Math.max(...fin.map((p) => p[0])) + reach,
      Math.max(...fin.map((p) => p[1])) + reach] : null;
    const flat = curves.length && win ? resample(curves, sp.resample, win) : [];
    // the samples bucketed (every one of them: the window of the grid holds them all), to
    // count those strictly inside a box as the scan over all of them counts
    let grid = null;
    if (flat.length) {
      const all = [Infinity, Infinity, -Infinity, -Infinity];
      for (let j = 0; j < flat.length; j += 2) {
        all[0] = Math.min(all[0], flat[j]);
        all[1] = Math.min(all[1], flat[j + 1]);
        all[2] = Math.max(all[2], flat[j]);
        all[3] = Math.max(all[3], flat[j + 1]);
      }
      grid = sampleGrid(flat, all);
    }
    const crowd = anchors.map(([px, py]) =>
      every.filter(([x, y]) => Math.hypot(x - px, y - py) < 40.0).length);
    let order = anchors.map((_, i) => i).sort((a, b) => crowd[b] - crowd[a]);
    const fails = (out) => out.filter((f) => f === null || !f.ok).length;
    let best = null;
    for (let round = 0; round <= sp.reorder; round++) {
      const out = greedy(order, anchors, every, markers, sizes, grid, frame, ms, gap,
        optional, opts.avoid || [], sp);
      const failed = order.filter((i) => out[i] === null || !out[i].ok);
      if (best === null || failed.length < fails(best)) best = out;
      if (!failed.length) break;
      order = failed.concat(order.filter((i) => !failed.includes(i)));
    }
    return best;
  }

  function greedy(order, pts, every, markers, sizes, grid, frame, ms, gap, optional,
                  avoid, sp) {
    const placed = avoid.map((b) => b.slice());
    const out = pts.map(() => null);
    const g = sp.margin.grow;
    for (const i of order) {
      const [px, py] = pts[i];
      const [w, h] = sizes[i];
      const others = every.filter(([x, y], j) =>
        Math.hypot(x - px, y - py) >= (ms[j] + ms[i]) / 2);
      let best = null, bestScore = Infinity;
      sp.fits.forEach((far, k) => {
        const d = (ms[i] / 2 + gap) * far;
        sp.directions.forEach(([ux, uy], rank) => {
          const t = Math.min(ux ? w / 2 / Math.abs(ux) : Infinity,
            uy ? h / 2 / Math.abs(uy) : Infinity);
          const cx = px + ux * (d + t), cy = py + uy * (d + t);
          const box = [cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2];
          const big = [box[0] - g, box[1] - g, box[2] + g, box[3] + g];
          let bad = 0;
          bad += 100 * hits(big, placed);
          bad += 100 * hits(big, markers);
          if (others.length) {
            const own = distToBox(px, py, big);
            const near = Math.min(...others.map(([x, y]) => distToBox(x, y, big)));
            bad += 100 * (near < own + sp.margin.nearer);
          }
          if (frame) {
            bad += 100 * (box[0] < frame[0] || box[1] < frame[1] || box[2] > frame[2] ||
              box[3] > frame[3]);
          }
          let soft = 10 * k + 0.5 * rank;
          if (grid) soft += 1.5 * grid.count(box);
          const score = bad * 1000 + soft;
          if (score < bestScore) {
            const dx = box[0] >= px ? 1 : box[2] <= px ? -1 : 0;
            const dy = box[1] >= py ? 1 : box[3] <= py ? -1 : 0;
            const ax = dx > 0 ? box[0] : dx < 0 ? box[2] : cx;
            const ay = dy > 0 ? box[1] : dy < 0 ? box[3] : cy;
            bestScore = score;
            best = { offset: [ax - px, ay - py], direction: [dx, dy], box,
              leader: far >= sp.leader, ok: bad === 0 };
          }
        });
      });
      if (!best.ok && optional[i]) continue;
      placed.push(best.box);
      out[i] = best;
    }
    return out;
  }

  /** The order of placement of a group of point names (labelling.label_order). */
  function labelOrder(names, spec) {
    return Math.min(...names.map((n) => ((spec.order.indexOf(n[0]) % 9) + 9) % 9));
  }

  /** The paper's label of a point name as a TeX body (layout.tex(name, math=False)). */
  function tex(name) {
    const m = /^([A-Za-z])_?([A-Za-z0-9]*)$/.exec(name);
    if (!m) return name;
    const [, head, rest] = m;
    return !rest ? head : rest.length === 1 ? `${head}_${rest}` : `${head}_{${rest}}`;
  }

  root.GCLabelling = { place, textSize, resample, labelOrder, tex, overlap, fit, extent };
})(typeof window !== "undefined" ? window : globalThis);
