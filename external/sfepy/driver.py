#!/usr/bin/env python3
"""SfePy driver for courant's ``fig1`` and ``fig1_masses`` scenes (external/sfepy/).

Writes courant's results exchange format 1 (README, "Results exchange format"), which
``courant score`` grades against the exact solution.  See external/sfepy/README.md.

What it reproduces
------------------
The seed paper's Fig. 1 bar, run with SfePy's own explicit central difference
(``ts.central_difference``) instead of courant's solver:

* homogeneous free-fixed bar, L = A = rho = E = 1 (c = 1, transit T = 1),
  N = 100 two-node linear elements (``1_2`` cells of a 1D SfePy mesh);
* Heaviside traction sigma(0, t) = sigma0 H(t), sigma0 = -1, H(0) = 1, applied as
  the nodal force F0 = -sigma0 A = +1 at node 0 (``dw_point_load``); u(L, t) = 0;
* scene ``fig1``: lumped mass at Co = 1, 0.5, 0.1 (cases ``co1``, ``co0.5``,
  ``co0.1``);
* scene ``fig1_masses``: LMM, CMM, AMM(1/2) and RMM(1/2) at 1 and 1/2 of each
  mass's critical Courant number (1, 1/sqrt(3), sqrt(2/3), sqrt(2/3)); cases
  ``lmm-co1``, ``lmm-co0.5``, ``cmm-co1``, ... ``rmm0.5-co0.5``.

The mass matrix is SfePy's ``de_mass`` term: ``beta`` blends the consistent
(beta = 0) and the row-sum lumped (beta = 1) mass.  RMM uses SfePy's ``ls.rmm``
linear "solver", which multiplies by M^-1 = A^-1 C A^-1 (A = lumped mass,
C = sum_e A_e AMM_e(beta)^-1 A_e), i.e. exactly courant's RMM(beta).

Time step: dt = t_out / ceil(t_out / dt_nominal * (1 - 1e-9)) with t_out = 0.5
and dt_nominal = Co_abs h / c; every case runs to t = 1.5 = 3 * 0.5, so both
output times are hit exactly (steps n and 3n).

Outputs (per scene directory ``<out>/<scene>/``, default out: results/ beside
this file):
* ``<case>.csv`` with header ``t,x_left,x_right,stress``: one row per element
  per output time (0.5 and 1.5), the element's end coordinates and its stress
  sigma_e^n = E (u_{e+1}^n - u_e^n) / h at exactly that time level;
* ``results.toml``: format 1, code, SfePy version and per case scheme, mass,
  dt, elements.

THE TIME-LEVEL TRAP (why the stresses are taken in a step hook)
---------------------------------------------------------------
``Problem.solve()`` returns Variables holding the state ONE STEP BEFORE t1 for
the elastodynamics solvers: ``ElastodynamicsBaseTS.__call__`` breaks out of its
loop after the last step *before* ``vec = vect`` and returns ``vec``
(SfePy 2026.3: sfepy/solvers/ts_solvers.py:750 ``if ts.nt >= 1: break``,
:757 ``vec = vect``, :759 ``return vec``), and ``Problem.solve()`` then does
``variables.set_state(vec)`` (sfepy/discrete/problem.py:1603).  Reading u from the
return value "the obvious way" thus gives u(t1 - dt).  The state passed to
``step_hook(pb, ts, variables)`` (called from ``poststep_fun``) is the newly
computed u^{n+1} with ``ts.time = t^{n+1}``, so this driver records the
profiles there, keyed by the integer step number.  SfePy's own scheme is the
standard one: a^0 from F(t=0) (H(0) = 1 with a constant load), and a^{n+1} from
F(t^{n+1}) and u^{n+1}.

Run
---
    bash external/sfepy/regenerate.sh         # venv + pinned install + both scenes
    # or by hand:
    python3 -m venv venv
    venv/bin/pip install -r external/sfepy/requirements.txt
    # (PyPI has only the sdist for Linux: pip compiles SfePy's C extensions with
    # scikit-build/cmake/ninja/Cython from PyPI and the system gcc; needs the
    # Python headers.  About 1.7-2.5 min on 2 cores.)
    venv/bin/python driver.py                 # both scenes into results/
    venv/bin/python driver.py --scene fig1 --out out
    venv/bin/python driver.py --check         # + numpy CD cross-check table
    venv/bin/python driver.py --compare-with results --out /tmp/fresh
                                              # regenerate, then compare with
                                              # the committed results (CI)
    venv/bin/python driver.py --naive-readback --scene fig1 --out DIR
                                              # the trap reproduced: profiles
                                              # read back after pb.solve()

``--naive-readback`` writes what a new user gets reading the state back after
``pb.solve()`` (one solve per output time): every profile one step late.
``courant score`` reports it as a time-level offset of -1 step
(tests/data/sfepy_naive_readback/ holds its output for fig1).

``--compare-with DIR`` compares the freshly written files with those in DIR
(same rows, times and element ends; stresses within ``--tolerance``, default
1e-10 |sigma0|) and exits 1 when they differ.

``--check`` re-runs every case with an independent numpy central difference
(half-step form, same masses) and prints max |sfepy - numpy| per output time,
the deviation from d'Alembert for lumped Co = 1, the offset of the value
``pb.solve()`` returns, and the times at which SfePy evaluated the load.
Dependencies: numpy and sfepy only.
"""
import argparse
import contextlib
import io
import math
import os
import sys
import time

