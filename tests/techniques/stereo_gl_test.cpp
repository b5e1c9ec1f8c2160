// Stereo rendering on the hmd-quest2 preset: a near object seen from two eyes
// (it shifts right in the left eye's image and left in the right's, relative
// to each eye's optical axis), every technique's foveal disc against native
// per eye, per-eye history that never mixes (the right eye's frames do not
// depend on what the left eye rendered), Shadertoy scenes rendering the same
// image per eye, and the renderer refusing shared or wrong-eye techniques.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/techniques/stereo_frame_runner.hpp"
#include "foveate/techniques/technique.hpp"
#include "gl_fixture.hpp"
#include "image_compare.hpp"

using namespace foveate;

namespace {

constexpr int kEye = 160;  // per-eye size in pixels
constexpr double kInf = std::numeric_limits<double>::infinity();

// A red 10 cm cube at the origin in front of a blue wall 3 m behind it; the
// camera 40 cm in front of the cube, looking at it.
struct NearObject {
  std::string model, camera;
  NearObject() {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(::testing::TempDir()) / "foveate_stereo";
    fs::create_directories(dir);
    model = (dir / "near.obj").string();
    camera = (dir / "near_camera.json").string();
    std::ofstream(dir / "near.mtl") << "newmtl red\nKd 0.9 0.1 0.1\nnewmtl blue\nKd 0.1 0.2 0.8\n";
    std::ofstream m(model);
    m << "mtllib near.mtl\nusemtl red\n";
    const double h = 0.05;
    for (int i = 0; i < 8; ++i)
      m << "v " << (i & 4 ? h : -h) << ' ' << (i & 2 ? h : -h) << ' ' << (i & 1 ? h : -h) << '\n';
    m << "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
    m << "usemtl blue\nv -4 -4 -3\nv 4 -4 -3\nv 4 4 -3\nv -4 4 -3\nf 9 10 11 12\n";
    std::ofstream(camera) << R"({"loop": false, "keyframes": [
      {"t": 0, "position": [0, 0, 0.4], "target": [0, 0, 0]},
      {"t": 100, "position": [0, 0, 0.4], "target": [0, 0, 0]}]})";
  }
  std::unique_ptr<Scene> load() const {
    SceneOptions o;
    o.camera_path = camera;
    return load_scene(model, o);
  }
};

// The mean x of the red (cube) pixels, and how many there are.
std::pair<double, int> red_centroid(const Image& img) {
  double sx = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.at(x, y);
      if (p[0] > p[1] + 60 && p[0] > p[2] + 60) {
        sx += x + 0.5;
        ++n;
      }
    }
  }
  return {n ? sx / n : 0.0, n};
}

using test::compare_disc;

// The native disc around the gaze: the smallest circle of the technique's
// overlay (layered's first layer, inset's ring where the blend begins).
double fovea_px(const Technique& t, const GazeState& g) {
  double r = 0.0;
  for (const OverlayShape& s : t.overlay(g)) {
    if (s.kind == OverlayShape::Kind::Circle && (r == 0.0 || s.w < r)) r = s.w;
  }
  return r;
}

class Stereo : public test::GlTest {
 protected:
  const StereoDisplay display =
      StereoDisplay::from(Display::load("hmd-quest2").resized(kEye, kEye));
  FrameRunnerOptions options() const {
    FrameRunnerOptions o;
    o.width = kEye;
    o.height = kEye;
    o.start_time_s = 1.0;
    return o;
  }
  std::unique_ptr<Technique> make(const std::string& name, Eye e) const {
    TechniqueConfig c;
    c.display = display.eye(e);
    c.acuity = AcuityModel::preset("A");
    return make_technique(name, c);
  }
  // Each eye's gaze for a combined gaze at the cyclopean centre converging
  // on the cube (0.35 m away).
  std::array<GazeState, 2> gaze_on_cube() const {
    GazeState g;
    g.gaze_px = {kEye / 2.0, kEye / 2.0};
    return eye_gaze_states(display, g, 0.35);
  }
};

