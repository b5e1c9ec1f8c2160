// The model corpus (tests/data/models/corpus, written by make_corpus.py): one
// small file per case that users' models bring, each checked on the image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "foveate/core/error.hpp"
#include "foveate/scenes/scene.hpp"
#include "mesh_fixture.hpp"

using namespace foveate;

namespace {

const std::string kCorpus = std::string(FOVEATE_TEST_DATA) + "/models/corpus";
constexpr int W = 96, H = 64;

using Corpus = test::MeshRender;

struct Coverage {
  int pixels = 0;  ///< covered by geometry (alpha 255)
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  [[nodiscard]] int width() const { return x1 - x0 + 1; }
  [[nodiscard]] int height() const { return y1 - y0 + 1; }
};

Coverage coverage(const Image& img) {
  Coverage c;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (img.at(x, y)[3] < 128) continue;
      ++c.pixels;
      c.x0 = std::min(c.x0, x), c.x1 = std::max(c.x1, x);
      c.y0 = std::min(c.y0, y), c.y1 = std::max(c.y1, y);
    }
  }
  return c;
}

// Covered pixels where `channel` clearly dominates the two others.
int dominant(const Image& img, int channel) {
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const uint8_t* p = img.at(x, y);
      if (p[3] < 128) continue;
      const int a = p[channel], b = p[(channel + 1) % 3], c = p[(channel + 2) % 3];
      if (a > 2 * b + 10 && a > 2 * c + 10) ++n;
    }
  }
  return n;
}

std::string rgb(const uint8_t* p) {
  return std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]) + "," +
         std::to_string(p[3]);
}

}  // namespace

// Every way a material names its texture file finds textures/Red.png: the
// quad's centre is red (the texture), not blue (the base colour), and
// nothing is warned.
TEST_F(Corpus, TexturePathForms) {
  for (const char* name : {"tex_backslash", "tex_dot_backslash", "tex_windows_absolute",
                           "tex_drive_slash", "tex_blender", "tex_letter_case"}) {
    testing::internal::CaptureStderr();
    auto scene = load_scene(kCorpus + "/" + name + ".obj");
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, "") << name;
    const Image img = shade(*scene, View::full(W, H), W, H, 0.0);
    const uint8_t* c = img.at(W / 2, H / 2);
    EXPECT_EQ(c[3], 255) << name;
    EXPECT_GT(c[0], 2 * c[2] + 20) << name << ": " << rgb(c);
    EXPECT_GT(c[0], 2 * c[1] + 20) << name << ": " << rgb(c);
  }
}

// A texture that cannot be found: one warning naming the model, the
// material and the texture; the model renders in its base colour (blue).
TEST_F(Corpus, MissingTextureIsAWarning) {
  testing::internal::CaptureStderr();
  auto scene = load_scene(kCorpus + "/tex_missing.obj");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("warning"), std::string::npos) << err;
  EXPECT_NE(err.find("tex_missing.obj"), std::string::npos) << err;
  EXPECT_NE(err.find("material 'm'"), std::string::npos) << err;
  EXPECT_NE(err.find("nowhere/not-here.png"), std::string::npos) << err;
  EXPECT_NE(err.find("not found"), std::string::npos) << err;
  const Image img = shade(*scene, View::full(W, H), W, H, 0.0);
  const uint8_t* c = img.at(W / 2, H / 2);
  EXPECT_GT(c[2], 2 * c[0] + 20) << rgb(c);
  // The older test file whose texture is missing renders too.
  EXPECT_NO_THROW(load_scene(std::string(FOVEATE_TEST_DATA) + "/models/missing_texture.obj"));
}

// An empty texture name is "no texture": base colour, no warning.
TEST_F(Corpus, EmptyTextureNameIsNoTexture) {
  testing::internal::CaptureStderr();
  auto scene = load_scene(kCorpus + "/tex_empty.obj");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  const Image img = shade(*scene, View::full(W, H), W, H, 0.0);
  const uint8_t* c = img.at(W / 2, H / 2);
  EXPECT_GT(c[2], 2 * c[0] + 20) << rgb(c);
}

