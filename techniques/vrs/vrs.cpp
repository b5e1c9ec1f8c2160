// vrs: variable-rate shading with the rates the acuity model gives
// (core/shading_rate.hpp: per 16-px tile the coarsest of 1x1 .. 4x4 whose
// sample spacing keeps two samples per MAR cycle), as engines and headsets
// foveate today. llvmpipe has no VRS, so this is the emulation: every rate
// class present is shaded into a target of its own reduced resolution (W / rw
// x H / rh), limited by a stencil mask to its tiles and the coarser tiles
// next to them, and on mesh scenes its G-buffer is filled only there too.
// The masks are drawn over those tiles alone (common/rects.hpp) and llvmpipe
// rejects whole 4x4 blocks before shading, so the other tiles cost nothing.
// Then the frame is put together in linear light: each pixel reads its class
// bilinearly, and a tile next to a finer one fades into it over one tile, so
// the 1x1 fovea is native and no tile edge shows. Every pass is drawn over
// the tiles that need it, so each output pixel runs one shader once. `fixed` takes the
// rates from the screen centre instead of the gaze (headsets without eye
// tracking).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <string>

#include "../common/registry.hpp"
#include "foveate/core/shading_rate.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

constexpr int kClasses = static_cast<int>(kShadingRates.size());

int class_of(ShadingRate r) {
  return static_cast<int>(std::find(kShadingRates.begin(), kShadingRates.end(), r) -
                          kShadingRates.begin());
}

// Per tile, the classes found in its 3x3 neighbourhood (itself included),
// bit k for class k, over a gx x gy grid of classes in row-major order.
std::vector<std::uint8_t> neighbourhood_classes(const std::vector<std::uint8_t>& classes, int gx,
                                                int gy) {
  static_assert(kClasses <= 8);
  std::vector<std::uint8_t> out(classes.size());
  for (int ty = 0; ty < gy; ++ty) {
    for (int tx = 0; tx < gx; ++tx) {
      unsigned bits = 0;
      for (int y = std::max(0, ty - 1); y <= std::min(gy - 1, ty + 1); ++y)
        for (int x = std::max(0, tx - 1); x <= std::min(gx - 1, tx + 1); ++x)
          bits |= 1u << classes[static_cast<size_t>(y) * size_t(gx) + size_t(x)];
      out[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)] = static_cast<std::uint8_t>(bits);
    }
  }
  return out;
}

// The lowest class in a neighbourhood's bits: the finest class nearby.
int finest_of(unsigned bits) { return std::countr_zero(bits); }