TEST_F(Stereo, NearObjectShiftsRightInTheLeftEyeAndLeftInTheRight) {
  const NearObject files;
  auto left = files.load(), right = files.load();
  StereoFrameRunner r(*left, *right, display, options());
  auto tl = make("native", Eye::Left), tr = make("native", Eye::Right);
  r.render(*tl, *tr, 0, gaze_on_cube());
  const Image li = r.read_eye(Eye::Left), ri = r.read_eye(Eye::Right);
  const auto [lx, ln] = red_centroid(li);
  const auto [rx, rn] = red_centroid(ri);
  ASSERT_GT(ln, 100);
  ASSERT_GT(rn, 100);
  // Relative to each eye's optical axis the cube (front face 0.35 m away)
  // sits +ipd/2 / 0.35 in tangent for the left eye and -ipd/2 / 0.35 for the
  // right: a disparity of f * 0.0635 / 0.35 px between them (f = 160 / 2.28).
  const double pl = display.left.principal_point().x, pr = display.right.principal_point().x;
  const double f = display.left.eye_distance_px();
  EXPECT_GT(lx - pl, 0.0);
  EXPECT_LT(rx - pr, 0.0);
  const double disparity = (lx - pl) - (rx - pr);
  EXPECT_NEAR(disparity, f * 0.0635 / 0.35, 0.15 * f * 0.0635 / 0.35);
  // In image coordinates both differ too: the principal points are mirrored
  // (left eye's axis right of centre).
  EXPECT_GT(pl, kEye / 2.0);
  EXPECT_LT(pr, kEye / 2.0);
  // The side-by-side output holds the left eye in its left half.
  const Image out = r.read_output();
  ASSERT_EQ(out.width, 2 * kEye);
  ASSERT_EQ(out.height, kEye);
  for (int y = 0; y < kEye; y += 7) {
    for (int x = 0; x < kEye; x += 5) {
      for (int ch = 0; ch < 4; ++ch) {
        ASSERT_EQ(out.at(x, y)[ch], li.at(x, y)[ch]);
        ASSERT_EQ(out.at(x + kEye, y)[ch], ri.at(x, y)[ch]);
      }
    }
  }
}

TEST_F(Stereo, EveryTechniqueMatchesNativePerEyeInTheFovea) {
  // Guenter et al.'s scene (textured terrain, objects at many distances),
  // gaze off the axis to the upper left, converging at 2 m.
  auto left = load_scene("guenter"), right = load_scene("guenter");
  StereoFrameRunner r(*left, *right, display, options());
  GazeState cyclopean;
  cyclopean.gaze_px = {0.4 * kEye, 0.45 * kEye};
  const auto gaze = eye_gaze_states(display, cyclopean, 2.0);
  auto nl = make("native", Eye::Left), nr = make("native", Eye::Right);
  r.render(*nl, *nr, 0, gaze);
  const Image ref[2] = {r.read_eye(Eye::Left), r.read_eye(Eye::Right)};
  for (const std::string& name : technique_names()) {
    ASSERT_EQ(scene_mismatch(technique_info(name), left->info()), "") << name;
    auto tl = make(name, Eye::Left), tr = make(name, Eye::Right);
    const int frames = std::max(tl->settle_frames(), 1);
    for (int k = 0; k < frames; ++k) r.render(*tl, *tr, 0, gaze);
    for (Eye e : kEyes) {
      const size_t i = static_cast<size_t>(e);
      const Technique& t = e == Eye::Left ? *tl : *tr;
      const double fovea = std::max(fovea_px(t, gaze[i]), display.eye(e).radius_px_at(2.5));
      const test::Comparison c = compare_disc(ref[i], r.read_eye(e), gaze[i].gaze_px, fovea);
      EXPECT_TRUE(c.within(test::Tolerance{}))
          << name << ", " << eye_name(e) << " eye: max " << c.max_error << ", mean " << c.mean_error
          << ", " << 100 * c.fraction << " % off by more than 16";
    }
  }
}

