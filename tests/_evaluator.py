"""An evaluator of the construction language that shares no code with graspcompass.

Its own tiny parser of ``.gc`` texts (params, lets, steps, claims), its own
expression reader (Python's ``ast`` walked into mpmath), its own geometry on
mpmath at 60 digits.  ``evaluate(text, point)`` replays a file at a point
(name -> value, numbers or text such as ``"atan(3/4)"`` / ``"pi - atan(1/2)"``)
and returns each claim's truth there, or None where an object does not exist
(a zero divisor, a negative radicand, parallel lines that must meet, coincident
points of a line or circle, a missing intersection).  Used by the tests to
re-check every PROVED claim at random admissible points and every counterexample.
"""

from __future__ import annotations

import ast
import random
import re

import mpmath

mpmath.mp.dps = 60
TOL = mpmath.mpf(10) ** -40


class Undefined(Exception):
    """An object that does not exist at the point."""


_FN = {
    "sqrt": mpmath.sqrt,
    "sin": mpmath.sin,
    "cos": mpmath.cos,
    "tan": mpmath.tan,
    "asin": mpmath.asin,
    "acos": mpmath.acos,
    "atan": mpmath.atan,
    "atan2": mpmath.atan2,
}


def num(text: str, names: dict) -> mpmath.mpf:
    """Evaluate an expression text with mpmath, refusing undefined steps."""

    def ev(n: ast.AST) -> mpmath.mpf:
        if isinstance(n, ast.Constant):
            return mpmath.mpf(str(n.value)) if isinstance(n.value, float) else mpmath.mpf(n.value)
        if isinstance(n, ast.Name):
            if n.id == "pi":
                return +mpmath.pi
            if n.id == "deg":
                return mpmath.pi / 180
            return names[n.id]
        if isinstance(n, ast.UnaryOp):
            v = ev(n.operand)
            return -v if isinstance(n.op, ast.USub) else v
        if isinstance(n, ast.BinOp):
            a, b = ev(n.left), ev(n.right)
            if isinstance(n.op, ast.Add):
                return a + b
            if isinstance(n.op, ast.Sub):
                return a - b
            if isinstance(n.op, ast.Mult):
                return a * b
            if isinstance(n.op, ast.Div):
                if abs(b) < TOL:
                    raise Undefined("division by zero")
                return a / b
            if isinstance(n.op, ast.Pow):
                if b < 0 and abs(a) < TOL:
                    raise Undefined("0 to a negative power")
                if a < 0 and b != int(b):
                    raise Undefined("root of a negative number")
                return a**b
        if isinstance(n, ast.Call):
            args = [ev(a) for a in n.args]
            f = n.func.id
            if f == "sqrt" and args[0] < -TOL:
                raise Undefined("sqrt of a negative number")
            if f == "sqrt":
                return mpmath.sqrt(max(args[0], 0))
            if f in ("asin", "acos") and abs(args[0]) > 1 + TOL:
                raise Undefined("asin/acos outside [-1, 1]")
            if f == "tan" and abs(mpmath.cos(args[0])) < TOL:
                raise Undefined("tan at a pole")
            return _FN[f](*args)
        raise ValueError(f"cannot read {ast.dump(n)}")

    t = text.strip()
    scale = 1
    if t.endswith("deg") and not t[:-3].rstrip().endswith(("*", "/")):
        t, scale = t[:-3], mpmath.pi / 180
    return ev(ast.parse(t, mode="eval").body) * scale


def _items(text: str) -> list[str]:
    out, depth, cur = [], 0, ""
    for ch in text:
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    return [*out, cur]


def _small(v: mpmath.mpf) -> bool:
    return abs(v) < TOL


# -- geometry (points as (x, y), lines as (point, direction), circles as (centre, r2)) --
def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def _line(p, d):
    if _small(_dot(d, d)):
        raise Undefined("a line without a direction")
    return ("line", p, d)


def _meet(l1, l2):
    den = _cross(l1[2], l2[2])
    if abs(den) < TOL * (1 + _dot(l1[2], l1[2])) * (1 + _dot(l2[2], l2[2])):
        raise Undefined("parallel lines")
    t = _cross(_sub(l2[1], l1[1]), l2[2]) / den
    return (l1[1][0] + t * l1[2][0], l1[1][1] + t * l1[2][1])


def _foot(p, ln):
    d = ln[2]
    t = _dot(_sub(p, ln[1]), d) / _dot(d, d)
    return (ln[1][0] + t * d[0], ln[1][1] + t * d[1])


def _circle(c, r2):
    if _small(r2):
        raise Undefined("a circle of radius 0")
    return ("circle", c, r2)