import numpy as np

import sfepy
from sfepy.base.base import output

# Quiet before importing the terms: otherwise SfePy prints (a bare print() to
# stdout plus a warning) that its optional JAX terms (sfepy/terms/terms_jax.py)
# cannot be imported.  Harmless: no JAX term is used here.
output.set_output(quiet=True)
with contextlib.redirect_stdout(io.StringIO()):
    from sfepy.base.conf import ProblemConf
    from sfepy.discrete import Problem
    from sfepy.discrete.fem import Mesh
    from sfepy.discrete.fem.meshio import UserMeshIO

# ----------------------------------------------------------------------------
# The bar (normalised units, methods.md §1-2).
# ----------------------------------------------------------------------------
L = 1.0          # length
AREA = 1.0       # cross-section
RHO = 1.0        # density
E = 1.0          # Young's modulus
C = math.sqrt(E / RHO)
N_EL = 100       # elements
H = L / N_EL     # element length
SIGMA0 = -1.0    # traction at x = 0 (compressive)
F0 = -SIGMA0 * AREA  # nodal force at node 0: outward normal is -x -> +1 along +x
T_OUT = 0.5      # first profile time; dt is fitted to it
PROFILE_TIMES = (0.5, 1.5)  # both multiples of T_OUT

# Critical Courant numbers of the masses (methods.md §5), beta = 1/2.
BETA = 0.5
CO_CRIT = {
    'lmm': 1.0,
    'cmm': 1.0 / math.sqrt(3.0),
    'amm': math.sqrt((1.0 + 2.0 * BETA) / 3.0),
    'rmm': math.sqrt((1.0 + 2.0 * BETA) / 3.0),
}
# SfePy's de_mass (lumping, beta) per mass kind, and the results.toml label.
MASS_SETUP = {
    'lmm': dict(lumping='row_sum', beta=1.0, rmm=False, label='lumped'),
    'cmm': dict(lumping='none', beta=0.0, rmm=False, label='consistent'),
    'amm': dict(lumping='row_sum', beta=BETA, rmm=False, label=f'amm({BETA})'),
    'rmm': dict(lumping='row_sum', beta=BETA, rmm=True, label=f'rmm({BETA})'),
}


def fitted_dt(co_abs, t_out=T_OUT):
    """dt <= co_abs h / c that hits t_out exactly (methods.md §1)."""
    dt_nominal = co_abs * H / C
    n = math.ceil(t_out / dt_nominal * (1.0 - 1e-9))
    return t_out / n, n


def scene_cases(scene):
    """[(case name, mass kind, absolute Courant number)] of a scene."""
    if scene == 'fig1':
        return [(f'co{co:g}', 'lmm', co) for co in (1.0, 0.5, 0.1)]
    elif scene == 'fig1_masses':
        out = []
        for kind in ('lmm', 'cmm', 'amm', 'rmm'):
            prefix = kind if kind in ('lmm', 'cmm') else f'{kind}{BETA:g}'
            for co in (1.0, 0.5):
                out.append((f'{prefix}-co{co:g}', kind, co * CO_CRIT[kind]))
        return out
    raise ValueError(f'unknown scene {scene!r}')


