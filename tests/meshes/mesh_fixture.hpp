#pragma once
// Renders a mesh scene the way a technique does (prepass, then the scene's
// shading over a view) for the mesh tests.
#include <gtest/gtest.h>

#include <functional>

#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/scenes/scene.hpp"
#include "gl_fixture.hpp"

namespace foveate::test {

class MeshRender : public GlTest {
 protected:
  // Renders `view` of `scene` (prepass, then one shading pass over the view's
  // target, with the rect mapping every technique uses), returning the target;
  // its alpha is 255 where the prepass drew geometry and 0 elsewhere.
  // `before_prepass`, when given, runs just before the prepass (to leave GL
  // state behind as a technique's earlier pass would); the shading pass
  // after it runs with the default PassState.
  Image shade(Scene& scene, const View& view, int width, int height, double time = 1.0,
              const std::function<void()>& before_prepass = {}) {
    FrameInput f;
    f.width = width;
    f.height = height;
    f.time_s = time;
    scene.update(f);
    if (before_prepass) before_prepass();
    scene.prepass(view);
    gpu::apply(gpu::PassState{});
    gpu::ShaderCompiler c({scene_shader_files()});
    std::vector<gpu::StageSource::Piece> pieces = {
        {"map",
         "uniform vec4 u_rect; uniform vec2 u_target;\n"
         "vec2 foveate_map(vec2 f) { return u_rect.xy + f * (u_rect.zw / u_target); }\n"}};
    for (const auto& p : scene.shade_source()) pieces.push_back(p);
    pieces.push_back(
        {"main",
         "out vec4 o_color;\nvoid main() { vec2 p = foveate_map(gl_FragCoord.xy);\n"
         "  o_color = vec4(scene_shade(p).rgb, fetch_surface(p).hit ? 1.0 : 0.0); }\n"});
    gpu::Program p = c.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
                              gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
                             "mesh test");
    gpu::Texture color = gpu::Texture::create_2d(GL_RGBA8, view.target_width, view.target_height);
    gpu::Framebuffer fbo = gpu::Framebuffer::create();
    fbo.attach(GL_COLOR_ATTACHMENT0, color);
    fbo.bind();
    glViewport(0, 0, view.target_width, view.target_height);
    gpu::Samplers samplers;
    scene.bind(p, view, samplers);
    p.set("u_rect", float(view.x0), float(view.y0), float(view.x1 - view.x0),
          float(view.y1 - view.y0));
    p.set("u_target", float(view.target_width), float(view.target_height));
    gpu::VertexArray vao = gpu::VertexArray::create();
    p.use();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return gpu::read_texture(color);
  }
  // Triangles rasterised by a prepass of `view`.
  double triangles(Scene& scene, const View& view, int width, int height, int lod = -1) {
    FrameInput f;
    f.width = width;
    f.height = height;
    f.time_s = 1.0;
    scene.update(f);
    gpu::Query q = gpu::Query::create(GL_PRIMITIVES_GENERATED);
    scene.prepass_begin(view);
    glBeginQuery(GL_PRIMITIVES_GENERATED, q.id());
    scene.prepass_draw(view, lod);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    scene.prepass_end();
    GLuint64 n = 0;
    glGetQueryObjectui64v(q.id(), GL_QUERY_RESULT, &n);
    return static_cast<double>(n);
  }
  static bool sky_like(const uint8_t* p) { return p[2] > p[0] && p[2] > 120; }
};

}  // namespace foveate::test
