#!/usr/bin/env python3
"""OpenSees driver for courant's 1D bar scenes (external/opensees/).

Runs each case of courant's ``fig1``, ``fig1_masses`` (LMM and CMM), ``fig1_schemes`` (central
difference), ``fig2``, ``fig2_reversed`` and ``layered`` (central difference) scenes with
OpenSees' own explicit integrators and writes courant's results exchange format 2 (README,
"Results exchange format"), which ``courant score`` grades. See external/opensees/README.md.

The model
---------
``model('basic', '-ndm', 1, '-ndf', 1)``; one node per mesh node, ``Truss`` elements with an
``Elastic`` uniaxial material of the element's modulus, area A and ``-rho rho A`` (lumped) or
``-cMass 1`` as well (consistent); the far end fixed; the traction sigma0 H(t) at x = 0 applied
as the nodal force F0 = -sigma0 A on node 0. The element stress is ``axialForce / A``.

The case geometry (node positions, output times, the time step) is courant's own: the driver
reads it from the exact answers ``courant reference <scene>`` writes (their element ends, times
and ``dt`` in results.toml), so OpenSees runs the very mesh and step courant runs. The material
per element is the scene's, evaluated at the element midpoint as courant does (``MATERIALS`` in
external/driver_common.py): E = 16 -> 1 linear (fig2), 1 -> 16 (fig2_reversed), two layers E = 64, rho = 4 then
E = rho = 1 (layered), E = rho = 1 otherwise.

Integrators and starts
----------------------
* ``CentralDifference`` (``integrator('CentralDifference')``): the three-level form with
  u^-1 = u^0 and the full F(0), so the first step gives u^1 = dt^2 M^-1 F0, twice the half-step
  start's (an extra impulse F0 dt / 2). *Corrected*: the load's time series gives F(0) = F0 / 2
  and F(t) = F0 after (``timeSeries('Path', ...)``), which makes the first step the half-step
  start's.
* ``ExplicitDifference`` (``integrator('ExplicitDifference')``): its first step is
  u^1 = u^0 + dt^2 a^0 with the committed a^0, which is 0 ("assuming Ut-1 = Ut"): no impulse at
  t = 0. *Corrected*: a^0 = M^-1 F0 / 2 set with ``setNodeAccel(node, 1, a, '-commit')`` (without
  ``-commit`` OpenSees overwrites it before the first step), so u^1 = dt^2/2 M^-1 F0, the
  half-step start's.

Each integrator is written twice: as it comes, and corrected (``--start as-it-comes|corrected``),
into ``<out>/<integrator>-<start>/<scene>/``.

Run
---
    bash external/opensees/regenerate.sh               # venv + pinned install + every set
    bash external/opensees/regenerate.sh --out /tmp/fresh --compare-with external/opensees/results
    bash external/opensees/regenerate.sh --out /tmp/x --check --repeat 1
        # every run against an independent numpy central difference with that start's first
        # impulse (as it comes and corrected), every fig6 spectrum against numpy's eigenvalues

Cost: ``wall_s`` in results.toml is the median over ``--repeat`` runs (default 3) of the wall
time of the ``analyze`` calls; ``steps`` the steps. With the default ``--out`` the driver also
times courant on the same cases right after (``courant_times.csv``).

Dependencies: numpy and openseespy only; the ``courant`` binary for the geometry
(``--courant PATH``, default ``cargo run --release --``).
"""
import argparse
import math
import os
import statistics
import sys
import time

import numpy as np

import openseespy.opensees as ops

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

sys.dont_write_bytecode = True  # no __pycache__ beside the committed files
sys.path.insert(0, os.path.dirname(HERE))
from driver_common import (  # noqa: E402  (external/driver_common.py, shared by the drivers)
    AREA, SCENES, SIGMA0, compare_dirs, courant_cases, courant_walls,
    element_properties, write_courant_times, write_spectrum_set,
)


INTEGRATORS = {
    'central-difference': 'CentralDifference',
    'explicit-difference': 'ExplicitDifference',
}
STARTS = ('as-it-comes', 'corrected')


def scene_cases(scene, names):
    """The cases of `scene` OpenSees runs, with their mass: every case of fig1; the LMM and CMM
    cases of fig1_masses (OpenSees' Truss has no averaged or reciprocal mass); the central
    difference cases of the others."""
    out = []
    for name in names:
        if scene == 'fig1':
            out.append((name, 'lumped'))
        elif scene == 'fig1_masses':
            if name.startswith('lmm-'):
                out.append((name, 'lumped'))
            elif name.startswith('cmm-'):
                out.append((name, 'consistent'))
        elif name.startswith('cd-'):
            out.append((name, 'lumped'))
    return out


