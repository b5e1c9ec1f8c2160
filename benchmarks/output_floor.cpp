// The floor under every foveated technique on this renderer: the cheapest
// ways to write every output pixel once from a lower-resolution image. On a
// GPU these are nearly free; on llvmpipe a full-resolution pass that reads a
// texture costs a fixed amount whatever its shader does, so no technique that
// composites layers can be faster than native / (its shading + this floor).
//
//   foveate_output_floor [WIDTH HEIGHT [SCALE [REPEATS]]]   (default 1920 1080 3 15)
//
// Prints a Markdown table: median ms of each method over REPEATS runs, each
// run bracketed by glFinish, after two unmeasured runs, and the share of the
// CPU that other processes took meanwhile (a table of 2026-11-23 measured
// under a load of 13-19 on two cores read four to six times too slow).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "foveate/bench/environment.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/format.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/shader.hpp"

using namespace foveate;

namespace {

const char* kConstant = R"(
out vec4 o_color;
void main() { o_color = vec4(0.25, 0.5, 0.75, 1.0); }
)";
const char* kFetch = R"(
in vec2 v_uv;
uniform sampler2D u_source;
out vec4 o_color;
void main() { o_color = texture(u_source, v_uv); }
)";
const char* kTexelFetch = R"(
uniform sampler2D u_source;
uniform vec2 u_texel;
out vec4 o_color;
void main() { o_color = texelFetch(u_source, ivec2(gl_FragCoord.xy * u_texel), 0); }
)";
const char* kFetch4 = R"(
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_texel;
out vec4 o_color;
void main() {
  o_color = 0.25 * (texture(u_source, v_uv + u_texel * vec2(-0.5, -0.5)) +
                    texture(u_source, v_uv + u_texel * vec2(0.5, -0.5)) +
                    texture(u_source, v_uv + u_texel * vec2(-0.5, 0.5)) +
                    texture(u_source, v_uv + u_texel * vec2(0.5, 0.5)));
}
)";
const char* kCompute = R"(
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_source;
layout(rgba8, binding = 0) writeonly uniform image2D u_out;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_out);
  if (p.x >= size.x || p.y >= size.y) return;
  imageStore(u_out, p, texture(u_source, (vec2(p) + 0.5) / vec2(size)));
}
)";

double median_ms(const std::function<void()>& run, int repeats) {
  for (int i = 0; i < 2; ++i) run();
  glFinish();
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    run();
    glFinish();
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

int positive(const char* text, const char* what) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > 16384) {
    std::fprintf(stderr, "foveate_output_floor: %s: expected 1..16384, got '%s'\n", what, text);
    std::exit(2);
  }
  return static_cast<int>(v);
}

struct Row {
  const char* method;
  double ms;
};

// The passes and copies measured, over the targets they need: an sRGB output
// as the techniques write, a full-resolution source and a layer of 1/scale
// the size in three formats.
class OutputFloor {
 public:
  OutputFloor(int width, int height, int scale)
      : W_(width),
        H_(height),
        w_(std::max(1, width / scale)),
        h_(std::max(1, height / scale)),
        constant_(fullscreen(kConstant, "constant.frag")),
        fetch_(fullscreen(kFetch, "fetch.frag")),
        fetch4_(fullscreen(kFetch4, "fetch4.frag")),
        texel_(fullscreen(kTexelFetch, "texel_fetch.frag")),
        compute_(compiler_.build({gpu::StageSource{GL_COMPUTE_SHADER, {{"copy.comp", kCompute}}}},
                                 "copy")),
        out_(gpu::RenderTarget::create(W_, H_)),                   // sRGB, as the output
        same_(gpu::RenderTarget::create(W_, H_)),                  // a full-resolution source
        low_(gpu::RenderTarget::create(w_, h_)),                   // a layer
        low_half_(gpu::RenderTarget::create(w_, h_, GL_RGBA16F)),  // linear layer
        low_unorm_(gpu::RenderTarget::create(w_, h_, GL_RGBA8)),   // no decode
        linear8_(gpu::RenderTarget::create(W_, H_, GL_RGBA8)),     // image-storable
        vao_(gpu::VertexArray::create()) {
    low_.clear(0.3f, 0.6f, 0.9f, 1.0f);
    same_.clear(0.3f, 0.6f, 0.9f, 1.0f);
    low_half_.clear(0.3f, 0.6f, 0.9f, 1.0f);
    low_unorm_.clear(0.3f, 0.6f, 0.9f, 1.0f);
    for (gpu::RenderTarget* t : {&low_, &low_half_, &low_unorm_})
      t->color().set_filter(GL_LINEAR, GL_LINEAR);
  }

  [[nodiscard]] int layer_width() const { return w_; }
  [[nodiscard]] int layer_height() const { return h_; }