def _line_circle(ln, c, branch):
    d, w = ln[2], _sub(ln[1], c[1])
    a, b = _dot(d, d), _dot(d, w)
    disc = b * b - a * (_dot(w, w) - c[2])
    if disc < -TOL:
        raise Undefined("no intersection")
    r = mpmath.sqrt(max(disc, 0))
    t = (-b + r) / a if branch == 0 else (-b - r) / a
    return (ln[1][0] + t * d[0], ln[1][1] + t * d[1])


def _radical(c1, c2):
    n = _sub(c2[1], c1[1])
    if _small(_dot(n, n)):
        raise Undefined("concentric circles")
    h = (c1[2] - c2[2] + _dot(c2[1], c2[1]) - _dot(c1[1], c1[1])) / 2
    k = h / _dot(n, n)
    return ("line", (n[0] * k, n[1] * k), (-n[1], n[0]))


def _step(op, ins, vals):
    if op == "point":
        return (vals[0], vals[1])
    if op == "line_through":
        return _line(ins[0], _sub(ins[1], ins[0]))
    if op == "line_with_direction":
        return _line(ins[0], (vals[0], vals[1]))
    if op == "line_at_angle":
        return _line(ins[0], (mpmath.sin(vals[0]), -mpmath.cos(vals[0])))
    if op == "perpendicular":
        return ("line", ins[1], (-ins[0][2][1], ins[0][2][0]))
    if op == "parallel":
        return ("line", ins[1], ins[0][2])
    if op == "foot":
        return _foot(ins[0], ins[1])
    if op == "midpoint":
        return ((ins[0][0] + ins[1][0]) / 2, (ins[0][1] + ins[1][1]) / 2)
    if op == "meet":
        return _meet(ins[0], ins[1])
    if op == "reflect":
        f = _foot(ins[0], ins[1])
        return (2 * f[0] - ins[0][0], 2 * f[1] - ins[0][1])
    if op == "circle_through":
        return _circle(ins[0], _dot(_sub(ins[1], ins[0]), _sub(ins[1], ins[0])))
    if op == "circle_on_diameter":
        c = ((ins[0][0] + ins[1][0]) / 2, (ins[0][1] + ins[1][1]) / 2)
        return _circle(c, _dot(_sub(ins[1], ins[0]), _sub(ins[1], ins[0])) / 4)
    if op == "intersect_line_circle":
        return _line_circle(ins[0], ins[1], int(vals[0]))
    if op == "intersect_circles":
        return _line_circle(_radical(ins[0], ins[1]), ins[0], int(vals[0]))
    if op == "signed_length":
        d = ins[2][2]
        return _dot(_sub(ins[1], ins[0]), d) / mpmath.sqrt(_dot(d, d))
    if op == "point_from_lengths":
        return (vals[0] * ins[0], vals[1] * ins[1])
    return _class_step(op, ins, vals)


# -- a geometry class's operations (issue 24), from their definitions in docs/language.md --
def _dist2(p, q):
    return _dot(_sub(p, q), _sub(p, q))


def _on_circle_or_fail(p, c):
    if not _small(_dist2(p, c[1]) - c[2]):
        raise Undefined("the point is not on the circle")


def _turned(p, centre, theta):
    u = _sub(p, centre)
    c, s = mpmath.cos(theta), mpmath.sin(theta)
    return (centre[0] + c * u[0] - s * u[1], centre[1] + s * u[0] + c * u[1])