# ----------------------------------------------------------------------------
# OpenSees.
# ----------------------------------------------------------------------------
def mass_matrix(nodes, rho, mass):
    """The assembled mass of the free nodes (the last node fixed): lumped or consistent."""
    n = len(nodes) - 1
    h = np.diff(nodes)
    m = np.zeros((n + 1, n + 1))
    for e in range(n):
        me = rho[e] * AREA * h[e]
        block = (me / 2.0 * np.eye(2) if mass == 'lumped'
                 else me / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]]))
        m[e:e + 2, e:e + 2] += block
    return m[:n, :n]


def run_opensees(scene, nodes, times, dt, mass, integrator, start):
    """One case: the element stresses at each (t, step), and the wall time of the time loop."""
    E, rho = element_properties(scene, nodes)
    n = len(nodes) - 1
    f0 = -SIGMA0 * AREA
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    for i, x in enumerate(nodes):
        ops.node(i, float(x))
    ops.fix(n, 1)
    for e in range(n):
        ops.uniaxialMaterial('Elastic', e + 1, float(E[e]))
        args = ['Truss', e + 1, e, e + 1, AREA, e + 1, '-rho', float(rho[e] * AREA)]
        if mass == 'consistent':
            args += ['-cMass', 1]
        ops.element(*args)
    if integrator == 'central-difference' and start == 'corrected':
        # F(0) = F0/2, F(t) = F0 from the first step on: the half-step start's first impulse.
        end = times[-1][1] * dt * 2.0 + 1.0
        ops.timeSeries('Path', 1, '-time', 0.0, 0.5 * dt, end, '-values', 0.5, 1.0, 1.0)
    else:
        ops.timeSeries('Constant', 1, '-factor', 1.0)
    ops.pattern('Plain', 1, 1)
    ops.load(0, f0)
    if integrator == 'explicit-difference' and start == 'corrected':
        # a^0 = M^-1 F0 / 2, committed (ExplicitDifference starts from the committed a^0, 0
        # otherwise; without '-commit' the value is overwritten before the first step).
        f = np.zeros(n)
        f[0] = f0
        a0 = 0.5 * np.linalg.solve(mass_matrix(nodes, rho, mass), f)
        for i in range(n):
            ops.setNodeAccel(i, 1, float(a0[i]), '-commit')
    ops.constraints('Plain')
    ops.numberer('Plain')
    # The cheapest solver OpenSees offers for the mass: a diagonal one for lumped mass, a banded
    # one (tridiagonal here) for consistent mass.
    ops.system('BandGeneral' if mass == 'consistent' else 'Diagonal')
    ops.algorithm('Linear')
    ops.integrator(INTEGRATORS[integrator])
    ops.analysis('Transient')
    wanted = dict((step, t) for t, step in times)
    profiles = {}
    step = 0
    started = time.perf_counter()
    for target in sorted(wanted):
        if ops.analyze(target - step, dt) != 0:
            raise RuntimeError(f'{scene}: OpenSees failed before step {target}')
        step = target
        profiles[wanted[target]] = (ops.getTime(), np.array(
            [ops.eleResponse(e + 1, 'axialForce')[0] / AREA for e in range(n)]))
    wall = time.perf_counter() - started
    return profiles, wall


# ----------------------------------------------------------------------------
# Spectra (fig6): OpenSees' eigen solver on the same bars.
# ----------------------------------------------------------------------------
SPECTRUM_MASSES = (('lmm', False), ('cmm', True))


def spectrum(n, ends, consistent):
    """Every angular frequency of a uniform bar of n elements (L = E = rho = A = 1), free-free
    (n + 1 modes, the rigid one first) or fixed-free (node 0 fixed, n modes), with the lumped or
    consistent mass: `eigen('-fullGenLapack', all)` of OpenSees' assembled K and M."""
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    h = 1.0 / n
    for i in range(n + 1):
        ops.node(i, i * h)
    if ends == 'fixed-free':
        ops.fix(0, 1)
    ops.uniaxialMaterial('Elastic', 1, 1.0)
    for e in range(n):
        args = ['Truss', e + 1, e, e + 1, AREA, 1, '-rho', 1.0]
        if consistent:
            args += ['-cMass', 1]
        ops.element(*args)
    modes = n + 1 if ends == 'free-free' else n
    values = ops.eigen('-fullGenLapack', modes)
    return [math.sqrt(max(v, 0.0)) for v in values]


