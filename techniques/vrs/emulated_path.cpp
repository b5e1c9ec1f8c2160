#include "emulated_path.hpp"

#include <algorithm>
#include <string>

#include "foveate/gpu/profiler.hpp"

namespace foveate::tech::vrs {

namespace {

// The part of a class's view that `texels` (of its grid) span.
View bounds(const View& full, const std::vector<PixelRect>& texels, ShadingRate r) {
  const PixelRect box = bounding_box(texels);
  View v = full;
  v.x0 = double(box[0] * r.width);
  v.y0 = double(box[1] * r.height);
  v.x1 = double(box[2] * r.width);
  v.y1 = double(box[3] * r.height);
  return v;
}

// A class's target size in texels for a width x height frame.
std::array<int, 2> class_size(ShadingRate r, int width, int height) {
  return {(width + r.width - 1) / r.width, (height + r.height - 1) / r.height};
}

}  // namespace

void EmulatedPath::adapt(TileClasses& classes, int gx, int gy, int width, int height) {
  if (!adapt_) return;
  ContentAdapt& a = *adapt_;
  const bool same = a.grid_x() == gx && a.grid_y() == gy && last_size_[0] == width &&
                    last_size_[1] == height &&
                    last_classes_.size() == static_cast<size_t>(gx) * size_t(gy);
  if (!same) {
    a.reset(gx, gy);
    busy_->discard();
  } else {
    const gpu::ProfileScope timed("adapt");
    // The busy tiles of what the last frame shaded (measure_busy_tiles).
    if (busy_->pending())
      busy_->read(
          [&](std::span<const std::uint8_t> busy) { a.mark(busy, last_classes_, measured_); });
    a.settle();
  }
  // The tiles refined this frame: the reconstruction does not fade their
  // neighbours into them.
  refined_ = a.refine(classes);
  coarsened_ = a.coarsen(classes);
}

FrameStats EmulatedPath::render(PassKit& kit, Scene& scene, const TileClasses& classes, int gx,
                                int gy, const gpu::RenderTarget& target) {
  const int W = target.width(), H = target.height();
  std::array<bool, kClasses> present{};
  for (int k = 0; k < kClasses; ++k) present[size_t(k)] = classes.count[size_t(k)] > 0;
  last_classes_ = classes.of_tile;
  last_size_ = {W, H};
  // The classes around each tile: its finest neighbour, and which classes
  // it borders.
  const std::vector<std::uint8_t> seen = seen_by_neighbours(classes.of_tile, refined_);
  Grid grid{classes.of_tile, neighbourhood_classes(seen, gx, gy), gx, gy};
  // A tile coarsened by `smooth` (and still at the class it was coarsened
  // to once small classes merged) fades into no finer neighbour: its
  // content is smooth, where the border between rates does not show, and
  // the finer class is not shaded over it.
  std::vector<bool> coarse(seen.size(), false);
  if (coarsened_.size() == seen.size()) {
    for (size_t t = 0; t < seen.size(); ++t) {
      const int c = classes.of_tile[t];
      coarse[t] = coarsened_[t] && (c == kRefinedClass || c == kClasses - 1);
      if (coarse[t]) grid.near[t] = static_cast<std::uint8_t>(1u << c);
    }
  }
  // The classes texture: a tile's own class in bits 0-2, as its neighbours
  // see it in bits 3-5, bit 6 where coarsened (busy_tiles.comp).
  std::vector<std::uint8_t> packed(seen.size());
  for (size_t t = 0; t < seen.size(); ++t)
    packed[t] = static_cast<std::uint8_t>(classes.of_tile[t] | seen[t] << 3 | (coarse[t] ? 64 : 0));
  upload_classes(classes_, grid_, gx, gy, packed);
  FrameStats s;
  s.native_pixels = double(W) * H;
  if (scene.info().has_meshes) scene.prepass(View::full(W, H));
  std::array<Shaded, kClasses> shaded;
  for (int k = 0; k < kClasses; ++k) {
    if (present[static_cast<size_t>(k)])
      shaded[static_cast<size_t>(k)] = shade_class(kit, scene, grid, k, W, H);
  }
  reconstruct(kit, grid, present, target);
  measure_busy_tiles(kit, present, gx, gy, W, H);
  // Read once the frame's last pass is sent (PixelCount).
  double edges = 0;
  for (int k = 0; k < kClasses; ++k) {
    if (!present[static_cast<size_t>(k)]) continue;
    const Shaded& n = shaded[static_cast<size_t>(k)];
    const double texels = n.texels.read(), reshaded = n.edges.read();
    s.parts.push_back({kShadingRates[static_cast<size_t>(k)].name(), texels});
    s.shaded_pixels += texels + edge_samples_ * reshaded;
    edges += reshaded;
  }
  if (edge_ > 0.0) s.parts.push_back({"supersampled edges", edge_samples_ * edges});
  return s;
}

void EmulatedPath::measure_busy_tiles(const PassKit& kit, const std::array<bool, kClasses>& present,
                                      int gx, int gy, int width, int height) {
  if (!adapt_) return;
  const gpu::ProfileScope timed("adapt");
  // The classes adapt refines, and the 2x2 class while it holds tiles
  // refined (there it counts those tiles alone; its own 2x2 tiles stay);
  // with `smooth`, also the 1x1 and 2x2 classes it may coarsen and the 4x4
  // class that holds tiles it coarsened.
  measured_[0] = smooth_ && present[0];
  bool any = measured_[0];
  for (int k = 1; k < kClasses; ++k) {
    const auto i = static_cast<size_t>(k);
    measured_[i] = present[i] && (adapt_refines(k) || (k == kRefinedClass && adapt_->any_held()) ||
                                  (smooth_ && (k == kRefinedClass || k == kClasses - 1)));
    any = any || measured_[i];
  }
  if (!any) {
    busy_->discard();
    return;
  }
  busy_->begin(kit, gx, gy);
  for (int k = 0; k < kClasses; ++k) {
    if (measured_[static_cast<size_t>(k)])
      busy_->measure(classes_, targets_[static_cast<size_t>(k)].color(), k, tile_, width, height);
  }
  busy_->queue();
}

EmulatedPath::Shaded EmulatedPath::shade_class(PassKit& kit, Scene& scene, const Grid& grid, int k,
                                               int W, int H) {
  const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
  const auto [tw, th] = class_size(r, W, H);
  // The texels the reconstruction may read from this class: over its own
  // tiles and the coarser tiles that border it (they fade into it), each
  // bilinear read reaching one texel beyond the tile's footprint.
  std::vector<PixelRect> texels;
  for (int ty = 0; ty < grid.gy; ++ty) {
    for (int tx = 0; tx < grid.gx; ++tx) {
      const int c = grid.at(tx, ty);
      if (c != k && !(c > k && (grid.near_at(tx, ty) >> k & 1u))) continue;
      const PixelRect p = tile_pixels(tx, ty, tile_, W, H);
      texels.push_back({std::max(0, p[0] / r.width - 1), std::max(0, p[1] / r.height - 1),
                        std::min(tw, (p[2] - 1) / r.width + 2),
                        std::min(th, (p[3] - 1) / r.height + 2)});
    }
  }
  texels = merge_runs(texels);
  gpu::RenderTarget& t = targets_[static_cast<size_t>(k)];
  t.ensure(tw, th, GL_SRGB8_ALPHA8, true);
  t.color().set_filter(GL_LINEAR, GL_LINEAR);
  t.color().set_wrap(GL_CLAMP_TO_EDGE);
  // The reconstruction reads no texel that this frame's mask leaves
  // unshaded, but the edge marks compare neighbours: those left unshaded
  // read as alpha 0 (not shaded), never as an earlier frame's. Nothing
  // reads beyond the texels' box and one texel around it (the edges'
  // neighbours), so only that is cleared: a clear costs per pixel, and the
  // 1x1 class's target is native's size for the fovea's tiles alone.
  t.clear(0, 0, 0, 0, bounding_box(texels, 1));
  const gpu::Program& mask_program = kit.over_rects("vrs/mask.frag");
  const gpu::PassState mark = gpu::PassState::stencil_mark();
  kit.rect_pass(mask_program, texels, t, mark);
  // The class's grid: texel i covers screen pixels [i rw, (i + 1) rw).
  const View view{0,  0,  double(tw * r.width), double(th * r.height), tw,
                  th, 1.0};  // native's geometric LOD, as hardware VRS keeps
  const View box = bounds(view, texels, r);
  gpu::PassState draw = gpu::PassState::stencil_equal();
  draw.scissor = {int(box.x0) / r.width, int(box.y0) / r.height, int(box.x1 - box.x0) / r.width,
                  int(box.y1 - box.y0) / r.height};
  // A mesh scene's classes all shade from native's G-buffer (render() fills
  // it once), as hardware VRS shades coarse pixels over full-rate geometry:
  // a G-buffer per class drew the geometry once per class, and the geometry
  // is what a G-buffer costs here. A screen-space scene has none.
  const View shade_view = scene.info().has_meshes ? View::full(W, H) : view;
  if (!scene.info().has_meshes) scene.prepass(view);
  // Texel i samples the centre of its block's first pixel, i rw + 0.5, not
  // the block's centre: that is a native pixel, whose G-buffer surface is
  // exact (the block's centre is a pixel corner, and the nearest G-buffer
  // pixel displaced every coarse class by half a pixel: 0.08 JOD on
  // guenter). The reconstruction reads at the same place (u_shift).
  View at = view;
  const double sx = 0.5 * (r.width - 1), sy = 0.5 * (r.height - 1);
  at.x0 -= sx, at.x1 -= sx, at.y0 -= sy, at.y1 -= sy;
  const auto set_mapping = [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, at); };
  Shaded shaded;
  shaded.texels = kit.shade(scene, shade_view, kMapRect, t, set_mapping, draw, true);
  // The 1x1 class is native's pixels, which native does not supersample.
  if (edge_ > 0.0 && k > 0) {
    gpu::RenderTarget& copy = scratch_[static_cast<size_t>(k)];
    copy.ensure(tw, th, GL_SRGB8_ALPHA8);
    shaded.edges = kit.supersample_edges(scene, shade_view, kMapRect, t, copy.color(), texels, 0,
                                         tw, edge_, set_mapping, false, 0, edge_samples_);
  }
  return shaded;
}

