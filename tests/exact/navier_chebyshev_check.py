#!/usr/bin/python3
"""Independent cross-check of plate_exact.h (not run by ctest).

Solves the same simply supported plate problem in a different formulation:
the second-order Navier (displacement) equations with the E'(z) terms,

  (mu (U' + p W))' - p ((lam+2mu) p U + lam q V - lam W') - q mu (q U + p V)
                                                           = -rho w^2 U
  (mu (V' + q W))' - q (lam p U + (lam+2mu) q V - lam W') - p mu (q U + p V)
                                                           = -rho w^2 V
  ((lam+2mu) W' - lam (p U + q V))' - p mu (U' + p W) - q mu (V' + q W)
                                                           = -rho w^2 W

discretised by multi-domain Chebyshev collocation (K elements of degree N,
continuity of displacements and tractions between elements). Statics: a
long-double assembly with iterative refinement; frequencies: a
double-precision generalised eigenproblem (accurate to ~1e-8 only).
Needs numpy and scipy (/usr/bin/python3 on the development machine).
"""
import numpy as np
import scipy.linalg as sl

LD = np.longdouble
PI = np.arccos(LD(-1))


def cheb(N):
    x = np.cos(PI * np.arange(N + 1, dtype=LD) / N)
    c = np.hstack([LD(2), np.ones(N - 1, dtype=LD), LD(2)]) * (-1) ** np.arange(N + 1)
    X = np.tile(x, (N + 1, 1)).T
    D = np.outer(c, 1 / c) / (X - X.T + np.eye(N + 1, dtype=LD))
    return D - np.diag(D.sum(axis=1)), x


def assemble(index, m=1, n=1, K=16, N=20, homogeneous=False, Em=LD(70e9), Ec=LD(380e9),
             rho_m=LD(2707), rho_c=LD(3800), nu=LD(3) / 10, a=LD(2) / 10, b=LD(1) / 10,
             h=LD(2) / 100):
    """Rows: equilibrium (nondimensional: z/h, moduli/Em) at the nodes, with
    boundary/interface rows overwritten; returns A, the row density (zero on
    constraint rows), the traction operators and the node data."""
    D, x = cheb(N)
    n1 = N + 1
    P, Q = m * PI / a * h, n * PI / b * h
    edges = np.linspace(LD(0), LD(1), K + 1)
    size = 3 * n1 * K
    A = np.zeros((size, size), dtype=LD)
    rho_rows = np.zeros(size, dtype=LD)
    dg, Z0 = np.diag, np.zeros((n1, n1), dtype=LD)
    blocks = []
    for e in range(K):
        L = edges[e + 1] - edges[e]
        zeta = edges[e] + (1 - x) / 2 * L  # node 0 at the element bottom
        D1 = -2 / L * D
        D2 = D1 @ D1
        if homogeneous:
            E, dE, rho = np.ones_like(zeta), 0 * zeta, np.full_like(zeta, rho_m)
        else:
            E = (Ec + (Em - Ec) * zeta ** index) / Em
            dE = (Em - Ec) * index * zeta ** (index - 1) / Em
            rho = rho_c + (rho_m - rho_c) * zeta ** index
        f = nu / ((1 + nu) * (1 - 2 * nu))
        lam, mu, dlam, dmu = E * f, E / (2 * (1 + nu)), dE * f, dE / (2 * (1 + nu))
        c33, dc33 = lam + 2 * mu, dlam + 2 * dmu
        Ex = np.hstack([dg(mu) @ D2 + dg(dmu) @ D1 - dg(c33 * P * P + mu * Q * Q),
                        dg(-(lam + mu) * P * Q),
                        dg(dmu * P) + dg((mu + lam) * P) @ D1])
        Ey = np.hstack([dg(-(lam + mu) * P * Q),
                        dg(mu) @ D2 + dg(dmu) @ D1 - dg(c33 * Q * Q + mu * P * P),
                        dg(dmu * Q) + dg((mu + lam) * Q) @ D1])
        Ez = np.hstack([-dg((mu + lam) * P) @ D1 - dg(dlam * P),
                        -dg((mu + lam) * Q) @ D1 - dg(dlam * Q),
                        dg(c33) @ D2 + dg(dc33) @ D1 - dg(mu * (P * P + Q * Q))])
        tractions = [np.hstack([dg(mu) @ D1, Z0, dg(mu * P)]),
                     np.hstack([Z0, dg(mu) @ D1, dg(mu * Q)]),
                     np.hstack([dg(-lam * P), dg(-lam * Q), dg(c33) @ D1])]
        off = 3 * n1 * e
        for c, Eq in enumerate([Ex, Ey, Ez]):
            A[off + c * n1: off + (c + 1) * n1, off:off + 3 * n1] = Eq
            rho_rows[off + c * n1: off + (c + 1) * n1] = rho
        blocks.append((off, tractions, zeta, D1, lam, mu))
    row = lambda e, c, i: blocks[e][0] + c * n1 + i
    constraint = []  # (row, element, traction component, node, sign) groups
    for c in range(3):
        constraint.append(row(0, c, 0))
        constraint.append(row(K - 1, c, N))
        A[row(0, c, 0)] = 0
        A[row(0, c, 0), :3 * n1] = blocks[0][1][c][0]
        off = blocks[-1][0]
        A[row(K - 1, c, N)] = 0
        A[row(K - 1, c, N), off:off + 3 * n1] = blocks[-1][1][c][N]
        for e in range(K - 1):
            r = row(e, c, N)  # displacement continuity
            A[r] = 0
            A[r, row(e, c, N)], A[r, row(e + 1, c, 0)] = 1, -1
            r2 = row(e + 1, c, 0)  # traction continuity
            A[r2] = 0
            oa, ob = blocks[e][0], blocks[e + 1][0]
            A[r2, oa:oa + 3 * n1] += blocks[e][1][c][N]
            A[r2, ob:ob + 3 * n1] -= blocks[e + 1][1][c][0]
            constraint += [r, r2]
    rho_rows[constraint] = 0
    return A, rho_rows, blocks, n1, N, K, P, Q


