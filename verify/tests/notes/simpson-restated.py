#!/usr/bin/env python3
"""The verdicts of simpson-restated.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}.
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
ql, qm, qr, th, t, x = sp.symbols("q_l q_m q_r theta t x", real=True)
V = sp.Function("V")
Vp = sp.Function("Vp")
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


def primes_as_Vp(e):
    e = e.replace(lambda s: isinstance(s, sp.Subs) and isinstance(s.expr, sp.Derivative), lambda s: Vp(s.point[0]))
    return e.replace(lambda s: isinstance(s, sp.Derivative) and s.expr.func == V, lambda s: Vp(s.variables[0]))


# As printed.
phi = [(1 - th) * (1 - 2 * th), 4 * th * (1 - th), th * (2 * th - 1)]
interp = ql * phi[0] + qm * phi[1] + qr * phi[2]
rule = lambda f: sp.Rational(1, 6) * (f(0) + 4 * f(sp.Rational(1, 2)) + f(1))
Lh = m / (12 * h) * ((3 * ql - 4 * qm + qr) ** 2 + 4 * (qr - ql) ** 2 + (ql - 4 * qm + 3 * qr) ** 2) - h / 6 * (V(ql) + 4 * V(qm) + V(qr))
internal = 4 * m / h**2 * (ql - 2 * qm + qr) + Vp(qm)
qm_printed = (ql + qr) / (2 * (1 - w**2 * h**2 / 8))

# simpson-degree: exact for x^k up to k = 3, not for k = 4.
exact = [sp.integrate(th**k, (th, 0, 1)) == rule(lambda s: s**k) for k in range(6)]
degree = exact.index(False) - 1
out["simpson-degree"] = {"verdict": verdict(degree == 3)}

# lagrangian: the rule applied to the action over [0, h], t = h theta, q(t) the interpolant.
q_of_t = interp  # in theta
dq_dt = sp.diff(interp, th) / h
integrand = m / 2 * dq_dt**2 - V(q_of_t)
derived = h * rule(lambda s: integrand.subs(th, s))
out["lagrangian"] = {"verdict": verdict(zero(sp.expand(derived - Lh)))}

# internal-node: dL_h/dq_m = 0 is the printed equation up to a factor free of the nodes.
ratio = sp.simplify(primes_as_Vp(sp.diff(Lh, qm)) / internal)
out["internal-node"] = {"verdict": verdict(not any(ratio.has(s) for s in (ql, qm, qr)))}

# implicit: q_m inside V' (a general V): a nonlinear equation for it.
out["implicit"] = {"verdict": verdict(any(a.has(qm) for a in internal.atoms(Vp)))}

# harmonic-node: the printed q_m solves the internal equation with V' = m omega^2 q.
harmonic = internal.replace(Vp, sp.Lambda(x, m * w**2 * x))
out["harmonic-node"] = {"verdict": verdict(zero(harmonic.subs(qm, qm_printed)))}

print(json.dumps(out, indent=1, sort_keys=True))
