// exp, log and erfc over arrays, for the kernels that run at every Gauss point: four
// lanes at a time by glibc's vector math library (libmvec, AVX2) where the CPU has AVX2
// and FMA, else element by element with the scalar libm. The vector functions are
// accurate to a few ulp (glibc documents at most 4), not correctly rounded: results
// differ from the scalar ones at rounding level.
#pragma once

#include <span>

namespace twb::batch {

// y[k] = f(x[k]); x and y have the same size and may be the same array.
void exp(std::span<const double> x, std::span<double> y);
void log(std::span<const double> x, std::span<double> y);
void erfc(std::span<const double> x, std::span<double> y);

// Whether the vector path is taken on this CPU.
bool vectorized();

}  // namespace twb::batch
