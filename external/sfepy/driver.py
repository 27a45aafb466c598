#!/usr/bin/env python3
"""SfePy driver for courant's 1D bar scenes (external/sfepy/).

Runs courant's ``fig1``, ``fig1_masses``, ``fig1_schemes`` (central difference), ``fig2``,
``fig2_reversed`` and ``layered`` (central difference) with SfePy's own explicit central
difference (``ts.central_difference``), and the spectra of ``fig6`` with its eigenvalue solver
(``eig.scipy``), and writes courant's results exchange format 2 (README, "Results exchange
format"), which ``courant score`` grades. See external/sfepy/README.md.

The model
---------
A 1D mesh of ``1_2`` cells; the field ``u`` with one component; ``dw_lin_elastic`` with the 1D
"stiffness tensor" D = [[E]]; ``de_mass`` with ``lumping = row_sum`` and ``beta`` blending the
consistent (0) and the lumped (1) mass (AMM(beta)); RMM(beta) through the linear solver
``ls.rmm``, which multiplies by the assembled M^-1 = A^-1 C A^-1 (courant's RMM(beta)). The
traction sigma0 H(t) at x = 0 (sigma0 = -1, H(0) = 1) is the nodal force F0 = -sigma0 A = +1
on node 0 (``dw_point_load``); the far end is fixed. The element stress is SfePy's
``ev_cauchy_stress`` (element average).

The geometry of each case (node positions, output times, the time step) is courant's own: the
driver reads it from the exact answers ``courant reference <scene>`` writes, so SfePy runs the
very mesh and step courant runs. The material per element is the scene's at the element
midpoint, as courant evaluates it (``MATERIALS``, external/driver_common.py): E = 16 -> 1 linear (fig2), 1 -> 16
(fig2_reversed), two layers E = 64, rho = 4 then E = rho = 1 (layered), E = rho = 1 otherwise;
SfePy gets it as a material function of the quadrature points (each point takes its element's
value).

THE TIME-LEVEL TRAP (why the stresses are taken in a step hook)
---------------------------------------------------------------
``Problem.solve()`` returns Variables holding the state ONE STEP BEFORE t1 for the
elastodynamics solvers: ``ElastodynamicsBaseTS.__call__`` breaks out of its loop after the last
step *before* ``vec = vect`` and returns ``vec`` (SfePy 2026.3: sfepy/solvers/ts_solvers.py:750
``if ts.nt >= 1: break``, :757 ``vec = vect``, :759 ``return vec``), and ``Problem.solve()``
then does ``variables.set_state(vec)`` (sfepy/discrete/problem.py:1603). The state passed to
``step_hook(pb, ts, variables)`` is the newly computed u^{n+1} with ``ts.time = t^{n+1}``, so
this driver records the profiles there, keyed by the integer step. ``--naive-readback`` writes
what the obvious read-back gives (every profile one step late), for the record.

Cost
----
``wall_s`` in results.toml is the median over ``--repeat`` runs (default 3) of the wall time of
``pb.solve()`` (SfePy's time loop; M and K are assembled in its first step); ``steps`` the steps
it took. With the default ``--out`` the driver also times courant on the same cases right then
(``courant run <scene>`` on one thread, median of as many runs) into ``courant_times.csv``.

Run
---
    bash external/sfepy/regenerate.sh                  # venv + pinned install + every set
    bash external/sfepy/regenerate.sh --out /tmp/fresh --compare-with external/sfepy/results
    bash external/sfepy/regenerate.sh --check          # + independent numpy models

Dependencies: numpy and sfepy; the ``courant`` binary for the geometry (``--courant PATH``).
"""
import argparse
import contextlib
import io
import math
import os
import statistics
import sys
import time

import numpy as np

import sfepy
from sfepy.base.base import output

# Quiet before importing the terms: otherwise SfePy prints (a bare print() to stdout plus a
# warning) that its optional JAX terms cannot be imported. Harmless: no JAX term is used here.
output.set_output(quiet=True)
with contextlib.redirect_stdout(io.StringIO()):
    from sfepy.base.conf import ProblemConf
    from sfepy.discrete import Problem
    from sfepy.discrete.fem import Mesh
    from sfepy.discrete.fem.meshio import UserMeshIO
    from sfepy.solvers import Solver

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