void EmulatedPath::reconstruct(PassKit& kit, const Grid& grid,
                               const std::array<bool, kClasses>& present,
                               const gpu::RenderTarget& target) {
  const int W = target.width(), H = target.height();
  // A tile with no finer neighbour is one bilinear read of its class; a tile
  // next to a finer class fades into it.
  std::array<std::vector<PixelRect>, kClasses> plain;
  std::vector<PixelRect> fading;
  for (int ty = 0; ty < grid.gy; ++ty) {
    for (int tx = 0; tx < grid.gx; ++tx) {
      const int c = grid.at(tx, ty);
      const PixelRect p = tile_pixels(tx, ty, tile_, W, H);
      if (finest_of(grid.near_at(tx, ty)) < c)
        fading.push_back(p);
      else
        plain[static_cast<size_t>(c)].push_back(p);
    }
  }
  // A class target's size in screen pixels (its texels times its rate), and
  // where its samples sit (shade_class).
  const auto set_extent = [&](const gpu::Program& p, const std::string& extent,
                              const std::string& shift, ShadingRate r) {
    const auto [tw, th] = class_size(r, W, H);
    p.set(extent.c_str(), float(tw * r.width), float(th * r.height));
    p.set(shift.c_str(), 0.5f * float(r.width - 1), 0.5f * float(r.height - 1));
  };
  const gpu::Program& copy = kit.over_rects("vrs/reconstruct_copy.frag");
  for (int k = 0; k < kClasses; ++k) {
    const size_t i = static_cast<size_t>(k);
    if (plain[i].empty()) continue;
    if (k == 0) {
      copy_native_tiles(kit, merge_runs(plain[i]), targets_[i], target);
      continue;
    }
    kit.rect_pass(copy, merge_runs(plain[i]), target, {},
                  [&](const gpu::Program& p, gpu::Samplers& smp) {
                    smp.bind(p, "u_src", targets_[i].color());
                    set_extent(p, "u_extent", "u_shift", kShadingRates[i]);
                  });
  }
  const size_t first =
      static_cast<size_t>(std::find(present.begin(), present.end(), true) - present.begin());
  kit.rect_pass(kit.over_rects("vrs/reconstruct.frag"), merge_runs(fading), target, {},
                [&](const gpu::Program& p, gpu::Samplers& smp) {
                  smp.bind(p, "u_classes", classes_);
                  for (int k = 0; k < kClasses; ++k) {
                    const size_t i = static_cast<size_t>(k);
                    const gpu::RenderTarget& t = targets_[present[i] ? i : first];
                    const std::string name = "u_class" + std::to_string(k);
                    smp.bind(p, name.c_str(), t.color());
                    const std::string at = "[" + std::to_string(k) + "]";
                    set_extent(p, "u_extent" + at, "u_shift" + at, kShadingRates[i]);
                  }
                  p.set("u_tile", tile_);
                });
}

}  // namespace foveate::tech::vrs
