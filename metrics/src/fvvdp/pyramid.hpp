#pragma once
// The decimated Laplacian pyramid of FovVideoVDP (Burt and Adelson's, with the
// 5-tap kernel of a = 0.4), with the reference implementation's edge rules so
// that the bands, and hence the JODs, agree with it.
#include <vector>

#include "foveate/metrics/metrics.hpp"

namespace foveate::metrics::fvvdp {

/// The generating kernel [1/4 - a/2, 1/4, a, 1/4, 1/4 - a/2] with a = 0.4.
inline constexpr float kKernel[5] = {0.05f, 0.25f, 0.4f, 0.25f, 0.05f};

/// Blurs with kKernel and keeps every other sample: ceil(w / 2) x ceil(h / 2).
/// Rows and columns are mirrored at the start (sample -1 is sample 0, -2 is
/// 1). At the end, rows are mirrored the same way; the last column follows
/// the rule for the last row of an image of the input's *height* parity (a
/// quirk of the reference, kept: it changes coarse bands of images whose
/// width and height halve to sizes of different parity).
Map reduce(const Map& in);
/// The same into `out`, with `rows` as working space: buffers of the right
/// size are reused without being cleared.
void reduce(const Map& in, Map& out, Map& rows);

/// Upsamples `in` to width x height (each at most twice in's, rounded down
/// by at most one): zeros between the samples, the first and last sample
/// repeated beyond the edges, blurred with 2 kKernel.
void expand(const Map& in, int width, int height, Map& out);
void expand(const Map& in, int width, int height, Map& out, Map& rows);

/// Sets a map's size, keeping its storage (and contents) when it has the size already.
inline void resize(Map& m, int width, int height) {
  m.width = width;
  m.height = height;
  m.values.resize(static_cast<size_t>(width) * height);
}

/// Number of band-pass levels the metric judges for an image of width x
/// height at `ppd`: the bands' frequencies are ppd / 2 and then 0.3228 ppd / 2
/// halved per level, up to and including the first at or below 0.5 cpd, but
/// no more than floor(log2(min(width, height))) - 1. The Gaussian pyramid has
/// one level more (its coarsest, the base band, is not judged).
int band_count(int width, int height, double ppd);
/// Centre frequency of band `b` in cycles per degree.
double band_frequency(int band, double ppd);

}  // namespace foveate::metrics::fvvdp