def static(index, homogeneous=False, q0=LD(1e6), K=16, N=20):
    A, _, blocks, n1, N, K, P, Q = assemble(index, K=K, N=N, homogeneous=homogeneous)
    rhs = np.zeros(A.shape[0], dtype=LD)
    rhs[blocks[-1][0] + 2 * n1 + N] = -q0 / LD(70e9)
    Ad = A.astype(float)
    sol = np.linalg.solve(Ad, rhs.astype(float)).astype(LD)
    for _ in range(6):  # iterative refinement with long-double residuals
        sol += np.linalg.solve(Ad, (rhs - A @ sol).astype(float)).astype(LD)
    h = LD(2) / 100
    out = {}
    for zt in [0, 0.25, 0.5, 0.75, 1]:
        e = min(int(round(zt * K)), K - 1)
        off, _, zeta, D1, lam, mu = blocks[e]
        i = 0 if abs(float(zeta[0]) - zt) < 1e-12 else N
        U, V, W = (sol[off + j * n1: off + (j + 1) * n1] for j in range(3))
        sxx = (-(lam[i] + 2 * mu[i]) * P * U[i] - lam[i] * Q * V[i] + lam[i] * (D1 @ W)[i])
        out[zt] = (float(-W[i] * h * LD(1e6)), float(sxx * LD(70e9) * LD(1e-6)))
    return out


def frequencies(index, m, n, homogeneous=False, K=8, N=16, count=3):
    A, rho, *_ = assemble(index, m, n, K=K, N=N, homogeneous=homogeneous)
    lam = sl.eigvals(-A.astype(float), np.diag(rho.astype(float)))
    lam = lam[np.isfinite(lam)]
    lam = np.sort(lam[np.abs(lam.imag) < 1e-6 * np.abs(lam.real)].real)
    lam = lam[lam > 0]
    return (np.sqrt(lam * 70e9) / 0.02 / (2 * np.pi))[:count]


if __name__ == "__main__":
    for name, idx, hom in [("homogeneous", 0, True), ("graded n = 1", 1, False),
                           ("graded n = 5", 5, False)]:
        s = static(idx, hom)
        print(name)
        print("  centre deflection [um] z = 0, h/2, h:",
              " ".join(f"{s[z][0]:.12e}" for z in (0, 0.5, 1)))
        print("  centre sigma_xx [MPa] z = 0, h/4, h/2, 3h/4, h:",
              " ".join(f"{s[z][1]:.12e}" for z in (0, 0.25, 0.5, 0.75, 1)))
        for mn in [(1, 1), (2, 1), (3, 1)]:
            print(f"  {mn} lowest frequencies [Hz]:",
                  " ".join(f"{f:.10e}" for f in frequencies(idx, *mn, homogeneous=hom)))
