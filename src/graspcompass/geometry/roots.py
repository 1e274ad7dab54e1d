"""The constructed square root: √D with its perfect squares taken out on the right branch.

A compass meets a line or a circle at ``(−b ± √D)/a``; the kernel takes √D ≥ 0 (branch 0 is
``+``).  When D has a square factor f² the root is ``|f|·√(D/f²)``, and ``|f| = f`` where f
is shown ≥ 0 for every value of the symbols (their sympy assumptions: a parameter
``> 0`` is positive, ``real`` is real): a sign decided by :func:`decide_sign`, an even
power, or a polynomial of degree ≤ 2 with rational coefficients whose augmented Gram
matrix is positive semi-definite (a squared length (b₁ − a₁)² + (b₂ − a₂)², expanded);
``|f| = −f`` where f is shown ≤ 0.  A square factor of unknown sign stays under the root,
so the value is the same number as ``sp.sqrt(D)`` for every value of the symbols.

Examples
--------
>>> import sympy as sp
>>> a, b = sp.symbols("a b", real=True)
>>> constructed_sqrt(sp.expand(3 * (a**2 + b**2)**2))
sqrt(3)*(a**2 + b**2)
>>> constructed_sqrt(sp.expand((a - b)**2))
sqrt(a**2 - 2*a*b + b**2)
"""

from __future__ import annotations

import sympy as sp

from .exact import decide_sign

__all__ = ["constructed_sqrt", "nonnegative"]

#: Radicands with more terms are left as they are (factoring them would cost more than
#: the root saves).
MAX_TERMS = 400


def _gram_psd(f: sp.Expr) -> bool:
    """f (degree ≤ 2, rational coefficients) is ≥ 0 everywhere: [[Q, l/2], [l/2, c]] ⪰ 0."""
    gens = sorted(f.free_symbols, key=str)
    if not gens or not all(g.is_real for g in gens):
        return False
    try:
        p = sp.Poly(f, *gens)
    except sp.PolynomialError:
        return False
    if p.total_degree() > 2 or not all(c.is_Rational for c in p.coeffs()):
        return False
    n = len(gens)
    m = sp.zeros(n + 1, n + 1)
    for monom, c in p.terms():
        idx = [i for i, e in enumerate(monom) for _ in range(e)]
        if len(idx) == 2:
            i, j = idx
            if i == j:
                m[i, i] += c
            else:
                m[i, j] += c / 2
                m[j, i] += c / 2
        elif len(idx) == 1:
            m[idx[0], n] += c / 2
            m[n, idx[0]] += c / 2
        else:
            m[n, n] += c
    # positive semi-definite: every principal minor is >= 0 (exact rationals)
    from itertools import combinations

    size = n + 1
    if size > 9:
        return False
    return all(
        m.extract(list(s), list(s)).det() >= 0
        for k in range(1, size + 1)
        for s in combinations(range(size), k)
    )


def nonnegative(f: sp.Expr) -> bool:
    """``f ≥ 0`` shown for every value of its symbols (False: not shown)."""
    if f.is_nonnegative:
        return True
    s = decide_sign(f)
    if s is not None and s >= 0:
        return True
    return _gram_psd(f) or _quadratic_in_one(f, 2)


def _quadratic_in_one(f: sp.Expr, depth: int) -> bool:
    """``f = A·v² + B·v + C ≥ 0`` for a real symbol v of degree 2 in f: A ≥ 0, C ≥ 0 and
    4AC − B² ≥ 0, each shown by :func:`nonnegative` (to ``depth`` levels).  Then f ≥ 0
    for every v: f = A(v + B/2A)² + (4AC − B²)/4A where A > 0, and B = 0, f = C where
    A = 0."""
    if depth <= 0 or not f.is_Add or len(f.args) > 40 or not all(s.is_real for s in f.free_symbols):
        return False
    for v in sorted(f.free_symbols, key=str):
        if not v.is_real:
            continue
        try:
            p = sp.Poly(f, v)
        except sp.PolynomialError:
            continue
        if p.degree() != 2 or any(c.has(v) for c in p.all_coeffs()):
            continue
        a, b, c = (sp.expand(x) for x in p.all_coeffs())
        d = sp.expand(4 * a * c - b**2)
        if all(_nonneg_at(x, depth - 1) for x in (a, c, d)):
            return True
    return False


def _nonneg_at(f: sp.Expr, depth: int) -> bool:
    if f.is_nonnegative:
        return True
    s = decide_sign(f)
    if s is not None and s >= 0:
        return True
    return _gram_psd(f) or _quadratic_in_one(f, depth)