def _class_step(op, ins, vals):
    if op == "second_intersection":
        c1, c2, known = ins
        pts = [_line_circle(_radical(c1, c2), c1, b) for b in (0, 1)]
        if not (_on(known, c1) and _on(known, c2)):
            raise Undefined("the known point is not common to the circles")
        far = [p for p in pts if not (_small(p[0] - known[0]) and _small(p[1] - known[1]))]
        return far[0] if far else pts[0]
    if op == "point_on_line":
        ln = ins[0]
        return (ln[1][0] + vals[0] * ln[2][0], ln[1][1] + vals[0] * ln[2][1])
    if op == "point_on_circle":
        _on_circle_or_fail(ins[1], ins[0])
        return _turned(ins[1], ins[0][1], 2 * mpmath.atan(vals[0]))
    if op == "circumcircle":
        p, q, r = ins
        if _small(_cross(_sub(q, p), _sub(r, p))):
            raise Undefined("collinear points")
        m = mpmath.matrix(
            [[2 * (q[0] - p[0]), 2 * (q[1] - p[1])], [2 * (r[0] - p[0]), 2 * (r[1] - p[1])]]
        )
        rhs = mpmath.matrix([_dot(q, q) - _dot(p, p), _dot(r, r) - _dot(p, p)])
        x = mpmath.lu_solve(m, rhs)
        centre = (x[0], x[1])
        return _circle(centre, _dist2(p, centre))
    if op == "circle_radius":
        return _circle(ins[0], vals[0] ** 2)
    if op == "circle_compass":
        return _circle(ins[0], _dist2(ins[1], ins[2]))
    if op == "bisector":
        a, b, c = ins
        u, v = _sub(a, b), _sub(c, b)
        if _small(_dot(u, u)) or _small(_dot(v, v)):
            raise Undefined("an angle without an arm")
        nu, nv = mpmath.sqrt(_dot(u, u)), mpmath.sqrt(_dot(v, v))
        return _line(b, (u[0] / nu + v[0] / nv, u[1] / nu + v[1] / nv))
    if op == "tangent_at":
        c, p = ins
        _on_circle_or_fail(p, c)
        r = _sub(p, c[1])
        return _line(p, (-r[1], r[0]))
    if op == "tangent_point":
        p, c = ins
        o = c[1]
        thales = _circle(((p[0] + o[0]) / 2, (p[1] + o[1]) / 2), _dist2(p, o) / 4)
        pts = [_line_circle(_radical(c, thales), c, b) for b in (0, 1)]
        if _small(_dist2(pts[0], pts[1])) and len(vals) and int(vals[0]) == 1:
            raise Undefined("one tangent only")
        left = [q for q in pts if _cross(_sub(p, o), _sub(q, o)) > 0]
        right = [q for q in pts if q not in left]
        return (left + right)[int(vals[0])]
    if op == "rotate":
        return _turned(ins[0], ins[1], vals[0])
    if op == "homothety":
        p, c = ins
        return (c[0] + vals[0] * (p[0] - c[0]), c[1] + vals[0] * (p[1] - c[1]))
    if op == "point_reflect":
        p, c = ins
        return (2 * c[0] - p[0], 2 * c[1] - p[1])
    if op == "radical_axis":
        return _radical(ins[0], ins[1])
    raise ValueError(f"the evaluator does not know {op}")


def _angle_mod_pi(a, b, c):
    """The directed angle from ray BA to ray BC, reduced to [0, pi)."""
    u, v = _sub(a, b), _sub(c, b)
    if _small(_dot(u, u)) or _small(_dot(v, v)):
        raise Undefined("an angle without an arm")
    return mpmath.atan2(_cross(u, v), _dot(u, v)) % mpmath.pi


def _same_mod_pi(x, y) -> bool:
    d = (x - y) % mpmath.pi
    return d < mpmath.mpf(10) ** -30 or mpmath.pi - d < mpmath.mpf(10) ** -30


def _class_claim(kind, words, value, env):
    if kind == "congruent":
        a, b, c, d = (env[w] for w in words)
        return _small(mpmath.sqrt(_dist2(a, b)) - mpmath.sqrt(_dist2(c, d)))
    if kind == "equal_angles":
        p = [env[w] for w in words]
        return _same_mod_pi(_angle_mod_pi(*p[:3]), _angle_mod_pi(*p[3:]))
    if kind == "angles":
        p = [env[w] for w in words]
        total = sum(_angle_mod_pi(*p[i : i + 3]) for i in range(0, len(p), 3))
        return _same_mod_pi(total, num(value, env))
    if kind == "tangent":
        a, b = env[words[0]], env[words[1]]
        if a[0] == "circle" and b[0] == "circle":
            d = mpmath.sqrt(_dist2(a[1], b[1]))
            if _small(d):
                raise Undefined("concentric circles")
            r1, r2 = mpmath.sqrt(a[2]), mpmath.sqrt(b[2])
            return _small(d - r1 - r2) or _small(d - abs(r1 - r2))
        ln, c = (a, b) if a[0] == "line" else (b, a)
        f = _foot(c[1], ln)
        return _small(mpmath.sqrt(_dist2(f, c[1])) - mpmath.sqrt(c[2]))
    if kind == "ratio":
        a, b, c, d = (env[w] for w in words)
        cd = mpmath.sqrt(_dist2(c, d))
        if _small(cd):
            raise Undefined("a ratio to a zero length")
        return _small(mpmath.sqrt(_dist2(a, b)) / cd - num(value, env))
    raise ValueError(f"the evaluator does not know the claim {kind}")


def _on(p, obj):
    if obj[0] == "line":
        return _small(_cross(_sub(p, obj[1]), obj[2]) / mpmath.sqrt(_dot(obj[2], obj[2])))
    return _small(_dot(_sub(p, obj[1]), _sub(p, obj[1])) - obj[2])


