// Vision pipelines run frame by frame in the simulator (one serving simulator process per run),
// on a scene directory, a generated scene, or in closed loop where the pipeline's decisions
// drive the simulated robot. A pipeline is a firmware entry in the kernel registry (its C
// orchestration over the kernels); its definition here says how a frame becomes a call and how
// the call's result buffer becomes a decision or a pose.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "check.h"
#include "family.h"
#include "scene/scene_io.h"

namespace bvb {

struct FrameInput {
  int index = 0;
  const Image *grey = nullptr;
  const std::vector<uint8_t> *uyvy = nullptr;  // when the scene has it
  FrameTruth truth;
  const Camera *camera = nullptr;
};

struct FrameOutput {
  bool has_decision = false;
  Drive decision = Drive::Stop;
  bool has_pose = false;
  double x_in = 0, y_in = 0, heading_deg = 0;
  std::vector<std::pair<std::string, double>> diag;  // pipeline-specific numbers, for the CSV
};

struct FrameRecord {
  FrameInput in;
  FrameOutput out;
  uint32_t cycles = 0;
};

struct PipelineDef {
  std::string name;     // bfbench pipeline NAME
  std::string summary;  // one line for --help
  std::string kernel;   // the registry entry; its C and asm implementations differ only in
                        // which kernels they call
  // The call for one frame. Buffers marked persistent (state) are written once and then live
  // in the window between frames.
  std::function<CheckCall(const FrameInput &in, Params &params)> make_call;
  std::function<FrameOutput(const std::vector<std::vector<uint8_t>> &bufs)> decode;
  // Extra summary lines measured against the ground truth (e.g. odometry errors).
  std::function<std::vector<std::string>(const std::vector<FrameRecord> &)> summarize;
};

std::vector<const PipelineDef *> &pipelines();
bool register_pipeline(const PipelineDef *p);
const PipelineDef *find_pipeline(const std::string &name);
#define BVB_PIPELINE(var) static const bool var##_registered_ = ::bvb::register_pipeline(&var)

const char *drive_name(Drive d);

struct PipelineRunOptions {
  std::string impl = "asm";   // asm | c | host
  bool compare_host = false;  // also run the host build and require identical outputs
  bool closed_loop = false;
  int max_frames = 0;         // 0: the scene's
  bool progress = false;
};

struct PipelineRun {
  std::vector<FrameRecord> frames;
  std::vector<std::string> mismatches;  // host vs Blackfin, when compared
  int collisions = 0;
};

// Runs `def` over the frames of a scene directory (open loop) or a generator (open or closed).
PipelineRun run_pipeline(const PipelineDef &def, const Target *target, const SceneData *dir,
                         SceneGenerator *gen, Params &params, const PipelineRunOptions &opts);

std::string pipeline_csv(const PipelineRun &run);
std::vector<std::string> pipeline_summary(const PipelineDef &def, const PipelineRun &run);

// The SRV-1's clock and the BF537's fastest grade.
constexpr double kSrv1Hz = 486e6, kBf537MaxHz = 600e6;

int pipeline_command(int argc, char **argv);

}  // namespace bvb