# ----------------------------------------------------------------------------
# SfePy problem description (the usual `define()` dict of a problem file).
# ----------------------------------------------------------------------------
def define(kind, n_steps, t1, load_log=None):
    """Problem description of the bar for mass `kind`, `n_steps` steps to t1.

    The three unknowns u, du, ddu (orders 0, 1, 2) are what SfePy's
    elastodynamics solvers expect: they pull M, C, K out of the diagonal
    blocks of the tangent matrix (see sfepy/examples/linear_elasticity/
    elastodynamic.py).  dw_zero keeps the (absent) damping block alive.
    """
    ms = MASS_SETUP[kind]

    def mesh_hook(mesh, mode):
        """1D mesh: N_EL `1_2` line cells on [0, L]."""
        if mode == 'read':
            coors = np.linspace(0.0, L, N_EL + 1).reshape((-1, 1))
            conn = np.c_[np.arange(N_EL), np.arange(1, N_EL + 1)]
            return Mesh.from_data('bar', coors, None, [conn.astype(np.int32)],
                                  [np.zeros(N_EL, dtype=np.int32)], ['1_2'])

    def get_load(ts, coors, mode=None, **kwargs):
        """Nodal force F0 H(t) at node 0, H(0) = 1.

        Special ('.val') parameter, evaluated by SfePy in prestep_fun() at
        ts.time = t^{n+1} before a^{n+1} is computed (and at t = 0 for a^0).
        In 1D the point-load value must be a Python scalar: SfePy's shape
        check of the '.: N' argument with N = 1 accepts only numbers.
        """
        if mode == 'special':
            if load_log is not None:
                load_log.append((ts.step, float(ts.time)))
            return {'val': F0 * (1.0 if ts.time >= 0.0 else 0.0)}

    filename_mesh = UserMeshIO(mesh_hook)

    regions = {
        'Omega': 'all',
        'Left': ('vertices in (x < %.16e)' % (1e-6 * H), 'vertex'),
        'Right': ('vertices in (x > %.16e)' % (L - 1e-6 * H), 'vertex'),
    }
    materials = {
        'solid': ({
            'D': np.array([[E]]),          # 1D "stiffness tensor": sigma = E eps
            'rho': RHO,
            '.lumping': ms['lumping'],     # 'row_sum' or 'none'
            '.beta': ms['beta'],           # 0 = consistent, 1 = lumped
        },),
        'load': 'get_load',
    }
    functions = {'get_load': (get_load,)}
    fields = {'displacement': ('real', 'vector', 'Omega', 1)}  # 1 component in 1D
    integrals = {'i': 2}   # exact for the mass of linear elements
    variables = {
        'u': ('unknown field', 'displacement', 0),
        'du': ('unknown field', 'displacement', 1),
        'ddu': ('unknown field', 'displacement', 2),
        'v': ('test field', 'displacement', 'u'),
        'dv': ('test field', 'displacement', 'du'),
        'ddv': ('test field', 'displacement', 'ddu'),
    }
    ebcs = {'fixed': ('Right', {'u.0': 0.0, 'du.0': 0.0, 'ddu.0': 0.0})}

    mass_term = 'de_mass.i.Omega(solid.rho, solid.lumping, solid.beta, ddv, ddu)'
    equations = {
        'balance': mass_term + """
            + dw_zero.i.Omega(dv, du)
            + dw_lin_elastic.i.Omega(solid.D, v, u)
            = dw_point_load.0.Left(load.val, v)""",
    }
    solvers = {
        'ls': ('ls.scipy_direct', {'use_presolve': True}),
        # ls.rmm: "solving" is the product with the directly assembled M^-1.
        # With it, ts.central_difference bypasses Newton (NoNLS) and uses the
        # residual of the u block only.
        'lsrmm': ('ls.rmm', {'rmm_term': mass_term}),
        # One Newton iteration solves M a = F - K u exactly.  eps_a tiny so that
        # the iteration is never skipped (it=0 returns the old acceleration if
        # ||r|| <= eps_a), line search off, no precision warnings.
        'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-300, 'eps_r': 1.0,
                                  'ls_on': 1e100, 'lin_red': None}),
        'tscd': ('ts.central_difference', {
            't0': 0.0,
            't1': t1,
            'dt': None,
            # n_step counts time LEVELS (t0 included): times = linspace(t0, t1,
            # n_step).  Give it explicitly; the default n_step = 10 would
            # otherwise take precedence over dt.
            'n_step': n_steps + 1,
            'is_linear': True,      # assemble M, K once
            'var_names': {'u': 'u', 'du': 'du', 'ddu': 'ddu'},
            'verbose': 0,
        }),
    }
    options = {
        'ts': 'tscd',
        'nls': 'newton',
        'ls': 'lsrmm' if ms['rmm'] else 'ls',
        'active_only': True,        # fixed DOF removed (courant deletes it too)
        'auto_transform_equations': False,
        'output_dir': '.',
    }
    return locals()


