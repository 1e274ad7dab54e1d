/* graspcompass — the zoomed inset of the web page's crowded region (issue 23).
 *
 * Where some labels of the board find no place that keeps the rules (no label over a
 * label or a marker, each label's centre nearer its own point than any other), the page
 * leaves them to a second, square panel beside the board: a magnified copy of the board's
 * drawing around the points left out, each marker at its drawn size, lines at their
 * drawn width, and the labels of every point in it placed again at that zoom.  A dashed
 * square on the board shows the region the inset magnifies.
 *
 * The copy is the board's own SVG (cloned after each update, its text dropped): what the
 * inset shows is what the board shows, step by step.  GCInset.create(board, holder) gives
 * {show(region, points, labels), hide(), rects(), zoom}; see placement.js (placeLabels).
 */
(function (root) {
  "use strict";

  const NS = "http://www.w3.org/2000/svg";

  function create(board, holder, frameColor) {
    const view = holder.querySelector(".gc-inset-view");
    const note = holder.querySelector(".gc-inset-note");
    const labelsSvg = document.createElementNS(NS, "svg");
    labelsSvg.setAttribute("class", "gc-inset-labels");
    view.appendChild(labelsSvg);
    let copy = null;
    let frame = null; // the dashed square on the board
    let current = null; // {region, points, labels}

    /** The board's pixel position of user point (x, y). */
    const px = (x, y) => [board.origin.scrCoords[1] + x * board.unitX,
      board.origin.scrCoords[2] - y * board.unitY];

    let active = true;
    function styleFrame() {
      if (!frame) return;
      frame.setAttribute("stroke-width", active ? "1.6" : "1");
      frame.setAttribute("stroke-opacity", active ? "1" : "0.6");
    }
    function drawFrame(region) {
      const svg = board.renderer.svgRoot;
      if (!frame) {
        frame = document.createElementNS(NS, "rect");
        frame.setAttribute("class", "gc-inset-frame");
        frame.setAttribute("fill", "none");
        frame.setAttribute("stroke", frameColor);
        frame.setAttribute("stroke-width", "1");
        frame.setAttribute("stroke-dasharray", "4 3");
        frame.setAttribute("pointer-events", "none");
        styleFrame();
      }
      if (frame.parentNode !== svg) svg.appendChild(frame);
      const [a, b] = [px(region[0], region[3]), px(region[1], region[2])];
      frame.setAttribute("x", a[0]);
      frame.setAttribute("y", a[1]);
      frame.setAttribute("width", Math.max(0, b[0] - a[0]));
      frame.setAttribute("height", Math.max(0, b[1] - a[1]));
    }

    /** Copy the board's drawing, magnified to ``region`` [x0, x1, y0, y1] (user units);
     * ``points``: the rendNodes of the shown point markers, kept at their drawn size. */
    function redraw() {
      if (!current) return;
      const { region, points, labels, draw } = current;
      const side = view.clientWidth;
      const [a, b] = [px(region[0], region[3]), px(region[1], region[2])];
      const w = b[0] - a[0];
      if (!(side > 0 && w > 0)) return;
      const z = side / w;
      const src = board.renderer.svgRoot;
      if (frame && frame.parentNode) frame.parentNode.removeChild(frame);
      const c = src.cloneNode(true);
      drawFrame(region);
      for (const t of Array.from(c.querySelectorAll("text, foreignObject"))) t.remove();
      for (const n of Array.from(c.querySelectorAll("[id]"))) {
        if (!n.closest("defs")) n.setAttribute("id", "gc-inset-" + n.getAttribute("id"));
      }
      // arrow heads: the copy's own markers, scaled back to their drawn size
      for (const m of Array.from(c.querySelectorAll("defs marker[id]"))) {
        const id = m.getAttribute("id");
        m.setAttribute("id", "gc-inset-" + id);
        for (const k of ["markerWidth", "markerHeight"]) {
          const v = parseFloat(m.getAttribute(k));
          if (Number.isFinite(v)) m.setAttribute(k, String(v / z));
        }
        for (const attr of ["marker-start", "marker-end", "marker-mid"]) {
          for (const u of Array.from(c.querySelectorAll(`[${attr}="url(#${id})"]`))) {
            u.setAttribute(attr, `url(#gc-inset-${id})`);
          }
        }
      }
      for (const m of Array.from(c.querySelectorAll("defs [id]"))) {
        if (m.tagName.toLowerCase() !== "marker") m.setAttribute("id", "gc-inset-d-" +
          m.getAttribute("id"));
      }
      c.setAttribute("viewBox", `${a[0]} ${a[1]} ${w} ${w}`);
      c.setAttribute("width", side);
      c.setAttribute("height", side);
      c.setAttribute("class", "gc-inset-copy");
      c.removeAttribute("style");
      c.style.position = "absolute";
      c.style.left = "0";
      c.style.top = "0";
      c.style.pointerEvents = "none";
      // the markers at their drawn size: each point's shape shrunk by 1/z about its centre
      const named = new Map(points.filter((p) => p.node).map((p) => [p.node, p.name]));
      for (const el of board.objectsList) {
        const node = el.rendNode;
        if (el.elType !== "point" || !node || !node.id || !el.visPropCalc.visible) continue;
        const twin = c.querySelector(`[id="gc-inset-${node.id}"]`);
        if (!twin) continue;
        const bb = node.getBBox();
        const cx = bb.x + bb.width / 2, cy = bb.y + bb.height / 2;
        const g = document.createElementNS(NS, "g");
        g.setAttribute("transform",
          `translate(${cx} ${cy}) scale(${1 / z}) translate(${-cx} ${-cy})`);
        twin.parentNode.insertBefore(g, twin);
        g.appendChild(twin);
        twin.setAttribute("data-gc-name", named.get(node) || `marker:${el.id}`);
      }
      if (copy) copy.remove();
      view.insertBefore(c, labelsSvg);
      copy = c;
      labelsSvg.setAttribute("width", side);
      labelsSvg.setAttribute("height", side);
      while (labelsSvg.firstChild) labelsSvg.removeChild(labelsSvg.firstChild);
      for (const lab of labels) {
        if (!lab.box) continue;
        const t = document.createElementNS(NS, "text");
        t.setAttribute("data-gc-name", lab.name);
        t.setAttribute("fill", lab.color);
        labelsSvg.appendChild(t);
        draw(t, lab.text, lab.box[0], lab.box[1]);
        if (lab.leader) {
          const l = document.createElementNS(NS, "line");
          const [x, y] = lab.leader;
          l.setAttribute("x1", x[0]);
          l.setAttribute("y1", x[1]);
          l.setAttribute("x2", y[0]);
          l.setAttribute("y2", y[1]);
          l.setAttribute("stroke", lab.color);
          l.setAttribute("stroke-width", "0.6");
          labelsSvg.appendChild(l);
        }
      }
      note.textContent = `×${z < 10 ? z.toFixed(1) : Math.round(z)} the dashed square`;
      api.zoom = z;
    }

    const api = {
      zoom: null,
      holder,
      /** Show the inset of ``region`` with the markers ``points`` [{name, node}] and the
       * ``labels`` [{name, text, box (inset px: left, top), color, leader}]; ``draw(node,
       * text, left, top)`` sets a label's text as the board sets its own. */
      show(region, points, labels, draw) {
        current = { region, points, labels, draw };
        holder.hidden = false; // drawn by redraw(), after the board's own update
      },
      hide() {
        current = null;
        holder.hidden = true;
        if (frame && frame.parentNode) frame.parentNode.removeChild(frame);
        if (copy) copy.remove();
        copy = null;
        while (labelsSvg.firstChild) labelsSvg.removeChild(labelsSvg.firstChild);
        api.zoom = null;
      },
      /** Copy the board again (after it was redrawn). */
      redraw,
      /** Whether this inset is the one in sight (its dashed square drawn bolder). */
      setActive(on) {
        active = !!on;
        styleFrame();
      },
      get shown() {
        return current !== null;
      },
      /** The inset's side in pixels (0 while hidden; read once per size of the page). */
      side: () => {
        if (!(sideNow > 0)) sideNow = view.clientWidth;
        return sideNow;
      },
      /** As drawn: the panel's rectangle, and per marker and label its rectangle. */
      rects() {
        const r = (n) => { const b = n.getBoundingClientRect(); return [b.left, b.top,
          b.right, b.bottom]; };
        if (!current || !copy) return null;
        const texts = new Map();
        for (const t of labelsSvg.querySelectorAll("text")) {
          texts.set(t.getAttribute("data-gc-name"), r(t));
        }
        const pts = [];
        for (const m of copy.querySelectorAll("[data-gc-name]")) {
          const name = m.getAttribute("data-gc-name");
          pts.push({ id: name, m: r(m), t: texts.get(name) || null });
        }
        return { board: r(view), pts };
      },
    };
    let sideNow = 0;
    if (typeof ResizeObserver !== "undefined") {
      new ResizeObserver(() => { sideNow = 0; }).observe(view);
    }
    holder.hidden = true;
    return api;
  }

  root.GCInset = { create };
})(typeof window !== "undefined" ? window : globalThis);
