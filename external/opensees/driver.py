#!/usr/bin/env python3
"""OpenSees driver for courant's 1D bar scenes (external/opensees/).

Runs each case of courant's ``fig1``, ``fig1_masses`` (LMM and CMM), ``fig1_schemes`` (central
difference), ``fig2``, ``fig2_reversed`` and ``layered`` (central difference) scenes with
OpenSees' own explicit integrators and writes courant's results exchange format 1 (README,
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
per element is the scene's, evaluated at the element midpoint as courant does (``MATERIALS``
below): E = 16 -> 1 linear (fig2), 1 -> 16 (fig2_reversed), two layers E = 64, rho = 4 then
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
    target/opensees-venv/bin/python external/opensees/driver.py --check
        # OpenSees against an independent numpy central difference (half-step form, the same
        # masses, the same corrected starts): the largest difference per case

Dependencies: numpy and openseespy only; the ``courant`` binary for the geometry
(``--courant PATH``, default ``cargo run --release --``).
"""
import argparse
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import openseespy.opensees as ops

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

SIGMA0 = -1.0  # traction at x = 0 in every scene here (compressive)
AREA = 1.0

INTEGRATORS = {
    'central-difference': 'CentralDifference',
    'explicit-difference': 'ExplicitDifference',
}
STARTS = ('as-it-comes', 'corrected')


def linear(left, right):
    return lambda x, length: left + (right - left) * x / length


def constant(value):
    return lambda x, length: value


def layers(spec):
    """(thickness, E, rho) from the loaded end; an interface belongs to the layer on its right."""
    def at(x):
        end = 0.0
        for thickness, e, rho in spec:
            end += thickness
            if x < end:
                return e, rho
        return spec[-1][1], spec[-1][2]
    return (lambda x, length: at(x)[0]), (lambda x, length: at(x)[1])


_LAYERED = layers([(0.5, 64.0, 4.0), (0.5, 1.0, 1.0)])

# Per scene: (modulus(x, L), density(x, L)) and the cases run (central difference only; the
# mass from the case name: cmm-* consistent, lumped otherwise).
MATERIALS = {
    'fig1': (constant(1.0), constant(1.0)),
    'fig1_masses': (constant(1.0), constant(1.0)),
    'fig1_schemes': (constant(1.0), constant(1.0)),
    'fig2': (linear(16.0, 1.0), constant(1.0)),
    'fig2_reversed': (linear(1.0, 16.0), constant(1.0)),
    'layered': _LAYERED,
}
SCENES = tuple(MATERIALS)


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
# The geometry of courant's cases, from its exact answers.
# ----------------------------------------------------------------------------
def courant_cases(courant, scene):
    """{case: (nodes, [(t, step)], dt)} from `courant reference <scene>`."""
    tmp = tempfile.mkdtemp(prefix='opensees-geometry-')
    try:
        subprocess.run(courant + ['reference', scene, '--out', tmp], check=True,
                       stdout=subprocess.DEVNULL)
        base = os.path.join(tmp, scene)
        dts = read_dts(os.path.join(base, 'results.toml'))
        cases = {}
        for f in sorted(os.listdir(base)):
            if not f.endswith('.csv'):
                continue
            name = f[:-4]
            rows = np.genfromtxt(os.path.join(base, f), delimiter=',', names=True,
                                 dtype=None, encoding='utf-8')
            t0 = rows['t'][0]
            first = rows[rows['t'] == t0]
            nodes = np.r_[first['x_left'], first['x_right'][-1]]
            dt = dts[name]
            times = []
            for t in sorted(set(rows['t'].tolist())):
                step = round(t / dt)
                assert abs(step * dt - t) <= 1e-9 * max(t, dt), (scene, name, t, dt)
                times.append((t, step))
            cases[name] = (nodes, times, dt)
        return cases
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def courant_walls(courant, scene, repeat):
    """{case: (median wall time s, steps)} of `courant run <scene>` on one thread (cases one at a
    time: COURANT_THREADS=1, RAYON_NUM_THREADS=1), median of `repeat` runs: the `wall_time_s`
    and `steps` of its summary.csv."""
    env = dict(os.environ, COURANT_THREADS='1', RAYON_NUM_THREADS='1')
    walls = {}
    steps = {}
    for _ in range(max(1, repeat)):
        tmp = tempfile.mkdtemp(prefix='opensees-courant-')
        try:
            subprocess.run(courant + ['run', scene, '--out', tmp], check=True, env=env,
                           stdout=subprocess.DEVNULL)
            rows = np.genfromtxt(os.path.join(tmp, scene, 'summary.csv'), delimiter=',',
                                 names=True, dtype=None, encoding='utf-8')
            for row in np.atleast_1d(rows):
                walls.setdefault(str(row['case']), []).append(float(row['wall_time_s']))
                steps[str(row['case'])] = int(row['steps'])
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    return {case: (statistics.median(w), steps[case]) for case, w in walls.items()}