def run_sfepy(kind, co_abs, load_log=None):
    """Run one case with SfePy.  Returns dict with the profiles per output time.

    profiles[t] = (ts.time, u_nodes, stress_elements) recorded in the step hook
    at integer step round(t / dt), i.e. the state u^n with t^n = t.
    """
    dt, n_out = fitted_dt(co_abs)
    ratio = [round(t / T_OUT) for t in PROFILE_TIMES]
    assert all(abs(r * T_OUT - t) < 1e-12 for r, t in zip(ratio, PROFILE_TIMES))
    out_steps = {r * n_out: t for r, t in zip(ratio, PROFILE_TIMES)}
    n_steps = max(out_steps)
    t1 = n_steps * dt

    conf = ProblemConf.from_dict(define(kind, n_steps, t1, load_log),
                                 sys.modules[__name__])
    pb = Problem.from_conf(conf)

    profiles = {}

    def step_hook(pb, ts, variables):
        # Called from poststep_fun() right after step n -> n+1 with ts.time =
        # t^{n+1} and `variables` holding u^{n+1}: the correct time level.
        if ts.step in out_steps:
            # Full nodal vector (the fixed node N included, = 0).
            u = variables.get_state_parts()['u'].copy()
            # Element stresses with SfePy's own term (constant in each linear
            # element, so el_avg is the element value).
            sig = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)',
                              mode='el_avg', copy_materials=False,
                              verbose=False).ravel().copy()
            profiles[out_steps[ts.step]] = (float(ts.time), u, sig)

    variables = pb.solve(step_hook=step_hook, save_results=False,
                         verbose=False)
    # What pb.solve() returns: NOT u(t1) but u(t1 - dt), see module docstring.
    u_returned = variables.get_state_parts()['u'].copy()

    coors = pb.domain.mesh.coors[:, 0]
    conn = pb.domain.mesh.get_conn('1_2')
    return dict(dt=dt, n_steps=n_steps, sfepy_dt=pb.get_solver().ts.dt,
                x_left=coors[conn[:, 0]], x_right=coors[conn[:, 1]],
                profiles=profiles, u_returned=u_returned)


def run_sfepy_naive(kind, co_abs):
    """The trap, for the record: one solve to each output time t, the stress
    read back from the state ``pb.solve()`` returns, written as time t.  SfePy
    returns the state one step before t (module docstring), so every profile
    is u(t - dt) labelled t.
    """
    dt, n_out = fitted_dt(co_abs)
    profiles = {}
    for t in PROFILE_TIMES:
        n_steps = round(t / dt)
        conf = ProblemConf.from_dict(define(kind, n_steps, n_steps * dt),
                                     sys.modules[__name__])
        pb = Problem.from_conf(conf)
        variables = pb.solve(save_results=False, verbose=False)
        u = variables.get_state_parts()['u'].copy()
        profiles[t] = (t, u, E * np.diff(u) / H)
        coors = pb.domain.mesh.coors[:, 0]
        conn = pb.domain.mesh.get_conn('1_2')
    return dict(dt=dt, n_steps=round(PROFILE_TIMES[-1] / dt),
                sfepy_dt=dt, x_left=coors[conn[:, 0]],
                x_right=coors[conn[:, 1]], profiles=profiles, u_returned=None)