  std::vector<Row> passes(int repeats) {
    std::vector<Row> rows;
    rows.push_back(
        {"clear (glClearNamedFramebufferfv)", median_ms([&] { out_.clear(0, 0, 0, 1); }, repeats)});
    rows.push_back(
        {"full-screen pass, constant colour", median_ms([&] { draw(constant_); }, repeats)});
    rows.push_back({"full-screen pass, 1 bilinear fetch from the layer",
                    median_ms([&] { draw(fetch_); }, repeats)});
    rows.push_back({"full-screen pass, 1 texelFetch (nearest) from the layer",
                    median_ms([&] { draw(texel_); }, repeats)});
    source_ = &low_half_;
    rows.push_back({"full-screen pass, 1 bilinear fetch from an RGBA16F layer",
                    median_ms([&] { draw(fetch_); }, repeats)});
    source_ = &low_unorm_;
    rows.push_back({"full-screen pass, 1 bilinear fetch from an RGBA8 (UNORM) layer",
                    median_ms([&] { draw(fetch_); }, repeats)});
    source_ = &low_;
    rows.push_back(
        {"full-screen pass, 4 bilinear fetches", median_ms([&] { draw(fetch4_); }, repeats)});
    return rows;
  }

  std::vector<Row> copies(int repeats) {
    std::vector<Row> rows;
    rows.push_back({"glBlitNamedFramebuffer, linear, layer -> output",
                    median_ms(
                        [&] {
                          glBlitNamedFramebuffer(low_.framebuffer(), out_.framebuffer(), 0, 0, w_,
                                                 h_, 0, 0, W_, H_, GL_COLOR_BUFFER_BIT, GL_LINEAR);
                        },
                        repeats)});
    rows.push_back({"glCopyImageSubData, full-resolution copy",
                    median_ms(
                        [&] {
                          glCopyImageSubData(same_.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                                             out_.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, W_, H_,
                                             1);
                        },
                        repeats)});
    rows.push_back({"compute shader, 1 fetch + imageStore (RGBA8)",
                    median_ms(
                        [&] {
                          compute_.use();
                          glBindTextureUnit(0, low_.color().id());
                          glBindImageTexture(0, linear8_.color().id(), 0, GL_FALSE, 0,
                                             GL_WRITE_ONLY, GL_RGBA8);
                          glDispatchCompute(static_cast<GLuint>((W_ + 7) / 8),
                                            static_cast<GLuint>((H_ + 7) / 8), 1);
                          glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
                        },
                        repeats)});
    return rows;
  }

 private:
  gpu::Program fullscreen(const char* frag, const char* what) const {
    return compiler_.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
                            gpu::StageSource{GL_FRAGMENT_SHADER, {{what, frag}}}},
                           what);
  }

  void draw(const gpu::Program& p) {
    out_.bind();
    gpu::apply(gpu::PassState{});
    p.use();
    glBindTextureUnit(0, source_->color().id());
    p.allow_missing({"u_source", "u_texel"});
    p.set("u_source", 0);
    if (p.uniform_if_present("u_texel") >= 0) {
      if (&p == &texel_)
        p.set("u_texel", float(w_) / float(W_), float(h_) / float(H_));
      else
        p.set("u_texel", 1.0f / float(w_), 1.0f / float(h_));
    }
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  int W_, H_, w_, h_;
  const gpu::ShaderCompiler compiler_;
  const gpu::Program constant_, fetch_, fetch4_, texel_, compute_;
  gpu::RenderTarget out_, same_, low_, low_half_, low_unorm_, linear8_;
  const gpu::RenderTarget* source_ = &low_;
  gpu::VertexArray vao_;
};

}  // namespace

int main(int argc, char** argv) {
  const int W = argc > 1 ? positive(argv[1], "WIDTH") : 1920;
  const int H = argc > 2 ? positive(argv[2], "HEIGHT") : 1080;
  const int scale = argc > 3 ? positive(argv[3], "SCALE") : 3;
  const int repeats = argc > 4 ? positive(argv[4], "REPEATS") : 15;
  try {
    auto context = gpu::create_headless_context({});
    const bench::CpuSample start = bench::sample_cpu();
    OutputFloor floor(W, H, scale);
    std::vector<Row> rows = floor.passes(repeats);
    for (Row& r : floor.copies(repeats)) rows.push_back(r);
    const double others = bench::others_cpu_share(start, bench::sample_cpu());
    // A run under 2 s is too short for the share (others_cpu_share): the
    // load average then says what else ran.
    const std::string share = others < 0 ? "an unknown share" : format_percent(others, 2);
    double load = -1;
    if (getloadavg(&load, 1) != 1) load = -1;
    const auto* renderer = glGetString(GL_RENDERER);
    std::printf(
        "Output floor at %dx%d from a %dx%d layer on %s (median of %d, glFinish-bracketed; other "
        "processes took %s of the CPU meanwhile; load average %.2f)\n\n",
        W, H, floor.layer_width(), floor.layer_height(),
        renderer ? reinterpret_cast<const char*>(renderer) : "?", repeats, share.c_str(), load);
    if (others >= bench::kBusyCpuShare) {
      std::fprintf(stderr,
                   "foveate_output_floor: warning: other processes took %s of the CPU: these "
                   "times are inflated; rerun on a quiet machine\n",
                   share.c_str());
    }
    std::printf("| method | ms |\n|---|---:|\n");
    for (const Row& r : rows) std::printf("| %s | %.1f |\n", r.method, r.ms);
  } catch (const Error& e) {
    std::fprintf(stderr, "foveate_output_floor: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
