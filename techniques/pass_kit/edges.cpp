// PassKit::supersample_edges: mark, list, shade packed, write back.
#include <algorithm>
#include <cstddef>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

// Offsets into the storage buffer (pass_kit/edges_rows.glsl).
constexpr GLintptr kDispatchOffset = 4, kDrawOffset = 16, kRowsOffset = 64;

// The storage's head as edges_list.comp's step 1 writes it (std430).
struct EdgeHead {
  GLuint total;
  GLuint dispatch[3];
  GLuint draw[4];  // DrawArraysIndirectCommand: vertices, rectangles, first, base
  GLint cover[2][4];
};
static_assert(sizeof(EdgeHead) == kRowsOffset && offsetof(EdgeHead, draw) == kDrawOffset &&
              offsetof(EdgeHead, dispatch) == kDispatchOffset);

// The cover's part in the buffer's first `rows` rows: only the rows in use
// are marked (and so reshaded); beyond them a taller buffer holds rows of
// no mapping, or a copy of row 0.
std::vector<PixelRect> in_rows(const std::vector<PixelRect>& cover, int rows) {
  std::vector<PixelRect> out;
  for (PixelRect r : cover) {
    r[3] = std::min(r[3], rows);
    if (r[3] > r[1]) out.push_back(r);
  }
  return out;
}