def _square_over_root(g: sp.Expr) -> sp.Expr | None:
    """h ≥ 0 with h² = g, where g = g0 + g1·√R has one square root √R among its atoms
    and h = α + β√R (α, β free of it): α² + β²R = g0, 2αβ = g1, so
    α² = (g0 ± √(g0² − g1²R))/2 with g0² − g1²R a perfect square.  None: not found."""
    roots = [a for a in g.atoms(sp.Pow) if a.exp == sp.Rational(1, 2) and a.base.free_symbols]
    if len(roots) != 1:
        return None
    s = roots[0]
    r = s.base
    t = sp.Dummy("t")
    try:
        p = sp.Poly(sp.expand(g.xreplace({s: t})), t)
    except sp.PolynomialError:
        return None
    if p.degree() > 2:
        return None
    c = [*p.all_coeffs()[::-1], 0, 0]
    g0, g1 = sp.expand(c[0] + c[2] * r), sp.expand(c[1])
    if g1 == 0:
        return None
    w = _poly_sqrt(sp.expand(g0**2 - g1**2 * r))
    if w is None:
        return None
    for a2 in ((g0 + w) / 2, (g0 - w) / 2):
        root = _poly_sqrt(sp.expand(a2))
        if root is None or root == 0:
            continue
        for alpha in (root, -root):
            beta = sp.cancel(g1 / (2 * alpha))
            h = alpha + beta * s
            if (
                sp.expand(h**2 - g).xreplace({s: t}).subs(t**2, r) == 0
                or sp.expand((sp.expand(h**2) - g).subs(s**2, r)) == 0
            ):
                if nonnegative(h):
                    return h
                if nonnegative(-h):
                    return -h
    return None


def _poly_sqrt(e: sp.Expr) -> sp.Expr | None:
    """A polynomial q with q² = e (either sign), or None when e is not a perfect square."""
    if e == 0:
        return sp.Integer(0)
    try:
        c, factors = sp.factor_list(e)
    except (sp.PolynomialError, NotImplementedError):
        return None
    rc = sp.sqrt(sp.sympify(c))
    if any(m % 2 for _, m in factors) or not rc.is_Rational:
        return None
    out = rc
    for f, m in factors:
        out *= f ** (m // 2)
    return out


def _split(d: sp.Expr) -> tuple[sp.Expr, sp.Expr] | None:
    """``(out, inside)`` with d = out²·inside and out ≥ 0, or None (nothing to take out)."""
    try:
        c, factors = sp.factor_list(d)
    except (sp.PolynomialError, NotImplementedError):
        return None
    out, inside, apart = sp.Integer(1), sp.sympify(c), sp.Integer(1)
    odd = [f for f, m in factors if m % 2]
    for f, m in factors:
        half = m // 2
        if half and nonnegative(f):
            out *= f**half
        elif half and nonnegative(-f):
            out *= (-f) ** half
        else:
            inside *= f ** (2 * half)
        if m % 2 and len(odd) > 1 and f.free_symbols and nonnegative(f):
            apart *= sp.sqrt(f)  # √(f·g) = √f·√g for f ≥ 0: one root per factor
        elif m % 2:
            inside *= f
    if apart != 1:
        return out * apart, inside
    return (out, inside) if out != 1 else None


def constructed_sqrt(d: sp.Expr) -> sp.Expr:
    """√d ≥ 0 with the square factors of ``d`` of known sign taken out (see the module):
    for d = N/D, √(f²X / (g²Y)) = (|f|/|g|)·√(X/Y)."""
    d = sp.sympify(d)
    if not d.free_symbols or not (d.is_Add or d.is_Mul or d.is_Pow):
        return sp.sqrt(d)
    if d.is_Add and len(d.args) > MAX_TERMS:
        return sp.sqrt(d)
    n, den = (
        sp.fraction(sp.together(d))
        if not d.is_Add
        or any(
            (a.is_Pow and a.exp.is_negative)
            or (a.is_Mul and any(x.is_Pow and x.exp.is_negative for x in a.args))
            for a in d.args
        )
        else (d, 1)
    )
    top = _split(n) if n.free_symbols else None
    bottom = _split(den) if sp.sympify(den).free_symbols else None
    if top is None and bottom is None:
        if den == 1 and d.is_Add:
            h = _square_over_root(d)
            if h is not None:
                return h
        return sp.sqrt(d)
    on, inn = top or (sp.Integer(1), n)
    od, ind = bottom or (sp.Integer(1), den)
    if sp.sympify(ind) == 1 and sp.sympify(inn).is_Add:
        h = _square_over_root(sp.expand(inn))
        if h is not None:
            return on / od * h
    return on / od * sp.sqrt(inn / ind)