sys.dont_write_bytecode = True  # no __pycache__ beside the committed files
sys.path.insert(0, os.path.dirname(HERE))
from driver_common import (  # noqa: E402  (external/driver_common.py, shared by the drivers)
    AREA, SCENES, SIGMA0, compare_dirs, courant_cases, courant_walls,
    element_properties, write_courant_times, write_spectrum_set,
)

F0 = -SIGMA0 * AREA  # nodal force at node 0: outward normal is -x -> +1 along +x
BETA = 0.5           # the beta of fig1_masses' and fig6's AMM and RMM


# de_mass (lumping, beta), the RMM flag, and the results.toml label, per mass kind.
MASS_SETUP = {
    'lmm': dict(lumping='row_sum', beta=1.0, rmm=False, label='lumped'),
    'cmm': dict(lumping='none', beta=0.0, rmm=False, label='consistent'),
    'amm': dict(lumping='row_sum', beta=BETA, rmm=False, label=f'amm({BETA})'),
    'rmm': dict(lumping='row_sum', beta=BETA, rmm=True, label=f'rmm({BETA})'),
}


def scene_cases(scene, names):
    """[(case, mass kind)] SfePy runs: every case of fig1 and fig1_masses (the mass from the
    name's prefix); the central difference cases (`cd-*`, lumped) of the others."""
    out = []
    for name in names:
        if scene == 'fig1':
            out.append((name, 'lmm'))
        elif scene == 'fig1_masses':
            out.append((name, name.split('-')[0].rstrip('0123456789.')))
        elif name.startswith('cd-'):
            out.append((name, 'lmm'))
    return out


# ----------------------------------------------------------------------------
# SfePy problem description (the usual `define()` dict of a problem file).
# ----------------------------------------------------------------------------
def define(nodes, E, rho, kind, n_steps=0, t1=0.0, fixed='right', load_log=None):
    """Problem description of the bar on `nodes` with element moduli `E` and densities `rho`,
    mass `kind`, `n_steps` steps to t1; `fixed` names the supported end ('right', 'left' or
    None: free-free, for spectra).

    The three unknowns u, du, ddu (orders 0, 1, 2) are what SfePy's elastodynamics solvers
    expect: they pull M, C, K out of the diagonal blocks of the tangent matrix (see
    sfepy/examples/linear_elasticity/elastodynamic.py). dw_zero keeps the (absent) damping
    block alive.
    """
    ms = MASS_SETUP[kind]
    n_el = len(nodes) - 1
    h_min = float(np.diff(nodes).min())

    def mesh_hook(mesh, mode):
        """1D mesh: `1_2` line cells on the given nodes."""
        if mode == 'read':
            conn = np.c_[np.arange(n_el), np.arange(1, n_el + 1)]
            return Mesh.from_data('bar', nodes.reshape((-1, 1)), None,
                                  [conn.astype(np.int32)],
                                  [np.zeros(n_el, dtype=np.int32)], ['1_2'])

    def get_solid(ts, coors, mode=None, **kwargs):
        """E and rho at the quadrature points: each point takes its element's values (the
        points are inside their elements, so the element is the interval holding them)."""
        if mode == 'qp':
            e = np.clip(np.searchsorted(nodes, coors[:, 0]) - 1, 0, n_el - 1)
            return {'D': E[e].reshape((-1, 1, 1)), 'rho': rho[e].reshape((-1, 1, 1))}

    def get_load(ts, coors, mode=None, **kwargs):
        """Nodal force F0 H(t) at node 0, H(0) = 1, evaluated by SfePy in prestep_fun() at
        ts.time = t^{n+1} (and at t = 0 for a^0). In 1D the value must be a Python scalar."""
        if mode == 'special':
            if load_log is not None:
                load_log.append((ts.step, float(ts.time)))
            return {'val': F0 * (1.0 if ts.time >= 0.0 else 0.0)}

    filename_mesh = UserMeshIO(mesh_hook)
    x0, x1 = float(nodes[0]), float(nodes[-1])
    regions = {
        'Omega': 'all',
        'Left': ('vertices in (x < %.16e)' % (x0 + 1e-6 * h_min), 'vertex'),
        'Right': ('vertices in (x > %.16e)' % (x1 - 1e-6 * h_min), 'vertex'),
    }
    materials = {
        'solid': 'get_solid',
        'mass': ({'.lumping': ms['lumping'], '.beta': ms['beta']},),
        'load': 'get_load',
    }
    functions = {'get_solid': (get_solid,), 'get_load': (get_load,)}
    fields = {'displacement': ('real', 'vector', 'Omega', 1)}
    integrals = {'i': 2}   # exact for the mass of linear elements
    variables = {
        'u': ('unknown field', 'displacement', 0),
        'du': ('unknown field', 'displacement', 1),
        'ddu': ('unknown field', 'displacement', 2),
        'v': ('test field', 'displacement', 'u'),
        'dv': ('test field', 'displacement', 'du'),
        'ddv': ('test field', 'displacement', 'ddu'),
    }
    ebcs = ({} if fixed is None else
            {'fixed': ('Right' if fixed == 'right' else 'Left',
                       {'u.0': 0.0, 'du.0': 0.0, 'ddu.0': 0.0})})
    mass_term = 'de_mass.i.Omega(solid.rho, mass.lumping, mass.beta, ddv, ddu)'
    stiffness_term = 'dw_lin_elastic.i.Omega(solid.D, v, u)'
    equations = {
        'balance': mass_term + ' + dw_zero.i.Omega(dv, du) + ' + stiffness_term
        + ' = dw_point_load.0.Left(load.val, v)',
    }
    solvers = {
        'ls': ('ls.scipy_direct', {'use_presolve': True}),
        # ls.rmm: "solving" is the product with the directly assembled M^-1. With it,
        # ts.central_difference bypasses Newton and uses the residual of the u block only.
        'lsrmm': ('ls.rmm', {'rmm_term': mass_term}),
        # One Newton iteration solves M a = F - K u exactly; eps_a tiny so that it is never
        # skipped (it = 0 returns the old acceleration if ||r|| <= eps_a).
        'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-300, 'eps_r': 1.0,
                                  'ls_on': 1e100, 'lin_red': None}),
        'tscd': ('ts.central_difference', {
            't0': 0.0, 't1': t1, 'dt': None,
            # n_step counts time LEVELS (t0 included) and takes precedence over dt.
            'n_step': n_steps + 1,
            'is_linear': True,      # assemble M, K once
            'var_names': {'u': 'u', 'du': 'du', 'ddu': 'ddu'},
            'verbose': 0,
        }),
        # All modes of a small dense problem: scipy.linalg.eigh of (K, M).
        'eig': ('eig.scipy', {'method': 'eigh'}),
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