# ----------------------------------------------------------------------------
# Independent numpy reference (for --check): half-step central difference.
# ----------------------------------------------------------------------------
def numpy_cd(kind, dt, n_steps, out_steps):
    """Central difference, half-step form, free nodes 0..N-1 (node N fixed).

    a^0 = M^-1 (F - K u^0), v^{1/2} = dt/2 a^0,
    u^{n+1} = u^n + dt v^{n+1/2}, a^{n+1} = M^-1 (F - K u^{n+1}),
    v^{n+3/2} = v^{n+1/2} + dt a^{n+1};  F = F0 e_0 (H(t) = 1 for t >= 0).
    Returns {step: nodal u (N + 1 values, fixed node included)}.
    """
    n = N_EL + 1
    m_e, k_e = RHO * AREA * H, E * AREA / H
    K = np.zeros((n, n))
    MC = np.zeros((n, n))
    ML = np.zeros((n, n))
    CR = np.zeros((n, n))
    f = m_e / (2.0 * (1.0 + 2.0 * BETA))
    for e in range(N_EL):
        ix = np.ix_([e, e + 1], [e, e + 1])
        K[ix] += k_e * np.array([[1.0, -1.0], [-1.0, 1.0]])
        MC[ix] += m_e / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
        ML[ix] += m_e / 2.0 * np.eye(2)
        CR[ix] += f * np.array([[2.0 + BETA, BETA - 1.0],
                                [BETA - 1.0, 2.0 + BETA]])
    fr = slice(0, N_EL)   # free DOFs: rows/columns of the fixed node deleted
    if kind == 'lmm':
        minv = np.diag(1.0 / np.diag(ML)[fr])
    elif kind == 'cmm':
        minv = np.linalg.inv(MC[fr, fr])
    elif kind == 'amm':
        minv = np.linalg.inv((1.0 - BETA) * MC[fr, fr] + BETA * ML[fr, fr])
    elif kind == 'rmm':
        ainv = 1.0 / np.diag(ML)
        minv = (ainv[:, None] * CR * ainv[None, :])[fr, fr]   # A^-1 C A^-1
    Kf = K[fr, fr]
    F = np.zeros(N_EL)
    F[0] = F0

    u = np.zeros(N_EL)
    a = minv @ (F - Kf @ u)
    v = 0.5 * dt * a
    out = {}
    for step in range(1, n_steps + 1):
        u = u + dt * v
        a = minv @ (F - Kf @ u)
        v = v + dt * a
        if step in out_steps:
            out[step] = np.r_[u, 0.0]
    return out


def exact_stress(x_left, x_right, t):
    """d'Alembert element averages (methods.md §3), homogeneous free-fixed bar."""
    def prim(x):  # integral of sigma(., t) from 0 to x
        s = np.zeros_like(x)
        for k in range(20):
            sg = (-1.0) ** k
            # H(t - (2kL + x)/c): active for x < c t - 2kL
            a1 = C * t - 2 * k * L
            s += sg * np.clip(np.minimum(x, a1), 0.0, None) * (a1 > 0)
            # H(t - (2(k+1)L - x)/c): active for x > 2(k+1)L - c t
            a2 = 2 * (k + 1) * L - C * t
            s += sg * np.clip(x - np.maximum(a2, 0.0), 0.0, None)
        return SIGMA0 * s
    return (prim(x_right) - prim(x_left)) / (x_right - x_left)


# ----------------------------------------------------------------------------
# Output.
# ----------------------------------------------------------------------------
def write_csv(path, res):
    with open(path, 'w') as fd:
        fd.write('t,x_left,x_right,stress\n')
        for t in PROFILE_TIMES:
            sig = res['profiles'][t][2]
            for xl, xr, s in zip(res['x_left'], res['x_right'], sig):
                # float(): numpy 2 reprs np.float64 as 'np.float64(...)'.
                fd.write(f'{t!r},{float(xl)!r},{float(xr)!r},{float(s)!r}\n')


def write_toml(path, rows):
    with open(path, 'w') as fd:
        fd.write('format = 1\n')
        fd.write('code = "sfepy"\n')
        fd.write(f'version = "{sfepy.__version__}"\n')
        for name, kind, res in rows:
            fd.write(f'\n[cases."{name}"]\n')
            fd.write('scheme = "central-difference"\n')
            fd.write(f'mass = "{MASS_SETUP[kind]["label"]}"\n')
            fd.write(f'dt = {float(res["dt"])!r}\n')
            fd.write(f'elements = {N_EL}\n')


