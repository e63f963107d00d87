#pragma once
// The SIMD kernel of the band's plan: band_cubic_planar()'s sufficient test
// on two chords at once (SSE2), and the vector helpers it needs.
// Part of the flattener's translation unit (included by flatten_curve.cpp
// alone, so that its kernels inline into the loops that call them).

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace bezcam {

namespace {

#if defined(__SSE2__)
using v2d = double __attribute__((vector_size(16)));
inline v2d vabs(v2d x) { return v2d(_mm_andnot_pd(_mm_set1_pd(-0.0), __m128d(x))); }
inline v2d vmax(v2d a, v2d b) { return v2d(_mm_max_pd(__m128d(a), __m128d(b))); }
inline v2d vsqrt(v2d x) { return v2d(_mm_sqrt_pd(__m128d(x))); }
// band_cubic_planar()'s sufficient test (the one without roots) on two
// chords at once, lane by lane the same arithmetic: ok[i] when it settles
// chord i (it fits, of bound dev[i]); otherwise band_cubic_planar() decides.
inline __attribute__((always_inline)) void band_sufficient2(const v2d* Sx, const v2d* Sy, v2d Ax, v2d Ay, v2d Bx,
                                                            v2d By, v2d budget, bool ok[2], double dev[2]) {
  const v2d abx = Bx - Ax, aby = By - Ay;
  const v2d l2 = abx * abx + aby * aby;
  auto cross_ab = [&](v2d x, v2d y) { return abx * y - aby * x; };
  auto dot_ab = [&](v2d x, v2d y) { return abx * x + aby * y; };
  const v2d w1x = Sx[1] - Ax, w1y = Sy[1] - Ay, w2x = Sx[2] - Ax, w2y = Sy[2] - Ay;
  const v2d d0x = Sx[0] - Ax, d0y = Sy[0] - Ay, d3x = Sx[3] - Bx, d3y = Sy[3] - By;
  const v2d c0 = cross_ab(d0x, d0y), c1 = cross_ab(w1x, w1y), c2 = cross_ab(w2x, w2y), c3 = cross_ab(d3x, d3y);
  const v2d l1 = dot_ab(w1x, w1y), l2p = dot_ab(w2x, w2y);
  const v2d a = 0.5 * (c0 + c1), b = 0.5 * (c1 + c2), c = 0.5 * (c2 + c3);
  const v2d ab = 0.5 * (a + b), bc = 0.5 * (b + c), m = 0.5 * (ab + bc);
  const v2d hin = vmax(vmax(vmax(vabs(a), vabs(ab)), vmax(vabs(m), vabs(bc))), vabs(c));
  const v2d hb = vmax(hin, vmax(vabs(c0), vabs(c3)));
  const v2d a0 = dot_ab(d0x, d0y), a3 = dot_ab(d3x, d3y);
  const v2d U2 = hb * hb + vmax(a0 * a0, a3 * a3);
  const auto fit = (l2 > 1e-300) & (l1 >= 0) & (l1 <= l2) & (l2p >= 0) & (l2p <= l2) & (U2 <= budget * budget * l2);
  const v2d dv = vsqrt(U2 / l2);
  ok[0] = fit[0] != 0, ok[1] = fit[1] != 0;
  dev[0] = dv[0], dev[1] = dv[1];
}
#endif

}  // namespace

}  // namespace bezcam