def problem(*args, **kwargs):
    conf = ProblemConf.from_dict(define(*args, **kwargs), sys.modules[__name__])
    return Problem.from_conf(conf)


def run_sfepy(scene, nodes, times, dt, kind, load_log=None):
    """One case: {t: (ts.time, u, stress)} recorded in the step hook at each output step, the
    state pb.solve() returns (one step before t1), and the wall time of pb.solve()."""
    E, rho = element_properties(scene, nodes)
    out_steps = {step: t for t, step in times}
    n_steps = max(out_steps)
    pb = problem(nodes, E, rho, kind, n_steps, n_steps * dt, load_log=load_log)
    profiles = {}

    def step_hook(pb, ts, variables):
        # Called right after step n -> n+1 with ts.time = t^{n+1} and `variables` holding u^{n+1}.
        if ts.step in out_steps:
            u = variables.get_state_parts()['u'].copy()
            sig = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg',
                              copy_materials=False, verbose=False).ravel().copy()
            profiles[out_steps[ts.step]] = (float(ts.time), u, sig)

    started = time.perf_counter()
    variables = pb.solve(step_hook=step_hook, save_results=False, verbose=False)
    wall = time.perf_counter() - started
    return dict(profiles=profiles, steps=n_steps, wall=wall,
                sfepy_dt=pb.get_solver().ts.dt,
                u_returned=variables.get_state_parts()['u'].copy())


def run_sfepy_naive(scene, nodes, times, dt, kind):
    """The trap, for the record: one solve to each output time t, the stress read back from the
    state ``pb.solve()`` returns (u(t - dt)), written as time t."""
    E, rho = element_properties(scene, nodes)
    profiles = {}
    for t, step in times:
        pb = problem(nodes, E, rho, kind, step, step * dt)
        variables = pb.solve(save_results=False, verbose=False)
        u = variables.get_state_parts()['u'].copy()
        profiles[t] = (t, u, E * np.diff(u) / np.diff(nodes))
    return dict(profiles=profiles, steps=max(s for _, s in times), wall=None)


# ----------------------------------------------------------------------------
# Spectra (fig6): SfePy's K and M, its eigenvalue solver.
# ----------------------------------------------------------------------------
SPECTRUM_MASSES = ('lmm', 'cmm', 'amm', 'rmm')


