"""What the drivers of other codes (external/<code>/driver.py) share: the scenes' materials as
courant evaluates them, the geometry of courant's cases read from its exact answers
(``courant reference <scene>``), courant's own times on the same cases (``courant run`` on one
thread), and the comparison of a regenerated set with the committed one (``--compare-with``).

Each driver puts this directory on ``sys.path`` and imports from here; it needs numpy only.
"""

import os
import shutil
import statistics
import subprocess
import tempfile
import time

import numpy as np

AREA = 1.0


SIGMA0 = -1.0        # traction at x = 0 in every scene here (compressive)


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


# Per scene: (modulus(x, L), density(x, L)).
MATERIALS = {
    'fig1': (constant(1.0), constant(1.0)),
    'fig1_masses': (constant(1.0), constant(1.0)),
    'fig1_schemes': (constant(1.0), constant(1.0)),
    'fig2': (linear(16.0, 1.0), constant(1.0)),
    'fig2_reversed': (linear(1.0, 16.0), constant(1.0)),
    'layered': _LAYERED,
}


SCENES = tuple(MATERIALS)


def element_properties(scene, nodes):
    """(E, rho) of each element at its midpoint, as courant evaluates the scene's material."""
    modulus, density = MATERIALS[scene]
    length = nodes[-1] - nodes[0]
    mid = 0.5 * (nodes[:-1] + nodes[1:]) - nodes[0]
    return (np.array([modulus(x, length) for x in mid]),
            np.array([density(x, length) for x in mid]))


# ----------------------------------------------------------------------------
# courant: the geometry of its cases, and its own times.
# ----------------------------------------------------------------------------
def courant_reference(courant, scene):
    """The directory of `courant reference <scene>` in a temporary root (caller removes it)."""
    tmp = tempfile.mkdtemp(prefix='courant-geometry-')
    subprocess.run(courant + ['reference', scene, '--out', tmp], check=True,
                   stdout=subprocess.DEVNULL)
    return tmp, os.path.join(tmp, scene)


def courant_cases(courant, scene):
    """{case: (nodes, [(t, step)], dt)} from `courant reference <scene>`."""
    import tomllib
    tmp, base = courant_reference(courant, scene)
    try:
        with open(os.path.join(base, 'results.toml'), 'rb') as fd:
            dts = {k: v['dt'] for k, v in tomllib.load(fd)['cases'].items()}
        cases = {}
        for f in sorted(os.listdir(base)):
            if not f.endswith('.csv'):
                continue
            name = f[:-4]
            rows = np.genfromtxt(os.path.join(base, f), delimiter=',', names=True)
            first = rows[rows['t'] == rows['t'][0]]
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
    """{case: (median wall time s, steps)} of `courant run <scene>` on one thread (COURANT_THREADS=1,
    RAYON_NUM_THREADS=1): the `wall_time_s` and `steps` of its summary.csv, median of `repeat`."""
    env = dict(os.environ, COURANT_THREADS='1', RAYON_NUM_THREADS='1')
    walls, steps = {}, {}
    for _ in range(max(1, repeat)):
        tmp = tempfile.mkdtemp(prefix='courant-times-')
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
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                return line.split(':', 1)[1].strip()
    except OSError:
        pass
    return 'unknown CPU'


def write_courant_times(path, rows, repeat):
    """courant's times on the cases a code ran, measured right after the code's on this machine (one
    thread, median of `repeat` runs): the yardstick of the cost ratios."""
    measured = time.strftime('%Y-%m-%d')
    cpu = cpu_name().replace(',', ' ')
    with open(path, 'w') as fd:
        fd.write('scene,case,steps,courant_wall_s,repeat,measured,cpu\n')
        for scene, case, steps, wall in rows:
            fd.write(f'{scene},{case},{steps},{wall:.6g},{repeat},{measured},{cpu}\n')


def without_wall(text):
    """results.toml without its `wall_s` lines (machine-specific; not compared)."""
    return [l for l in text.splitlines() if not l.startswith('wall_s =')]


def compare_dirs(fresh, committed, tolerance):
    """Every file of `committed` is in `fresh` with the same rows (times, element ends, modes and
    masses as written), every stress within `tolerance` |sigma0| and every frequency within
    `tolerance` relative, results.toml the same but for `wall_s`. Returns the failures."""
    bad = []
    for root, _, files in os.walk(committed):
        rel = os.path.relpath(root, committed)
        for f in sorted(files):
            if f == 'stated.toml':   # courant's statement about the set, not the driver's
                continue
            a, b = os.path.join(root, f), os.path.join(fresh, rel, f)
            if not os.path.exists(b):
                bad.append(f'{b}: missing')
                continue
            if f.endswith('.toml'):
                if without_wall(open(a).read()) != without_wall(open(b).read()):
                    bad.append(f'{b}: differs from {a} (wall_s aside)')
                continue
            la, lb = open(a).read().splitlines(), open(b).read().splitlines()
            if len(la) != len(lb) or la[0] != lb[0]:
                bad.append(f'{b}: header or length differs from {a}')
                continue
            spectrum = la[0] == 'mode,omega,mass'
            worst = 0.0
            for i, (x, y) in enumerate(zip(la[1:], lb[1:]), start=2):
                x, y = x.split(','), y.split(',')
                if spectrum:
                    same_rows = (x[0], x[2]) == (y[0], y[2])
                    d = abs(float(x[1]) - float(y[1])) / max(abs(float(x[1])), 1.0)
                else:
                    same_rows = x[:3] == y[:3]
                    d = abs(float(x[3]) - float(y[3])) / abs(SIGMA0)
                if not same_rows:
                    bad.append(f'{b}:{i}: row {y} against {x}')
                    break
                worst = max(worst, d)
            if worst > tolerance:
                bad.append(f'{b}: differs by {worst:.2e} > {tolerance:g}')
    return bad


def write_spectrum_set(directory, courant, code, masses, computed, reference, check):
    """fig6's cases (`<ends>-n<N>`, from courant's exact answers) into `directory`: every mode of
    each mass, numbered as courant's closed forms (free-free from 0, the rigid mode).
    `masses`: [(label, key)]; `computed(n, ends, key)` the code's frequencies, `reference(n, ends,
    key)` an independent numpy model's. With `check`, returns the largest difference of omega^2
    from the model's over the largest omega^2 (so that the rigid mode's round-off, omega ~ 1e-7,
    the square root of ~1e-14, counts as what it is); else 0. The caller writes results.toml."""
    tmp, base = courant_reference(courant, 'fig6')
    try:
        names = sorted(f[:-4] for f in os.listdir(base) if f.endswith('.csv'))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(directory, exist_ok=True)
    worst = 0.0
    for name in names:
        ends, n = name.rsplit('-n', 1)
        first = 0 if ends == 'free-free' else 1
        with open(os.path.join(directory, f'{name}.csv'), 'w') as fd:
            fd.write('mode,omega,mass\n')
            for label, key in masses:
                omegas = computed(int(n), ends, key)
                for i, omega in enumerate(omegas):
                    fd.write(f'{first + i},{omega!r},{label}\n')
                if check:
                    ref = reference(int(n), ends, key)
                    top = max(ref) ** 2
                    d = max(abs(a * a - b * b) / top for a, b in zip(omegas, ref))
                    worst = max(worst, d)
                    print(f'check eigen fig6 {name:16s} {label}: max |omega_{code}^2 - '
                          f'omega_numpy^2| / omega_max^2 = {d:.2e}')
    print(f'eigen/fig6: {len(names)} case(s), masses {", ".join(m[0] for m in masses)}')
    return worst
