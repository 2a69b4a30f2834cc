// What the obstacle-avoidance pipelines (harness/pipelines/*.cpp) share: the firmware structs
// as bytes, the result's decoding, where working buffers go, and the frame sequences their
// checks and benches run on.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "bvb/pipeline.h"
#include "check.h"
#include "family.h"
#include "session/runner.h"
#include "scene/scene_io.h"

namespace bvb {
namespace pipe {

template <class T> std::vector<uint8_t> bytes_of(const T &v) {
  std::vector<uint8_t> b(sizeof(T));
  std::memcpy(b.data(), &v, sizeof(T));
  return b;
}

template <class T> T from_bytes(const std::vector<uint8_t> &b) {
  T v{};
  std::memcpy(&v, b.data(), std::min(sizeof(T), b.size()));
  return v;
}

bvb_pipe_frame frame_info(const FrameInput &in, int stages);

// The decision and the named diag words of a result buffer.
FrameOutput decode_result(const std::vector<uint8_t> &result, const std::vector<std::string> &diag_names);

// Bytes each L1 memory offers buffers in the product firmware (from its linker symbols), and a
// first-fit placer over them: a buffer goes to the first listed memory with room, else SDRAM.
class Placer {
 public:
  Placer();
  uint32_t place(const Buffer &b, std::initializer_list<uint32_t> prefer);

 private:
  uint64_t room_[BVB_PLACE_COUNT] = {};
};

// The first row that can show floor: below the horizon of the scene's camera (camera.h).
int horizon_row(const Camera &cam);

// The frame a scene shows at `index`, with its truth, for checks and benches.
struct SceneFrame {
  Image grey;
  FrameTruth truth;
  Camera camera;
};
// Frames [0, count) of a scene spec (scene_io.h) rendered by the generator.
std::vector<SceneFrame> render_frames(const std::string &spec, int count);
// Frames [first, first + count) of a bundled scene (frames/scenes/NAME).
std::vector<SceneFrame> bundled_frames(const std::string &name, int first, int count);
std::string bundled_scene_dir(const std::string &name);
// The benches' two frames at w x h (scene/bench_scene.h: stored, hash-checked, resampled with
// integer code), so that a pipeline's bench input is the same bytes on every host.
std::vector<SceneFrame> bench_frames(int w, int h);

// Runs `def` over `frames` on the host and returns each frame's call with the state it starts
// from filled in (the host build's state after the previous frame): each call then checks one
// frame on its own, with no session. The last element of `outputs` gets each frame's decoding.
std::vector<CheckCall> host_sequence(const PipelineDef &def, const std::vector<SceneFrame> &frames,
                                     Params &params, int state_buffer,
                                     std::vector<FrameOutput> *outputs = nullptr);

}  // namespace pipe
}  // namespace bvb