class Vrs final : public Technique {
 public:
  Vrs(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        acuity_(c.acuity),
        tile_(v.integer("tile")),
        min_class_(v.real("min_class")),
        simulate_(v.boolean("hardware") && v.boolean("simulate_driver") &&
                  !hardware_available(v.integer("tile"))),
        hardware_(v.boolean("hardware") && (simulate_ || hardware_available(v.integer("tile")))),
        fixed_(v.boolean("fixed")) {
    ShadingRateOptions o;
    o.tile_px = tile_;
    o.validate();
  }

  // The rates for this gaze (GL grid: rows from the bottom, as the shaders
  // read them). The planner keeps what the display alone decides, and the
  // image is kept while the gaze holds still: a moving gaze costs about
  // 0.85 ms of CPU a frame at 1080p, a still one nothing.
  const ShadingRateImage& rates(const GazeState& g, int w, int h) const {
    if (!planner_ || planner_->display().width_px != w || planner_->display().height_px != h) {
      const Display d =
          w == display_.width_px && h == display_.height_px ? display_ : display_.resized(w, h);
      ShadingRateOptions o;
      o.tile_px = tile_;
      o.origin_bottom_left = true;
      planner_.emplace(d, acuity_, o);
      cached_ = false;
    }
    const Vec2d at = fixed_ ? planner_->display().principal_point() : g.gaze_px;
    const double margin = fixed_ ? 0.0 : latency_margin_deg(g);
    const double scale = fixed_ ? 1.0 : std::max(1.0, g.fovea_scale);
    const std::array<double, 4> key = {at.x, at.y, margin, scale};
    if (!cached_ || key != cached_key_) {
      cached_rates_ = planner_->image(at, margin, scale);
      cached_key_ = key;
      cached_ = true;
    }
    return cached_rates_;
  }

  // Every rate class costs the emulation passes of its own (on mesh scenes
  // the geometry once more), so a class with fewer than min_class of the
  // tiles is shaded at the coarsest class that is as fine in both axes and
  // large enough (1x1 at worst): finer than the model asks, never coarser.
  void merge_small_classes(std::vector<std::uint8_t>& classes,
                           std::array<size_t, kClasses>& count) const {
    const auto least = static_cast<size_t>(std::ceil(min_class_ * double(classes.size())));
    std::array<int, kClasses> into{};
    for (int k = 0; k < kClasses; ++k) into[size_t(k)] = k;
    for (int k = kClasses - 1; k > 0; --k) {
      const size_t n = count[size_t(k)];
      if (n == 0 || n >= least) continue;
      const ShadingRate r = kShadingRates[size_t(k)];
      int best = 0;
      for (int j = 1; j < kClasses; ++j) {
        const ShadingRate c = kShadingRates[size_t(j)];
        if (j == k || count[size_t(j)] < least || c.width > r.width || c.height > r.height)
          continue;
        if (c.width * c.height >
            kShadingRates[size_t(best)].width * kShadingRates[size_t(best)].height)
          best = j;
      }
      into[size_t(k)] = best;
      count[size_t(best)] += n;
      count[size_t(k)] = 0;
    }
    for (std::uint8_t& c : classes) c = static_cast<std::uint8_t>(into[c]);
  }

  // Whether the driver shades at the rates itself (GL_NV_shading_rate_image)
  // with tiles of this size: then no emulation is needed.
  static bool hardware_available(int tile) {
    if (!epoxy_has_gl_extension("GL_NV_shading_rate_image")) return false;
    GLint w = 0, h = 0;
    glGetIntegerv(GL_SHADING_RATE_IMAGE_TEXEL_WIDTH_NV, &w);
    glGetIntegerv(GL_SHADING_RATE_IMAGE_TEXEL_HEIGHT_NV, &h);
    return w == tile && h == tile;
  }

  // The hardware path: the driver shades at the rates itself
  // (GL_NV_shading_rate_image): the class of each tile indexes a palette of
  // the extension's rates (gl_nv_palette), bound as the shading-rate image
  // while the frame is shaded once at native resolution; coverage and depth
  // stay per pixel. A tile next to a finer one is shaded at the finest rate
  // around it (the component-wise least, which is again a rate of the set),
  // as the emulation shades each class over the coarser tiles beside it. The
  // driver copies a fragment's colour to all its pixels, a visible mosaic
  // (on an H100 the raw frame's error steps across rate borders 2.3 times as
  // fast as beside them, 1.06 for the emulation), so the frame is then put
  // together as the emulation does (vrs/hardware_reconstruct.frag): the 1x1
  // tiles copied, the others interpolated between fragment centres and faded
  // into their finer neighbours over one tile. Never runs on llvmpipe;
  // scripts/gpu-bench.sh benches it beside the emulation (vrs.hardware=0).
  FrameStats render_hardware(Scene& scene, const ShadingRateImage& m,
                             const std::vector<std::uint8_t>& classes,
                             const gpu::RenderTarget& target) {
    const int W = target.width(), H = target.height();
    const int gx = m.tiles_x, gy = m.tiles_y;
    std::vector<std::uint8_t> shade(classes.size());
    FrameStats s;
    s.native_pixels = double(W) * H;
    std::vector<PixelRect> fine, coarse;  // the 1x1 tiles, the others
    for (int ty = 0; ty < gy; ++ty) {
      for (int tx = 0; tx < gx; ++tx) {
        const size_t i = static_cast<size_t>(ty) * size_t(gx) + size_t(tx);
        const PixelRect p = tile_pixels(tx, ty, W, H);
        (classes[i] == 0 ? fine : coarse).push_back(p);
        ShadingRate r = kShadingRates[classes[i]];
        for (int y = std::max(0, ty - 1); y <= std::min(gy - 1, ty + 1); ++y) {
          for (int x = std::max(0, tx - 1); x <= std::min(gx - 1, tx + 1); ++x) {
            const ShadingRate n =
                kShadingRates[classes[static_cast<size_t>(y) * size_t(gx) + size_t(x)]];
            r = {std::min(r.width, n.width), std::min(r.height, n.height)};
          }
        }
        const int k = class_of(r);  // the rates are closed under the component-wise least
        shade[i] = static_cast<std::uint8_t>(k < kClasses ? k : 0);
        const int w = p[2] - p[0], h = p[3] - p[1];
        s.shaded_pixels += double((w + r.width - 1) / r.width) * ((h + r.height - 1) / r.height);
      }
    }
    const auto upload = [&](gpu::Texture& texture, const std::vector<std::uint8_t>& data) {
      if (!texture || grid_w_ != gx || grid_h_ != gy) {
        texture = gpu::Texture::create_2d(GL_R8UI, gx, gy);
        texture.set_filter(GL_NEAREST, GL_NEAREST);
      }
      texture.upload(gx, gy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, data.data());
    };
    upload(classes_, shade);
    upload(own_, classes);
    grid_w_ = gx;
    grid_h_ = gy;
    gpu::RenderTarget& frame = targets_[0];
    frame.ensure(W, H, GL_SRGB8_ALPHA8, true);
    frame.color().set_filter(GL_LINEAR, GL_LINEAR);
    frame.color().set_wrap(GL_CLAMP_TO_EDGE);
    const View view = View::full(W, H);
    scene.prepass(view);
    // Mesh scenes shade a coarse fragment from the G-buffer pixel at its
    // centre (deferred_common.glsl); procedural scenes at the centre itself.
    const float sample_offset = scene.info().has_meshes ? 0.5f : 0.0f;
    if (simulate_) {
      // No shading-rate image here: what the driver would leave is made
      // from a full-resolution frame (vrs/simulate_driver.frag), so that the
      // rest of this path runs, and is tested, on any renderer.
      gpu::RenderTarget& full = targets_[1];
      full.ensure(W, H, GL_SRGB8_ALPHA8, true);
      full.color().set_filter(GL_LINEAR, GL_LINEAR);
      kit_.shade(scene, view, kMapRect, full,
                 [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
      kit_.rect_pass(kit_.over_rects("vrs/simulate_driver.frag"), {{0, 0, W, H}}, frame, {},
                     [&](const gpu::Program& p, gpu::Samplers& smp) {
                       smp.bind(p, "u_full", full.color());
                       smp.bind(p, "u_shade", classes_);
                       set_rates(p);
                       p.set("u_tile", tile_);
                       p.set("u_sample_offset", sample_offset);
                     });
    } else {
      const auto& palette = gl_nv_palette();
      const std::vector<GLenum> rates(palette.begin(), palette.end());
      glShadingRateImagePaletteNV(0, 0, static_cast<GLsizei>(rates.size()), rates.data());
      glBindShadingRateImageNV(classes_.id());
      glEnable(GL_SHADING_RATE_IMAGE_NV);
      kit_.shade(scene, view, kMapRect, frame,
                 [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
      glDisable(GL_SHADING_RATE_IMAGE_NV);
      glBindShadingRateImageNV(0);
    }
    copy_native_tiles(merge_runs(fine), frame, target);
    kit_.rect_pass(kit_.over_rects("vrs/hardware_reconstruct.frag"), merge_runs(coarse), target, {},
                   [&](const gpu::Program& p, gpu::Samplers& smp) {
                     smp.bind(p, "u_frame", frame.color());
                     smp.bind(p, "u_shade", classes_);
                     smp.bind(p, "u_own", own_);
                     set_rates(p);
                     p.set("u_tile", tile_);
                     p.set("u_sample_offset", sample_offset);
                   });
    s.parts.push_back({"hardware rates", s.shaded_pixels});
    return s;
  }

  // The 1x1 tiles without a coarser neighbour's fade, from a full-resolution
  // `src` of the target's size: a copy of the bytes where the target has a
  // texture of the same format (0.5-1 ms for a whole 1080p frame on
  // llvmpipe, against 25-35 ms for a pass that fetches each pixel), else a
  // pass that reads each pixel at its centre (reconstruct_copy.frag).
  void copy_native_tiles(const std::vector<PixelRect>& rects, const gpu::RenderTarget& src,
                         const gpu::RenderTarget& target) {
    if (rects.empty()) return;
    if (target.color().id() != 0 && target.color().format() == src.color().format() &&
        target.width() == src.width() && target.height() == src.height()) {
      const gpu::ProfileScope timed("reconstruct_copy");
      for (const PixelRect& r : rects) {
        glCopyImageSubData(src.color().id(), GL_TEXTURE_2D, 0, r[0], r[1], 0, target.color().id(),
                           GL_TEXTURE_2D, 0, r[0], r[1], 0, r[2] - r[0], r[3] - r[1], 1);
      }
      return;
    }
    kit_.rect_pass(kit_.over_rects("vrs/reconstruct_copy.frag"), rects, target, {},
                   [&](const gpu::Program& p, gpu::Samplers& smp) {
                     smp.bind(p, "u_src", src.color());
                     p.set("u_extent", float(src.width()), float(src.height()));
                   });
  }

  // Tile (tx, ty)'s pixels (GL: rows from the bottom) in a W x H target.
  PixelRect tile_pixels(int tx, int ty, int W, int H) const {
    return {tx * tile_, ty * tile_, std::min(W, (tx + 1) * tile_), std::min(H, (ty + 1) * tile_)};
  }

  // u_rates[k]: the width and height of kShadingRates[k].
  static void set_rates(const gpu::Program& p) {
    for (int k = 0; k < kClasses; ++k) {
      const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
      const std::string e = "u_rates[" + std::to_string(k) + "]";
      p.set(e.c_str(), float(r.width), float(r.height));
    }
  }

  // The part of a class's view that `texels` (of its grid) span.
  static View bounds(const View& full, const std::vector<PixelRect>& texels, ShadingRate r) {
    PixelRect box{full.target_width, full.target_height, 0, 0};
    for (const PixelRect& q : texels)
      box = {std::min(box[0], q[0]), std::min(box[1], q[1]), std::max(box[2], q[2]),
             std::max(box[3], q[3])};
    View v = full;
    v.x0 = double(box[0] * r.width);
    v.y0 = double(box[1] * r.height);
    v.x1 = double(box[2] * r.width);
    v.y1 = double(box[3] * r.height);
    return v;
  }

  // Radius (pixels) of the disc around the centre that only 1x1 tiles cover.
  static double native_radius(const ShadingRateImage& m, Vec2d c) {
    double r = 1e9;
    for (int ty = 0; ty < m.tiles_y; ++ty) {
      for (int tx = 0; tx < m.tiles_x; ++tx) {
        if (m.at(tx, ty) == ShadingRate{1, 1}) continue;
        const auto t = m.tile_rect(tx, ty);
        r = std::min(r, std::hypot(c.x - std::clamp(c.x, double(t[0]), double(t[2])),
                                   c.y - std::clamp(c.y, double(t[1]), double(t[3]))));
      }
    }
    return r;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const ShadingRateImage& m = rates(gaze, W, H);
    const int gx = m.tiles_x, gy = m.tiles_y;
    std::vector<std::uint8_t> classes(m.rates.size());
    std::array<size_t, kClasses> count{};
    for (size_t i = 0; i < m.rates.size(); ++i) {
      const int k = class_of(m.rates[i]);
      classes[i] = static_cast<std::uint8_t>(k);
      ++count[static_cast<size_t>(k)];
    }
    if (hardware_) return render_hardware(scene, m, classes, target);
    merge_small_classes(classes, count);
    std::array<bool, kClasses> present{};
    for (int k = 0; k < kClasses; ++k) present[size_t(k)] = count[size_t(k)] > 0;
    const auto class_at = [&](int tx, int ty) {
      return int(classes[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)]);
    };
    // The classes around each tile: its finest neighbour, and which classes
    // it borders.
    const std::vector<std::uint8_t> near = neighbourhood_classes(classes, gx, gy);
    if (!classes_ || grid_w_ != gx || grid_h_ != gy) {
      classes_ = gpu::Texture::create_2d(GL_R8UI, gx, gy);
      classes_.set_filter(GL_NEAREST, GL_NEAREST);
      grid_w_ = gx;
      grid_h_ = gy;
    }
    classes_.upload(gx, gy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, classes.data());
    const auto tile_rect = [&](int tx, int ty) { return tile_pixels(tx, ty, W, H); };

    FrameStats s;
    s.native_pixels = double(W) * H;
    gpu::PassState mask;
    mask.stencil_func = GL_ALWAYS;
    mask.stencil_pass_op = GL_REPLACE;
    mask.stencil_ref = 1;
    mask.stencil_write = true;
    mask.color_off = true;
    gpu::PassState shade;
    shade.stencil_func = GL_EQUAL;
    shade.stencil_ref = 1;
    const gpu::Program& mask_program = kit_.over_rects("vrs/mask.frag");
    const bool meshes = scene.info().has_meshes;
    int first = -1;
    for (int k = 0; k < kClasses; ++k) {
      if (!present[static_cast<size_t>(k)]) continue;
      if (first < 0) first = k;
      const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
      const int tw = (W + r.width - 1) / r.width, th = (H + r.height - 1) / r.height;
      // The texels the reconstruction may read from this class: over its own
      // tiles and the coarser tiles that fade into it, each bilinear read
      // reaching one texel beyond the tile's footprint.
      std::vector<PixelRect> texels;
      for (int ty = 0; ty < gy; ++ty) {
        for (int tx = 0; tx < gx; ++tx) {
          // Its own tiles, and coarser tiles that border it (they fade into it).
          const int c = class_at(tx, ty);
          const unsigned bits = near[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)];
          if (c != k && !(c > k && (bits >> k & 1u))) continue;
          const PixelRect p = tile_rect(tx, ty);
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
      // Only the stencil needs clearing: the reconstruction reads no texel
      // that this frame's mask leaves unshaded.
      gpu::open_write_masks();
      glClearNamedFramebufferfi(t.framebuffer(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
      kit_.rect_pass(mask_program, texels, t, mask);
      // The class's grid: texel i covers screen pixels [i rw, (i + 1) rw).
      const View view{0,  0,  double(tw * r.width), double(th * r.height), tw,
                      th, 1.0};  // native's geometric LOD, as hardware VRS keeps
      const View box = bounds(view, texels, r);
      gpu::PassState draw = shade;
      draw.scissor = {int(box.x0) / r.width, int(box.y0) / r.height, int(box.x1 - box.x0) / r.width,
                      int(box.y1 - box.y0) / r.height};
      if (meshes) {
        // The G-buffer is filled only where this class shades: the same
        // texels, marked in the G-buffer's stencil before the geometry, and
        // the geometry is culled and scissored to their bounding box. (The
        // box is not the view itself: a sub-frustum's projection rounds
        // differently, and the 1x1 class must rasterise exactly as native.)
        scene.prepass_begin(view);
        kit_.rect_pass_in_bound(mask_program, texels, tw, th, mask);
        gpu::apply(draw);
        scene.prepass_draw(box, -1);
        gpu::apply({});
        scene.prepass_end();
      } else {
        scene.prepass(view);
      }
      const double n = kit_.shade(
          scene, view, kMapRect, t,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); }, draw, true);
      s.parts.push_back({r.name(), n});
      s.shaded_pixels += n;
    }
    // Put together: a tile with no finer neighbour is one bilinear read of
    // its class; a tile next to a finer class fades into it.
    std::array<std::vector<PixelRect>, kClasses> plain;
    std::vector<PixelRect> fading;
    for (int ty = 0; ty < gy; ++ty) {
      for (int tx = 0; tx < gx; ++tx) {
        const int c = class_at(tx, ty);
        if (finest_of(near[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)]) < c)
          fading.push_back(tile_rect(tx, ty));
        else
          plain[static_cast<size_t>(c)].push_back(tile_rect(tx, ty));
      }
    }
    // A class target's size in screen pixels (its texels times its rate).
    const auto set_extent = [&](const gpu::Program& p, const char* name, ShadingRate r) {
      p.set(name, float(((W + r.width - 1) / r.width) * r.width),
            float(((H + r.height - 1) / r.height) * r.height));
    };
    const gpu::Program& copy = kit_.over_rects("vrs/reconstruct_copy.frag");
    for (int k = 0; k < kClasses; ++k) {
      const size_t i = static_cast<size_t>(k);
      if (plain[i].empty()) continue;
      if (k == 0) {
        copy_native_tiles(merge_runs(plain[i]), targets_[i], target);
        continue;
      }
      kit_.rect_pass(copy, merge_runs(plain[i]), target, {},
                     [&](const gpu::Program& p, gpu::Samplers& smp) {
                       smp.bind(p, "u_src", targets_[i].color());
                       set_extent(p, "u_extent", kShadingRates[i]);
                     });
    }
    kit_.rect_pass(kit_.over_rects("vrs/reconstruct.frag"), merge_runs(fading), target, {},
                   [&](const gpu::Program& p, gpu::Samplers& smp) {
                     smp.bind(p, "u_classes", classes_);
                     for (int k = 0; k < kClasses; ++k) {
                       const size_t i = static_cast<size_t>(k);
                       const gpu::RenderTarget& t = targets_[present[i] ? i : size_t(first)];
                       const std::string name = "u_class" + std::to_string(k);
                       smp.bind(p, name.c_str(), t.color());
                       const std::string e = "u_extent[" + std::to_string(k) + "]";
                       set_extent(p, e.c_str(), kShadingRates[i]);
                     }
                     p.set("u_tile", tile_);
                   });
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const ShadingRateImage& m = rates(gaze, display_.width_px, display_.height_px);
    const Vec2d c = fixed_ ? display_.principal_point() : gaze.gaze_px;
    std::vector<OverlayShape> shapes = {
        {OverlayShape::Kind::Circle, c.x, c.y, native_radius(m, c), 0, 1, 0.1f, 0.1f}};
    shapes.push_back(gaze_dot(gaze));
    return shapes;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    GazeState g;
    g.gaze_px = display_.principal_point();
    const ShadingRateImage& m = rates(g, display_.width_px, display_.height_px);
    return {{"native_radius_px", native_radius(m, g.gaze_px)},
            {"pixel_ratio", m.pixel_ratio()},
            {"fraction_4x4", m.fraction({4, 4})},
            {"hardware_path", hardware_ ? 1.0 : 0.0},
            {"simulated_driver", simulate_ ? 1.0 : 0.0}};
  }

 private:
  Display display_;
  AcuityModel acuity_;
  int tile_;
  double min_class_;
  bool simulate_;
  bool hardware_;
  gpu::Texture own_;  // hardware path: the model's class per tile (classes_ holds the shaded one)
  mutable std::optional<ShadingRatePlanner> planner_;
  mutable bool cached_ = false;
  mutable std::array<double, 4> cached_key_{};
  mutable ShadingRateImage cached_rates_;
  bool fixed_;
  PassKit kit_;
  gpu::Texture classes_;
  int grid_w_ = 0, grid_h_ = 0;
  std::array<gpu::RenderTarget, kClasses> targets_;
};

}  // namespace

TechniqueInfo vrs_info() {
  TechniqueInfo t;
  t.name = "vrs";
  t.summary =
      "Variable-rate shading with the acuity model's rates per tile (1x1 .. 4x4): the driver's "
      "(GL_NV_shading_rate_image) where it has it, else emulated: each rate class shaded at its "
      "reduced resolution over its tiles, reconstructed in linear light.";
  t.source = "VK_KHR_fragment_shading_rate / D3D12 VRS tier 2, rates from Guenter et al.'s model";
  t.params = {
      plan_margin_param(1.5),
      param("tile", "shading-rate tile size (8, 16 or 32)", "px", ParamType::Integer, 8, 32, 16),
      param("fixed",
            "rates from the lens centre (the principal point), not the gaze (no eye tracking)", "",
            ParamType::Boolean, 0, 1, 0),
  };
  t.params.push_back(param(
      "min_class",
      "a rate class with fewer than this fraction of the tiles is shaded at a finer class "
      "present (each class costs the emulation a pass, and on mesh scenes the geometry, of its "
      "own; 0 = every class as the model gives it)",
      "", ParamType::Real, 0.0, 0.5, 0.02));
  t.params.push_back(param("hardware",
                           "shade with the driver's variable-rate shading "
                           "(GL_NV_shading_rate_image) where it has the extension with this "
                           "tile size; 0 = always the emulation",
                           "", ParamType::Boolean, 0, 1, 1));
  t.params.push_back(param("simulate_driver",
                           "with hardware=1 where the driver has no shading-rate image "
                           "(llvmpipe): take the hardware path anyway, the driver's coarse "
                           "fragments made from a full-resolution frame (as slow as native; "
                           "to test and judge that path without the GPU)",
                           "", ParamType::Boolean, 0, 1, 0));
  t.resolve_passes = {"hardware_reconstruct", "reconstruct", "reconstruct_copy"};
  t.make = construct<Vrs>();
  return t;
}

}  // namespace foveate::tech