// A sphere without UVs whose texture (red and green stripes across u) is
// mapped by projection: with generated UVs both colours cover a good part of
// the sphere (without, every pixel would sample the same texel).
TEST_F(Corpus, ProjectionMappingsGetUvs) {
  for (const char* kind : {"planar", "cylindrical", "spherical", "box"}) {
    auto scene = load_scene(kCorpus + "/mapping_" + kind + ".lwo");
    const Image img = shade(*scene, View::full(W, H), W, H, 0.0);
    const Coverage cov = coverage(img);
    ASSERT_GT(cov.pixels, 200) << kind;
    EXPECT_GT(dominant(img, 0), cov.pixels / 8) << kind << ": red";
    EXPECT_GT(dominant(img, 1), cov.pixels / 8) << kind << ": green";
  }
}

// KHR_texture_transform (offset 0.5, 0; scale 0.5) selects the texture's
// top-right texel, green, for the whole quad; untransformed UVs would show
// all four colours.
TEST_F(Corpus, GltfTextureTransform) {
  auto scene = load_scene(kCorpus + "/texture_transform.gltf");
  const Image img = shade(*scene, View::full(W, H), W, H, 0.0);
  const Coverage cov = coverage(img);
  ASSERT_GT(cov.pixels, 300);
  EXPECT_GT(dominant(img, 1), cov.pixels / 3);
  EXPECT_EQ(dominant(img, 0), 0);
  EXPECT_EQ(dominant(img, 2), 0);
}

// A 1 x 1 x 3 box standing on Z: upright (taller than wide on screen) from
// an FBX file's UpAxis metadata and from an OBJ with up = "z"; the OBJ
// without it lies on its side (wider than tall). At 6 s the orbit sees the
// box from the side (+X), whichever way it lies.
TEST_F(Corpus, ZUpStandsUpright) {
  auto fbx = load_scene(kCorpus + "/tall_zup.fbx");
  const Coverage a = coverage(shade(*fbx, View::full(W, H), W, H, 6.0));
  EXPECT_GT(a.height(), 3 * a.width() / 2) << a.width() << "x" << a.height();
  SceneOptions z;
  z.up = "z";
  auto obj_z = load_scene(kCorpus + "/tall_zup.obj", z);
  const Coverage b = coverage(shade(*obj_z, View::full(W, H), W, H, 6.0));
  EXPECT_GT(b.height(), 3 * b.width() / 2) << b.width() << "x" << b.height();
  auto obj = load_scene(kCorpus + "/tall_zup.obj");
  const Coverage c = coverage(shade(*obj, View::full(W, H), W, H, 6.0));
  EXPECT_GT(c.width(), c.height()) << c.width() << "x" << c.height();
  // up = "y" overrides the FBX file's Z: it lies down like the plain OBJ.
  SceneOptions y;
  y.up = "y";
  auto fbx_y = load_scene(kCorpus + "/tall_zup.fbx", y);
  const Coverage d = coverage(shade(*fbx_y, View::full(W, H), W, H, 6.0));
  EXPECT_GT(d.width(), d.height()) << d.width() << "x" << d.height();
  SceneOptions bad;
  bad.up = "x";
  EXPECT_THROW(load_scene(kCorpus + "/tall_zup.obj", bad), Error);
}

// A flat model is seen from its face at time 0: a 2x2 quad standing in the
// YZ plane (edge-on from the orbit's old start) and one lying flat each
// cover more than 15 % of the frame.
TEST_F(Corpus, FlatModelsSeenFromTheirFace) {
  for (const char* name : {"flat_wall", "flat_floor"}) {
    auto scene = load_scene(kCorpus + "/" + name + ".obj");
    const Coverage c = coverage(shade(*scene, View::full(W, H), W, H, 0.0));
    EXPECT_GT(c.pixels, W * H * 15 / 100) << name << ": " << c.pixels;
  }
}