def sfepy_matrices(nodes, kind, fixed):
    """K and M (dense, free DOFs) of a uniform bar (E = rho = A = 1) assembled by SfePy; for RMM
    the inverse of the M^-1 that ls.rmm assembles (SfePy assembles only M^-1 for it)."""
    n = len(nodes) - 1
    pb = problem(nodes, np.ones(n), np.ones(n), kind, fixed=fixed)
    pb.time_update()
    k = pb.evaluate('dw_lin_elastic.i.Omega(solid.D, v, u)', mode='weak',
                    dw_mode='matrix', copy_materials=False, verbose=False)
    if MASS_SETUP[kind]['rmm']:
        rmm = Solver.any_from_conf(pb.get_solver_conf('lsrmm'), context=pb)
        m = np.linalg.inv(rmm.init_rmm(None).toarray())
    else:
        m = pb.evaluate('de_mass.i.Omega(solid.rho, mass.lumping, mass.beta, ddv, ddu)',
                        mode='weak', dw_mode='matrix', copy_materials=False,
                        verbose=False).toarray()
    return pb, k.toarray(), m


def sfepy_spectrum(n, ends, kind):
    """Every angular frequency of the bar (free-free: n + 1 modes, the rigid one first;
    fixed-free: node 0 fixed, n modes), from SfePy's eig.scipy (eigh) of its K and M."""
    nodes = np.linspace(0.0, 1.0, n + 1)
    pb, k, m = sfepy_matrices(nodes, kind, None if ends == 'free-free' else 'left')
    eig = Solver.any_from_conf(pb.get_solver_conf('eig'))
    values = np.sort(np.asarray(eig(k, m, n_eigs=None, eigenvectors=False)).real)
    return [math.sqrt(max(v, 0.0)) for v in values], k, m


def numpy_spectrum(n, ends, kind):
    """The independent model: K and M assembled here element by element, numpy's eigvalsh of
    M^-1/2 K M^-1/2 (M^-1 = A^-1 C A^-1 for RMM, methods.md §5)."""
    h = 1.0 / n
    size = n + 1
    k = np.zeros((size, size))
    m = np.zeros((size, size))
    c = np.zeros((size, size))
    f = h / (2.0 * (1.0 + 2.0 * BETA))
    for e in range(n):
        ix = np.ix_([e, e + 1], [e, e + 1])
        k[ix] += np.array([[1.0, -1.0], [-1.0, 1.0]]) / h
        mc = h / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
        ml = h / 2.0 * np.eye(2)
        m[ix] += {'lmm': ml, 'cmm': mc, 'amm': (1 - BETA) * mc + BETA * ml,
                  'rmm': ml}[kind]
        c[ix] += f * np.array([[2.0 + BETA, BETA - 1.0], [BETA - 1.0, 2.0 + BETA]])
    keep = slice(0, size) if ends == 'free-free' else slice(1, size)
    if kind == 'rmm':
        a = np.diag(m)
        minv = (c / a[:, None] / a[None, :])[keep, keep]
    else:
        minv = np.linalg.inv(m[keep, keep])
    w, v = np.linalg.eigh(minv)
    root = v @ np.diag(np.sqrt(w)) @ v.T
    values = np.sort(np.linalg.eigvalsh(root @ k[keep, keep] @ root))
    return [math.sqrt(max(x, 0.0)) for x in values]


def write_spectra(directory, courant, check):
    """fig6's spectra of every mass (`write_spectrum_set`) and their results.toml. Returns the
    largest difference from the numpy model's when `check`."""
    worst = write_spectrum_set(
        directory, courant, 'sfepy', [(k, k) for k in SPECTRUM_MASSES],
        lambda n, ends, kind: sfepy_spectrum(n, ends, kind)[0], numpy_spectrum, check)
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write(f'format = 2\ncode = "sfepy"\nversion = "{sfepy.__version__}"\n')
    return worst


