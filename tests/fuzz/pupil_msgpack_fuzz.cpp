// One Pupil Capture gaze frame (a msgpack map) as the live receiver decodes
// it. decode_pupil_gaze never throws: any exception at all is a finding. The
// input as text is also a pupil:HOST:PORT address.
#include "foveate/gaze/pupil.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foveate::gaze;
  const std::string payload = foveate::fuzz::text(data, size);
  (void)decode_pupil_gaze(payload);
  foveate::fuzz::expect_clean([&] {
    const PupilOptions o = parse_pupil_address(payload);
    foveate::fuzz::check(o.port >= 1 && o.port <= 65535 && !o.host.empty());
  });
  return 0;
}