def write_spectra(directory, courant, check=False):
    """fig6's spectra of the lumped and the consistent mass (`write_spectrum_set`) and their
    results.toml. Returns the largest difference from the numpy model's when `check`."""
    worst = write_spectrum_set(directory, courant, 'opensees', SPECTRUM_MASSES, spectrum,
                               numpy_spectrum, check)
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write(f'format = 1\ncode = "opensees"\nversion = "{ops.version()}"\n')
    return worst


# ----------------------------------------------------------------------------
# Independent numpy model (--check): central difference, half-step form.
# ----------------------------------------------------------------------------
# The first-step impulse of each variant, in units of the half-step start's (v^{1/2} = s dt a^0,
# a^0 = M^-1 F0): CentralDifference as it comes (u^-1 = u^0, full F(0)) gives u^1 = dt^2 a^0
# (s = 1); ExplicitDifference as it comes (committed a^0 = 0) gives u^1 = u^0 (s = 0); both
# corrected give the half-step start's u^1 = dt^2/2 a^0 (s = 1/2).
START_IMPULSE = {
    ('central-difference', 'as-it-comes'): 1.0,
    ('explicit-difference', 'as-it-comes'): 0.0,
    ('central-difference', 'corrected'): 0.5,
    ('explicit-difference', 'corrected'): 0.5,
}


def numpy_cd(scene, nodes, times, dt, mass, start=0.5):
    """Central difference on the same bar, stiffness and masses assembled here:
    v^{1/2} = start dt M^-1 F0, u^{n+1} = u^n + dt v^{n+1/2},
    v^{n+3/2} = v^{n+1/2} + dt M^-1 (F0 - K u^{n+1}); start = 1/2 is the half-step start
    (methods.md §2), 1 and 0 the starts of OpenSees' integrators as they come."""
    E, rho = element_properties(scene, nodes)
    n = len(nodes) - 1
    h = np.diff(nodes)
    k = np.zeros((n + 1, n + 1))
    for e in range(n):
        ke = E[e] * AREA / h[e]
        k[e:e + 2, e:e + 2] += ke * np.array([[1.0, -1.0], [-1.0, 1.0]])
    k = k[:n, :n]
    minv = np.linalg.inv(mass_matrix(nodes, rho, mass))
    f = np.zeros(n)
    f[0] = -SIGMA0 * AREA
    u = np.zeros(n)
    v = start * dt * (minv @ f)
    wanted = dict((step, t) for t, step in times)
    out = {}
    for step in range(1, max(wanted) + 1):
        u = u + dt * v
        v = v + dt * (minv @ (f - k @ u))
        if step in wanted:
            full = np.r_[u, 0.0]
            out[wanted[step]] = E * np.diff(full) / h
    return out


def numpy_spectrum(n, ends, consistent):
    """The independent model of a fig6 bar: K and M assembled here, numpy's eigvalsh of
    M^-1/2 K M^-1/2 (node 0 fixed for fixed-free)."""
    h = 1.0 / n
    k = np.zeros((n + 1, n + 1))
    m = np.zeros((n + 1, n + 1))
    for e in range(n):
        k[e:e + 2, e:e + 2] += np.array([[1.0, -1.0], [-1.0, 1.0]]) / h
        m[e:e + 2, e:e + 2] += (h / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]]) if consistent
                                else h / 2.0 * np.eye(2))
    keep = slice(0, n + 1) if ends == 'free-free' else slice(1, n + 1)
    w, v = np.linalg.eigh(m[keep, keep])
    root = v @ np.diag(1.0 / np.sqrt(w)) @ v.T
    values = np.sort(np.linalg.eigvalsh(root @ k[keep, keep] @ root))
    return [math.sqrt(max(x, 0.0)) for x in values]


