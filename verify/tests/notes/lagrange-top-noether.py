#!/usr/bin/env python3
"""The verdicts of lagrange-top-noether.toml, derived in sympy from the mathematics, not from the
harness: the top's Lagrangian as printed for its momenta and its theta equation, and a general
L(theta, theta', phi', psi') (sympy's undefined functions for its partial derivatives) for Noether.

Prints claim id -> {"verdict": ...}.
"""
import json
import sympy as sp

I1, I3, M, g, ell, h = sp.symbols("I_1 I_3 M g ell h", positive=True)
t = sp.Symbol("t", real=True)
th, ph, ps = (sp.Function(n)(t) for n in ("theta", "phi", "psi"))
out = {}


def verdict(ok, false="erratum"):
    return "holds" if ok else false


def zero(e):
    return sp.simplify(sp.expand(e)) == 0


# The top, as printed (top), in the states and their derivatives.
thd, phd, psd = (sp.diff(x, t) for x in (th, ph, ps))
L = I1 / 2 * (thd**2 + phd**2 * sp.sin(th) ** 2) + I3 / 2 * (psd + phd * sp.cos(th)) ** 2 - M * g * ell * sp.cos(th)

# momentum-phi, momentum-psi: the chain p = dL/d(velocity) = printed.
printed_pphi = I1 * phd * sp.sin(th) ** 2 + I3 * (psd + phd * sp.cos(th)) * sp.cos(th)
printed_ppsi = I3 * (psd + phd * sp.sin(th))
out["momentum-phi"] = {"verdict": verdict(zero(sp.diff(L, phd) - printed_pphi))}
ok = zero(sp.diff(L, psd) - printed_ppsi)
out["momentum-psi"] = {"verdict": verdict(ok)}

# euler-lagrange-theta: d/dt dL/dtheta' - dL/dtheta along a motion, against the printed right side.
el = sp.diff(sp.diff(L, thd), t) - sp.diff(L, th)
printed_el = I1 * sp.diff(th, t, 2) - I1 * phd**2 * sp.sin(th) * sp.cos(th) + I3 * (psd + phd * sp.cos(th)) * phd * sp.sin(th) - M * g * ell * sp.sin(th)
out["euler-lagrange-theta"] = {"verdict": verdict(zero(el - printed_el))}

# noether-phi, noether-psi: a general L(theta, u, v, w) (partials L_1 ... L_4), Simpson's L_h.
Ls = [sp.Function(f"L_{k}") for k in range(1, 5)]


class Lg(sp.Function):
    """A general L(theta, theta', phi', psi'): its partial derivatives are L_1 ... L_4."""

    def fdiff(self, argindex=1):
        return Ls[argindex - 1](*self.args)


nodes = {c: sp.symbols(f"{c}_l {c}_m {c}_r", real=True) for c in ("theta", "phi", "psi")}
gear = lambda l, m, r: ((-3 * l + 4 * m - r) / h, (r - l) / h, (l - 4 * m + 3 * r) / h)
vel = {c: gear(*nodes[c]) for c in nodes}
Lh = h / 6 * sum(wt * Lg(nodes["theta"][k], vel["theta"][k], vel["phi"][k], vel["psi"][k]) for k, wt in enumerate((1, 4, 1)))
for c in ("phi", "psi"):
    l, m, r = nodes[c]
    shift = sp.diff(Lh, l) + sp.diff(Lh, m) + sp.diff(Lh, r)
    start, end = -sp.diff(Lh, l), sp.diff(Lh, r)
    out[f"noether-{c}"] = {"verdict": verdict(zero(shift) and zero(end - start + sp.diff(Lh, m)))}

print(json.dumps(out, indent=1, sort_keys=True))
