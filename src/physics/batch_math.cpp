#include "physics/batch_math.h"

#include <cmath>
#include <cstddef>

#if defined(__x86_64__)
#include <immintrin.h>

// libmvec's AVX2 variants (x86_64 vector function ABI names: 'd' = AVX2, 4 lanes). They
// and the loops calling them are compiled for AVX2 only, and called only when the CPU
// has it. (clang, which builds the scene fuzzer, has no option stack and needs none: the
// functions carry their target.)
#if !defined(__clang__)
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif
extern "C" {
__m256d _ZGVdN4v_exp(__m256d);
__m256d _ZGVdN4v_log(__m256d);
__m256d _ZGVdN4v_erfc(__m256d);
}

namespace {

template <__m256d (*vector_f)(__m256d)>
__attribute__((target("avx2,fma"))) void map_avx2(const double* x, double* y, std::size_t n) {
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) _mm256_storeu_pd(y + k, vector_f(_mm256_loadu_pd(x + k)));
  if (k == n) return;
  // The tail through the same vector function, so a value does not depend on its place.
  alignas(32) double in[4] = {1.0, 1.0, 1.0, 1.0}, out[4];
  for (std::size_t l = 0; k + l < n; ++l) in[l] = x[k + l];
  _mm256_store_pd(out, vector_f(_mm256_load_pd(in)));
  for (std::size_t l = 0; k + l < n; ++l) y[k + l] = out[l];
}

}  // namespace
#if !defined(__clang__)
#pragma GCC pop_options
#endif
#endif

namespace twb::batch {

namespace {

double scalar_exp(double x) { return std::exp(x); }
double scalar_log(double x) { return std::log(x); }
double scalar_erfc(double x) { return std::erfc(x); }

#if defined(__x86_64__)
const bool has_avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");

template <__m256d (*vector_f)(__m256d), double (*scalar_f)(double)>
void map(std::span<const double> x, std::span<double> y) {
  if (has_avx2) {
    map_avx2<vector_f>(x.data(), y.data(), x.size());
    return;
  }
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = scalar_f(x[k]);
}
#define TWB_BATCH(vector_f, scalar_f) map<vector_f, scalar_f>
#else
const bool has_avx2 = false;

template <double (*scalar_f)(double)>
void map(std::span<const double> x, std::span<double> y) {
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = scalar_f(x[k]);
}
#define TWB_BATCH(vector_f, scalar_f) map<scalar_f>
#endif

}  // namespace

void exp(std::span<const double> x, std::span<double> y) { TWB_BATCH(_ZGVdN4v_exp, scalar_exp)(x, y); }
void log(std::span<const double> x, std::span<double> y) { TWB_BATCH(_ZGVdN4v_log, scalar_log)(x, y); }
void erfc(std::span<const double> x, std::span<double> y) { TWB_BATCH(_ZGVdN4v_erfc, scalar_erfc)(x, y); }
bool vectorized() { return has_avx2; }

}  // namespace twb::batch