# ----------------------------------------------------------------------------
# Output.
# ----------------------------------------------------------------------------
def write_set(directory, scene, rows, integrator, start):
    os.makedirs(directory, exist_ok=True)
    for name, mass, nodes, profiles, dt, wall, steps in rows:
        with open(os.path.join(directory, f'{name}.csv'), 'w') as fd:
            fd.write('t,x_left,x_right,stress\n')
            for t in sorted(profiles):
                for xl, xr, s in zip(nodes[:-1], nodes[1:], profiles[t][1]):
                    fd.write(f'{t!r},{float(xl)!r},{float(xr)!r},{float(s)!r}\n')
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write('format = 2\n')
        fd.write('code = "opensees"\n')
        fd.write(f'version = "{ops.version()}"\n')
        for name, mass, nodes, profiles, dt, wall, steps in rows:
            fd.write(f'\n[cases."{name}"]\n')
            # OpenSees' integrators are central difference; only the corrected start is
            # courant's, so only the corrected sets declare the scheme (its signatures then
            # apply); the sets as they come are graded on the error bounds alone.
            if start == 'corrected':
                fd.write('scheme = "central-difference"\n')
            fd.write(f'mass = "{mass}"\n')
            fd.write(f'dt = {dt!r}\n')
            fd.write(f'elements = {len(nodes) - 1}\n')
            # OpenSees' own time: the median wall time of its time loop (the analyze calls).
            fd.write(f'wall_s = {wall:.6g}\n')
            fd.write(f'steps = {steps}\n')


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--scene', choices=SCENES + ('fig6', 'all'), default='all')
    p.add_argument('--integrator', choices=tuple(INTEGRATORS) + ('all',), default='all')
    p.add_argument('--start', choices=STARTS + ('all',), default='all')
    p.add_argument('--out', default=os.path.join(HERE, 'results'))
    p.add_argument('--courant', default=None,
                   help='the courant binary (default: cargo run --release --)')
    p.add_argument('--compare-with', default=None)
    p.add_argument('--tolerance', type=float, default=1e-10)
    p.add_argument('--check', action='store_true',
                   help='compare every run (each start) and every spectrum with an '
                        'independent numpy model')
    p.add_argument('--repeat', type=int, default=3,
                   help='runs per case; wall_s in results.toml is their median (default 3)')
    p.add_argument('--courant-times', default=None,
                   help="write courant's times on the same cases (one thread, same machine, "
                        'median of --repeat) here; default: external/opensees/courant_times.csv '
                        'when every set is regenerated into the default --out')
    args = p.parse_args()
    courant = ([args.courant] if args.courant else
               ['cargo', 'run', '--quiet', '--release', '--manifest-path',
                os.path.join(ROOT, 'Cargo.toml'), '--'])
    scenes = SCENES if args.scene == 'all' else tuple(s for s in (args.scene,) if s != 'fig6')
    integrators = tuple(INTEGRATORS) if args.integrator == 'all' else (args.integrator,)
    starts = STARTS if args.start == 'all' else (args.start,)
    # courant's times are written when asked, or when every set is regenerated in place.
    every_set = (args.scene, args.integrator, args.start) == ('all', 'all', 'all')
    times_file = args.courant_times or (
        os.path.join(HERE, 'courant_times.csv')
        if every_set and os.path.abspath(args.out) == os.path.join(HERE, 'results') else None)
    courant_rows = []
    worst = 0.0
    written = []
    for scene in scenes:
        geometry = courant_cases(courant, scene)
        cases = scene_cases(scene, sorted(geometry))
        for integrator in integrators:
            for start in starts:
                rows = []
                for name, mass in cases:
                    nodes, times, dt = geometry[name]
                    walls = []
                    for _ in range(max(1, args.repeat)):
                        profiles, wall = run_opensees(scene, nodes, times, dt, mass,
                                                      integrator, start)
                        walls.append(wall)
                    for t, (t_ops, _) in profiles.items():
                        assert abs(t_ops - t) <= 1e-9 * max(t, 1.0), (name, t, t_ops)
                    if args.check:
                        ref = numpy_cd(scene, nodes, times, dt, mass,
                                       START_IMPULSE[(integrator, start)])
                        diff = max(np.max(np.abs(profiles[t][1] - ref[t])) for t in ref)
                        worst = max(worst, diff)
                        print(f'check {integrator}-{start:12s} {scene:14s} {name:12s} '
                              f'max |opensees - numpy| = {diff:.2e}')
                    steps = max(step for _, step in times)
                    rows.append((name, mass, nodes, profiles, dt, statistics.median(walls),
                                 steps))
                directory = os.path.join(args.out, f'{integrator}-{start}', scene)
                write_set(directory, scene, rows, integrator, start)
                written.append(os.path.relpath(directory, args.out))
                print(f'{integrator}-{start}/{scene}: {len(rows)} case(s), wall '
                      + ', '.join(f'{r[0]} {r[5]:.3f} s' for r in rows))
        if times_file:
            walls = courant_walls(courant, scene, args.repeat)
            courant_rows += [(scene, name, walls[name][1], walls[name][0]) for name, _ in cases]
    if args.scene in ('all', 'fig6'):
        worst = max(worst, write_spectra(os.path.join(args.out, 'eigen', 'fig6'), courant,
                                         args.check))
        written.append(os.path.join('eigen', 'fig6'))
    if times_file:
        write_courant_times(times_file, courant_rows, args.repeat)
        print(f"courant's times: {times_file}")
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
        print(f'compare: {args.out} equals {args.compare_with} (stresses within '
              f'{args.tolerance} |sigma0|)')


if __name__ == '__main__':
    main()
