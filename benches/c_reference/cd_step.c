/*
 * C reference for one lumped-mass central-difference step on a graded 1D bar.
 *
 * Measurement aid for benches/cd_step.rs (not part of the cargo build). Same model as the Rust
 * bench: uniform mesh on [0, 1] with N elements, modulus E linear 16 -> 1 (sampled at element
 * midpoints), density 1, area 1, free left end loaded by F = 1 on node 0, fixed right end,
 * dt = 0.5 * min_e h_e / c_e (Courant 0.5). Ghost-padded layout as in the solver's kernel.rs:
 *
 *   padded index p = node + 1, p = 0 .. N+2 (ghosts at 0 and N+2, zero stiffness/mass/motion)
 *   u[p], v[p]      displacement u^n and half-step velocity v^{n+1/2}       length N+3
 *   k[j]            stiffness of the link between padded nodes j and j+1    length N+2
 *                   (k[0] = k[N+1] = 0: ghost links)
 *   s[p] = dt/m_p   0 at the ghosts and at the fixed node p = N+1           length N+3
 *
 * One step:  u += dt v;  r_p = k[p](u[p+1]-u[p]) - k[p-1](u[p]-u[p-1]) (+ F on p = 1);
 *            v[p] += s[p] r_p   for p = 1 .. N+1.
 *
 * Variants (all do the same arithmetic per node; the load is added to node 0 after the sweep):
 *   two_pass  : loop 1 over u, loop 2 over v  (the structure of kernel.rs)
 *   fused     : one pass, u updated one node ahead of the velocity stencil
 *   blocked   : the two passes strip-mined in blocks of B nodes (u one block ahead), so the
 *               second pass reads u from L1; one sweep over memory like `fused`, but each
 *               inner loop vectorises like the two-pass loops.
 *
 * Timing: clock_gettime(CLOCK_MONOTONIC); each repetition runs ceil(target / (N+1)) steps
 * (target node-steps per repetition, default 5e7), REPS repetitions (default 9); the median over
 * repetitions is printed as ns per node-step (node-steps = (N+1) * steps). A checksum of u and
 * v is printed so the work cannot be optimised away.
 *
 * Build and run: bash benches/c_reference/run.sh   (gcc -O3 -march=native)
 * Usage: cd_step [node_steps_per_rep [reps [N ...]]]
 */
#define _POSIX_C_SOURCE 200112L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef BLOCK
#define BLOCK 512
#endif

typedef struct {
    long n;       /* elements */
    long p;       /* padded length N+3 */
    double dt;
    double *u, *v, *k, *s;
} Bar;

static double *alloc(long len) {
    double *x = NULL;
    if (posix_memalign((void **)&x, 64, (size_t)len * sizeof(double)) != 0) {
        perror("posix_memalign");
        exit(1);
    }
    memset(x, 0, (size_t)len * sizeof(double));
    return x;
}

static void bar_init(Bar *b, long n) {
    const double pi = 3.14159265358979323846;
    b->n = n;
    b->p = n + 3;
    b->u = alloc(b->p);
    b->v = alloc(b->p);
    b->k = alloc(b->p); /* N+2 used */
    b->s = alloc(b->p);
    double h = 1.0 / (double)n;
    double *m = alloc(b->p);
    double min_transit = INFINITY;
    for (long e = 0; e < n; e++) {
        double x = (e + 0.5) * h;          /* midpoint */
        double E = 16.0 + (1.0 - 16.0) * x; /* linear 16 -> 1 */
        double rho = 1.0, A = 1.0;
        b->k[e + 1] = E * A / h;
        double me = rho * A * h;
        m[e + 1] += 0.5 * me; /* node e     -> padded e+1 */
        m[e + 2] += 0.5 * me; /* node e + 1 -> padded e+2 */
        double transit = h / sqrt(E / rho);
        if (transit < min_transit) min_transit = transit;
    }
    b->dt = 0.5 * min_transit;
    for (long q = 1; q <= n + 1; q++) b->s[q] = b->dt / m[q];
    b->s[n + 1] = 0.0; /* fixed right end */
    /* smooth initial half-step velocity, zero at the fixed end: v = 1e-3 cos(pi x / 2) */
    for (long i = 0; i < n; i++) b->v[i + 1] = 1e-3 * cos(0.5 * pi * (double)i * h);
    free(m);
}

static void bar_free(Bar *b) {
    free(b->u);
    free(b->v);
    free(b->k);
    free(b->s);
}

/* ---- variants ------------------------------------------------------------------------------ */

static void step_two_pass(Bar *restrict b, double force) {
    const long last = b->n + 1; /* padded index of the last real node */
    double *restrict u = b->u, *restrict v = b->v;
    const double *restrict k = b->k, *restrict s = b->s;
    const double dt = b->dt;
    for (long q = 0; q < b->p; q++) u[q] += dt * v[q];
    for (long q = 1; q <= last; q++) {
        double r = k[q] * (u[q + 1] - u[q]) - k[q - 1] * (u[q] - u[q - 1]);
        v[q] += s[q] * r;
    }
    v[1] += s[1] * force;
}