# ----------------------------------------------------------------------------
# Independent numpy model (--check): central difference, half-step form.
# ----------------------------------------------------------------------------
def numpy_cd(scene, nodes, times, dt, kind, extra_steps=()):
    """Half-step central difference on the same bar, masses assembled here (methods.md §2, §5):
    a^0 = M^-1 F0, v^{1/2} = dt/2 a^0, u^{n+1} = u^n + dt v^{n+1/2},
    v^{n+3/2} = v^{n+1/2} + dt M^-1 (F0 - K u^{n+1}). Returns {step: nodal u, fixed node
    included} at the output steps and `extra_steps`."""
    E, rho = element_properties(scene, nodes)
    n = len(nodes) - 1
    h = np.diff(nodes)
    size = n + 1
    k = np.zeros((size, size))
    mc = np.zeros((size, size))
    ml = np.zeros((size, size))
    cr = np.zeros((size, size))
    for e in range(n):
        ix = np.ix_([e, e + 1], [e, e + 1])
        me = rho[e] * AREA * h[e]
        k[ix] += E[e] * AREA / h[e] * np.array([[1.0, -1.0], [-1.0, 1.0]])
        mc[ix] += me / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
        ml[ix] += me / 2.0 * np.eye(2)
        cr[ix] += me / (2.0 * (1.0 + 2.0 * BETA)) * np.array(
            [[2.0 + BETA, BETA - 1.0], [BETA - 1.0, 2.0 + BETA]])
    fr = slice(0, n)   # free DOFs: the fixed last node deleted
    if kind == 'lmm':
        minv = np.diag(1.0 / np.diag(ml)[fr])
    elif kind == 'cmm':
        minv = np.linalg.inv(mc[fr, fr])
    elif kind == 'amm':
        minv = np.linalg.inv((1.0 - BETA) * mc[fr, fr] + BETA * ml[fr, fr])
    else:
        a = np.diag(ml)
        minv = (cr / a[:, None] / a[None, :])[fr, fr]
    kf = k[fr, fr]
    f = np.zeros(n)
    f[0] = F0
    wanted = {s for _, s in times} | set(extra_steps)
    u = np.zeros(n)
    v = 0.5 * dt * (minv @ f)
    out = {}
    for step in range(1, max(wanted) + 1):
        u = u + dt * v
        v = v + dt * (minv @ (f - kf @ u))
        if step in wanted:
            out[step] = np.r_[u, 0.0]
    return out


def check_case(scene, nodes, times, dt, kind, res, load_log):
    """SfePy's run against the numpy model; returns (largest stress difference, report)."""
    h = np.diff(nodes)
    E, _ = element_properties(scene, nodes)
    n_steps = res['steps']
    ref = numpy_cd(scene, nodes, times, dt, kind, extra_steps=(n_steps - 1,))
    worst = 0.0
    lines = []
    for t, step in times:
        ts_time, u, sig = res['profiles'][t]
        d = float(np.abs(sig - E * np.diff(ref[step]) / h).max())
        worst = max(worst, d)
        lines.append(f'   t={t:.6g}: ts.time-t={ts_time - t:+.1e} '
                     f'max|sig_sfepy-sig_numpy|={d:.2e} '
                     f'max|ev_cauchy_stress-E du/h|={np.abs(sig - E * np.diff(u) / h).max():.1e}')
    ur = res['u_returned']
    lines.append(
        f'   pb.solve() state: |u-u_np(t1-dt)|={np.abs(ur - ref[n_steps - 1]).max():.1e} '
        f'|u-u_np(t1)|={np.abs(ur - ref[n_steps]).max():.1e}; load evaluated '
        f'{len(load_log)}x, t={load_log[0][1]:g}..{load_log[-1][1]:.10g}; '
        f'ts.dt-dt={res["sfepy_dt"] - dt:+.1e}')
    return worst, '\n'.join(lines)


