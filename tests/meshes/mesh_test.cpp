// Mesh scenes: real OBJ, glTF and PLY files, the guenter scene, LODs and
// culling, sub-frustum rendering, and bad model files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/scenes/scene.hpp"
#include "mesh_fixture.hpp"
#include "mesh_scene_base.hpp"

using namespace foveate;

namespace {

const std::string kModels = std::string(FOVEATE_TEST_DATA) + "/models";

using Meshes = test::MeshRender;

std::string load_error(const std::string& path) {
  try {
    load_scene(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_F(Meshes, ObjWithMaterialAndTexture) {
  auto scene = load_scene(kModels + "/cube.obj");
  const SceneInfo info = scene->info();
  EXPECT_TRUE(info.has_meshes);
  EXPECT_TRUE(info.has_mesh_lods);
  EXPECT_EQ(info.triangles, 12u);
  const Image img = shade(*scene, View::full(128, 96), 128, 96);
  // Framed automatically: the cube covers the centre, the corners show the sky.
  EXPECT_FALSE(sky_like(img.at(64, 48)));
  EXPECT_TRUE(sky_like(img.at(2, 2)));
  // The texture's quadrant colours appear on the cube.
  bool red = false, green = false;
  for (int y = 20; y < 76; ++y) {
    for (int x = 30; x < 98; ++x) {
      const uint8_t* p = img.at(x, y);
      red = red || (p[0] > 2 * p[1] + 20 && p[0] > 2 * p[2] + 20);
      green = green || (p[1] > 2 * p[0] + 20 && p[1] > 2 * p[2] + 20);
    }
  }
  EXPECT_TRUE(red);
  EXPECT_TRUE(green);
}

TEST_F(Meshes, GltfBaseColour) {
  auto scene = load_scene(kModels + "/quad.gltf");
  EXPECT_EQ(scene->info().triangles, 2u);
  const Image img = shade(*scene, View::full(96, 64), 96, 64);
  const uint8_t* c = img.at(48, 32);
  EXPECT_GT(c[0], c[1] + 40) << int(c[0]) << "," << int(c[1]) << "," << int(c[2]);
  EXPECT_GT(c[0], c[2] + 40);
}

TEST_F(Meshes, ThreeLodsOfAboutTenAndOnePercent) {
  auto scene = load_scene(kModels + "/sphere.ply");
  // A large view, so that automatic LOD keeps full detail at level 0.
  const double full = triangles(*scene, View::full(1024, 1024), 1024, 1024, 0);
  const double mid = triangles(*scene, View::full(1024, 1024), 1024, 1024, 1);
  const double low = triangles(*scene, View::full(1024, 1024), 1024, 1024, 2);
  EXPECT_GT(full, 4000);
  EXPECT_NEAR(mid / full, 0.10, 0.04);
  EXPECT_NEAR(low / full, 0.01, 0.008);
  EXPECT_GE(low, 3);
}

TEST_F(Meshes, AutomaticLodSeesThePixelPitch) {
  auto scene = load_scene(kModels + "/sphere.ply");
  View fine = View::full(256, 256);
  View coarse = fine;
  coarse.pixel_scale = 16.0;
  EXPECT_LT(triangles(*scene, coarse, 256, 256), triangles(*scene, fine, 256, 256));
  // The guenter scene: a layer at sampling factor 4 draws far fewer triangles
  // than native, and a small inner layer culls most objects.
  auto g = load_scene("guenter");
  const double native = triangles(*g, View::full(320, 180), 320, 180);
  View outer = View::full(320, 180);
  outer.target_width = 80;
  outer.target_height = 45;
  outer.pixel_scale = 4.0;
  View inner{140, 70, 180, 110, 40, 40, 1.0};
  EXPECT_LT(triangles(*g, outer, 320, 180), 0.5 * native);
  EXPECT_LT(triangles(*g, inner, 320, 180), 0.5 * native);
  EXPECT_GT(native, 20000);
}

TEST_F(Meshes, SkipRectangleLeavesOutObjectsWhollyInsideIt) {
  // A skip rectangle far wider than the screen leaves out every object but
  // those that reach out of its frustum (the floor, which runs behind the
  // eye: 16 % of the triangles); one over the centre leaves out the objects
  // wholly inside it and keeps those that reach beyond it; an empty one
  // changes nothing.
  auto g = load_scene("guenter");
  const double all = triangles(*g, View::full(320, 180), 320, 180);
  View everything = View::full(320, 180);
  everything.skip_x0 = -1000;
  everything.skip_y0 = -1000;
  everything.skip_x1 = 1320;
  everything.skip_y1 = 1180;
  EXPECT_LT(triangles(*g, everything, 320, 180), 0.25 * all);
  View centre = View::full(320, 180);
  centre.skip_x0 = 100;
  centre.skip_y0 = 40;
  centre.skip_x1 = 220;
  centre.skip_y1 = 140;
  const double some = triangles(*g, centre, 320, 180);
  EXPECT_LT(some, all);
  EXPECT_GT(some, 0.2 * all);
  View none = View::full(320, 180);
  none.skip_x0 = none.skip_x1 = 160;
  EXPECT_EQ(triangles(*g, none, 320, 180), all);
}

TEST_F(Meshes, SubFrustumEqualsTheCropOfTheFullFrame) {
  for (const std::string& name : {kModels + "/cube.obj", std::string("guenter")}) {
    auto scene = load_scene(name);
    const Image full = shade(*scene, View::full(128, 96), 128, 96);
    // Screen rect [32, 96] x [24, 72] (GL origin bottom-left) into a 64x48 target.
    const Image part = shade(*scene, View{32, 24, 96, 72, 64, 48, 1.0}, 128, 96);
    int off = 0;
    for (int y = 0; y < 48; ++y) {
      for (int x = 0; x < 64; ++x) {
        const uint8_t* a = part.at(x, y);
        const uint8_t* b = full.at(32 + x, (96 - 72) + y);
        for (int c = 0; c < 3; ++c) off += std::abs(int(a[c]) - int(b[c])) > 24 ? 1 : 0;
      }
    }
    // Rasterisation of a sub-frustum can differ on edge pixels only.
    EXPECT_LT(off, 64 * 48 * 3 / 50) << name;
  }
}

TEST_F(Meshes, ObjectPositionsAreTheVisibleObjects) {
  auto g = load_scene("guenter");
  FrameInput f;
  f.width = 320;
  f.height = 180;
  f.time_s = 2.0;
  g->update(f);
  const auto pos = g->object_positions();
  // Only objects in front of the camera and on screen: some of the 400, not all.
  ASSERT_GT(pos.size(), 10u);
  EXPECT_LT(pos.size(), 400u);
  for (const Vec2d& p : pos) {
    EXPECT_GE(p.x, 0);
    EXPECT_LE(p.x, 320);
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.y, 180);
  }
}

TEST_F(Meshes, EachSurfaceIsLitOnTheSideTheEyeSees) {
  // One cube three ways: counter-clockwise faces with outward normals (GL's
  // front faces), the same faces wound clockwise (files disagree on
  // winding, as guenter's own parametric objects did), and outward faces
  // whose normals point inward (a surface seen from its back). Shading
  // takes the normal of the side the eye sees, so all three look alike
  // (by gl_FrontFacing's word the second and third would be lit from inside).
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("foveate-winding-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  // Counter-clockwise seen from outside, with each face's outward normal.
  const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {0, 4, 7, 3},
                           {5, 1, 2, 6}, {7, 6, 2, 3}, {0, 1, 5, 4}};
  const int normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  const auto write = [&](const std::string& name, bool clockwise, float normal_sign) {
    std::ofstream f(dir / name);
    for (const auto& p : v) f << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (const auto& n : normals)
      f << "vn " << normal_sign * float(n[0]) << ' ' << normal_sign * float(n[1]) << ' '
        << normal_sign * float(n[2]) << '\n';
    for (int i = 0; i < 6; ++i) {
      f << 'f';
      for (int k = 0; k < 4; ++k) {
        const int c = clockwise ? faces[i][3 - k] : faces[i][k];
        f << ' ' << c + 1 << "//" << i + 1;
      }
      f << '\n';
    }
    return (dir / name).string();
  };
  const std::string paths[3] = {write("ccw.obj", false, 1.0f), write("cw.obj", true, 1.0f),
                                write("inward.obj", false, -1.0f)};
  Image img[3];
  for (int i = 0; i < 3; ++i) {
    auto scene = load_scene(paths[i]);
    img[i] = shade(*scene, View::full(96, 72), 96, 72);
  }
  fs::remove_all(dir);
  ASSERT_EQ(img[0].at(48, 36)[3], 255);  // the cube fills the centre (alpha: geometry)
  for (int i = 1; i < 3; ++i) {
    int worst = 0;
    for (int y = 0; y < 72; ++y)
      for (int x = 0; x < 96; ++x)
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(int(img[i].at(x, y)[c]) - int(img[0].at(x, y)[c])));
    EXPECT_LE(worst, 2) << paths[i];
  }
}

TEST_F(Meshes, AWhiteTextureChangesNothing) {
  // The prepass has a program for materials with an albedo texture and one
  // for those without (the texture read costs llvmpipe every fragment even
  // under a branch not taken). A white texture multiplies the albedo by one,
  // so the same cube with and without it must shade the same: the two
  // programs write the same G-buffer.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("foveate-white-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Image white(2, 2);
  std::fill(white.rgba.begin(), white.rgba.end(), std::uint8_t{255});
  write_png((dir / "white.png").string(), white);
  const auto write = [&](const std::string& name, bool textured) {
    std::ofstream m(dir / (name + ".mtl"));
    m << "newmtl clay\nKd 0.8 0.5 0.3\nNs 10\n" << (textured ? "map_Kd white.png\n" : "");
    std::ofstream f(dir / (name + ".obj"));
    f << "mtllib " << name << ".mtl\n";
    for (const char* v :
         {"-1 -1 -1", "1 -1 -1", "1 1 -1", "-1 1 -1", "-1 -1 1", "1 -1 1", "1 1 1", "-1 1 1"})
      f << "v " << v << '\n';
    f << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl clay\n";
    for (const char* q : {"5/1 6/2 7/3 8/4", "2/1 1/2 4/3 3/4", "1/1 5/2 8/3 4/4",
                          "6/1 2/2 3/3 7/4", "8/1 7/2 3/3 4/4", "1/1 2/2 6/3 5/4"})
      f << "f " << q << '\n';
    return (dir / (name + ".obj")).string();
  };
  const std::string paths[2] = {write("plain", false), write("white", true)};
  Image img[2];
  for (int i = 0; i < 2; ++i) {
    auto scene = load_scene(paths[i]);
    img[i] = shade(*scene, View::full(96, 72), 96, 72);
  }
  fs::remove_all(dir);
  ASSERT_EQ(img[0].at(48, 36)[3], 255);  // the cube fills the centre
  // The clay colour shows (red over green over blue), lit.
  const uint8_t* c = img[0].at(48, 36);
  EXPECT_GT(c[0], c[1]);
  EXPECT_GT(c[1], c[2]);
  int worst = 0;
  for (size_t i = 0; i < img[0].rgba.size(); ++i)
    worst = std::max(worst, std::abs(int(img[0].rgba[i]) - int(img[1].rgba[i])));
  EXPECT_EQ(worst, 0) << "largest channel difference between the plain and the white-textured cube";
}

TEST_F(Meshes, BadModelFiles) {
  EXPECT_NE(load_error(kModels + "/nope.obj").find("nor an existing file"), std::string::npos);
  const std::string empty = load_error(kModels + "/empty.obj");
  EXPECT_NE(empty.find("empty.obj"), std::string::npos) << empty;
  EXPECT_NE(empty.find("empty"), std::string::npos) << empty;
  const std::string trunc = load_error(kModels + "/truncated.obj");
  EXPECT_NE(trunc.find("truncated.obj"), std::string::npos) << trunc;
  const std::string bad = load_error(kModels + "/malformed.glb");
  EXPECT_NE(bad.find("malformed.glb"), std::string::npos) << bad;
  const std::string none = load_error(kModels + "/no_triangles.obj");
  EXPECT_NE(none.find("no triangles"), std::string::npos) << none;
  EXPECT_NE(load_error(kModels).find("directory"), std::string::npos);
}

TEST_F(Meshes, PrepassIgnoresTheStateItFinds) {
  // A technique's pass before a prepass may leave a scissor, a stencil test
  // or blending on (vrs's class passes are scissored): the prepass clears and
  // draws its whole G-buffer regardless, so the frame is the same.
  auto scene = load_scene(kModels + "/cube.obj");
  const View view = View::full(64, 48);
  const Image clean = shade(*scene, view, 64, 48);
  const Image after = shade(*scene, view, 64, 48, 1.0, [] {
    gpu::PassState dirty = gpu::PassState::stencil_equal(7);
    dirty.scissor = {0, 0, 8, 8};
    gpu::apply(dirty);
    glEnable(GL_BLEND);
  });
  int geometry = 0, differ = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      geometry += clean.at(x, y)[3] == 255 ? 1 : 0;
      differ += std::equal(clean.at(x, y), clean.at(x, y) + 4, after.at(x, y)) ? 0 : 1;
    }
  }
  EXPECT_GT(geometry, 64 * 48 / 10);  // the cube covers part of the frame
  EXPECT_EQ(differ, 0);
}