// Non-finite vertices are dropped with their triangles and counted in one
// warning; the rest is framed exactly as the finite cube alone.
TEST_F(Corpus, NonFiniteVerticesDropped) {
  testing::internal::CaptureStderr();
  auto bad = load_scene(kCorpus + "/nonfinite_cube.obj");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("nonfinite_cube.obj"), std::string::npos) << err;
  EXPECT_NE(err.find("3 vertices with an inf or NaN"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  auto good = load_scene(kCorpus + "/finite_cube.obj");
  EXPECT_EQ(bad->info().triangles, good->info().triangles);
  const Image a = shade(*bad, View::full(W, H), W, H, 0.0);
  const Image b = shade(*good, View::full(W, H), W, H, 0.0);
  const Coverage ca = coverage(a), cb = coverage(b);
  EXPECT_GT(cb.pixels, 300);
  EXPECT_EQ(ca.pixels, cb.pixels);
  EXPECT_EQ(ca.x0, cb.x0);
  EXPECT_EQ(ca.y1, cb.y1);
}

TEST_F(Corpus, NothingFiniteIsAnError) {
  try {
    load_scene(kCorpus + "/all_nan.obj");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("all_nan.obj"), std::string::npos) << m;
    EXPECT_NE(m.find("no finite vertices"), std::string::npos) << m;
  }
}

// All-zero normals are regenerated: the quad is lit like the one with
// proper normals (flat_wall faces +X, zero_normals +Z: both face the camera
// at time 0), not black.
TEST_F(Corpus, ZeroNormalsRegenerated) {
  auto zero = load_scene(kCorpus + "/zero_normals.obj");
  const Image img = shade(*zero, View::full(W, H), W, H, 0.0);
  const uint8_t* c = img.at(W / 2, H / 2);
  EXPECT_EQ(c[3], 255);
  EXPECT_GT(c[0] + c[1] + c[2], 3 * 90) << rgb(c);
  auto wall = load_scene(kCorpus + "/flat_wall.obj");
  const Image wall_img = shade(*wall, View::full(W, H), W, H, 0.0);
  const uint8_t* w = wall_img.at(W / 2, H / 2);
  EXPECT_NEAR(c[1], w[1], 40) << rgb(c) << " vs " << rgb(w);
}

// The memory guard refuses a header that declares two billion vertices
// before the importer allocates them, naming the file, the count and the
// option; a small budget refuses an ordinary file too.
TEST_F(Corpus, MemoryGuard) {
  auto message = [](const std::string& path, std::uint64_t limit) -> std::string {
    SceneOptions o;
    o.model_memory_limit = limit;
    try {
      load_scene(path, o);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string huge = message(kCorpus + "/huge_header.ply", 0);
  EXPECT_NE(huge.find("huge_header.ply"), std::string::npos) << huge;
  EXPECT_NE(huge.find("2000000000 vertices"), std::string::npos) << huge;
  EXPECT_NE(huge.find("--model-memory-limit"), std::string::npos) << huge;
  const std::string small = message(std::string(FOVEATE_TEST_DATA) + "/models/sphere.ply", 4096);
  EXPECT_NE(small.find("sphere.ply"), std::string::npos) << small;
  EXPECT_NE(small.find("4.0 KiB"), std::string::npos) << small;
  EXPECT_EQ(message(std::string(FOVEATE_TEST_DATA) + "/models/sphere.ply", 64u << 20), "no error");
}

// What importers leave behind and assimp's validation would refuse is
// repaired: a face with an index out of range is dropped with a warning (the
// good quad still renders); an empty STL solid after a real one is ignored.
TEST_F(Corpus, ImporterLeftoversRepaired) {
  testing::internal::CaptureStderr();
  auto ply = load_scene(kCorpus + "/bad_index.ply");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("bad_index.ply: 1 faces without vertex indices or with indices out of range"),
            std::string::npos)
      << err;
  EXPECT_EQ(ply->info().triangles, 2u);
  EXPECT_GT(coverage(shade(*ply, View::full(W, H), W, H, 0.0)).pixels, W * H / 10);
  auto stl = load_scene(kCorpus + "/empty_solid.stl");
  EXPECT_EQ(stl->info().triangles, 2u);
  EXPECT_GT(coverage(shade(*stl, View::full(W, H), W, H, 0.0)).pixels, W * H / 10);
}

// A model whose triangles all have zero area is an error that says so, not
// an empty frame.
TEST_F(Corpus, OnlyDegenerateTrianglesIsAnError) {
  const std::string path = testing::TempDir() + "/collinear.obj";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("v 0 0 0\nv 1 2 3\nv -1 -2 -3\nf 1 2 3\n", f);
    std::fclose(f);
  }
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("zero area"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}