def compare_dirs(fresh, committed, tolerance):
    """Max |stress difference| per file between two result directories; the
    rows (t, x_left, x_right) must be identical.  Returns the failures."""
    failures = []
    names = sorted(n for n in os.listdir(committed) if n.endswith('.csv'))
    if names != sorted(n for n in os.listdir(fresh) if n.endswith('.csv')):
        return [f'{fresh}: files differ from {committed}']
    for name in names:
        a = np.genfromtxt(os.path.join(fresh, name), delimiter=',', names=True)
        b = np.genfromtxt(os.path.join(committed, name), delimiter=',',
                          names=True)
        keys = ('t', 'x_left', 'x_right')
        if a.shape != b.shape or any(not np.array_equal(a[k], b[k])
                                     for k in keys):
            failures.append(f'{name}: rows differ')
            continue
        diff = float(np.abs(a['stress'] - b['stress']).max()) / abs(SIGMA0)
        status = 'ok' if diff <= tolerance else 'DIFFERS'
        print(f'  {name}: max |stress - committed| / |sigma0| = {diff:.2e} '
              f'({status}, tolerance {tolerance:g})')
        if diff > tolerance:
            failures.append(f'{name}: {diff:.2e} > {tolerance:g}')
    return failures


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--scene', choices=['fig1', 'fig1_masses', 'all'],
                        default='all')
    parser.add_argument('--out', default=os.path.join(here, 'results'),
                        help='output root directory (default: results/ '
                             'beside this file)')
    parser.add_argument('--check', action='store_true',
                        help='compare with an independent numpy CD')
    parser.add_argument('--naive-readback', action='store_true',
                        help='read the state back after pb.solve() (one step '
                             'late: the trap, for the record)')
    parser.add_argument('--compare-with', metavar='DIR',
                        help='after writing, compare with the result '
                             'directories in DIR; exit 1 if they differ')
    parser.add_argument('--tolerance', type=float, default=1e-10,
                        help='largest |stress difference| / |sigma0| '
                             'accepted by --compare-with (default 1e-10)')
    args = parser.parse_args()

    scenes = ['fig1', 'fig1_masses'] if args.scene == 'all' else [args.scene]
    t_start = time.perf_counter()
    failures = []
    for scene in scenes:
        t_scene = time.perf_counter()
        odir = os.path.join(args.out, scene)
        os.makedirs(odir, exist_ok=True)
        rows = []
        for name, kind, co_abs in scene_cases(scene):
            load_log = []
            tc = time.perf_counter()
            if args.naive_readback:
                res = run_sfepy_naive(kind, co_abs)
            else:
                res = run_sfepy(kind, co_abs, load_log)
            tc = time.perf_counter() - tc
            write_csv(os.path.join(odir, f'{name}.csv'), res)
            rows.append((name, kind, res))
            msg = (f'{scene}/{name}: mass={kind} Co={res["dt"] / H * C:.10g} '
                   f'dt={res["dt"]!r} steps={res["n_steps"]} wall={tc:.2f}s')
            if args.check and not args.naive_readback:
                msg += '\n' + check_case(kind, res, load_log)
            print(msg, flush=True)
        write_toml(os.path.join(odir, 'results.toml'), rows)
        print(f'{scene}: wall {time.perf_counter() - t_scene:.2f} s', flush=True)
        if args.compare_with:
            failures += compare_dirs(odir, os.path.join(args.compare_with, scene),
                                     args.tolerance)
    print(f'total wall {time.perf_counter() - t_start:.2f} s')
    if failures:
        print('differs from the committed results:\n  ' + '\n  '.join(failures))
        sys.exit(1)


def check_case(kind, res, load_log):
    """Cross-check one SfePy run; returns a printable report."""
    dt, n_steps = res['dt'], res['n_steps']
    out_steps = {round(t / dt): t for t in PROFILE_TIMES}
    ref = numpy_cd(kind, dt, n_steps, list(out_steps) + [n_steps - 1])
    lines = []
    for step, t in sorted(out_steps.items()):
        ts_time, u, sig = res['profiles'][t]
        sig_np = E * np.diff(ref[step]) / H
        sig_u = E * np.diff(u) / H          # stress from SfePy's nodal u
        line = (f'   t={t}: ts.time-t={ts_time - t:+.1e} '
                f'max|sig_sfepy-sig_numpy|={np.abs(sig - sig_np).max():.2e} '
                f'max|u_sfepy-u_numpy|={np.abs(u - ref[step]).max():.2e} '
                f'max|ev_cauchy_stress-E du/h|={np.abs(sig - sig_u).max():.1e}')
        if kind == 'lmm':
            ex = exact_stress(res['x_left'], res['x_right'], t)
            line += f' max|sig-exact|={np.abs(sig - ex).max():.2e}'
        lines.append(line)
    # The trap: pb.solve()'s returned state equals the numpy state at N-1.
    ur = res['u_returned']
    lines.append(
        f'   pb.solve() state: |u-u_np(t1-dt)|={np.abs(ur - ref[n_steps - 1]).max():.1e}'
        f' |u-u_np(t1)|={np.abs(ur - ref[n_steps]).max():.1e}'
        f'; load evaluated {len(load_log)}x at steps {load_log[0][0]}..'
        f'{load_log[-1][0]}, t={load_log[0][1]:g}..{load_log[-1][1]:.10g}'
        f'; sfepy ts.dt-dt={res["sfepy_dt"] - dt:+.1e}')
    return '\n'.join(lines)


if __name__ == '__main__':
    main()
