/* The machine's roof (bench/roofline/run.py): fused multiply-add throughput per core at each vector
 * width (scalar, 128, 256 and 512 bits of float64) and memory bandwidth (a STREAM-like triad at a
 * size that stays in L1, one that stays in L2 and one far beyond the last-level cache).
 *
 * fma_peak: `chains` independent dependency chains of a = a * b + c per lane (enough to hide the FMA
 *           latency on every x86-64 core since Haswell: latency 4-5 cycles x 2 pipes < 12 chains),
 *           `iters` rounds, on `threads` OpenMP threads; returns flop/s (one FMA = 2 flop) summed over
 *           the threads. Compiled per width with target attributes, so one shared object serves every
 *           CPU; the caller asks only for the widths the CPU has.
 * triad:    a[i] = b[i] + s * c[i] over n doubles, `reps` timings of about 4e6 updates each (n small:
 *           many passes), `threads` threads; returns the best bytes/s
 *           counted as 3 x 8 B per element (the write-allocate read of a is not counted, as STREAM).
 * Built with `gcc -O3 -fopenmp -shared -fPIC` (no -march: the widths are chosen per function). */
#include <immintrin.h>
#include <omp.h>
#include <stdlib.h>

#define CHAINS 12

#define FMA_VEC(NAME, TARGET, VT, SET1, FMADD, STORE, LANES)                                     \
    __attribute__((target(TARGET))) static double NAME(long iters) {                            \
        VT a0 = SET1(1.0), a1 = SET1(1.1), a2 = SET1(1.2), a3 = SET1(1.3), a4 = SET1(1.4),      \
           a5 = SET1(1.5), a6 = SET1(1.6), a7 = SET1(1.7), a8 = SET1(1.8), a9 = SET1(1.9),      \
           a10 = SET1(2.0), a11 = SET1(2.1);                                                    \
        VT b = SET1(0.999999), c = SET1(1e-7);                                                  \
        for (long i = 0; i < iters; i++) {                                                      \
            a0 = FMADD(a0, b, c); a1 = FMADD(a1, b, c); a2 = FMADD(a2, b, c);                   \
            a3 = FMADD(a3, b, c); a4 = FMADD(a4, b, c); a5 = FMADD(a5, b, c);                   \
            a6 = FMADD(a6, b, c); a7 = FMADD(a7, b, c); a8 = FMADD(a8, b, c);                   \
            a9 = FMADD(a9, b, c); a10 = FMADD(a10, b, c); a11 = FMADD(a11, b, c);               \
            __asm__ volatile("" : "+x"(a0), "+x"(a1), "+x"(a2), "+x"(a3), "+x"(a4), "+x"(a5));  \
            __asm__ volatile("" : "+x"(a6), "+x"(a7), "+x"(a8), "+x"(a9), "+x"(a10), "+x"(a11)); \
        }                                                                                       \
        double out[LANES];                                                                      \
        STORE(out, a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10 + a11);                \
        double s = 0;                                                                           \
        for (int k = 0; k < LANES; k++) s += out[k];                                            \
        return s;                                                                               \
    }

static inline double set1_sd(double x) { return x; }
__attribute__((target("fma"))) static inline double fmadd_sd(double a, double b, double c) {
    return __builtin_fma(a, b, c);
}
static inline void store_sd(double *out, double x) { out[0] = x; }

FMA_VEC(fma_scalar, "fma", double, set1_sd, fmadd_sd, store_sd, 1)
FMA_VEC(fma_128, "fma", __m128d, _mm_set1_pd, _mm_fmadd_pd, _mm_storeu_pd, 2)
FMA_VEC(fma_256, "avx2,fma", __m256d, _mm256_set1_pd, _mm256_fmadd_pd, _mm256_storeu_pd, 4)
FMA_VEC(fma_512, "avx512f,fma", __m512d, _mm512_set1_pd, _mm512_fmadd_pd, _mm512_storeu_pd, 8)

/* flop/s over `threads` threads of FMA at `width` bits (64 = scalar); a sink keeps the results. */
double fma_peak(int width, long iters, int threads) {
    double sink = 0.0, t0 = 0.0, t1 = 0.0;
#pragma omp parallel num_threads(threads) reduction(+ : sink)
    {
#pragma omp barrier
#pragma omp master
        t0 = omp_get_wtime();
        switch (width) {
        case 64: sink += fma_scalar(iters); break;
        case 128: sink += fma_128(iters); break;
        case 256: sink += fma_256(iters); break;
        default: sink += fma_512(iters); break;
        }
#pragma omp barrier
#pragma omp master
        t1 = omp_get_wtime();
    }
    if (sink == 12345.678) return -1.0; /* never: keeps the work */
    return 2.0 * CHAINS * (width / 64) * (double)iters * threads / (t1 - t0);
}

/* One pass of the triad over [lo, hi), compiled for the widest vectors the CPU has. */
__attribute__((target_clones("avx512f", "avx2", "default"))) static void triad_pass(
    double *restrict a, const double *restrict b, const double *restrict c, long lo, long hi) {
    for (long i = lo; i < hi; i++) a[i] = b[i] + 0.5 * c[i];
}

/* Triad bandwidth [B/s] over n doubles per array, `reps` passes, `threads` threads (each thread
 * works on its own first-touched slice). */
double triad(long n, int reps, int threads) {
    double *a = aligned_alloc(64, ((n * 8 + 63) / 64) * 64);
    double *b = aligned_alloc(64, ((n * 8 + 63) / 64) * 64);
    double *c = aligned_alloc(64, ((n * 8 + 63) / 64) * 64);
    if (!a || !b || !c) return -1.0;
    double best = 0.0;
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
        for (long i = 0; i < n; i++) { a[i] = 0.0; b[i] = 1.0; c[i] = 2.0; }
    }
    long passes = 4000000 / n + 1; /* about 4e6 element updates per timing, whatever n */
    for (int r = 0; r < reps; r++) {
        double t0 = omp_get_wtime();
#pragma omp parallel num_threads(threads)
        {
            int t = omp_get_thread_num(), nt = omp_get_num_threads();
            long lo = n * t / nt, hi = n * (t + 1) / nt; /* the slice this thread first touched */
            for (long inner = 0; inner < passes; inner++) triad_pass(a, b, c, lo, hi);
        }
        double t = omp_get_wtime() - t0;
        double bw = (double)passes * 24.0 * (double)n / t;
        if (bw > best) best = bw;
    }
    volatile double keep = a[n / 2];
    (void)keep;
    free(a); free(b); free(c);
    return best;
}