static void step_fused(Bar *restrict b, double force) {
    const long last = b->n + 1;
    double *restrict u = b->u, *restrict v = b->v;
    const double *restrict k = b->k, *restrict s = b->s;
    const double dt = b->dt;
    u[0] += dt * v[0];
    u[1] += dt * v[1];
    double ul = u[0], uc = u[1];
    for (long q = 1; q <= last; q++) {
        double un = u[q + 1] + dt * v[q + 1]; /* v[q+1] is still v^{n+1/2} here */
        u[q + 1] = un;
        double r = k[q] * (un - uc) - k[q - 1] * (uc - ul);
        v[q] += s[q] * r;
        ul = uc;
        uc = un;
    }
    v[1] += s[1] * force;
}

static void step_blocked(Bar *restrict b, double force) {
    const long last = b->n + 1;
    const long p = b->p;
    double *restrict u = b->u, *restrict v = b->v;
    const double *restrict k = b->k, *restrict s = b->s;
    const double dt = b->dt;
    /* u is advanced block by block, one block ahead of the velocity sweep, which needs u up to
       index hi (exclusive) + 1. */
    long u_done = 0; /* u[0 .. u_done) are at level n+1 */
    for (long lo = 1; lo <= last; lo += BLOCK) {
        long hi = lo + BLOCK; /* velocity sweep over [lo, min(hi, last+1)) */
        if (hi > last + 1) hi = last + 1;
        long need = hi + 1; /* u[0 .. need) must be new */
        if (need > p) need = p;
        for (long q = u_done; q < need; q++) u[q] += dt * v[q];
        u_done = need;
        for (long q = lo; q < hi; q++) {
            double r = k[q] * (u[q + 1] - u[q]) - k[q - 1] * (u[q] - u[q - 1]);
            v[q] += s[q] * r;
        }
    }
    for (long q = u_done; q < p; q++) u[q] += dt * v[q];
    v[1] += s[1] * force;
}

/* ---- timing -------------------------------------------------------------------------------- */

typedef void (*StepFn)(Bar *restrict, double);

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double checksum(const Bar *b) {
    double c = 0.0;
    for (long q = 0; q < b->p; q++) c += b->u[q] + 1e3 * b->v[q];
    return c;
}

static double measure(const char *name, StepFn f, long n, double target, int reps) {
    Bar b;
    bar_init(&b, n);
    long nodes = n + 1;
    long steps = (long)ceil(target / (double)nodes);
    if (steps < 1) steps = 1;
    double *t = malloc((size_t)reps * sizeof(double));
    for (long i = 0; i < (steps < 10 ? steps : 10); i++) f(&b, 1.0); /* warm up */
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        for (long i = 0; i < steps; i++) f(&b, 1.0);
        double t1 = now();
        t[r] = (t1 - t0) * 1e9 / ((double)steps * (double)nodes);
    }
    qsort(t, (size_t)reps, sizeof(double), cmp);
    double med = t[reps / 2];
    printf("%-9s N=%-8ld steps/rep=%-9ld reps=%d  median %.3f ns/node-step  (min %.3f, max %.3f)"
           "  checksum %.9e\n",
           name, n, steps, reps, med, t[0], t[reps - 1], checksum(&b));
    fflush(stdout);
    free(t);
    bar_free(&b);
    return med;
}

/* All variants must give the same state (same arithmetic, same order per node). */
static int self_check(void) {
    StepFn fns[3] = {step_two_pass, step_fused, step_blocked};
    Bar b[3];
    for (int i = 0; i < 3; i++) {
        bar_init(&b[i], 3000);
        for (int st = 0; st < 2000; st++) fns[i](&b[i], 1.0);
    }
    int ok = 1;
    for (int i = 1; i < 3; i++)
        for (long q = 0; q < b[0].p; q++)
            if (b[i].u[q] != b[0].u[q] || b[i].v[q] != b[0].v[q]) ok = 0;
    for (int i = 0; i < 3; i++) bar_free(&b[i]);
    return ok;
}

int main(int argc, char **argv) {
    double target = argc > 1 ? atof(argv[1]) : 5e7;
    int reps = argc > 2 ? atoi(argv[2]) : 9;
    long sizes_default[3] = {1000, 100000, 1000000};
    long *sizes = sizes_default;
    int nsizes = 3;
    if (argc > 3) {
        nsizes = argc - 3;
        sizes = malloc((size_t)nsizes * sizeof(long));
        for (int i = 0; i < nsizes; i++) sizes[i] = atol(argv[3 + i]);
    }
    if (!self_check()) {
        fprintf(stderr, "variants disagree (bitwise) after 2000 steps\n");
        return 1;
    }
    printf("self-check: two_pass, fused, blocked (B=%d) bitwise identical after 2000 steps\n",
           BLOCK);
    printf("%.3g node-steps per repetition, %d repetitions\n", target, reps);
    for (int i = 0; i < nsizes; i++) {
        long n = sizes[i];
        double a = measure("two_pass", step_two_pass, n, target, reps);
        double f = measure("fused", step_fused, n, target, reps);
        double bl = measure("blocked", step_blocked, n, target, reps);
        const char *best = a <= f && a <= bl ? "two_pass" : (f <= bl ? "fused" : "blocked");
        printf("  N=%ld fastest: %s (fused/two_pass = %.2f, blocked/two_pass = %.2f)\n", n, best,
               f / a, bl / a);
    }
    return 0;
}
