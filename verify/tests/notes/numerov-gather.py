#!/usr/bin/env python3
"""The verdicts of numerov-gather.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}.
"""
import json
import sympy as sp

w, h = sp.symbols("omega h", positive=True)
qm1, qj, qp1, r, q, v, t = sp.symbols("q_jm1 q_j q_jp1 r q v t", real=True)
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


scheme = (qp1 - 2 * qj + qm1) / h**2 + sp.Rational(1, 12) * w**2 * (qp1 + 10 * qj + qm1)
truncation_printed = w**6 * h**4 / 240 * q
x = w**2 * h**2
characteristic = r**2 - (2 - sp.Rational(5, 6) * x) / (1 + x / 12) * r + 1

# consistency: on smooth states the scheme tends to q'' + omega^2 q (a multiple of it, h^0).
qf = sp.Function("qf")
smooth = scheme.subs({qm1: qf(t - h), qj: qf(t), qp1: qf(t + h)}, simultaneous=True)
leading = sp.simplify(sp.series(smooth, h, 0, 1).removeO())
ratio = sp.simplify(leading / (sp.diff(qf(t), t, 2) + w**2 * qf(t)))
out["consistency"] = {"verdict": verdict(not ratio.has(qf) and not ratio.has(h) and ratio != 0)}

on_exact = scheme.subs({qm1: q * sp.cos(w * h) - v / w * sp.sin(w * h), qj: q, qp1: q * sp.cos(w * h) + v / w * sp.sin(w * h)}, simultaneous=True)
series = sp.series(on_exact, h, 0, 6).removeO()
out["truncation"] = {"verdict": verdict(zero(series - truncation_printed))}
lead = min(k for (k,) in sp.Poly(sp.series(on_exact, h, 0, 10).removeO(), h).monoms())
out["fourth-order"] = {"verdict": verdict(lead - (-2) - 2 == 4)}

at_r = sp.expand(scheme.subs({qm1: 1, qj: r, qp1: r**2}, simultaneous=True))
monic = sp.expand(at_r / sp.Poly(at_r, r).coeff_monomial(r**2))
out["characteristic"] = {"verdict": verdict(zero(monic - characteristic))}

th = sp.symbols("theta", positive=True)
trace = sp.simplify(((2 - sp.Rational(5, 6) * x) / (1 + x / 12)).subs(w, th / h))
stable = sp.solve_univariate_inequality(sp.Abs(trace) < 2, th, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["stable"] = {"verdict": verdict(stable == sp.Interval.open(0, sp.sqrt(6)))}
# conditionally stable: stable on some band of omega h > 0, not on all of them.
out["conditionally-stable"] = {"verdict": verdict(stable != sp.EmptySet and stable != sp.Interval.open(0, sp.oo))}

print(json.dumps(out, indent=1, sort_keys=True))
