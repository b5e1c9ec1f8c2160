#pragma once
// Fast Fourier transforms for the band-pass pyramid of the acuity-aware error:
// a mixed-radix (2, 3, 4, 5) Stockham transform on split real / imaginary
// arrays that transforms many sequences at once, and the 2-D transform of real
// images as half spectra.
#include <cstddef>
#include <vector>

namespace foveate::metrics::detail {

/// The smallest size >= n of the form 2^a 3^b 5^c with a >= 2, so that the
/// size and its half are even.
int fft_size(int n);

/// A complex DFT of length n applied to v sequences at once. The data hold n
/// elements, each a vector of v complex numbers stored contiguously in split
/// arrays: element k of sequence j is (re[k * v + j], im[k * v + j]).
/// Unnormalised; forward X[k] = sum_t x[t] exp(-2 pi i k t / n), inverse with +i.
class FftPlan {
 public:
  explicit FftPlan(int n);
  [[nodiscard]] int size() const { return n_; }
  /// In place; `work` is resized as needed.
  void transform(float* re, float* im, int v, bool inverse, std::vector<float>& work) const;

 private:
  struct Stage {
    int radix;
    int length;            // length of the sub-transforms this stage splits
    int stride;            // number of interleaved sub-transforms (s)
    std::size_t twiddles;  // offset of this stage's twiddles in tw_re_ / tw_im_
  };
  int n_;
  std::vector<Stage> stages_;
  std::vector<float> tw_re_, tw_im_;  // per stage, p-major: w^(p k), k = 1..radix-1
};

/// A plan of the given size from a per-thread cache.
const FftPlan& fft_plan(int n);

/// Half spectrum of a real w x h signal (w and h even): kx = 0..w/2 and
/// ky = 0..h-1 (ky >= h/2 stands for ky - h), stored row by row (ky major).
struct HalfSpectrum {
  int w = 0, h = 0;
  std::vector<float> re, im;
  [[nodiscard]] int stride() const { return w / 2 + 1; }
};

/// Forward transform of a real image stored row-major (w x h).
HalfSpectrum rfft2(const float* data, int w, int h);
/// Inverse transform (unnormalised: the forward then the inverse multiply by
/// w * h) into `out` (w x h, row-major).
void irfft2(HalfSpectrum spectrum, float* out);

}  // namespace foveate::metrics::detail