// Stores each listed texel's packed shading into `buffer` (an sRGB buffer
// through a view of its bytes): one invocation per entry, 64 to a group,
// `count` of them, or as many as the storage's head says when indirect.
void store_packed(const gpu::Program& scatter, const gpu::Texture& shaded, const gpu::Texture& list,
                  const gpu::Buffer& rows, const gpu::RenderTarget& buffer, int columns,
                  bool indirect, GLuint count) {
  // One invocation per entry stores its texel: drawn as points instead, a
  // rasteriser's cost per point outweighed the packed shading on a cheap
  // scene whose every texel is an edge (detail).
  const bool srgb = buffer.color().format() == GL_SRGB8_ALPHA8;
  const gpu::Texture bytes = srgb ? gpu::Texture::view(buffer.color(), GL_RGBA8) : gpu::Texture();
  const gpu::Texture& out = srgb ? bytes : buffer.color();
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  gpu::Samplers samplers;
  scatter.use();
  samplers.bind(scatter, "u_shaded", shaded);
  glBindImageTexture(1, list.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(2, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, out.format());
  scatter.set("u_block_columns", columns);
  scatter.set("u_srgb", srgb ? 1 : 0);
  if (indirect) {
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, rows.id());
    glDispatchComputeIndirect(kDispatchOffset);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  } else {
    glDispatchCompute((count + 63) / 64, 1, 1);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(2, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
}

}  // namespace

PassKit::EdgeScratch& PassKit::edge_scratch(int w, int h) {
  // A window resized again and again would add a size each time: the
  // storage is dropped when more sizes than a frame needs pile up.
  constexpr size_t kMostSizes = 8;
  if (edges_.size() >= kMostSizes && !edges_.count({w, h})) edges_.clear();
  EdgeScratch& e = edges_[{w, h}];
  if (!e.list) {
    e.marks = gpu::Texture::create_2d(GL_R32UI, (w + 31) / 32, h);
    e.list = gpu::Texture::create_2d(GL_R32UI, w, h);
    for (const gpu::Texture* t : {&e.marks, &e.list}) t->set_filter(GL_NEAREST, GL_NEAREST);
    e.rows =
        gpu::Buffer::create(kRowsOffset + static_cast<GLsizeiptr>(sizeof(GLuint)) * h, nullptr);
    e.columns = std::max(1, w / 4);  // 4x4 blocks to a row: room for every texel
    const int most_blocks = (w * h + 15) / 16;
    e.shaded.ensure(4 * e.columns, 4 * ((most_blocks + e.columns - 1) / e.columns), GL_RGBA16F);
  }
  const auto compute = [&](gpu::Program& p, const char* file) {
    if (!p) p = compiler_.build({gpu::StageSource{GL_COMPUTE_SHADER, {{file, {}}}}}, file);
  };
  compute(edge_list_, "pass_kit/edges_list.comp");
  compute(edge_scatter_, "pass_kit/edges_scatter.comp");
  return e;
}

void PassKit::list_edges(const EdgeScratch& e, const gpu::RenderTarget& buffer,
                         const gpu::Texture& scratch, const std::vector<PixelRect>& cover,
                         int first, int last, double contrast, bool wrap_rows, int rows) {
  const int w = buffer.width(), h = buffer.height();
  const gpu::ProfileScope timed("edges");
  const int used = rows > 0 ? std::min(rows, h) : h;
  const std::vector<PixelRect> marked = in_rows(cover, used);
  // The copy holds what the marks compare and what the shading of a marked
  // texel reads (u_centre): the texels covered and their neighbours, all
  // rows where rows wrap. A buffer only partly covered (vrs's 1x1 class:
  // the fovea of a native-sized target) is not copied whole.
  PixelRect box = bounding_box(marked, 1);
  if (wrap_rows) box[1] = 0, box[3] = used;
  box = {std::max(box[0], std::max(first, 0)), std::max(box[1], 0),
         std::min(box[2], std::min(last, w)), std::min(box[3], used)};
  if (box[2] > box[0] && box[3] > box[1]) {
    glCopyImageSubData(buffer.color().id(), GL_TEXTURE_2D, 0, box[0], box[1], 0, scratch.id(),
                       GL_TEXTURE_2D, 0, box[0], box[1], 0, box[2] - box[0], box[3] - box[1], 1);
  }
  const GLuint zero = 0;
  glClearTexImage(e.marks.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindImageTexture(0, e.marks.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  gpu::PassState mark;
  mark.color_off = true;
  rect_pass(over_rects("pass_kit/edges.frag"), marked, buffer, mark,
            [&](const gpu::Program& p, gpu::Samplers& samplers) {
              samplers.bind(p, "u_buffer", scratch);
              p.set("u_edge", float(contrast));
              p.set("u_columns", float(first), float(std::min(last, w)));
              p.set("u_wrap_rows", wrap_rows ? 1 : 0);
              p.set("u_rows", used);
            });
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, e.marks.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(1, e.list.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, e.rows.id());
  edge_list_.use();
  edge_list_.set("u_block_columns", e.columns);
  const auto groups = static_cast<GLuint>((h + 63) / 64);
  for (int step = 0; step < 3; ++step) {
    edge_list_.set("u_step", step);
    glDispatchCompute(step == 1 ? 1 : groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                    GL_COMMAND_BARRIER_BIT);
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
}

PixelCount PassKit::supersample_edges(Scene& scene, const View& view, const std::string& mapping,
                                      const gpu::RenderTarget& buffer, const gpu::Texture& scratch,
                                      const std::vector<PixelRect>& cover, int first, int last,
                                      double contrast, const SetUniforms& set, bool wrap_rows,
                                      int rows, int samples) {
  if (samples != 2 && samples != 4) {
    throw Error("supersample_edges: samples=" + std::to_string(samples) + ": must be 2 or 4");
  }
  EdgeScratch& e = edge_scratch(buffer.width(), buffer.height());
  list_edges(e, buffer, scratch, cover, first, last, contrast, wrap_rows, rows);
  const bool indirect = indirect_edges();
  // Read back: the total, and the packed pass's rectangles (its 4x4 blocks
  // of 16 entries, shade_edges.frag) as the GPU laid them out for the draw.
  EdgeHead head{};
  if (!indirect) {
    glGetNamedBufferSubData(e.rows.id(), 0, sizeof(head), &head);
    if (head.total == 0) return PixelCount(0.0);
  }
  const GLuint count = head.total;
  // The shading and the store read the total from the storage's head, bound
  // at 0 for both (edges_rows.glsl).
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, e.rows.id());
  const SetUniforms set_packed = [&](const gpu::Program& p, gpu::Samplers& samplers) {
    set(p, samplers);
    samplers.bind(p, "u_edge_list", e.list);
    p.set("u_edge_samples", samples);
    samplers.bind(p, "u_centre", scratch);
    p.set("u_block_columns", e.columns);
  };
  if (indirect) {
    const gpu::Program& p = scene_program_with(scene, mapping, "pass_kit/shade_edges.frag", 1,
                                               "pass_kit/packed_rects.vert");
    const gpu::ProfileScope timed(pass_name(p));
    gpu::Samplers samplers;
    scene.bind(p, view, samplers);
    set_packed(p, samplers);
    e.shaded.bind();
    gpu::apply({});
    p.use();
    p.set("u_viewport", float(e.shaded.width()), float(e.shaded.height()));
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, e.rows.id());
    glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(kDrawOffset));
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  } else {
    std::vector<PixelRect> packed;
    for (GLuint i = 0; i < std::min<GLuint>(head.draw[1], 2); ++i)
      packed.push_back({head.cover[i][0], head.cover[i][1], head.cover[i][2], head.cover[i][3]});
    scene_pass(scene, view, scene_program_with(scene, mapping, "pass_kit/shade_edges.frag"),
               e.shaded, {}, set_packed, &packed);
  }
  store_packed(edge_scatter_, e.shaded.color(), e.list, e.rows, buffer, e.columns, indirect, count);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  // The storage is reused by the next call of this size: the total is
  // copied out, to be read with the frame's other counts.
  return indirect ? count_from(e.rows, 0) : PixelCount(static_cast<double>(count));
}

}  // namespace foveate::tech