TEST_F(Stereo, PerEyeHistoryNeverMixes) {
  // The right eye renders the near object with layered (temporal history,
  // half-rate outer layers) for four frames. Whatever the left eye renders
  // beside it (another scene, another gaze), the right eye's frames are the
  // same, bit for bit, as the right eye rendered alone.
  const NearObject files;
  const auto gaze = gaze_on_cube();
  auto right_frames = [&](std::unique_ptr<Scene> left_scene, Vec2d left_gaze) {
    auto right = files.load();
    StereoFrameRunner r(*left_scene, *right, display, options());
    auto tl = make("layered", Eye::Left), tr = make("layered", Eye::Right);
    std::vector<Image> out;
    for (int k = 0; k < 4; ++k) {
      std::array<GazeState, 2> g = gaze;
      g[0].gaze_px = left_gaze;
      r.render(*tl, *tr, k, g);
      out.push_back(r.read_eye(Eye::Right));
    }
    return out;
  };
  const std::vector<Image> a = right_frames(files.load(), gaze[0].gaze_px);
  const std::vector<Image> b = right_frames(load_scene("detail"), {20.0, 30.0});
  // Alone: one FrameRunner for the right eye.
  auto right = files.load();
  FrameRunnerOptions o = options();
  o.eye = eye_view(display, Eye::Right);
  FrameRunner alone(*right, o);
  auto t = make("layered", Eye::Right);
  for (int k = 0; k < 4; ++k) {
    alone.render(*t, k, gaze[1]);
    const Image c = alone.read_output();
    ASSERT_EQ(a[k].rgba, c.rgba) << "frame " << k;
    ASSERT_EQ(b[k].rgba, c.rgba) << "frame " << k;
  }
}

TEST_F(Stereo, FixedFoveationCentresOnEachEyesLens) {
  // vrs without eye tracking (fixed) takes its rates from the lens centre:
  // each eye's principal point, mirrored between the eyes, not the image centre.
  for (Eye e : kEyes) {
    TechniqueConfig c;
    c.display = display.eye(e);
    c.acuity = AcuityModel::preset("A");
    c.params = {{"fixed", 1.0}};
    auto t = make_technique("vrs", c);
    GazeState g;
    g.gaze_px = {10.0, 10.0};  // ignored when fixed
    const std::vector<OverlayShape> shapes = t->overlay(g);
    ASSERT_FALSE(shapes.empty());
    EXPECT_DOUBLE_EQ(shapes[0].x, display.eye(e).principal_point().x) << eye_name(e);
    EXPECT_DOUBLE_EQ(shapes[0].y, display.eye(e).principal_point().y) << eye_name(e);
  }
  EXPECT_GT(display.left.principal_point().x, kEye / 2.0 + 5.0);
}

TEST_F(Stereo, ShadertoyScenesRenderTheSameImagePerEye) {
  auto left = load_scene("detail"), right = load_scene("detail");
  StereoFrameRunner r(*left, *right, display, options());
  auto tl = make("native", Eye::Left), tr = make("native", Eye::Right);
  GazeState g;
  g.gaze_px = {kEye / 2.0, kEye / 2.0};
  r.render(*tl, *tr, 0, eye_gaze_states(display, g, kInf));
  EXPECT_EQ(r.read_eye(Eye::Left).rgba, r.read_eye(Eye::Right).rgba);
}

TEST_F(Stereo, SharedOrWrongEyeTechniquesAreRefused) {
  auto left = load_scene("cheap"), right = load_scene("cheap");
  StereoFrameRunner r(*left, *right, display, options());
  auto tl = make("layered", Eye::Left), tr = make("layered", Eye::Right);
  const auto gaze = gaze_on_cube();
  try {
    r.render(*tl, *tl, 0, gaze);
    FAIL() << "one technique for both eyes was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("technique instance of its own"), std::string::npos);
  }
  try {
    r.render(*tr, *tl, 0, gaze);
    FAIL() << "swapped eyes were accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("given for the left eye is configured for another view"),
              std::string::npos)
        << e.what();
  }
  try {
    StereoFrameRunner shared(*left, *left, display, options());
    FAIL() << "one scene for both eyes was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("scene instance of its own"), std::string::npos);
  }
}

}  // namespace
