// Scenes: a spec string -> a frame sequence with ground truth, generated frame by frame
// (SceneGenerator, also the closed-loop API), written to and read back from a directory.
//
// Spec string: comma-separated key=value pairs, e.g.
//   arena=boxes,path=square,size=160x120,frames=200,seed=7,noise=2
// Keys (defaults in brackets; inches, degrees, frames; the range each accepts after the colon,
// also printed by `bfbench scene --help`; a value outside is an InputError naming the key):
//   arena=NAME|FILE [boxes]    an arena of frames/arenas/ (world.h) or a path to an arena file
//   path=NAME|SCRIPT [straight]  straight | turn | square | odo_a | odo_b | avoid | a script
//                              like F36+R90+F11 (paths.h; at most a million steps). avoid: the
//                              robot drives forward and turns away whenever the truth says
//                              blocked (an oracle driver)
//   length=IN [36]: -1000..1000  straight's length (negative: backwards)
//   angle=DEG [90]: -3600..3600  turn's angle (+ left)
//   side=IN [36]: 0.01..1000     square's side        dir=left|right [left] square's turns
//   size=WxH [160x120]: 2..4096 a side
//   frames=N|auto [auto]: 1..100000; auto: the path's steps + 1 (avoid: 300); a longer run
//                              stands still at the end, a shorter one is cut
//   seed=N [1]: 0..999999999999999999   sensor noise and encoder slip/noise
//   noise=SIGMA [0]: 0..100   Gaussian noise per RGB channel, in levels
//   speed=IN [0.5]: 0.001..12 per frame    turn_rate=DEG [3]: 0.001..90 per frame
//   fx=PX|auto [auto]: 0.05..20 x the width   focal length, fy = fx (fields of view 169 to
//                              2.9 deg); auto = 0.875 * width (camera.h)
//   cam_height=IN [4]: 0.5..36  tilt=DEG [10]: -60..80  cam_offset=IN [0]: -12..12  (camera.h)
//   ss=N [3]: 1..8    supersampling per axis at edges (render.h)
//   mover=none|cross|arena [none]  cross: a dark red cylinder (radius 2.5, height 5) shuttling
//                     across the start heading 30 in ahead, from 12 in right to 12 in left
//                     of it and back, 0.4 in/frame (in view from the start pose); arena: the
//                     arena file's movers
//   flicker=A [0]: 0..0.9   flicker_period=N [50]: 2..100000   gain x (1 + A sin(2 pi frame / N))
//   light_step=K|none [none]: 0..100000  step_gain=G [1]: 0..10  step_offset=O [0]: -255..255
//                     from frame K on: gain x G, + O
//   slip=S [0]: 0..1  enc_noise=T [0]: 0..100 ticks  tpi=N [50]: 1..10000
//   wheelbase=IN [4]: 0.5..60   encoders (paths.h)
//   radius=IN [3]: 0.1..60  the robot's disc    block_dist=IN [12]: 0..1000  D of "blocked" (world.h)
//   start=X:Y:H|arena [arena]: X, Y -1000..1000, H -360..360
//   texture_seed=N|arena [arena]: 0..999999999999999999 (as an arena file's texture_seed)
//   uyvy=0|1 [1] flow=0|1 [1] rgb=0|1 [0]   which files write_scene writes
//
// Scene directory (everything in one directory, self-describing):
//   scene.txt        "key = value" lines: format, the resolved spec, the intrinsics, the script
//   arena.txt        the arena as used (format_arena), so the directory needs nothing else
//   frame_NNNN.pgm   grey (= the Y plane of the .uyvy), NNNN = frame index, 4+ digits
//   frame_NNNN.uyvy  UYVY 4:2:2, U Y0 V Y1 (uyvy=1)       frame_NNNN.ppm  RGB (rgb=1)
//   flow_NNNN.flo    true flow frame NNNN -> NNNN+1 (flow=1; Middlebury, unknown = 1e10)
//   truth.csv        one row per frame:
//     frame,x_in,y_in,heading_deg,step_fwd_in,step_turn_deg,blocked,clearance_in,collision,
//     left_ticks,right_ticks,gain,offset
//     (step_*: the motion from the previous frame to this one; clearance_in: corridor_clearance,
//     "inf" when nothing is ahead; blocked = clearance_in <= block_dist; collision: the robot's
//     disc overlaps an obstacle; ticks cumulative since frame 0)
//   columns.csv      one row per frame and column: frame,column,distance_in,boundary_row
//                    (render.h ColumnTruth; distance "inf" when the floor is open)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "camera.h"
#include "image.h"
#include "paths.h"
#include "render.h"
#include "world.h"