def cpu_name():
    """The CPU model, from /proc/cpuinfo."""
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                return line.split(':', 1)[1].strip()
    except OSError:
        pass
    return 'unknown CPU'


def read_dts(path):
    """`dt` of every `[cases."name"]` table of a results.toml (tomllib: Python >= 3.11)."""
    import tomllib
    with open(path, 'rb') as fd:
        meta = tomllib.load(fd)
    return {name: table['dt'] for name, table in meta['cases'].items()}


def element_properties(scene, nodes):
    """(E, rho) of each element at its midpoint, as courant evaluates the scene's material."""
    modulus, density = MATERIALS[scene]
    length = nodes[-1] - nodes[0]
    mid = 0.5 * (nodes[:-1] + nodes[1:]) - nodes[0]
    return (np.array([modulus(x, length) for x in mid]),
            np.array([density(x, length) for x in mid]))


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


def write_spectra(directory, courant):
    """fig6's cases (`<ends>-n<N>`, from courant's exact answers): every mode of the lumped
    and the consistent mass, modes numbered as courant's closed forms (free-free from 0, the
    rigid mode)."""
    tmp = tempfile.mkdtemp(prefix='opensees-fig6-')
    try:
        subprocess.run(courant + ['reference', 'fig6', '--out', tmp], check=True,
                       stdout=subprocess.DEVNULL)
        names = sorted(f[:-4] for f in os.listdir(os.path.join(tmp, 'fig6'))
                       if f.endswith('.csv'))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(directory, exist_ok=True)
    for name in names:
        ends, n = name.rsplit('-n', 1)
        first = 0 if ends == 'free-free' else 1
        with open(os.path.join(directory, f'{name}.csv'), 'w') as fd:
            fd.write('mode,omega,mass\n')
            for label, consistent in SPECTRUM_MASSES:
                for i, omega in enumerate(spectrum(int(n), ends, consistent)):
                    fd.write(f'{first + i},{omega!r},{label}\n')
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write(f'format = 1\ncode = "opensees"\nversion = "{ops.version()}"\n')
    print(f'eigen/fig6: {len(names)} case(s), masses lmm and cmm')


# ----------------------------------------------------------------------------
# Independent numpy model (--check): central difference, half-step form.
# ----------------------------------------------------------------------------
def numpy_cd(scene, nodes, times, dt, mass):
    """Half-step central difference on the same bar: a^0 = M^-1 F0, v^{1/2} = dt/2 a^0,
    u^{n+1} = u^n + dt v^{n+1/2}, v^{n+3/2} = v^{n+1/2} + dt M^-1 (F0 - K u^{n+1})."""
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
    v = 0.5 * dt * (minv @ f)
    wanted = dict((step, t) for t, step in times)
    out = {}
    for step in range(1, max(wanted) + 1):
        u = u + dt * v
        v = v + dt * (minv @ (f - k @ u))
        if step in wanted:
            full = np.r_[u, 0.0]
            out[wanted[step]] = E * np.diff(full) / h
    return out


# ----------------------------------------------------------------------------
# Output.
# ----------------------------------------------------------------------------
def write_set(directory, scene, rows, integrator, start):
    os.makedirs(directory, exist_ok=True)
    for name, mass, nodes, profiles, dt, wall in rows:
        with open(os.path.join(directory, f'{name}.csv'), 'w') as fd:
            fd.write('t,x_left,x_right,stress\n')
            for t in sorted(profiles):
                for xl, xr, s in zip(nodes[:-1], nodes[1:], profiles[t][1]):
                    fd.write(f'{t!r},{float(xl)!r},{float(xr)!r},{float(s)!r}\n')
    with open(os.path.join(directory, 'results.toml'), 'w') as fd:
        fd.write('format = 1\n')
        fd.write('code = "opensees"\n')
        fd.write(f'version = "{ops.version()}"\n')
        for name, mass, nodes, profiles, dt, wall in rows:
            fd.write(f'\n[cases."{name}"]\n')
            # OpenSees' integrators are central difference; only the corrected start is
            # courant's, so only the corrected sets declare the scheme (its signatures then
            # apply); the sets as they come are graded on the error bounds alone.
            if start == 'corrected':
                fd.write('scheme = "central-difference"\n')
            fd.write(f'mass = "{mass}"\n')
            fd.write(f'dt = {dt!r}\n')
            fd.write(f'elements = {len(nodes) - 1}\n')


def write_cost(path, rows, repeat):
    """The cost table: per case and integrator, the steps and the median wall times of OpenSees'
    time loop and of courant's run of the same case, both on one thread on this machine now."""
    measured = time.strftime('%Y-%m-%d')
    cpu = cpu_name().replace(',', ' ')
    with open(path, 'w') as fd:
        fd.write('scene,case,integrator,start,steps,opensees_wall_s,courant_wall_s,'
                 'ratio,repeat,measured,cpu\n')
        for scene, case, integrator, start, steps, ops_wall, own in rows:
            fd.write(f'{scene},{case},{integrator},{start},{steps},{ops_wall:.6g},{own:.6g},'
                     f'{ops_wall / own:.4g},{repeat},{measured},{cpu}\n')