def _concyclic(pts) -> bool:
    """On one circle or one line: the distinct points (coincident ones are one point);
    three or fewer always are; else the line or the circle through the first three
    distinct ones must hold every other."""
    distinct = []
    for p in pts:
        if not any(_small(p[0] - q[0]) and _small(p[1] - q[1]) for q in distinct):
            distinct.append(p)
    if len(distinct) <= 3:
        return True
    p, q, r = distinct[:3]
    if _small(_cross(_sub(q, p), _sub(r, p))):  # collinear: the line pq is the only one
        return all(_small(_cross(_sub(q, p), _sub(s, p))) for s in distinct)
    # circumcentre from |c - p|² = |c - q|² = |c - r|² (two linear equations)
    a1, b1 = 2 * (q[0] - p[0]), 2 * (q[1] - p[1])
    a2, b2 = 2 * (r[0] - p[0]), 2 * (r[1] - p[1])
    c1 = q[0] ** 2 + q[1] ** 2 - p[0] ** 2 - p[1] ** 2
    c2 = r[0] ** 2 + r[1] ** 2 - p[0] ** 2 - p[1] ** 2
    det = a1 * b2 - a2 * b1
    centre = ((c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det)
    r2 = _dot(_sub(p, centre), _sub(p, centre))
    return all(_small(_dot(_sub(s, centre), _sub(s, centre)) - r2) for s in distinct)


def _claim(body: str, env: dict) -> bool:
    words = body.split()
    kind = words[0]
    if kind == "collinear":
        pts = [env[w] for w in words[1:]]
        return all(
            _small(_cross(_sub(b, a), _sub(c, a)))
            for i, a in enumerate(pts)
            for j, b in enumerate(pts)
            for k, c in enumerate(pts)
            if i < j < k
        )
    if kind == "concyclic":
        return _concyclic([env[w] for w in words[1:]])
    if kind in ("congruent", "equal_angles", "tangent"):
        return _class_claim(kind, words[1:], None, env)
    if kind in ("ratio", "angles"):
        head, _, value = body.partition("==")
        return _class_claim(kind, head.split()[1:], value.strip(), env)
    if kind == "concurrent":
        lines = [env[w] for w in words[1:]]
        for i in range(len(lines)):
            for j in range(i + 1, len(lines)):
                if not _small(_cross(lines[i][2], lines[j][2])):
                    p = _meet(lines[i], lines[j])
                    return all(_on(p, ln) for ln in lines)
        return all(_on(ln[1], lines[0]) for ln in lines)
    if kind == "on":
        return _on(env[words[1]], env[words[2]])
    if kind in ("parallel", "perpendicular"):
        a, b = env[words[1]][2], env[words[2]][2]
        v = _cross(a, b) if kind == "parallel" else _dot(a, b)
        return _small(v / mpmath.sqrt(_dot(a, a) * _dot(b, b)))
    if kind == "sign":
        rest = body[4:].strip()
        m = re.search(r"==|!=|>=|<=|>|<", rest)
        a, b = num(rest[: m.start()], env), num(rest[m.end() :], env)
        d, rel = a - b, m.group()
        return {
            "==": _small(d),
            "!=": not _small(d),
            ">": d > TOL,
            ">=": d > -TOL,
            "<": d < -TOL,
            "<=": d < TOL,
        }[rel]
    m = re.match(r"(\S+)\s*==\s*(.*)$", body)
    left, right = env[m.group(1)], m.group(2).strip()
    pm = re.fullmatch(r"point\s*\((.*)\)", right)
    if pm:
        x, y = (num(t, env) for t in _items(pm.group(1)))
        return _small(left[0] - x) and _small(left[1] - y)
    if right in env and not isinstance(env[right], mpmath.mpf):
        other = env[right]
        if isinstance(left, tuple) and len(left) == 2 and not isinstance(left[0], str):
            return _small(left[0] - other[0]) and _small(left[1] - other[1])
        if left[0] == "circle":
            return all(_small(u - v) for u, v in zip((*left[1], left[2]), (*other[1], other[2])))
        return _on(other[1], left) and _small(_cross(left[2], other[2]))
    return _small(left - num(right, env))


def evaluate(text: str, point: dict) -> list[bool | None]:
    """Each claim's truth at ``point`` (None: a claim's object does not exist there)."""
    env: dict = {}
    for k, v in point.items():
        env[k] = num(str(v), {})
    results: list[bool | None] = []
    broken: set[str] = set()
    for raw in text.splitlines():
        line = re.sub(r'"[^"]*"', "", raw.split("#")[0]).strip()
        if not line or line.startswith(("param", "hypothesis")):
            continue
        if line.startswith("let "):
            name, expr = line[4:].split("=", 1)
            try:
                env[name.strip()] = num(expr, env)
            except (Undefined, ZeroDivisionError, ValueError):
                broken.add(name.strip())
            continue
        if line.startswith("claim "):
            body = line[6:].split(" under ")[0].strip()
            used = set(re.findall(r"[A-Za-z_][A-Za-z0-9_-]*", body))
            if used & broken:
                results.append(None)
                continue
            try:
                results.append(_claim(body, env))
            except (Undefined, ZeroDivisionError, KeyError):
                results.append(None)
            continue
        m = re.match(r"(\S+)\s*=\s*(\w+)\s*(.*)$", line)
        name, op, rest = m.groups()
        vals_m = re.search(r"\((.*)\)", rest)
        head = rest[: vals_m.start()] if vals_m else rest
        ins_names = [
            w
            for w in head.split()
            if w not in ("role", "key", "optional", "ref") and not w.isdigit()
        ][
            : {
                "point": 0,
                "line_with_direction": 1,
                "line_at_angle": 1,
                "point_from_lengths": 2,
                "signed_length": 3,
                "intersect_line_circle": 2,
                "intersect_circles": 2,
                "point_on_line": 1,
                "circumcircle": 3,
                "circle_radius": 1,
                "circle_compass": 3,
                "bisector": 3,
                "second_intersection": 3,
            }.get(op, 2)
        ]
        if any(n in broken for n in ins_names):
            broken.add(name)
            continue
        try:
            vals = [num(v, env) for v in _items(vals_m.group(1))] if vals_m else []
            env[name] = _step(op, [env[n] for n in ins_names], vals)
        except (Undefined, ZeroDivisionError):
            broken.add(name)
    return results


def random_point(params: dict[str, str], rng: random.Random, cond1: bool = False) -> dict:
    """A random point (text values) of the declared domains (and condition (1))."""
    for _ in range(1000):
        pt: dict[str, str] = {}
        for name, dom in params.items():
            if dom == "angle":
                pt[name] = repr(rng.uniform(0.01, 3.14159))
            elif dom == "half_angle":
                pt[name] = repr(rng.uniform(0.01, 1.56))
            elif dom == "real":
                pt[name] = repr(rng.uniform(-5, 5))
            else:
                pt[name] = repr(rng.uniform(0.05, 5))
        for i in "12":
            if f"mu{i}" in pt and f"xi{i}" in pt:
                pt[f"mu{i}"] = repr(float(mpmath.tan(float(pt[f"xi{i}"]))))
        if not cond1 or _cond1(pt):
            return pt
    raise RuntimeError("no admissible point")


def _cond1(pt: dict) -> bool:
    for i in "12":
        if f"phi{i}" not in pt:
            continue
        phi = float(pt[f"phi{i}"])
        xi = (
            float(pt[f"xi{i}"])
            if f"xi{i}" in pt
            else float(mpmath.atan(float(pt[f"mu{i}"])))
            if f"mu{i}" in pt
            else None
        )
        if xi is None:
            continue
        if not (mpmath.pi / 2 < phi + xi < 3 * mpmath.pi / 2 and abs(phi - xi) < mpmath.pi / 2):
            return False
    return True


def params_of(text: str) -> dict[str, str]:
    """``param NAME DOMAIN`` lines -> {name: domain word}."""
    out = {}
    for raw in text.splitlines():
        m = re.match(r"\s*param\s+(\S+)\s+(.*?)\s*(#.*)?$", raw)
        if m:
            d = m.group(2)
            out[m.group(1)] = {"> 0": "positive", ">= 0": "nonnegative"}.get(d, d)
    return out


def hypotheses_hold(text: str, point: dict) -> bool:
    """Every ``hypothesis NAME: LEFT REL RIGHT`` line of ``text`` holds at ``point``
    (its own reading: floats at 50 digits, a strict inequality by more than TOL)."""
    env = {k: num(str(v), {}) for k, v in point.items()}
    for raw in text.splitlines():
        m = re.match(r"\s*hypothesis\s+\w+\s*:\s*(.*?)\s*(#.*)?$", raw)
        if not m:
            continue
        r = re.search(r"!=|>=|<=|>|<", m.group(1))
        d = num(m.group(1)[: r.start()], env) - num(m.group(1)[r.end() :], env)
        ok = {"!=": abs(d) > TOL, ">": d > TOL, ">=": d > -TOL, "<": d < -TOL, "<=": d < TOL}[
            r.group()
        ]
        if not ok:
            return False
    return True