namespace bvb {

struct SceneSpec {
  std::string arena = "boxes";
  std::string path = "straight";
  double length_in = 36, angle_deg = 90, side_in = 36;
  bool square_left = true;
  int width = 160, height = 120;
  int frames = 0;  // 0 = auto
  uint64_t seed = 1;
  double noise = 0;
  double speed_in = 0.5, turn_rate_deg = 3;
  double fx = 0;  // 0 = auto
  double cam_height_in = kDefaultCamHeightIn, tilt_deg = kDefaultTiltDeg,
         cam_offset_in = kDefaultCamOffsetIn;
  int supersample = 3;
  std::string mover = "none";
  double flicker = 0;
  int flicker_period = 50;
  int light_step = -1;  // -1 = none
  double step_gain = 1, step_offset = 0;
  double slip = 0, enc_noise = 0, tpi = 50, wheelbase_in = 4;
  double radius_in = kRobotRadiusIn, block_dist_in = 12;
  bool has_start = false;
  Pose start;
  bool has_texture_seed = false;
  uint64_t texture_seed = 0;
  bool write_uyvy = true, write_flow = true, write_rgb = false;
};

// Throws InputError naming the key on an unknown or repeated key or a bad value.
SceneSpec parse_scene_spec(const std::string &spec);
// One line per key, "  key: what it accepts", from the table parse_scene_spec checks with.
std::string scene_spec_ranges();
// Every key, in a fixed order: parse_scene_spec(format_scene_spec(s)) == s.
std::string format_scene_spec(const SceneSpec &s);

struct FrameTruth {
  int frame = 0;
  Pose pose;
  Step step;  // the motion from the previous frame to this one (zero in frame 0)
  bool blocked = false;
  double clearance_in = 0;
  bool collision = false;
  int64_t left_ticks = 0, right_ticks = 0;
  double gain = 1, offset = 0;
};

// A pipeline's steering decision; SceneGenerator::drive_step turns it into one frame's motion.
enum class Drive { Stop, Forward, Left, Right };

// Generates a scene one frame at a time. Scripted use: render()/truth()/columns() for the
// current frame, then advance(). Closed loop: advance(step, true) with the vision's command;
// the robot then stops short of obstacles (the step is not taken when it would collide, though
// the wheels still turn and the encoders count it).
class SceneGenerator {
 public:
  explicit SceneGenerator(const SceneSpec &spec);  // loads spec.arena
  SceneGenerator(const SceneSpec &spec, const World &arena);

  const SceneSpec &spec() const { return spec_; }  // frames resolved
  const Camera &camera() const { return cam_; }
  const World &arena() const { return arena_; }    // with the movers spec.mover selects
  const std::string &script() const { return script_; }  // "avoid" for the oracle driver
  int frame() const { return frame_; }
  int frames() const { return spec_.frames; }
  const Pose &pose() const { return pose_; }

  World world_now() const { return world_at_frame(arena_, frame_); }
  RenderOptions render_options() const;  // lighting and noise of the current frame
  RenderResult render() const;
  ColumnTruth columns() const;
  FrameTruth truth() const;

  // The spec's path's step from the current frame (for avoid: the oracle's decision).
  Step next_step();
  // Forward: spec speed; Left/Right: a turn in place at the spec's turn rate; Stop: nothing.
  Step drive_step(Drive d) const;
  // Moves to the next frame. Returns false when stop_at_obstacles refused a colliding step.
  bool advance(const Step &step, bool stop_at_obstacles);
  bool advance() { return advance(next_step(), false); }

 private:
  void init(const World &arena);
  SceneSpec spec_;
  Camera cam_;
  World arena_;
  std::string script_;
  std::vector<Step> steps_;
  EncoderModel enc_model_;
  Encoders enc_;
  int frame_ = 0;
  Pose pose_;
  Step last_step_;
  int avoid_dir_ = 0;
  double avoid_turned_ = 0;
};

Camera scene_camera(const SceneSpec &s);

// Generates the whole scene into `dir` (written under a temporary name, read back, then
// renamed). An existing `dir` is an error unless `replace` is set and it is empty or holds only
// files a scene writes (scene.txt among them): anything else in it is refused, never deleted.
void write_scene(const SceneSpec &spec, const std::string &dir, bool replace = false);

struct SceneData {
  std::string dir;
  SceneSpec spec;
  Camera camera;
  int frames = 0;
  bool has_uyvy = false, has_flow = false, has_rgb = false;
  World arena;
  std::vector<FrameTruth> truth;      // [frame]
  std::vector<ColumnTruth> columns;   // [frame]

  std::string file(const char *stem, int k, const char *ext) const;
  Image grey(int k) const;
  std::vector<uint8_t> uyvy(int k) const;
  Image rgb(int k) const;
  FlowField flow(int k) const;  // frame k -> k + 1
};

// Reads a scene directory's text files and checks that every frame file it names exists;
// InputError (naming the file and line) on anything malformed.
SceneData read_scene(const std::string &dir);

// read_scene's parsers, one per file, on the file's text (`where` names it in errors): the same
// code read_scene runs, callable without a directory (the fuzz targets in fuzz/ call them).
// scene.txt fills d's spec, camera, frames and has_* flags.
void parse_scene_txt(const std::string &text, const std::string &where, SceneData *d);
std::vector<FrameTruth> parse_truth_csv(const std::string &text, const std::string &where);
// frames, width and height come from scene.txt: the rows must be exactly frames x width.
std::vector<ColumnTruth> parse_columns_csv(const std::string &text, const std::string &where, int frames,
                                           int width, int height);

}  // namespace bvb
