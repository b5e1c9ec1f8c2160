#include "foveate/techniques/rect_pass.hpp"

#include <algorithm>
#include <cmath>

namespace foveate::tech {

void RectPass::draw(const gpu::Program& program, const std::vector<PixelRect>& rects, int width,
                    int height) {
  if (rects.empty()) return;
  const auto bytes = static_cast<GLsizeiptr>(rects.size() * sizeof(PixelRect));
  // A fresh store per pass: several rect passes are queued back to back.
  if (!buffer_) buffer_ = gpu::Buffer::create_streamed();
  if (!vao_) vao_ = gpu::VertexArray::create();
  buffer_.stream(bytes, rects.data());
  program.use();
  program.set("u_viewport", float(width), float(height));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_.id());
  glBindVertexArray(vao_.id());
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(rects.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
}

void RectPass::draw(const gpu::Program& program, const std::vector<PixelRect>& rects,
                    const gpu::RenderTarget& target, const gpu::PassState& state) {
  target.bind();
  gpu::apply(state);
  draw(program, rects, target.width(), target.height());
}

std::vector<PixelRect> merge_runs(const std::vector<PixelRect>& rects) {
  std::vector<PixelRect> out;
  for (const PixelRect& r : rects) {
    if (!out.empty()) {
      PixelRect& last = out.back();
      if (last[1] == r[1] && last[3] == r[3] && last[2] >= r[0] && last[0] <= r[0]) {
        last[2] = std::max(last[2], r[2]);
        continue;
      }
    }
    out.push_back(r);
  }
  return out;
}

PixelRect bounding_box(const std::vector<PixelRect>& rects, int grow) {
  if (rects.empty()) return {0, 0, 0, 0};
  PixelRect box = rects.front();
  for (const PixelRect& r : rects)
    box = {std::min(box[0], r[0]), std::min(box[1], r[1]), std::max(box[2], r[2]),
           std::max(box[3], r[3])};
  return {box[0] - grow, box[1] - grow, box[2] + grow, box[3] + grow};
}

std::vector<PixelRect> clip_rects(const std::vector<PixelRect>& rects, const PixelRect& bounds) {
  std::vector<PixelRect> out;
  for (const PixelRect& r : rects) {
    const PixelRect c{std::max(r[0], bounds[0]), std::max(r[1], bounds[1]),
                      std::min(r[2], bounds[2]), std::min(r[3], bounds[3])};
    if (c[2] > c[0] && c[3] > c[1]) out.push_back(c);
  }
  return out;
}

std::vector<PixelRect> coarsen_runs(const std::vector<PixelRect>& rects, double waste) {
  struct Box {
    PixelRect r;
    double covered;
  };
  const auto area = [](const PixelRect& r) { return double(r[2] - r[0]) * (r[3] - r[1]); };
  std::vector<Box> open;
  std::vector<PixelRect> out;
  size_t i = 0;
  while (i < rects.size()) {
    // One band: the rectangles sharing this one's rows.
    size_t j = i;
    while (j < rects.size() && rects[j][1] == rects[i][1] && rects[j][3] == rects[i][3]) ++j;
    std::vector<Box> next;
    std::vector<bool> taken(open.size(), false);
    for (size_t k = i; k < j; ++k) {
      const PixelRect& r = rects[k];
      bool merged = false;
      for (size_t o = 0; o < open.size() && !merged; ++o) {
        const PixelRect& b = open[o].r;
        if (taken[o] || b[3] != r[1] || r[0] >= b[2] || r[2] <= b[0]) continue;
        const PixelRect u{std::min(b[0], r[0]), b[1], std::max(b[2], r[2]), r[3]};
        bool clear = true;
        for (size_t q = i; q < j && clear; ++q)
          clear = q == k || rects[q][2] <= u[0] || rects[q][0] >= u[2];
        for (size_t q = 0; q < open.size() && clear; ++q)
          clear = q == o || open[q].r[2] <= u[0] || open[q].r[0] >= u[2];
        const double covered = open[o].covered + area(r);
        if (!clear || area(u) - covered > waste * area(u)) continue;
        next.push_back({u, covered});
        taken[o] = true;
        merged = true;
      }
      if (!merged) next.push_back({r, area(r)});
    }
    for (size_t o = 0; o < open.size(); ++o)
      if (!taken[o]) out.push_back(open[o].r);
    open = std::move(next);
    i = j;
  }
  for (const Box& b : open) out.push_back(b.r);
  return out;
}

std::vector<PixelRect> disc_rects(double cx, double cy, double radius, int width, int height,
                                  int band) {
  return annulus_rects(cx, cy, 0.0, radius, width, height, band);
}

std::vector<PixelRect> annulus_rects(double cx, double cy, double inner, double outer, int width,
                                     int height, int band) {
  std::vector<PixelRect> out;
  if (outer <= 0.0 || width <= 0 || height <= 0) return out;
  const bool bounded = std::isfinite(outer);
  const int first = bounded ? std::max(0, pixel_index(std::floor(cy - outer)) / band * band) : 0;
  const int last = bounded ? std::min(height, pixel_index(std::ceil(cy + outer)) + 1) : height;
  for (int y0 = first; y0 < last; y0 += band) {
    const int y1 = std::min(height, y0 + band);
    // Nearest and farthest row centres of the band from the centre's row.
    const double near_dy = std::max(0.0, std::max(y0 + 0.5 - cy, cy - (y1 - 0.5)));
    const double far_dy = std::max(std::abs(y0 + 0.5 - cy), std::abs(y1 - 0.5 - cy));
    if (near_dy > outer) continue;
    int x0 = 0, x1 = width;
    if (bounded) {
      const double half = std::sqrt(outer * outer - near_dy * near_dy);
      x0 = std::max(0, pixel_index(std::floor(cx - half - 0.5)));
      x1 = std::min(width, pixel_index(std::ceil(cx + half + 0.5)));
    }
    if (x1 <= x0) continue;
    // Columns whose centres lie inside `inner` on every row of the band:
    // (x + 0.5 - cx)^2 + far_dy^2 < inner^2, less a pixel for safety.
    int h0 = 0, h1 = 0;
    if (far_dy < inner) {
      const double half = std::sqrt(inner * inner - far_dy * far_dy) - 1.0;
      h0 = std::max(x0, pixel_index(std::ceil(cx - half - 0.5)));
      h1 = std::min(x1, pixel_index(std::floor(cx + half - 0.5)) + 1);
    }
    if (h1 <= h0) {
      out.push_back({x0, y0, x1, y1});
      continue;
    }
    if (h0 > x0) out.push_back({x0, y0, h0, y1});
    if (x1 > h1) out.push_back({h1, y0, x1, y1});
  }
  return out;
}

}  // namespace foveate::tech
