// The mesh loader's front end. foveate hands a model file to assimp with the
// flags below (scenes/src/assimp_scene.cpp) and then copies what assimp
// returns into vertex and index arrays; that copy and the upload live in a
// constructor that needs a GL context, so this target runs the import with the
// same flags from memory and checks what the copy relies on: every face that
// is a triangle indexes existing vertices, vertex arrays exist, material
// indices are checked before use. A crash inside assimp itself is reported as
// a finding too (assimp is the system's libassimp, not instrumented).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#pragma GCC diagnostic pop

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // The first byte picks the format hint (what the file extension would say);
  // assimp also sniffs the content.
  static const char* const kHints[] = {"obj", "ply", "gltf", "glb", "stl", "off"};
  const char* hint = kHints[data[0] % (sizeof kHints / sizeof *kHints)];
  // One importer for every input (building one registers every format and
  // costs more than most imports); each ReadFile frees the previous scene.
  static Assimp::Importer* const importer = [] {
    auto* i = new Assimp::Importer();
    i->SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    return i;
  }();
  const aiScene* s = importer->ReadFileFromMemory(
      data + 1, size - 1,
      aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
          aiProcess_PreTransformVertices | aiProcess_SortByPType | aiProcess_ValidateDataStructure,
      hint);
  if (!s || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode) return 0;
  for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
    const aiMesh* am = s->mMeshes[mi];
    foveate::fuzz::check(am != nullptr);
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || am->mNumFaces == 0) continue;
    foveate::fuzz::check(am->mNumVertices == 0 || am->mVertices != nullptr);
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) foveate::fuzz::check(face.mIndices[k] < am->mNumVertices);
    }
  }
  return 0;
}