# ----------------------------------------------------------------------------
# Output.
# ----------------------------------------------------------------------------
def write_set(directory, rows):
    os.makedirs(directory, exist_ok=True)
    for name, kind, nodes, dt, res in rows:
        with open(os.path.join(directory, f'{name}.csv'), 'w') as fd:
            fd.write('t,x_left,x_right,stress\n')
            for t in sorted(res['profiles']):
                for xl, xr, s in zip(nodes[:-1], nodes[1:], res['profiles'][t][2]):
                    # float(): numpy 2 reprs np.float64 as 'np.float64(...)'.
                    fd.write(f'{t!r},{float(xl)!r},{float(xr)!r},{float(s)!r}\n')
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write(f'format = 2\ncode = "sfepy"\nversion = "{sfepy.__version__}"\n')
        for name, kind, nodes, dt, res in rows:
            fd.write(f'\n[cases."{name}"]\n')
            fd.write('scheme = "central-difference"\n')
            fd.write(f'mass = "{MASS_SETUP[kind]["label"]}"\n')
            fd.write(f'dt = {float(dt)!r}\n')
            fd.write(f'elements = {len(nodes) - 1}\n')
            if res['wall'] is not None:
                fd.write(f'wall_s = {res["wall"]:.6g}\n')
                fd.write(f'steps = {res["steps"]}\n')


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--scene', choices=SCENES + ('fig6', 'all'), default='all')
    p.add_argument('--out', default=os.path.join(HERE, 'results'))
    p.add_argument('--courant', default=None,
                   help='the courant binary (default: cargo run --release --)')
    p.add_argument('--compare-with', metavar='DIR', default=None,
                   help='after writing, compare with the sets in DIR; exit 1 if they differ')
    p.add_argument('--tolerance', type=float, default=1e-10,
                   help='largest |stress difference| / |sigma0| (and relative frequency '
                        'difference) --compare-with accepts (default 1e-10)')
    p.add_argument('--check', action='store_true',
                   help='compare every run with an independent numpy model')
    p.add_argument('--repeat', type=int, default=3,
                   help='runs per case; wall_s is their median (default 3)')
    p.add_argument('--naive-readback', action='store_true',
                   help='read the state back after pb.solve() (one step late: the trap)')
    p.add_argument('--courant-times', default=None,
                   help="write courant's times on the same cases here; default: "
                        'external/sfepy/courant_times.csv when every set is regenerated in place')
    args = p.parse_args()
    courant = ([args.courant] if args.courant else
               ['cargo', 'run', '--quiet', '--release', '--manifest-path',
                os.path.join(ROOT, 'Cargo.toml'), '--'])
    scenes = SCENES if args.scene == 'all' else tuple(s for s in (args.scene,) if s != 'fig6')
    in_place = os.path.abspath(args.out) == os.path.join(HERE, 'results')
    times_file = args.courant_times or (os.path.join(HERE, 'courant_times.csv')
                                        if args.scene == 'all' and in_place
                                        and not args.naive_readback else None)
    started = time.perf_counter()
    worst = 0.0
    courant_rows = []
    written = []
    for scene in scenes:
        geometry = courant_cases(courant, scene)
        rows = []
        for name, kind in scene_cases(scene, sorted(geometry)):
            nodes, times, dt = geometry[name]
            if args.naive_readback:
                res = run_sfepy_naive(scene, nodes, times, dt, kind)
            else:
                runs = []
                for _ in range(max(1, args.repeat)):
                    load_log = []
                    runs.append((run_sfepy(scene, nodes, times, dt, kind, load_log), load_log))
                res, load_log = runs[-1]
                res['wall'] = statistics.median(r['wall'] for r, _ in runs)
            msg = (f'{scene}/{name}: mass={kind} dt={dt!r} steps={res["steps"]}'
                   + (f' wall_s={res["wall"]:.4f}' if res['wall'] is not None else ''))
            if args.check and not args.naive_readback:
                d, report = check_case(scene, nodes, times, dt, kind, res, load_log)
                worst = max(worst, d)
                msg += f' check max|sfepy-numpy|={d:.2e}\n' + report
            print(msg, flush=True)
            rows.append((name, kind, nodes, dt, res))
        write_set(os.path.join(args.out, scene), rows)
        written.append(scene)
        if times_file:
            walls = courant_walls(courant, scene, args.repeat)
            courant_rows += [(scene, name, *walls[name]) for name, *_ in rows]
    if args.scene in ('all', 'fig6') and not args.naive_readback:
        worst = max(worst, write_spectra(os.path.join(args.out, 'eigen', 'fig6'), courant,
                                         args.check))
        written.append(os.path.join('eigen', 'fig6'))
    if times_file:
        courant_rows = [(s, c, steps, w) for s, c, w, steps in courant_rows]
        write_courant_times(times_file, courant_rows, args.repeat)
        print(f"courant's times: {times_file}")
    print(f'total wall {time.perf_counter() - started:.2f} s')
    if args.check:
        print(f'check: largest difference from the numpy models {worst:.2e}')
        if worst > 1e-9:
            sys.exit(1)
    if args.compare_with:
        bad = [b for d in written for b in compare_dirs(
            os.path.join(args.out, d), os.path.join(args.compare_with, d), args.tolerance)]
        for b in bad:
            print(b, file=sys.stderr)
        if bad:
            sys.exit(1)
        print(f'compare: {args.out} equals {args.compare_with} (wall_s aside; stresses '
              f'within {args.tolerance:g} |sigma0|)')


if __name__ == '__main__':
    main()
