#!/usr/bin/env python3
"""The verdicts of leapfrog-plain-tex.toml, derived in sympy from the mathematics, not from the harness.

Prints claim id -> {"verdict": ...}. Classes as docs/claims-file.md's shapes give them: a printed
value that differs from the one derived is an "erratum" (the correction proved).
"""
import json
import sympy as sp

m, w, h = sp.symbols("m omega h", positive=True)
qm1, qn, qp1, r, q, v = sp.symbols("q_nm1 q_n q_np1 r q v", real=True)
Vp = sp.Function("Vp")  # V', for a general V
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(e) == 0


# As printed (transcribed once, by hand).
general = (qp1 - 2 * qn + qm1) / h**2 + Vp(qn) / m
harmonic = (qp1 - 2 * qn + qm1) / h**2 + w**2 * qn
V = sp.Rational(1, 2) * m * w**2 * q**2
characteristic = r**2 - (2 - w**2 * h**2) * r + 1
discriminant_printed = w**2 * h**2 * (w**2 * h**2 - 2)
truncation_printed = w**4 * h**2 / 12 * q

# explicit: q_{n+1} never inside V', and the scheme linear in it; the note says explicit.
linear = sp.Poly(general.subs(Vp(qn), sp.Symbol("F")), qp1).degree() == 1
out["explicit"] = {"verdict": verdict(linear and not any(a.has(qp1) for a in general.atoms(Vp)))}

# harmonic-form: the general scheme with V' = m omega^2 q, up to a factor free of the states.
ratio = sp.simplify(harmonic / general.replace(Vp, sp.Lambda(q, sp.diff(V, q))))
out["harmonic-form"] = {"verdict": verdict(not any(ratio.has(s) for s in (qm1, qn, qp1)))}

# characteristic: the scheme at (1, r, r^2), scaled to r^2's coefficient 1.
at_r = sp.expand(harmonic.subs({qm1: 1, qn: r, qp1: r**2}, simultaneous=True))
monic = sp.expand(at_r / sp.Poly(at_r, r).coeff_monomial(r**2))
out["characteristic"] = {"verdict": verdict(zero(monic - characteristic))}

# discriminant: b^2 - 4ac of the printed polynomial.
a, b, c = [sp.Poly(characteristic, r).coeff_monomial(r**k) for k in (2, 1, 0)]
out["discriminant"] = {"verdict": verdict(zero(b**2 - 4 * a * c - discriminant_printed))}

# stable: |trace| < 2 (roots of modulus 1, simple) exactly on 0 < omega h < 2 as its first band.
th = sp.symbols("theta", positive=True)
trace = (2 - w**2 * h**2).subs(w, th / h)
stable_set = sp.solve_univariate_inequality(sp.Abs(trace) < 2, th, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["stable"] = {"verdict": verdict(stable_set == sp.Interval.open(0, 2))}

# coefficient-sign: 1 - (omega h)^2/4 > 0 exactly on 0 < omega h < 2.
positive_set = sp.solve_univariate_inequality(1 - th**2 / 4 > 0, th, relational=False).intersect(sp.Interval.open(0, sp.oo))
out["coefficient-sign"] = {"verdict": verdict(positive_set == sp.Interval.open(0, 2))}

# truncation: the scheme on the exact solution through q_n, q(t +- h) = q cos(omega h) +- (v/omega) sin(omega h).
on_exact = harmonic.subs({qm1: q * sp.cos(w * h) - v / w * sp.sin(w * h), qn: q, qp1: q * sp.cos(w * h) + v / w * sp.sin(w * h)}, simultaneous=True)
series = sp.series(on_exact, h, 0, 4).removeO()
out["truncation"] = {"verdict": verdict(zero(series - truncation_printed))}

# second-order: leading power 2 of the series, the q_{n+1} coefficient of order h^-2: order 2 - (-2) - 2 = 2.
lead = min(k for (k,) in sp.Poly(sp.series(on_exact, h, 0, 8).removeO(), h).monoms())
out["second-order"] = {"verdict": verdict(lead - (-2) - 2 == 2)}

print(json.dumps(out, indent=1, sort_keys=True))
