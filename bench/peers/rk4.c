/* Baselines of issue 5: classical RK4 on the Cartesian constrained ODE of the spherical pendulum
 * (docs/theory.md T-2.4): x' = v, v' = -g e3 + lambda x, lambda = (g z - |v|^2) / l^2. No projection.
 *
 * rk4_run:      one trajectory, a plain loop (what a careful C programmer writes first).
 * rk4_ensemble: N trajectories in structure-of-arrays form, blocks of BLOCK lanes whose inner loops
 *               carry `#pragma omp simd` (hand-vectorised: branch-free, unit stride), OpenMP over
 *               blocks with `nthreads` threads.
 * Built by bench/peers/run.py with `gcc -O3 -march=native -fopenmp -shared -fPIC`; called via ctypes
 * (one call per run, so the call overhead is negligible). */
#include <omp.h>
#include <stddef.h>

static inline void rhs(const double *y, double l2inv, double g, double *dy) {
    double lam = (g * y[2] - (y[3] * y[3] + y[4] * y[4] + y[5] * y[5])) * l2inv;
    dy[0] = y[3];
    dy[1] = y[4];
    dy[2] = y[5];
    dy[3] = lam * y[0];
    dy[4] = lam * y[1];
    dy[5] = lam * y[2] - g;
}

void rk4_run(double *y, double l, double g, double dt, long n) {
    double k1[6], k2[6], k3[6], k4[6], t[6];
    double l2inv = 1.0 / (l * l), h2 = 0.5 * dt, h6 = dt / 6.0;
    for (long s = 0; s < n; s++) {
        rhs(y, l2inv, g, k1);
        for (int i = 0; i < 6; i++) t[i] = y[i] + h2 * k1[i];
        rhs(t, l2inv, g, k2);
        for (int i = 0; i < 6; i++) t[i] = y[i] + h2 * k2[i];
        rhs(t, l2inv, g, k3);
        for (int i = 0; i < 6; i++) t[i] = y[i] + dt * k3[i];
        rhs(t, l2inv, g, k4);
        for (int i = 0; i < 6; i++) y[i] += h6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}

#define BLOCK 64

/* One RHS evaluation over a block of lanes: in[c][j] (c = 0..5 components) -> out[c][j]. */
static inline void rhs_block(double in[6][BLOCK], const double *l2inv, const double *g, double out[6][BLOCK]) {
#pragma omp simd
    for (int j = 0; j < BLOCK; j++) {
        double lam = (g[j] * in[2][j] - (in[3][j] * in[3][j] + in[4][j] * in[4][j] + in[5][j] * in[5][j])) *
                     l2inv[j];
        out[0][j] = in[3][j];
        out[1][j] = in[4][j];
        out[2][j] = in[5][j];
        out[3][j] = lam * in[0][j];
        out[4][j] = lam * in[1][j];
        out[5][j] = lam * in[2][j] - g[j];
    }
}

/* y: (6, n) structure of arrays, updated in place; l, g: (n,). n need not be a multiple of BLOCK. */
void rk4_ensemble(double *y, const double *l, const double *g, long n, double dt, long steps, int nthreads) {
    long nblocks = (n + BLOCK - 1) / BLOCK;
    double h2 = 0.5 * dt, h6 = dt / 6.0;
#pragma omp parallel for num_threads(nthreads) schedule(static)
    for (long b = 0; b < nblocks; b++) {
        double s[6][BLOCK], t[6][BLOCK], k1[6][BLOCK], k2[6][BLOCK], k3[6][BLOCK], k4[6][BLOCK];
        double li[BLOCK], gg[BLOCK];
        long base = b * BLOCK;
        int m = (int)((n - base) < BLOCK ? (n - base) : BLOCK);
        for (int j = 0; j < BLOCK; j++) {
            int jj = j < m ? j : 0; /* pad a partial block with copies of its first lane */
            li[j] = 1.0 / (l[base + jj] * l[base + jj]);
            gg[j] = g[base + jj];
            for (int c = 0; c < 6; c++) s[c][j] = y[c * n + base + jj];
        }
        for (long k = 0; k < steps; k++) {
            rhs_block(s, li, gg, k1);
            for (int c = 0; c < 6; c++)
#pragma omp simd
                for (int j = 0; j < BLOCK; j++) t[c][j] = s[c][j] + h2 * k1[c][j];
            rhs_block(t, li, gg, k2);
            for (int c = 0; c < 6; c++)
#pragma omp simd
                for (int j = 0; j < BLOCK; j++) t[c][j] = s[c][j] + h2 * k2[c][j];
            rhs_block(t, li, gg, k3);
            for (int c = 0; c < 6; c++)
#pragma omp simd
                for (int j = 0; j < BLOCK; j++) t[c][j] = s[c][j] + dt * k3[c][j];
            rhs_block(t, li, gg, k4);
            for (int c = 0; c < 6; c++)
#pragma omp simd
                for (int j = 0; j < BLOCK; j++)
                    s[c][j] += h6 * (k1[c][j] + 2.0 * k2[c][j] + 2.0 * k3[c][j] + k4[c][j]);
        }
        for (int j = 0; j < m; j++)
            for (int c = 0; c < 6; c++) y[c * n + base + j] = s[c][j];
    }
}