def compare_dirs(fresh, committed, tolerance):
    """Every file the driver writes in `committed` is in `fresh` with the same text but for the
    stresses, which agree within `tolerance` (|sigma0| = 1); `stated.toml` is courant's, not the
    driver's, and is left out."""
    bad = []
    for root, _, files in os.walk(committed):
        rel = os.path.relpath(root, committed)
        for f in files:
            if f == 'stated.toml':
                continue
            a, b = os.path.join(root, f), os.path.join(fresh, rel, f)
            if not os.path.exists(b):
                bad.append(f'{b}: missing')
                continue
            if f.endswith('.toml'):
                if open(a).read() != open(b).read():
                    bad.append(f'{b}: differs from {a}')
                continue
            la, lb = open(a).read().splitlines(), open(b).read().splitlines()
            if len(la) != len(lb):
                bad.append(f'{b}: {len(lb)} lines, {a} {len(la)}')
                continue
            spectrum = la[0] == 'mode,omega,mass'
            for i, (x, y) in enumerate(zip(la, lb)):
                if i == 0:
                    if x != y:
                        bad.append(f'{b}: header differs')
                    continue
                x, y = x.split(','), y.split(',')
                if spectrum:
                    # mode and mass as written, omega within `tolerance` relative.
                    w = max(abs(float(x[1])), 1.0)
                    same = (x[0], x[2]) == (y[0], y[2]) and \
                        abs(float(x[1]) - float(y[1])) <= tolerance * w
                else:
                    same = x[:3] == y[:3] and abs(float(x[3]) - float(y[3])) <= tolerance
                if not same:
                    bad.append(f'{b}:{i + 1}: {y} against {x}')
                    break
    return bad


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
                   help='compare the corrected runs with an independent numpy model')
    p.add_argument('--repeat', type=int, default=3,
                   help='runs per case; the median wall time is printed')
    p.add_argument('--cost', default=None,
                   help='write the cost table (OpenSees and courant wall times of every case, '
                        'one thread, same machine) here; default: external/opensees/cost.csv '
                        'when --out is the default')
    args = p.parse_args()
    courant = ([args.courant] if args.courant else
               ['cargo', 'run', '--quiet', '--release', '--manifest-path',
                os.path.join(ROOT, 'Cargo.toml'), '--'])
    scenes = SCENES if args.scene == 'all' else tuple(s for s in (args.scene,) if s != 'fig6')
    integrators = tuple(INTEGRATORS) if args.integrator == 'all' else (args.integrator,)
    starts = STARTS if args.start == 'all' else (args.start,)
    # The cost table is written when asked, or when every set is regenerated in place.
    every_set = (args.scene, args.integrator, args.start) == ('all', 'all', 'all')
    cost_file = args.cost or (os.path.join(HERE, 'cost.csv')
                              if every_set
                              and os.path.abspath(args.out) == os.path.join(HERE, 'results')
                              else None)
    cost_rows = []
    worst = 0.0
    for scene in scenes:
        geometry = courant_cases(courant, scene)
        courant_wall = courant_walls(courant, scene, args.repeat) if cost_file else {}
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
                    if args.check and start == 'corrected':
                        ref = numpy_cd(scene, nodes, times, dt, mass)
                        diff = max(np.max(np.abs(profiles[t][1] - ref[t])) for t in ref)
                        worst = max(worst, diff)
                        print(f'check {integrator:20s} {scene:14s} {name:16s} '
                              f'max |opensees - numpy| = {diff:.2e}')
                    rows.append((name, mass, nodes, profiles, dt, statistics.median(walls)))
                    if name in courant_wall:
                        own, steps = courant_wall[name]
                        cost_rows.append((scene, name, integrator, start, steps,
                                          statistics.median(walls), own))
                directory = os.path.join(args.out, f'{integrator}-{start}', scene)
                write_set(directory, scene, rows, integrator, start)
                print(f'{integrator}-{start}/{scene}: {len(rows)} case(s), wall '
                      + ', '.join(f'{r[0]} {r[5]:.3f} s' for r in rows))
    if args.scene in ('all', 'fig6'):
        write_spectra(os.path.join(args.out, 'eigen', 'fig6'), courant)
    if cost_file:
        write_cost(cost_file, cost_rows, args.repeat)
        print(f'cost: {cost_file}')
    if args.check:
        print(f'check: largest difference {worst:.2e} |sigma0|')
        if worst > 1e-9:
            sys.exit(1)
    if args.compare_with:
        bad = compare_dirs(args.out, args.compare_with, args.tolerance)
        for b in bad:
            print(b, file=sys.stderr)
        if bad:
            sys.exit(1)
        print(f'compare: {args.out} equals {args.compare_with} (stresses within '
              f'{args.tolerance} |sigma0|)')


if __name__ == '__main__':
    main()
