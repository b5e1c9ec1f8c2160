// The channel JSON beside a Shadertoy file (NAME.json: {"iChannel0":
// "file.png", ...}). Its reading lives in an internal function of
// scenes/src/shadertoy_scene.cpp that also needs GL for the scene around it,
// so this target runs the same library calls that function makes on the text
// (parse_json, then JsonReader: four optional strings, no other key). Reading
// the images the JSON names is the image decoder's business, not this parser's.
#include <string>

#include "foveate/core/json_read.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  foveate::fuzz::expect_clean([&] {
    const nlohmann::json j = foveate::parse_json(foveate::fuzz::text(data, size), "fuzz.json");
    foveate::JsonReader r(j, "fuzz.json");
    for (int i = 0; i < 4; ++i) {
      std::string f;
      const std::string key = "iChannel" + std::to_string(i);
      r.string(key.c_str(), f);
    }
    r.finish();
  });
  return 0;
}