TEST_F(Meshes, PrepassRestoresTheFramebufferItFound) {
  auto scene = load_scene(kModels + "/cube.obj");
  FrameInput f;
  f.width = 64;
  f.height = 48;
  scene->update(f);
  gpu::RenderTarget mine = gpu::RenderTarget::create(64, 48);
  mine.bind();
  glViewport(1, 2, 30, 20);
  scene->prepass(View::full(64, 48));
  GLint fb = 0, vp[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fb);
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(static_cast<GLuint>(fb), mine.framebuffer());
  EXPECT_EQ(vp[0], 1);
  EXPECT_EQ(vp[3], 20);
  // Shading bound for a view other than the prepass's is a technique bug, said so.
  gpu::ShaderCompiler c({scene_shader_files()});
  std::vector<gpu::StageSource::Piece> pieces = {
      {"map", "vec2 foveate_map(vec2 f) { return f; }\n"}};
  for (const auto& p : scene->shade_source()) pieces.push_back(p);
  pieces.push_back(
      {"main", "out vec4 o_color;\nvoid main() { o_color = scene_shade(gl_FragCoord.xy); }\n"});
  gpu::Program p = c.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
                            gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
                           "mesh test");
  gpu::Samplers samplers;
  EXPECT_THROW(scene->bind(p, View::full(32, 24), samplers), Error);
}
