"""Independent re-checker of proof certificates: Fraction arithmetic on dicts, no sympy.

A certificate (see :func:`graspcompass.proof.prove_identity`) states, for each
entry of an identity, a numerator ``N`` (the numerator of ``lhs - rhs`` as a
sparse polynomial), relations and cofactors with ``N = sum q_i * rel_i``.  This
module re-expands the sum with :class:`fractions.Fraction` coefficients and
compares it with ``N``; it accepts only relations of an allowed form:

* ``s**2 + c**2 - 1`` for a declared sine/cosine pair of one angle (the
  variables named ``sin(a)`` and ``cos(a)``, each in one pair only);
* ``w**2 - P`` for a declared root ``w = sqrt(P)`` whose radicand uses only roots
  declared after it (inner roots), never itself.

A sign certificate adds the witness factors, each with a reason: a rational
number, a symbol's domain (§2.2, or a sign declared as a hypothesis), the sine
or cosine of an angle form whose interval (summed from declared intervals, as
rational multiples of π; those marked "(1)" must be those of condition (1))
lies inside one half-turn where it has one sign, and products, powers, sums of
those.  The product of the factor signs must be the claimed sign.

What the re-checker does *not* see: that ``N`` is the numerator of the claim
(sympy's conversion of the expression) and that each factor's text names the
polynomial used in the identity.

Examples
--------
>>> recheck({"kind": "identity", "entries": [{"vars": ["sin(a)", "cos(a)"],
...     "relations": [{"kind": "pythagoras", "angle": "a", "sin": 0, "cos": 1,
...                    "poly": [["1/1", [2, 0]], ["1/1", [0, 2]], ["-1/1", [0, 0]]]}],
...     "numerator": [["2/1", [2, 0]], ["2/1", [0, 2]], ["-2/1", [0, 0]]],
...     "cofactors": [[["2/1", [0, 0]]]]}], "denominators": []})
True
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..boundary.errors import GraspCompassError

__all__ = ["RecheckError", "problems", "recheck"]

Poly = dict[tuple[int, ...], Fraction]


class RecheckError(GraspCompassError):
    """A certificate that does not re-check; the message lists what is wrong."""


def _poly(terms: Any, n: int) -> Poly:
    out: Poly = {}
    for coeff, exps in terms:
        if (
            not isinstance(coeff, str)
            or len(exps) != n
            or any(not isinstance(e, int) or e < 0 for e in exps)
        ):
            raise RecheckError(f"malformed term {coeff!r} {exps!r} (expected {n} exponents)")
        m = tuple(exps)
        out[m] = out.get(m, Fraction(0)) + Fraction(coeff)
    return {m: c for m, c in out.items() if c}


def _mul(a: Poly, b: Poly) -> Poly:
    out: Poly = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            m = tuple(x + y for x, y in zip(ma, mb))
            out[m] = out.get(m, Fraction(0)) + ca * cb
    return {m: c for m, c in out.items() if c}


def _add(a: Poly, b: Poly, k: Fraction = Fraction(1)) -> Poly:
    out = dict(a)
    for m, c in b.items():
        out[m] = out.get(m, Fraction(0)) + k * c
    return {m: c for m, c in out.items() if c}


def _mono(n: int, i: int, e: int) -> tuple[int, ...]:
    return tuple(e if j == i else 0 for j in range(n))


def _entry(entry: dict[str, Any]) -> list[str]:
    names = entry["vars"]
    n = len(names)
    if len(set(names)) != n:
        return [f"variable names repeat: {names}"]
    out: list[str] = []
    used: set[int] = set()
    rels: list[Poly] = []
    roots = [r["var"] for r in entry["relations"] if r.get("kind") == "root"]
    for pos, r in enumerate(entry["relations"]):
        poly = _poly(r["poly"], n)
        if r.get("kind") == "pythagoras":
            i, j, a = r["sin"], r["cos"], r["angle"]
            if i == j or {i, j} & used or not (0 <= i < n and 0 <= j < n):
                out.append(f"relation {pos}: bad or reused variables {i}, {j}")
            elif (names[i], names[j]) != (f"sin({a})", f"cos({a})"):
                out.append(f"relation {pos}: {names[i]}, {names[j]} are not sin, cos of {a}")
            want = {
                _mono(n, i, 2): Fraction(1),
                _mono(n, j, 2): Fraction(1),
                (0,) * n: Fraction(-1),
            }
            used |= {i, j}
        elif r.get("kind") == "root":
            w = r["var"]
            rad = _poly(r["radicand"], n)
            later = set(roots[roots.index(w) + 1 :])
            bad = {k for m in rad for k, e in enumerate(m) if e and k in roots and k not in later}
            if w in used or not 0 <= w < n or bad:
                out.append(
                    f"relation {pos}: root {w} reused, out of range, or its radicand "
                    f"uses {sorted(bad)}"
                )
            used.add(w)
            want = _add({_mono(n, w, 2): Fraction(1)}, rad, Fraction(-1))
        else:
            out.append(f"relation {pos}: unknown kind {r.get('kind')!r}")
            continue
        if poly != want:
            out.append(f"relation {pos} is not of its declared form ({r['kind']})")
        rels.append(poly)
    cof = entry["cofactors"]
    if len(cof) != len(rels):
        return [*out, f"{len(cof)} cofactors for {len(rels)} relations"]
    total: Poly = {}
    for q, rel in zip(cof, rels):
        total = _add(total, _mul(_poly(q, n), rel))
    if total != _poly(entry["numerator"], n):
        out.append("sum of cofactor * relation differs from the numerator")
    return out


#: Condition (1) and the domains of ξ, φ (§2.2) as rational multiples of π.
_COND1: dict[tuple[tuple[str, int], ...], tuple[Fraction, Fraction]] = {}
for _i in ("1", "2"):
    _COND1[((f"xi{_i}", 1),)] = (Fraction(0), Fraction(1, 2))
    _COND1[((f"phi{_i}", 1),)] = (Fraction(0), Fraction(1))
    _COND1[((f"phi{_i}", 1), (f"xi{_i}", 1))] = (Fraction(1, 2), Fraction(3, 2))
    _COND1[((f"phi{_i}", 1), (f"xi{_i}", -1))] = (Fraction(-1, 2), Fraction(1, 2))
_POSITIVE = {"x1", "x2", "mu1", "mu2", "F_e", "phi1", "phi2", "xi1", "xi2"}
_NONNEG = {"y"}


def _key(form: dict[str, int]) -> tuple:
    return tuple(sorted((k, v) for k, v in form.items() if v))


def _smul(a: tuple[int, int], b: tuple[int, int]) -> tuple[int, int]:
    p = [x * y for x in a for y in b]
    return min(p), max(p)


def _sadd(a: tuple[int, int], b: tuple[int, int]) -> tuple[int, int] | None:
    if a[0] >= 0 and b[0] >= 0:
        return (1 if max(a[0], b[0]) > 0 else 0), 1
    if a[1] <= 0 and b[1] <= 0:
        return -1, (-1 if min(a[1], b[1]) < 0 else 0)
    return None


def _trig(node: dict, ivs: dict, out: list[str]) -> tuple[int, int] | None:
    total: dict[str, int] = {}
    lo = hi = Fraction(node["const"])
    for p in node["pieces"]:
        key, c = _key(p["form"]), p["coeff"]
        a, b = (Fraction(x) for x in p["interval"])
        if ivs.get(key) != (a, b) or c not in (1, -1):
            out.append(f"interval {p} is not a declared hypothesis")
            return None
        for k, v in p["form"].items():
            total[k] = total.get(k, 0) + c * v
        lo, hi = (lo + a, hi + b) if c == 1 else (lo - b, hi - a)
    if _key(total) != _key(node["form"]):
        out.append(f"the pieces do not add up to the form {node['form']}")
        return None
    if [lo, hi] != [Fraction(x) for x in node["interval"]] or not lo < hi:
        out.append(f"interval of {node['form']} is ({lo}, {hi}), not {node['interval']}")
        return None
    shift = (
        Fraction(1, 2) if node["func"] == "cos" else Fraction(0) if node["func"] == "sin" else None
    )
    if shift is None:
        out.append(f"unknown function {node['func']}")
        return None
    k = (lo + shift).__floor__()
    if hi + shift > k + 1:
        out.append(f"{node['func']} changes sign on ({lo}, {hi})·π")
        return None
    return (1, 1) if k % 2 == 0 else (-1, -1)


def _sign(node: dict, cert: dict, ivs: dict, out: list[str]) -> tuple[int, int] | None:
    t = node.get("type")
    got: tuple[int, int] | None
    if t == "number":
        v = Fraction(node["value"])
        got = (0, 0) if v == 0 else (1, 1) if v > 0 else (-1, -1)
    elif t == "enclosure":
        lo, hi = Fraction(node["lo"]), Fraction(node["hi"])
        got = (1, 1) if lo > 0 and lo <= hi else (-1, -1) if hi < 0 and lo <= hi else None
    elif t == "symbol":
        name = node["name"]
        got = (
            (1, 1)
            if name in _POSITIVE
            else (0, 1)
            if name in _NONNEG
            else tuple(cert.get("symbols", {}).get(name, ())) or None
        )  # type: ignore[assignment]
    elif t == "trig":
        got = _trig(node, ivs, out)
    elif t == "sqrt":
        b = _sign(node["base"], cert, ivs, out)
        got = b if b is not None and b[0] >= 0 else None
    elif t == "pow":
        b, e = _sign(node["base"], cert, ivs, out), node["exp"]
        got = None
        if b is not None and isinstance(e, int) and not (e < 0 and b[0] <= 0 <= b[1]):
            got = (1, 1)
            for _ in range(abs(e)):
                got = _smul(got, b)
    elif t in ("mul", "add"):
        parts = [_sign(a, cert, ivs, out) for a in node["args"]]
        got = None if any(p is None for p in parts) or not parts else parts[0]
        for p in parts[1:]:
            if got is None:
                break
            got = _smul(got, p) if t == "mul" else _sadd(got, p)  # type: ignore[arg-type]
    else:
        out.append(f"unknown reason {t!r}")
        return None
    if got is None or list(got) != list(node.get("sign", ())):
        out.append(f"the sign {node.get('sign')} of a {t} node does not follow (got {got})")
        return None
    return got


def _sign_cert(cert: dict[str, Any]) -> list[str]:
    out = problems(cert.get("identity") or {})
    ivs: dict[tuple, tuple[Fraction, Fraction]] = {}
    for iv in cert.get("intervals", []):
        key, (a, b) = _key(iv["form"]), (Fraction(x) for x in iv["interval"])
        if iv.get("source") == "(1)" and _COND1.get(key) != (a, b):
            out.append(f"interval {iv} is not that of condition (1)")
            continue
        if iv.get("source") != "(1)" and not cert.get("hypotheses"):
            out.append(f"interval {iv} is used but no hypothesis is stated")
        ivs[key] = (a, b)
    total = (1, 1)
    for f in cert.get("factors", []):
        s = _sign(f["reason"], cert, ivs, out)
        if s is None or s[0] != s[1] or s[0] == 0:
            out.append(f"factor {f['factor']} has no strict sign")
            return out
        total = _smul(total, s)
    if not cert.get("factors") or total[0] != cert.get("sign"):
        out.append(f"the factor signs multiply to {total[0]}, not {cert.get('sign')}")
    return out


def problems(certificate: dict[str, Any]) -> list[str]:
    """What is wrong with ``certificate`` (empty list: it re-checks)."""
    try:
        kind = certificate.get("kind")
        if kind == "identity":
            out = []
            if not certificate.get("entries"):
                return ["no entries"]
            for i, e in enumerate(certificate["entries"]):
                if not e:
                    out.append(f"entry {i} has no certificate")
                    continue
                out += [f"entry {i}: {p}" for p in _entry(e)]
            for d in certificate.get("denominators", []):
                if d.get("status") not in ("implied", "condition"):
                    out.append(f"denominator {d.get('factor')} has no status")
            return out
        if kind == "sign":
            return _sign_cert(certificate)
        return [f"unknown certificate kind {kind!r}"]
    except (KeyError, TypeError, ValueError, ZeroDivisionError, AttributeError) as exc:
        return [f"malformed certificate: {type(exc).__name__}: {exc}"]


def recheck(certificate: dict[str, Any], strict: bool = False) -> bool:
    """True when ``certificate`` re-checks; with ``strict``, raise :class:`RecheckError` if not."""
    bad = problems(certificate)
    if bad and strict:
        raise RecheckError("; ".join(bad))
    return not bad
